// fp3_top -- the FP3 processor: workload scheduler with NUM_CONTEXTS
// contexts sharing one issue slot (paper §6.3), NUM_LANES lanes that each
// execute every issued instruction on their own register bank and
// arithmetic unit (fp3_lane), busy flags, a host port and a write-back
// trace port.
//
// Lanes: the scheduler, the instruction memory, the decode, the busy flags
// (scoreboard) and the write-back tag lines exist once; the register banks
// and the FP cores are replicated NUM_LANES times (fp3_lane).  Each issue
// of context c runs on lane 0 .. NUM_LANES-1 of c in the same cycle, so
// NUM_CONTEXTS x NUM_LANES objects are in flight, and the issue timing of
// a context does not depend on NUM_LANES, but for beq.  A beq is taken
// only when its operands are bit-identical in every lane of its context
// (the lanes of a context share one PC); otherwise every lane falls
// through.  Exception flags are sticky per context and lane.
//
// Broadcast stages (NUM_LANES > 1): the scheduler drives every lane across
// the die, and lane 0's live value table chooses the RAM of every lane's
// reads (fp3_lane).  So that each of those wires leaves a flip-flop and
// enters one, lane 0 takes the operation stream (read indices, write-back
// tags, operation) through one register of its own and the other lanes
// through two, lane 0's LVT choice reaches them through one more, and the
// lanes register their beq compare; lane 0's results wait a cycle, so that
// every lane's results (and the trace port's write-backs) come LD = 2
// cycles after the tag lines name them.  The scoreboard is unchanged: the
// busy flags take their set and clear in the scheduler's time, and each
// lane sees its reads and write-backs at the same distances as without
// the stages.  What they cost: a beq resolves FP3_LANES_BEQ_CYCLES (3)
// later, a run drains LD cycles longer (FP3_LANES_STAGE_CYCLES), host
// reads take FP3_LANES_HOST_READ_CYCLES (1) more (the other lanes see the
// host's address a cycle after lane 0, for the same LVT choice), and
// 140-180 flip-flops per stage and lane (fp3_lane).  A one-lane build has
// none of them.
//
// Host port: a simple synchronous word port.  A write (host_we_i) takes
// effect at the clock edge; read data for host_addr_i is registered and
// appears on host_rdata_o 1 + 3 FMAX_PIPE cycles later, and one more with
// lanes (the register window's read stages; INFO1 reports FMAX_PIPE and
// INFO2 the lanes, and reading them with the address held for five cycles
// works for every build).  The map (HR_* in
// rtl/fp3_isa.vh, generated from sw/isa/fp3_isa.h) holds control, status,
// counters, configuration, the register window and the program window.
// CTX selects the context whose status and registers the host sees, LANE
// the lane whose registers and flags it sees; CONTEXTS says how many
// contexts (0 .. CONTEXTS-1) a START runs (every lane of each).
// Registers and instruction memory accept writes only while no run is in
// progress; a write while running is ignored, and the register window
// reads as zero while running (the register file's read ports belong to
// the issue pipeline then).
//
// Pipeline of one operation (P = 2 FMAX_PIPE, R = 1 + 3 FMAX_PIPE):
//   pick     (P = 2 only) cycle t - 2: the scheduler grants it, the grant
//            registered; t - 1: its fields are picked, registered
//   issue    cycle t: its register addresses go to the register file
//   read     cycles t + 1 .. t + R: the data leave the register-file RAMs,
//            bypassed (fp3_regfile READ_STAGES = R)
//   unit     the FP cores take ADD_LATENCY / MUL_LATENCY / DIV_LATENCY
//            cycles and the move path 1 + P (WB_PORTS = 1: ADD_LATENCY):
//            write-back in cycle W = t + R + latency.
// The scoreboard hears of a write-back P + R cycles ahead (fp3_wb_tag), so
// that a dependent instruction can issue R - 1 cycles before it and take
// the value from the bypass: it issues 1 + latency cycles after its
// producer for either FMAX_PIPE.  FMAX_PIPE = 1 also registers the fetch
// grant before the instruction memory and the word twice after it (the
// block RAM's output register and one in the fabric; fp3_sched_fetch
// FETCH_STAGE), and cuts the scheduler's loop of readiness and grant
// twice (fp3_sched_queue g_ready_reg, fp3_sched_issue g_grant_reg), for
// which the add, mul and div/sqrt tag lines announce their write-backs two
// more cycles ahead where their latency (5 or more) leaves room.  What it
// costs: a consumer of a move, or of an add, mul, div or sqrt of latency L < 5,
// waits 5 - L cycles more (the move path counts as L = 3), a context is
// granted at most every third cycle and fetches at most every fifth, a
// beq resolves 10 cycles later
// (FP3_BEQ_CYCLES + FP3_FMAX_PIPE_CYCLES), a run takes a few cycles more,
// and host reads take 4 cycles; it needs ADD_LATENCY and MUL_LATENCY of
// at least 3 (and DIV_LATENCY of at least 3).
//
// Trace port (in the spirit of RISC-V RVFI; DESIGN.md "Observe, don't
// stop"): every issue (with its context and unit), every endi and every
// write-back (context, register, value) is visible each cycle, so a host
// can check every result while the machine runs freely.  It adds no state
// but the tags' delay to the lanes' time (LD, above).  A write-back's data
// carry every lane: lane l in bits [32l +: 32] (the context, register and
// valid are the lanes' common ones).
//
// Parameters
//   NUM_CONTEXTS contexts, 1..64                (defaults: sw/isa/fp3_isa.h)
//   NUM_LANES    lanes per context, 1..64 (MAX_LANES): objects in flight
//                NUM_CONTEXTS x NUM_LANES; 1 is the processor without lanes
//   NUM_REGS     registers per context, 2..256
//   IMEM_DEPTH   instruction memory entries, 2..1024
//   ADD_LATENCY  add/sub core latency in cycles (operands to result)
//   MUL_LATENCY  mul core latency in cycles
//   MUL_FEED     1: a fabric register in front of each lane's multiplier
//                DSP blocks (fp_mul FEED; MUL_LATENCY 7 to 10, whose
//                product is in DSP blocks as at MUL_LATENCY - 1): on a
//                chip full of lanes the route to the blocks gets a cycle
//                of its own.  Results as with 0; only the latency counts
//   ROUND        0 round to nearest even, 1 round toward zero
//   FTZ          0 IEEE subnormals, 1 flush subnormals to zero
//   HAS_ADD      0: no add/sub core; add and sub are illegal instructions
//   HAS_SUB      0: the adder only adds; sub is an illegal instruction
//   HAS_MUL      0: no mul core; mul is an illegal instruction
//                (hardware sized to a scene: `fp3 configure`)
//   HAS_SIGN     0: no sign group; abs, neg, min, max are illegal
//                (1: fp_sign on the move path, fp3_arith)
//   HAS_DIV, HAS_SQRT  1: fp_div / fp_sqrt in every lane (fp3_arith's
//                div/sqrt unit, a fourth write-back port and tag line);
//                0: div / sqrt are illegal instructions (the host refuses
//                programs with them before running them).  Reported in
//                INFO2
//   DIV_LATENCY  the div/sqrt unit's latency (fp_div and fp_sqrt LATENCY),
//                1..255, reported in INFO1[26:19]
//   FMAX_PIPE    0: the default pipeline; 1: for clock rate, registers
//                before and after the instruction memory, two in the
//                scheduler's issue loop, two between its grant and the
//                issue, and three more operand-read stages: a LUT-RAM
//                register file (see "Pipeline" above)
//   WB_PORTS     write-back ports of each lane's register file.  4: one
//                per unit (add/sub, mul, move, div/sqrt), each writing
//                RAMs of its own, and a live value table (LVT, 2 bits per
//                register, in flip-flops, with its decoders: about 9,400
//                LUT4s for 512 registers) naming the RAM that holds each
//                register's last value (fp3_regfile).  1: every unit
//                writes back ADD_LATENCY cycles after the operand read, so
//                no two write-backs share a cycle (one issue per cycle)
//                and one port, one RAM per read port and no LVT serve
//                them: the move path is delayed to ADD_LATENCY (a
//                consumer of a move waits that much longer; with many
//                contexts the issue slot does not notice), and the build
//                needs MUL_LATENCY == ADD_LATENCY and no div/sqrt unit
//                (its latency is its own).  Elaboration errors otherwise.
//                The chip build uses 1 (docs/lanes.md)
//   CTX_CHECKED  0: a write to CTX of a number >= NUM_CONTEXTS, or to LANE
//                of one >= NUM_LANES, is ignored here; 1: the host port's
//                writer never makes one (fp3_axil refuses it with SLVERR,
//                deciding it as the data arrive), so the 32-bit compares
//                are left out: CTX's was in front of its enable, a
//                critical path
//   HOST_WSEL    0: a write's register is decoded here from host_addr_i;
//                1: the writer decodes it and gives it on host_wsel_i
//                (fp3_axil: decoded as the address is captured, held
//                with it), so that the 12-bit compares are
//                not in front of the host registers' enables
`default_nettype none
module fp3_top #(
  parameter integer NUM_CONTEXTS = 8,
  parameter integer NUM_LANES    = 1,
  parameter integer NUM_REGS     = 32,
  parameter integer IMEM_DEPTH   = 256,
  parameter integer ADD_LATENCY  = 4,
  parameter integer MUL_LATENCY  = 3,
  parameter integer MUL_FEED     = 0,
  parameter integer ROUND        = 0,
  parameter integer FTZ          = 0,
  parameter integer HAS_ADD      = 1,
  parameter integer HAS_SUB      = 1,
  parameter integer HAS_MUL      = 1,
  parameter integer HAS_DIV      = 1,
  parameter integer HAS_SQRT     = 1,
  parameter integer HAS_SIGN     = 1,
  parameter integer DIV_LATENCY  = 8,
  parameter integer FMAX_PIPE    = 0,
  parameter integer WB_PORTS     = 4,
  parameter integer CTX_CHECKED  = 0,
  parameter integer HOST_WSEL    = 0
) (
  input  wire        clk_i,
  input  wire        rst_i,
  // host port
  input  wire        host_we_i,
  input  wire [11:0] host_addr_i,
  input  wire [31:0] host_wdata_i,
  input  wire [7:0]  host_wsel_i,   // HOST_WSEL = 1: fp3_host_dec of host_addr_i (else unused)
  output wire [31:0] host_rdata_o,
  output wire        running_o,
  output wire        done_o,
  // trace port (contexts as 6-bit numbers; data: lane l in [32l +: 32])
  output wire        tr_issue_o,
  output wire [5:0]  tr_issue_ctx_o,
  output wire [2:0]  tr_issue_unit_o,
  output wire        tr_endi_o,
  output wire        tr_add_valid_o,
  output wire [5:0]  tr_add_ctx_o,
  output wire [7:0]  tr_add_reg_o,
  output wire [32*NUM_LANES-1:0] tr_add_data_o,
  output wire        tr_mul_valid_o,
  output wire [5:0]  tr_mul_ctx_o,
  output wire [7:0]  tr_mul_reg_o,
  output wire [32*NUM_LANES-1:0] tr_mul_data_o,
  output wire        tr_mov_valid_o,
  output wire [5:0]  tr_mov_ctx_o,
  output wire [7:0]  tr_mov_reg_o,
  output wire [32*NUM_LANES-1:0] tr_mov_data_o,
  output wire        tr_div_valid_o,
  output wire [5:0]  tr_div_ctx_o,
  output wire [7:0]  tr_div_reg_o,
  output wire [32*NUM_LANES-1:0] tr_div_data_o
);
`include "fp3_isa.vh"

  localparam integer IW = (NUM_REGS <= 2) ? 1 : $clog2(NUM_REGS);
  localparam integer CW = (NUM_CONTEXTS <= 2) ? 1 : $clog2(NUM_CONTEXTS);
  localparam integer LW = (NUM_LANES <= 2) ? 1 : $clog2(NUM_LANES);   // LANE's width
  localparam integer NL = NUM_LANES;
  localparam integer XW = CW + IW;
  localparam integer AW = (IMEM_DEPTH <= 2) ? 1 : $clog2(IMEM_DEPTH);
  localparam integer PICK  = 2 * FMAX_PIPE;  // pick stages
  localparam integer READ  = 1 + 3 * FMAX_PIPE;  // operand-read stages, host read cycles
  localparam integer AHEAD = PICK + READ;    // write-back announcement
  // With lanes, the broadcast stages (fp3_lane IN_STAGES, OUT_STAGES,
  // EQ_STAGE, HOST_STAGES; "Broadcast stages" above): BC registers at lane
  // 0's inputs, 2 BC at the other lanes' (lane 0's LVT choice and the host
  // port reach them through one more), the results of every lane LD cycles
  // after the tag lines name them, and the beq compare registered in the
  // lane (BC).
  localparam integer BC = (NUM_LANES > 1) ? 1 : 0;
  localparam integer LD = 2 * BC;
  // The move path's latency: with the pick stages, PICK more, so that its
  // announcement comes after its issue (the issue sets the busy flag).
  // With one write-back port (WB_PORTS = 1) the add/sub core's, so that
  // no two units write back in one cycle.
  localparam [0:0]   WB1 = WB_PORTS == 1;
`ifdef FP3_MUTANT_MOV_SHORT
  // A broken build for formal/sched.sby's mutant_wb1: the move path a
  // cycle shorter than the add/sub core, so that a move and an add issued
  // a cycle apart write back in one cycle.
  localparam integer MOV_LATENCY = WB1 ? ADD_LATENCY - 1 : 1 + PICK;
`else
  localparam integer MOV_LATENCY = WB1 ? ADD_LATENCY : 1 + PICK;
`endif
  // The div/sqrt unit is built (either core): else its tag line never
  // starts an operation, and synthesis removes it and its compares.
  localparam [0:0] HAS_DSU = HAS_DIV != 0 || HAS_SQRT != 0;

  generate
    if (NUM_LANES < 1 || NUM_LANES > MAX_LANES) begin : g_bad_lanes
      // Elaboration error on purpose: LANE, INFO2[31:24] and the trace
      // port's data are sized for 1 .. MAX_LANES lanes.
      fp3_top_error_NUM_LANES_must_be_1_to_64 u_error ();
    end
    if (FMAX_PIPE != 0 && (ADD_LATENCY < 3 || MUL_LATENCY < 3 || DIV_LATENCY < 3))
    begin : g_bad_latency
      // Elaboration error on purpose: the announcement of a write-back
      // (and the cycle before it, fp3_wb_tag early_*) must come after the
      // issue that sets its busy flag: latency >= PICK + 1.
      fp3_top_error_FMAX_PIPE_needs_ADD_MUL_and_DIV_LATENCY_of_at_least_3 u_error ();
    end
    if (WB_PORTS != 1 && WB_PORTS != 4) begin : g_bad_wb_ports
      // Elaboration error on purpose: one port per unit, or one for all.
      fp3_top_error_WB_PORTS_must_be_1_or_4 u_error ();
    end
    if (WB_PORTS == 1 && (ADD_LATENCY != MUL_LATENCY || HAS_DIV != 0 || HAS_SQRT != 0))
    begin : g_bad_wb_one
      // Elaboration error on purpose: one write-back port needs every
      // unit's results ADD_LATENCY cycles after its issue (the move path
      // is delayed to it; the div/sqrt unit's latency is its own).
      fp3_top_error_WB_PORTS_1_needs_ADD_LATENCY_equal_to_MUL_LATENCY_and_no_div_sqrt u_error ();
    end
    if (DIV_LATENCY < 1 || DIV_LATENCY > 255) begin : g_bad_div_latency
      // Elaboration error on purpose: INFO1 reports DIV_LATENCY in 8 bits.
      fp3_top_error_DIV_LATENCY_must_be_1_to_255 u_error ();
    end
  endgenerate

  // ---- host port decode ----------------------------------------------------
  // The register or window host_addr_i names (hsel: reads, and writes
  // with HOST_WSEL = 0), and the one a write takes (wsel): fp3_host_dec's
  // one-hot {LANE, program high word, program low word, register window,
  // CTX, CONTEXTS, STEPS, CTRL}.
  wire [7:0]  hsel, wsel;
  wire        hsel_imem_ok;   // (hsel[6] has it for the writes)
  fp3_host_dec #(.NUM_REGS(NUM_REGS), .IW(IW), .IMEM_DEPTH(IMEM_DEPTH), .AW(AW)) u_host_dec (
    .addr_i    (host_addr_i),
    .wsel_o    (hsel),
    .imem_ok_o (hsel_imem_ok)
  );
  generate
    if (HOST_WSEL != 0) begin : g_wsel_in
      assign wsel = host_wsel_i;
      wire unused_hsel = &{1'b0, hsel[7:5], hsel[3:0], hsel_imem_ok};   // (reads use hsel[4])
    end else begin : g_wsel_here
      assign wsel = hsel;
      wire unused_wsel = &{1'b0, host_wsel_i, hsel_imem_ok};
    end
  endgenerate
  wire [AW-1:0] imem_idx = host_addr_i[AW:1];   // (hsel checks its range)

  wire        running;
  wire [NL-1:0] run_l;     // RUNNING's copies, one per lane's read address (fp3_sched_loop)
  reg  [31:0] steps_q;
  reg  [31:0] contexts_q;
  reg  [CW-1:0] ctx_q;     // context the host sees
  reg  [LW-1:0] lane_q;    // lane the host sees
  reg  [31:0] imem_lo_q;   // low half of an instruction being written

  wire host_idle   = !running;
  // A write to CTX taken (ctx_q and its copies, below)
  wire ctx_we      = host_we_i && host_idle && wsel[3] &&
                     (CTX_CHECKED != 0 || host_wdata_i < NUM_CONTEXTS);
  // ... and to LANE
  wire lane_we     = host_we_i && host_idle && wsel[7] &&
                     (CTX_CHECKED != 0 || host_wdata_i < NUM_LANES);
  wire wr_ctrl     = host_we_i && wsel[0];
  wire start       = wr_ctrl && host_wdata_i[0];
  wire clear       = wr_ctrl && host_wdata_i[1];
  wire host_reg_we = host_we_i && host_idle && wsel[4];
  wire imem_we     = host_we_i && host_idle && wsel[6];
  // the instruction word a write of its high half completes
  wire [63:0] imem_wdata = {host_wdata_i, imem_lo_q};

  // What a START needs of STEPS and CONTEXTS, decided as the host writes
  // them (the scheduler's START then compares nothing 32 bits wide): STEPS
  // is 0, is 1, STEPS - 2; CONTEXTS is outside 1..NUM_CONTEXTS; the
  // contexts it starts (k < CONTEXTS), one bit each.
  reg                    steps_zero_q, steps_one_q, contexts_bad_q;
  reg  [31:0]            steps_last2_q;
  reg  [NUM_CONTEXTS-1:0] contexts_run_q;
  integer k;
  always @(posedge clk_i) begin
    if (rst_i) begin
      steps_q        <= 32'd0;
      steps_zero_q   <= 1'b1;
      steps_one_q    <= 1'b0;
      steps_last2_q  <= 32'hffff_fffe;
      contexts_q     <= 32'd1;
      contexts_bad_q <= 1'b0;
      contexts_run_q <= {{(NUM_CONTEXTS-1){1'b0}}, 1'b1};
      ctx_q          <= {CW{1'b0}};
      lane_q         <= {LW{1'b0}};
    end else if (host_we_i && host_idle) begin
      if (wsel[1]) begin
        steps_q       <= host_wdata_i;
        steps_zero_q  <= host_wdata_i == 32'd0;
        steps_one_q   <= host_wdata_i == 32'd1;
        steps_last2_q <= host_wdata_i - 32'd2;
      end
      if (wsel[2]) begin
        contexts_q     <= host_wdata_i;
        contexts_bad_q <= host_wdata_i == 32'd0 || host_wdata_i > NUM_CONTEXTS;
        for (k = 0; k < NUM_CONTEXTS; k = k + 1) contexts_run_q[k] <= k < host_wdata_i;
      end
      if (ctx_we)                     ctx_q      <= host_wdata_i[CW-1:0];
      if (lane_we)                    lane_q     <= host_wdata_i[LW-1:0];
    end
    if (host_we_i && wsel[5]) imem_lo_q <= host_wdata_i;
  end
  // CTX's copies for the selected context's words, kept, each placed
  // beside its multiplexers: the scheduler's (STATUS's error, FAULT_PC,
  // STEPS_DONE: ctx_sch) and the flags' (FLAGS: ctx_flg).  ctx_q, which
  // also indexes the register file's host port, across the die to the
  // flags' multiplexer is otherwise a critical path of the placement.
  wire [CW-1:0] ctx_sch, ctx_flg;
  fp3_keep #(.W(CW)) u_ctx_sch (
    .clk_i (clk_i),
    .d_i   (rst_i ? {CW{1'b0}} : ctx_we ? host_wdata_i[CW-1:0] : ctx_sch),
    .q_o   (ctx_sch)
  );
  fp3_keep #(.W(CW)) u_ctx_flg (
    .clk_i (clk_i),
    .d_i   (rst_i ? {CW{1'b0}} : ctx_we ? host_wdata_i[CW-1:0] : ctx_flg),
    .q_o   (ctx_flg)
  );

  // ---- scheduler -----------------------------------------------------------
  wire          done, any_error;
  wire [3:0]    error;
  wire [31:0]   fault_pc, steps_done;
  wire [63:0]   cycles, issued, stalls;
  wire [XW-1:0] ra, rb, rd;
  wire [CW-1:0] issue_ctx;
  wire          idle;
  wire          issue, issue_sub, issue_imm, endi, beq;
  wire [2:0]    issue_sop;                // sign group: {abs/neg/min/max, fp_sign op}
  reg           br_taken_q;               // beq resolution (read stage)
  reg [NUM_CONTEXTS-1:0] br_q;            // ... its context, one-hot (none: no beq)
  reg [AW-1:0]  br_target_q;
  wire [2:0]    issue_unit;
  wire [31:0]   imm;
  wire [(1<<XW)-1:0] busy;
  // The four write-back ports' tag lines: add, mul, move, div/sqrt (div).
  wire          add_valid, mul_valid, mov_valid, div_valid;
  wire [XW-1:0] add_idx, mul_idx, mov_idx, div_idx;
  wire          adda_valid, mula_valid, mova_valid, diva_valid;   // write-backs AHEAD cycles on
  wire [XW-1:0] adda_idx, mula_idx, mova_idx, diva_idx;
  wire          adde_valid, mule_valid, move_valid, dive_valid;   // ... and a cycle before that
  wire [XW-1:0] adde_idx, mule_idx, move_idx, dive_idx;
  wire          addp_valid, mulp_valid, movp_valid, divp_valid;   // ... and a cycle before that
  wire [XW-1:0] addp_idx, mulp_idx, movp_idx, divp_idx;
  wire          addp2_valid, mulp2_valid, movp2_valid, divp2_valid;   // ... and before that
  wire [XW-1:0] addp2_idx, mulp2_idx, movp2_idx, divp2_idx;
  wire          addp3_valid, mulp3_valid, movp3_valid, divp3_valid;   // ... and before that
  wire [XW-1:0] addp3_idx, mulp3_idx, movp3_idx, divp3_idx;
  wire          addn_valid, muln_valid, movn_valid, divn_valid;   // write-backs in two cycles
  wire [XW-1:0] addn_idx, muln_idx, movn_idx, divn_idx;
  wire          pick_wr;                              // the next issue's destination
  wire [XW-1:0] pick_rd;
  wire [2:0]    pick_unit;
  wire          pick_mov = pick_wr && pick_unit == UNIT_MOV;   // ... to the move path

  fp3_scheduler #(.NUM_CONTEXTS(NUM_CONTEXTS), .CW(CW), .NUM_REGS(NUM_REGS), .IW(IW),
                  .IMEM_DEPTH(IMEM_DEPTH), .AW(AW), .HAS_ADD(HAS_ADD),
                  .HAS_SUB(HAS_SUB), .HAS_MUL(HAS_MUL), .HAS_DIV(HAS_DIV), .HAS_SQRT(HAS_SQRT),
                  .HAS_SIGN(HAS_SIGN), .PICK_STAGES(PICK),
                  .FETCH_STAGE(FMAX_PIPE), .DRAIN(AHEAD + LD), .RUN_COPIES(NL),
                  .MOV_LONG(WB1 ? 1 : 0)) u_sched (
    .clk_i            (clk_i),
    .rst_i            (rst_i),
    .imem_we_i        (imem_we),
    .imem_waddr_i     (imem_idx),
    .imem_wdata_i     (imem_wdata),
    .start_i          (start),
    .clear_i          (clear),
    .steps_zero_i     (steps_zero_q),
    .steps_one_i      (steps_one_q),
    .steps_last2_i    (steps_last2_q),
    .contexts_bad_i   (contexts_bad_q),
    .contexts_run_i   (contexts_run_q),
    .sel_ctx_i        (ctx_sch),
    .running_o        (running),
    .run_copy_o       (run_l),
    .done_o           (done),
    .any_error_o      (any_error),
    .error_sel_o      (error),
    .fault_pc_sel_o   (fault_pc),
    .steps_done_sel_o (steps_done),
    .cycles_o         (cycles),
    .issued_o         (issued),
    .stalls_o         (stalls),
    .busy_i           (busy),
    .ahead_valid_i    ({diva_valid, mova_valid, mula_valid, adda_valid}),
    .ahead_idx_i      ({diva_idx, mova_idx, mula_idx, adda_idx}),
    .early_valid_i    ({dive_valid, move_valid, mule_valid, adde_valid}),
    .early_idx_i      ({dive_idx, move_idx, mule_idx, adde_idx}),
    .pre_valid_i      ({divp_valid, movp_valid, mulp_valid, addp_valid}),
    .pre_idx_i        ({divp_idx, movp_idx, mulp_idx, addp_idx}),
    .pre2_valid_i     ({divp2_valid, movp2_valid, mulp2_valid, addp2_valid}),
    .pre2_idx_i       ({divp2_idx, movp2_idx, mulp2_idx, addp2_idx}),
    .pre3_valid_i     ({divp3_valid, movp3_valid, mulp3_valid, addp3_valid}),
    .pre3_idx_i       ({divp3_idx, movp3_idx, mulp3_idx, addp3_idx}),
    .idle_i           (idle),
    .br_i             (br_q),
    .br_taken_i       (br_taken_q),
    .br_target_i      (br_target_q),
    .issue_o          (issue),
    .issue_ctx_o      (issue_ctx),
    .ra_o             (ra),
    .rb_o             (rb),
    .rd_o             (rd),
    .issue_unit_o     (issue_unit),
    .issue_sub_o      (issue_sub),
    .issue_sop_o      (issue_sop),
    .issue_imm_o      (issue_imm),
    .imm_o            (imm),
    .endi_o           (endi),
    .beq_o            (beq),
    .pick_wr_o        (pick_wr),
    .pick_rd_o        (pick_rd),
    .pick_unit_o      (pick_unit)
  );

  // ---- lanes: register banks and arithmetic units -------------------------
  // Banks are indexed {context, register}: 2**XW entries; the banks of
  // contexts >= NUM_CONTEXTS are never written and synthesize away.
  // With the pick stages the busy flags take their set and clear a cycle
  // ahead (fp3_regfile FLAGS_AHEAD): the instruction picked and the tag
  // lines' early announcements.  Every lane sees the same indices; lane
  // 0's busy flags are the scoreboard, and its live value table chooses
  // the RAM of every lane's reads (fp3_lane; lanes 1 .. have neither).
  // The host writes the lane LANE names.
  wire [32*NL-1:0] ra_data_l;                       // lane l in [32l +: 32]
  wire [NL-1:0]    eq_l;                             // lane l's operands are equal
  wire [32*NL-1:0] add_data_l, mul_data_l, mov_data_l, div_data_l;
  wire [5*NL-1:0]  add_flags_l, mul_flags_l, mov_flags_l, div_flags_l;
  wire [(1<<XW)*NL-1:0] busy_l;
  wire [NL-1:0]    idle_l;
  wire [4*NL-1:0]  lvt_a_l, lvt_b_l;                 // LVT choices (lane 0's used)
  wire [3:0]       lvt_a_bc, lvt_b_bc;               // ... as lanes 1 .. take it
  generate
    if (BC != 0) begin : g_lvt_stage
      // Lanes 1 .. run a cycle behind lane 0: its choice, registered.
      fp3_keep #(.W(8)) u_lvt (
        .clk_i (clk_i),
        .d_i   ({lvt_a_l[3:0], lvt_b_l[3:0]}),
        .q_o   ({lvt_a_bc, lvt_b_bc})
      );
    end else begin : g_lvt_now
      assign {lvt_a_bc, lvt_b_bc} = {lvt_a_l[3:0], lvt_b_l[3:0]};
    end
  endgenerate
  // The read stage's operation, for every lane (below)
  wire          rd_valid, rd_sub, rd_imm, rd_beq;
  wire [2:0]    rd_sop;
  wire [2:0]    rd_unit;
  wire [31:0]   rd_immval;
  wire [CW-1:0] rd_ctx;
  genvar ln;
  generate
    for (ln = 0; ln < NL; ln = ln + 1) begin : g_lane
      fp3_lane #(.ENTRIES(1 << XW), .XW(XW), .READ_STAGES(READ), .FLAGS_AHEAD(FMAX_PIPE),
                 .CTRL(ln == 0 ? 1 : 0), .HOST_ALL(NL > 1 ? 1 : 0), .WB_PORTS(WB_PORTS),
                 .ADD_LATENCY(ADD_LATENCY), .MUL_LATENCY(MUL_LATENCY), .MUL_FEED(MUL_FEED),
                 .MOV_LATENCY(MOV_LATENCY), .DIV_LATENCY(DIV_LATENCY), .ROUND(ROUND),
                 .FTZ(FTZ), .HAS_ADD(HAS_ADD), .HAS_SUB(HAS_SUB), .HAS_MUL(HAS_MUL),
                 .HAS_DIV(HAS_DIV), .HAS_SQRT(HAS_SQRT), .HAS_SIGN(HAS_SIGN),
                 .IN_STAGES(ln == 0 ? BC : 2 * BC), .OUT_STAGES(ln == 0 ? BC : 0),
                 .EQ_STAGE(BC), .HOST_STAGES(ln == 0 ? 0 : BC)) u_lane (
        .clk_i           (clk_i),
        .rst_i           (rst_i),
        .ra_i            (ra),
        .rb_i            (rb),
        .ra_data_o       (ra_data_l[32*ln +: 32]),
        .eq_o            (eq_l[ln]),
        .busy_o          (busy_l[(1<<XW)*ln +: (1<<XW)]),
        .set_i           (pick_wr),
        .set_idx_i       (pick_rd),
        .clr0_valid_i    (FMAX_PIPE != 0 ? adde_valid : adda_valid),
        .clr0_idx_i      (FMAX_PIPE != 0 ? adde_idx   : adda_idx),
        .clr1_valid_i    (FMAX_PIPE != 0 ? mule_valid : mula_valid),
        .clr1_idx_i      (FMAX_PIPE != 0 ? mule_idx   : mula_idx),
        .clr2_valid_i    (FMAX_PIPE != 0 ? move_valid : mova_valid),
        .clr2_idx_i      (FMAX_PIPE != 0 ? move_idx   : mova_idx),
        .clr3_valid_i    (FMAX_PIPE != 0 ? dive_valid : diva_valid),
        .clr3_idx_i      (FMAX_PIPE != 0 ? dive_idx   : diva_idx),
        .wb0_valid_i     (add_valid),
        .wb0_idx_i       (add_idx),
        .wb1_valid_i     (mul_valid),
        .wb1_idx_i       (mul_idx),
        .wb2_valid_i     (mov_valid),
        .wb2_idx_i       (mov_idx),
        .wb3_valid_i     (div_valid),
        .wb3_idx_i       (div_idx),
        .wb0_in2_valid_i (addn_valid),
        .wb0_in2_idx_i   (addn_idx),
        .wb1_in2_valid_i (muln_valid),
        .wb1_in2_idx_i   (muln_idx),
        .wb2_in2_valid_i (movn_valid),
        .wb2_in2_idx_i   (movn_idx),
        .wb3_in2_valid_i (divn_valid),
        .wb3_in2_idx_i   (divn_idx),
        .host_sel_i      (!run_l[ln]),
        .host_we_i       (host_reg_we && lane_q == ln[LW-1:0]),
        .host_idx_i      ({ctx_q, host_addr_i[IW-1:0]}),
        .host_wdata_i    (host_wdata_i),
        .idle_o          (idle_l[ln]),
        .lvt_a_o         (lvt_a_l[4*ln +: 4]),
        .lvt_b_o         (lvt_b_l[4*ln +: 4]),
        .lvt_a_i         (lvt_a_bc),
        .lvt_b_i         (lvt_b_bc),
        .valid_i         (rd_valid),
        .unit_i          (rd_unit),
        .sub_i           (rd_sub),
        .sop_i           (rd_sop),
        .imm_i           (rd_imm),
        .imm_val_i       (rd_immval),
        .add_data_o      (add_data_l[32*ln +: 32]),
        .add_flags_o     (add_flags_l[5*ln +: 5]),
        .mul_data_o      (mul_data_l[32*ln +: 32]),
        .mul_flags_o     (mul_flags_l[5*ln +: 5]),
        .mov_data_o      (mov_data_l[32*ln +: 32]),
        .mov_flags_o     (mov_flags_l[5*ln +: 5]),
        .div_data_o      (div_data_l[32*ln +: 32]),
        .div_flags_o     (div_flags_l[5*ln +: 5])
      );
    end
  endgenerate
  assign busy = busy_l[(1<<XW)-1:0];
  assign idle = idle_l[0];
  // (lanes 1 .. NL-1 have no flags: constant; their LVT outputs repeat
  // lane 0's choice)
  wire unused_lane_flags = &{1'b0, busy_l, idle_l, lvt_a_l, lvt_b_l};

  // ---- operand-read stages ------------------------------------------------
  // The register file answers a read of the issue cycle t in cycle t + READ;
  // the rest of the issued operation waits beside it (one copy for all
  // lanes).
  fp_pipe #(.WIDTH(3 + 1 + 3 + 1 + 32 + CW), .DEPTH(READ)) u_read (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (issue && issue_unit != UNIT_NONE),
    .data_i  ({issue_unit, issue_sub, issue_sop, issue_imm, imm, issue_ctx}),
    .valid_o (rd_valid),
    .data_o  ({rd_unit, rd_sub, rd_sop, rd_imm, rd_immval, rd_ctx})
  );
  // A beq (no unit) rides in a valid bit of its own, which reset clears:
  // as a data bit it would leave reset holding whatever it held, and an
  // outcome of it could reach a run started within READ + LD + BC
  // cycles of the reset (formal/sched.sby bmc_fmax_lanes).
  wire rd_beq_nil;   // (no data: the valid bit is the beq)
  wire unused_rd_beq_nil = &{1'b0, rd_beq_nil};
  fp_pipe #(.WIDTH(1), .DEPTH(READ)) u_read_beq (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (issue && beq),
    .data_i  (1'b0),
    .valid_o (rd_beq),
    .data_o  (rd_beq_nil)
  );

  // ---- write-back tag lines ------------------------------------------------
  fp3_wb_tag #(.XW(XW), .ISSUE_TO_WB(READ + ADD_LATENCY), .AHEAD(AHEAD)) u_add_tag (
    .clk_i         (clk_i),
    .rst_i         (rst_i),
    .valid_i       (issue && issue_unit == UNIT_ADD),
    .idx_i         (rd),
    .pvalid_i      (pick_wr && pick_unit == UNIT_ADD),
    .pidx_i        (pick_rd),
    .pre_valid_o   (addp_valid),
    .pre_idx_o     (addp_idx),
    .pre2_valid_o  (addp2_valid),
    .pre2_idx_o    (addp2_idx),
    .pre3_valid_o  (addp3_valid),
    .pre3_idx_o    (addp3_idx),
    .early_valid_o (adde_valid),
    .early_idx_o   (adde_idx),
    .ahead_valid_o (adda_valid),
    .ahead_idx_o   (adda_idx),
    .next2_valid_o (addn_valid),
    .next2_idx_o   (addn_idx),
    .wb_valid_o    (add_valid),
    .wb_idx_o      (add_idx)
  );
  fp3_wb_tag #(.XW(XW), .ISSUE_TO_WB(READ + MUL_LATENCY), .AHEAD(AHEAD)) u_mul_tag (
    .clk_i         (clk_i),
    .rst_i         (rst_i),
    .valid_i       (issue && issue_unit == UNIT_MUL),
    .idx_i         (rd),
    .pvalid_i      (pick_wr && pick_unit == UNIT_MUL),
    .pidx_i        (pick_rd),
    .pre_valid_o   (mulp_valid),
    .pre_idx_o     (mulp_idx),
    .pre2_valid_o  (mulp2_valid),
    .pre2_idx_o    (mulp2_idx),
    .pre3_valid_o  (mulp3_valid),
    .pre3_idx_o    (mulp3_idx),
    .early_valid_o (mule_valid),
    .early_idx_o   (mule_idx),
    .ahead_valid_o (mula_valid),
    .ahead_idx_o   (mula_idx),
    .next2_valid_o (muln_valid),
    .next2_idx_o   (muln_idx),
    .wb_valid_o    (mul_valid),
    .wb_idx_o      (mul_idx)
  );
`ifdef FP3_MUTANT_DIV_TAG_SHORT
  // A broken line for formal/sched.sby's mutant_div: a stage short, so the
  // div/sqrt unit's write-backs are announced, and their indices written
  // back, a cycle before the results exist.
  localparam integer DIV_TAG_CUT = 1;
`else
  localparam integer DIV_TAG_CUT = 0;
`endif
  fp3_wb_tag #(.XW(XW), .ISSUE_TO_WB(READ + DIV_LATENCY - DIV_TAG_CUT), .AHEAD(AHEAD)) u_div_tag (
    .clk_i         (clk_i),
    .rst_i         (rst_i),
    .valid_i       (HAS_DSU && issue && issue_unit == UNIT_DIV),
    .idx_i         (rd),
    .pvalid_i      (HAS_DSU && pick_wr && pick_unit == UNIT_DIV),
    .pidx_i        (pick_rd),
    .pre_valid_o   (divp_valid),
    .pre_idx_o     (divp_idx),
    .pre2_valid_o  (divp2_valid),
    .pre2_idx_o    (divp2_idx),
    .pre3_valid_o  (divp3_valid),
    .pre3_idx_o    (divp3_idx),
    .early_valid_o (dive_valid),
    .early_idx_o   (dive_idx),
    .ahead_valid_o (diva_valid),
    .ahead_idx_o   (diva_idx),
    .next2_valid_o (divn_valid),
    .next2_idx_o   (divn_idx),
    .wb_valid_o    (div_valid),
    .wb_idx_o      (div_idx)
  );
  // The move path's tag line announces a cycle after the issue at the
  // latest (MOV_LATENCY = 1 + PICK, so its early_* are its input).  With
  // the pick stages its input is a copy of the issue register's move and
  // destination, registered from the pick and kept (else Yosys merges it
  // with the issue register), so that the announcement's compares in the
  // scheduler and the register file hang on a register of their own, not
  // on the issue register across the die (a critical path: 5.9 ns of
  // routing).
  // With one write-back port the move line is as long as the add line
  // and takes its input as that does.
  wire          mov_issue;
  wire [XW-1:0] mov_rd;
  generate
    if (PICK != 0 && !WB1) begin : g_mov_copy
      fp3_keep #(.W(1 + XW)) u_mov_copy (
        .clk_i (clk_i),
        .d_i   ({pick_mov, pick_rd}),
        .q_o   ({mov_issue, mov_rd})
      );
    end else begin : g_mov_issue
      assign mov_issue = issue && issue_unit == UNIT_MOV;
      assign mov_rd    = rd;
    end
  endgenerate
  fp3_wb_tag #(.XW(XW), .ISSUE_TO_WB(READ + MOV_LATENCY), .AHEAD(AHEAD)) u_mov_tag (
    .clk_i         (clk_i),
    .rst_i         (rst_i),
    .valid_i       (mov_issue),
    .idx_i         (mov_rd),
    .pvalid_i      (pick_mov),
    .pidx_i        (pick_rd),
    .pre_valid_o   (movp_valid),
    .pre_idx_o     (movp_idx),
    .pre2_valid_o  (movp2_valid),
    .pre2_idx_o    (movp2_idx),
    .pre3_valid_o  (movp3_valid),
    .pre3_idx_o    (movp3_idx),
    .early_valid_o (move_valid),
    .early_idx_o   (move_idx),
    .ahead_valid_o (mova_valid),
    .ahead_idx_o   (mova_idx),
    .next2_valid_o (movn_valid),
    .next2_idx_o   (movn_idx),
    .wb_valid_o    (mov_valid),
    .wb_idx_o      (mov_idx)
  );

  // ---- the write-backs in the lanes' time --------------------------------
  // The tag lines LD cycles late: the cycle in which the lanes' results
  // (fp3_lane {add,mul,mov,div}_data_o) are those the tags name, for the
  // trace port and the sticky flags.
  wire          lt_add_valid, lt_mul_valid, lt_mov_valid, lt_div_valid;
  wire [XW-1:0] lt_add_idx, lt_mul_idx, lt_mov_idx, lt_div_idx;
  fp_pipe #(.WIDTH(XW), .DEPTH(LD)) u_lt_add (
    .clk_i (clk_i), .rst_i (rst_i), .valid_i (add_valid), .data_i (add_idx),
    .valid_o (lt_add_valid), .data_o (lt_add_idx));
  fp_pipe #(.WIDTH(XW), .DEPTH(LD)) u_lt_mul (
    .clk_i (clk_i), .rst_i (rst_i), .valid_i (mul_valid), .data_i (mul_idx),
    .valid_o (lt_mul_valid), .data_o (lt_mul_idx));
  fp_pipe #(.WIDTH(XW), .DEPTH(LD)) u_lt_mov (
    .clk_i (clk_i), .rst_i (rst_i), .valid_i (mov_valid), .data_i (mov_idx),
    .valid_o (lt_mov_valid), .data_o (lt_mov_idx));
  fp_pipe #(.WIDTH(XW), .DEPTH(LD)) u_lt_div (
    .clk_i (clk_i), .rst_i (rst_i), .valid_i (div_valid), .data_i (div_idx),
    .valid_o (lt_div_valid), .data_o (lt_div_idx));

  // ---- branch resolution -------------------------------------------------
  // A beq's operands, read like any others, are compared in each lane (a
  // 32-bit equality of bit patterns: fp3_lane eq_o, LD + BC cycles after
  // the read stage) and the outcome registered here: taken only if equal
  // in every lane.  The scheduler sees it READ + 1 + LD + BC cycles after
  // the issue, its context decoded.
  wire          bq_beq;
  wire [CW-1:0] bq_ctx;
  wire [AW-1:0] bq_target;
  fp_pipe #(.WIDTH(CW + AW), .DEPTH(LD + BC)) u_br (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (rd_beq),
    .data_i  ({rd_ctx, rd_immval[AW-1:0]}),
    .valid_o (bq_beq),
    .data_o  ({bq_ctx, bq_target})
  );
  integer bc;
  always @(posedge clk_i) begin
    for (bc = 0; bc < NUM_CONTEXTS; bc = bc + 1)
      br_q[bc] <= !rst_i && bq_beq && bq_ctx == bc[CW-1:0];
    br_taken_q  <= &eq_l;
    br_target_q <= bq_target;
  end

  // ---- sticky exception flags of the run, per context and lane -------------
  // Cleared in the run's first cycle, a cycle after its START (fclr_q; as
  // the scheduler clears its counters), in which nothing has issued yet:
  // so the host port's decode does not reach the flags.
  reg fclr_q;
  always @(posedge clk_i) fclr_q <= start && host_idle;
  // Each lane keeps its flags in an array of its own, indexed by context,
  // so that the host's selection is a context multiplexer in each lane and
  // a lane multiplexer behind them (an index context * NL + lane would
  // make Yosys build a multiplier and an adder into the host's read path
  // when NL is not a power of two).
  //
  // The flags take their inputs a cycle late: each lane registers the four
  // write-back tag lines' valid and context (copies of its own, fp3_keep,
  // so each is placed by its lane's flags and not by the tag line) and its
  // cores' flags, and decodes the context from those registers.  So the
  // route from the tag lines across the die to every lane has a cycle of
  // its own with no logic in it; it cost one flip-flop per bit (4 x (1 +
  // CW) + 20 a lane).  The host's FLAGS read ORs the staged cycle into the
  // array (flags_ctx), so it sees every write-back up to the previous
  // cycle, as if the flags took their inputs directly.
  wire [4*(1+CW)-1:0] wb_tags = {lt_div_valid, lt_div_idx[XW-1:IW], lt_mov_valid,
                                 lt_mov_idx[XW-1:IW], lt_mul_valid, lt_mul_idx[XW-1:IW],
                                 lt_add_valid, lt_add_idx[XW-1:IW]};
  wire [5*NL-1:0]     flags_ctx;  // lane l's flags of context ctx_flg in [5l +: 5]
  // The flags that staged tags (tags, as wb_tags) and staged core flags
  // (fl: add, mul, mov, div, 5 bits each) bring to context ctx: the OR of
  // the units whose tag is valid and names ctx.
  function [4:0] staged_flags(input [4*(1+CW)-1:0] tags, input [19:0] fl, input [CW-1:0] ctx);
    integer u;
    begin
      staged_flags = 5'd0;
      for (u = 0; u < 4; u = u + 1)
        if (tags[(1+CW)*u + CW] && tags[(1+CW)*u +: CW] == ctx)
          staged_flags = staged_flags | fl[5*u +: 5];
    end
  endfunction
  genvar fc, fl;
  generate
    for (fl = 0; fl < NL; fl = fl + 1) begin : g_lane_flags
      wire [4*(1+CW)-1:0] tags_q;   // this lane's copy of wb_tags, a cycle late
      fp3_keep #(.W(4*(1+CW))) u_tags (
        .clk_i (clk_i),
        .d_i   (rst_i ? {4*(1+CW){1'b0}} : wb_tags),
        .q_o   (tags_q)
      );
      reg  [19:0] fl_q;             // the cores' flags, a cycle late: add, mul, mov, div
      always @(posedge clk_i)
        fl_q <= {div_flags_l[5*fl +: 5], mov_flags_l[5*fl +: 5],
                 mul_flags_l[5*fl +: 5], add_flags_l[5*fl +: 5]};
      // in_q[c]: this lane's staged flags of context c (all units' ORed)
      wire [5*NUM_CONTEXTS-1:0] in_q;
      for (fc = 0; fc < NUM_CONTEXTS; fc = fc + 1) begin : g_in
        assign in_q[5*fc +: 5] = staged_flags(tags_q, fl_q, fc[CW-1:0]);
      end
      reg [4:0] flags_q [0:NUM_CONTEXTS-1];  // sticky exception flags of this lane, by context
      for (fc = 0; fc < NUM_CONTEXTS; fc = fc + 1) begin : g_flags
        always @(posedge clk_i) begin
          if (rst_i || fclr_q) flags_q[fc] <= 5'd0;
          else flags_q[fc] <= flags_q[fc] | in_q[5*fc +: 5];
        end
      end
      // The staged cycle's flags of context ctx_flg, from the staged tags
      // compared with ctx_flg itself (in_q indexed by ctx_flg would be a
      // shifter by 5 * ctx_flg, several hundred LUTs a lane).
      wire [4:0] in_sel = staged_flags(tags_q, fl_q, ctx_flg);
`ifdef FP3_MUTANT_FLAGS_UNSTAGED
      // Deliberately broken (formal/sched.sby:mutant_flags): the read
      // misses the staged cycle's write-backs.
      wire unused_in_sel = &{1'b0, in_sel};
      assign flags_ctx[5*fl +: 5] = flags_q[ctx_flg];
`else
      assign flags_ctx[5*fl +: 5] = flags_q[ctx_flg] | in_sel;
`endif
    end
  endgenerate

  // ---- host read mux (registered) ------------------------------------------
  // The words of the four addresses host_addr_i[11:2] names (hr_four),
  // then the one host_addr_i[1:0] names.  With READ >= 2 (FMAX_PIPE) the
  // four words are registered between the two halves (HSPLIT), sampled in
  // the cycle of the address as before, and the read takes READ cycles
  // still.  The words of context CTX (STATUS, STEPS_DONE, FAULT_PC,
  // FLAGS) are then registered in every cycle instead, as selected, and
  // taken in the second half (so the context select does not reach the
  // address's multiplexer): the same cycle's values.
  localparam integer HSPLIT = (READ >= 2) ? 1 : 0;
  // The selected context's flags, of lane LANE (flags_sel).  With HSPLIT
  // FLAGS takes its own path: each lane's flags of context ctx_flg
  // registered beside that lane in every cycle (fsel_q, 5 flip-flops a
  // lane), and the lane multiplexer after those registers, in the second
  // half, by a copy of LANE of its own (lane_flg, kept).  So the context
  // multiplexers and the staged cycle's compares end in their lane, and
  // only a registered 5-bit word a lane crosses the die to the
  // multiplexer; the read returns the address cycle's flags as the other
  // words of context CTX do.
  wire [5*NL-1:0] flags_src;   // flags_ctx, or (HSPLIT) flags_ctx of the cycle before
  wire [4:0]      flags_sel;
  generate
    if (HSPLIT != 0) begin : g_flags_split
      reg [5*NL-1:0] fsel_q;
      always @(posedge clk_i) fsel_q <= flags_ctx;
      assign flags_src = fsel_q;
    end else begin : g_flags_now
      assign flags_src = flags_ctx;
    end
    if (NL == 1) begin : g_flags_one
      assign flags_sel = flags_src;
    end else begin : g_flags_lane
      wire [LW-1:0] lane_fl;   // the lane multiplexer's select
      if (HSPLIT != 0) begin : g_lane_flg
        fp3_keep #(.W(LW)) u_lane_flg (
          .clk_i (clk_i),
          .d_i   (rst_i ? {LW{1'b0}} : lane_we ? host_wdata_i[LW-1:0] : lane_fl),
          .q_o   (lane_fl)
        );
      end else begin : g_lane_q
        assign lane_fl = lane_q;
      end
      assign flags_sel = flags_src[5*lane_fl +: 5];
    end
  endgenerate
  wire [31:0] w_status = {20'd0, error, 5'd0, any_error, done, running};
  wire [31:0] w_flags  = {27'd0, flags_sel};
  wire        in_four  = HSPLIT == 0;   // the context's words are in hr_four
  // The scalar registers are words 0x000 .. 0x01F of the map (HR_INFO2,
  // the last, is checked below): hr_four is chosen by host_addr_i[4:2]
  // only, and whether the address is among those words at all (scal) is
  // applied after the choice (with HSPLIT, registered beside it).  So no
  // compare of the whole address clears the four words' registers (as a
  // synchronous reset from the address decode it was a critical path).
  wire        scal = host_addr_i[11:5] == 7'd0;
  reg [127:0] hr_four;
  integer hk;
  always @(*) begin
    hr_four = 128'd0;
    for (hk = 0; hk < 4; hk = hk + 1) begin
      case ({host_addr_i[4:2], hk[1:0]})
        HR_STATUS[4:0]:     hr_four[32*hk +: 32] = in_four ? w_status : 32'd0;
        HR_STEPS[4:0]:      hr_four[32*hk +: 32] = steps_q;
        HR_STEPS_DONE[4:0]: hr_four[32*hk +: 32] = in_four ? steps_done : 32'd0;
        HR_FAULT_PC[4:0]:   hr_four[32*hk +: 32] = in_four ? fault_pc : 32'd0;
        HR_FLAGS[4:0]:      hr_four[32*hk +: 32] = in_four ? w_flags : 32'd0;
        HR_CYCLES_LO[4:0]:  hr_four[32*hk +: 32] = cycles[31:0];
        HR_CYCLES_HI[4:0]:  hr_four[32*hk +: 32] = cycles[63:32];
        HR_ISSUED_LO[4:0]:  hr_four[32*hk +: 32] = issued[31:0];
        HR_ISSUED_HI[4:0]:  hr_four[32*hk +: 32] = issued[63:32];
        HR_STALLS_LO[4:0]:  hr_four[32*hk +: 32] = stalls[31:0];
        HR_STALLS_HI[4:0]:  hr_four[32*hk +: 32] = stalls[63:32];
        HR_INFO0[4:0]:      hr_four[32*hk +: 32] = {IMEM_DEPTH[15:0], NUM_REGS[15:0]};
        HR_INFO1[4:0]:      hr_four[32*hk +: 32] = {5'd0, DIV_LATENCY[7:0], FMAX_PIPE[0], FTZ[0],
                                                    ROUND[0], MUL_LATENCY[7:0], ADD_LATENCY[7:0]};
        HR_ID[4:0]:         hr_four[32*hk +: 32] = ID_VALUE;
        HR_CTX[4:0]:        hr_four[32*hk +: 32] = {{(32-CW){1'b0}}, ctx_q};
        HR_CONTEXTS[4:0]:   hr_four[32*hk +: 32] = contexts_q;
        HR_INFO2[4:0]:      hr_four[32*hk +: 32] = {NUM_LANES[7:0], 1'b0, WB1, HAS_SIGN[0],
                                                    HAS_SQRT[0], HAS_DIV[0], HAS_MUL[0],
                                                    HAS_SUB[0], HAS_ADD[0], NUM_CONTEXTS[15:0]};
        HR_LANE[4:0]:       hr_four[32*hk +: 32] = {{(32-LW){1'b0}}, lane_q};
        default:            hr_four[32*hk +: 32] = 32'd0;
      endcase
    end
  end
  generate
    if (HR_INFO2 > 12'h01F || HR_LANE > 12'h01F) begin : g_bad_map
      // Elaboration error on purpose: the scalar map outgrew host_addr_i[4:0].
      fp3_top_error_scalar_registers_must_be_words_0_to_31 u_error ();
    end
  endgenerate
  wire         hr_reg = hsel[4] && host_idle;   // a register of the window
  wire [31:0]  rdata_d;    // the word host_addr_i named (READ - HSPLIT cycles to go)
  wire         hr_reg_w;   // ... it is the register file's
  generate
    if (HSPLIT != 0) begin : g_host_split
      reg [127:0] four_q;
      reg [1:0]   lo_q;
      reg         scal_q;
      reg         reg_q;
      reg [31:0]  st_q, sd_q, fpc_q;   // context CTX's words (FLAGS: w_flags, from fsel_q)
      reg [3:0]   ctxw_q;  // one-hot: host_addr_i named one of them (STATUS .. FLAGS)
      always @(posedge clk_i) begin
        four_q   <= hr_four;
        lo_q     <= host_addr_i[1:0];
        scal_q   <= scal;
        reg_q    <= hr_reg && !rst_i;
        st_q     <= w_status;
        sd_q     <= steps_done;
        fpc_q    <= fault_pc;
        ctxw_q   <= {host_addr_i == HR_FLAGS, host_addr_i == HR_FAULT_PC,
                     host_addr_i == HR_STEPS_DONE, host_addr_i == HR_STATUS};
      end
      assign rdata_d = ({32{scal_q}} & four_q[32*lo_q +: 32]) | ({32{ctxw_q[0]}} & st_q) |
                       ({32{ctxw_q[1]}} & sd_q) | ({32{ctxw_q[2]}} & fpc_q) |
                       ({32{ctxw_q[3]}} & w_flags);
      assign hr_reg_w = reg_q;
    end else begin : g_host_one
      assign rdata_d  = {32{scal}} & hr_four[32*host_addr_i[1:0] +: 32];
      assign hr_reg_w = hr_reg;
    end
  endgenerate
  // A register of the window comes straight from the register file's read
  // port A, which answers READ cycles after the address; the other
  // registers are delayed to match.
  wire [31:0] rdata_q;
  wire        reg_read_q;
  fp_pipe #(.WIDTH(32), .DEPTH(READ - HSPLIT + BC)) u_host_read (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (hr_reg_w),
    .data_i  (rdata_d),
    .valid_o (reg_read_q),
    .data_o  (rdata_q)
  );
  wire [31:0] ra_data_sel = ra_data_l[32*lane_q +: 32];   // lane LANE's port A
  assign host_rdata_o = reg_read_q ? ra_data_sel : rdata_q;

  // ---- outputs -------------------------------------------------------------
  assign running_o       = running;
  assign done_o          = done;
  assign tr_issue_o      = issue;
  assign tr_issue_ctx_o  = {{(6-CW){1'b0}}, issue_ctx};
  assign tr_issue_unit_o = issue_unit;
  assign tr_endi_o       = endi;
  assign tr_add_valid_o  = lt_add_valid;
  assign tr_add_ctx_o    = {{(6-CW){1'b0}}, lt_add_idx[XW-1:IW]};
  assign tr_add_reg_o    = {{(8-IW){1'b0}}, lt_add_idx[IW-1:0]};
  assign tr_add_data_o   = add_data_l;
  assign tr_mul_valid_o  = lt_mul_valid;
  assign tr_mul_ctx_o    = {{(6-CW){1'b0}}, lt_mul_idx[XW-1:IW]};
  assign tr_mul_reg_o    = {{(8-IW){1'b0}}, lt_mul_idx[IW-1:0]};
  assign tr_mul_data_o   = mul_data_l;
  assign tr_mov_valid_o  = lt_mov_valid;
  assign tr_mov_ctx_o    = {{(6-CW){1'b0}}, lt_mov_idx[XW-1:IW]};
  assign tr_mov_reg_o    = {{(8-IW){1'b0}}, lt_mov_idx[IW-1:0]};
  assign tr_mov_data_o   = mov_data_l;
  assign tr_div_valid_o  = lt_div_valid;
  assign tr_div_ctx_o    = {{(6-CW){1'b0}}, lt_div_idx[XW-1:IW]};
  assign tr_div_reg_o    = {{(8-IW){1'b0}}, lt_div_idx[IW-1:0]};
  assign tr_div_data_o   = div_data_l;

  // Host address bits that select windows but are not register indices.
  wire unused_addr = &{1'b0, host_addr_i};
`ifdef FP3_SCHED_CHECK
  // The staged sticky flags read as flags that take each write-back in its
  // own cycle (formal/sched.sby): a reference array of every lane's flags
  // by context, updated directly from the tag lines and the cores' flags,
  // equals what the host's FLAGS read sees of every lane, in every cycle
  // after reset.
  reg [5*NL-1:0] fref_q [0:NUM_CONTEXTS-1];
  integer fk;
  always @(posedge clk_i) begin
    for (fk = 0; fk < NUM_CONTEXTS; fk = fk + 1) begin
      if (rst_i || fclr_q) fref_q[fk] <= {5*NL{1'b0}};
      else fref_q[fk] <= fref_q[fk] |
                         (lt_add_valid && lt_add_idx[XW-1:IW] == fk[CW-1:0] ? add_flags_l : {5*NL{1'b0}}) |
                         (lt_mul_valid && lt_mul_idx[XW-1:IW] == fk[CW-1:0] ? mul_flags_l : {5*NL{1'b0}}) |
                         (lt_mov_valid && lt_mov_idx[XW-1:IW] == fk[CW-1:0] ? mov_flags_l : {5*NL{1'b0}}) |
                         (lt_div_valid && lt_div_idx[XW-1:IW] == fk[CW-1:0] ? div_flags_l : {5*NL{1'b0}});
    end
  end
  reg f_flags_past = 1'b0;
  always @(posedge clk_i) f_flags_past <= 1'b1;
  always @(*) if (f_flags_past && !rst_i) flags_staged_exact: assert (flags_ctx == fref_q[ctx_flg]);
  // The scheduler's scoreboard and issue properties (formal/sched.sby),
  // checked on this processor's own tag lines, flags and bypass; its copy
  // of the program from the scheduler's program writes.
  fp3_sched_check #(.NUM_CONTEXTS(NUM_CONTEXTS), .CW(CW), .IW(IW), .IMEM_DEPTH(IMEM_DEPTH),
                    .AW(AW), .READ(READ), .AHEAD(AHEAD), .ADD_LATENCY(ADD_LATENCY),
                    .MUL_LATENCY(MUL_LATENCY), .MOV_LATENCY(MOV_LATENCY),
                    .DIV_LATENCY(DIV_LATENCY), .HAS_DIV(HAS_DIV), .HAS_SQRT(HAS_SQRT),
                    .FLAGS_AHEAD(FMAX_PIPE)) u_sched_check (
    .clk_i            (clk_i),
    .rst_i            (rst_i),
    .prog_we_i        (imem_we),
    .prog_addr_i      (imem_idx),
    .prog_word_i      (imem_wdata),
    .start_i          (start),
    .running_i        (running),
    .contexts_run_i   (contexts_run_q),
    .steps_i          (steps_q),
    .sel_ctx_i        (ctx_sch),
    .steps_done_sel_i (steps_done),
    .issued_i         (issued),
    .stalls_i         (stalls),
    .issue_i          (issue),
    .issue_ctx_i      (issue_ctx),
    .ra_i             (ra),
    .rb_i             (rb),
    .rd_i             (rd),
    .issue_unit_i     (issue_unit),
    .issue_imm_i      (issue_imm),
    .imm_i            (imm),
    .endi_i           (endi),
    .beq_i            (beq),
    .busy_i           (busy),
    .add_valid_i      (add_valid),
    .add_idx_i        (add_idx),
    .mul_valid_i      (mul_valid),
    .mul_idx_i        (mul_idx),
    .mov_valid_i      (mov_valid),
    .mov_idx_i        (mov_idx),
    .div_valid_i      (div_valid),
    .div_idx_i        (div_idx),
    .br_i             (br_q),
    .br_taken_i       (br_taken_q)
  );
`endif
endmodule
`default_nettype wire
