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
// Broadcast stages (NUM_LANES > 1; fp3_simd has them and their
// reasons): registers between the scheduler and the lanes, and between
// lane 0's live value table and the other lanes, so that no wire crosses
// the die to every lane without leaving a flip-flop.  The scoreboard keeps
// the scheduler's time; the lanes' results come LD = 2 cycles after the
// tag lines name them.  What they cost: a beq resolves
// FP3_LANES_BEQ_CYCLES (3) later, a run drains LD cycles longer
// (FP3_LANES_STAGE_CYCLES), host reads take FP3_LANES_HOST_READ_CYCLES (1)
// more.  A one-lane build has none of them.
//
// The parts, one module each:
//   fp3_host       the host port: writable registers, the write strobes
//                  to the scheduler and the register window, the
//                  registered read multiplexer (FLAGS, status, counters,
//                  configuration, the register window)
//   fp3_scheduler  fetch, queues, the ready step, issue, the integration
//                  loop, run control and counters
//   fp3_wb_tag     one tag line per write-back port (here): each unit's
//                  destination from issue to write-back, announced ahead
//                  to the scoreboard and the bypass
//   fp3_simd       NUM_LANES lanes (fp3_lane: register bank and arithmetic
//                  unit), the operand-read stages, beq's resolution and
//                  the sticky exception flags
//   trace port     the issue and the lanes' write-backs (the outputs
//                  below)
//
// Host port (fp3_host): a simple synchronous word port.  A write (host_we_i) takes
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

  // ---- host port -----------------------------------------------------------
  // The scheduler's run state, status and counters (fp3_scheduler, below),
  // which the host port reads:
  wire          running;
  wire [NL-1:0] run_l;       // RUNNING's copies, one per lane's read address (fp3_sched_loop)
  wire          done, any_error;
  wire [3:0]    error;
  wire [31:0]   fault_pc, steps_done;
  wire [63:0]   cycles, issued, stalls;
  // ... and what the host port gives the scheduler and the lanes:
  wire          imem_we, start, clear;
  wire [AW-1:0] imem_idx;
  wire [63:0]   imem_wdata;
  wire [31:0]   steps, steps_last2;
  wire          steps_zero, steps_one, contexts_bad;
  wire [NUM_CONTEXTS-1:0] contexts_run;
  wire [CW-1:0] ctx_sch, ctx_flg;   // CTX: the scheduler's copy, the flags'
  wire [NL-1:0] host_reg_we;        // a register-window write, per lane (LANE's)
  wire [XW-1:0] host_reg_idx;       // ... its index {CTX, register}
  wire [32*NL-1:0] ra_data_l;       // every lane's port A (the host's reads)
  wire          fclr;               // the sticky flags clear (the run's first cycle)
  wire [5*NL-1:0] flags_ctx;        // every lane's sticky flags of context ctx_flg
  fp3_host #(.NUM_CONTEXTS(NUM_CONTEXTS), .CW(CW), .NUM_LANES(NUM_LANES), .NUM_REGS(NUM_REGS),
             .IW(IW), .IMEM_DEPTH(IMEM_DEPTH), .AW(AW), .READ_STAGES(READ), .HOST_STAGES(BC),
             .ADD_LATENCY(ADD_LATENCY), .MUL_LATENCY(MUL_LATENCY), .DIV_LATENCY(DIV_LATENCY),
             .ROUND(ROUND), .FTZ(FTZ), .FMAX_PIPE(FMAX_PIPE), .HAS_ADD(HAS_ADD),
             .HAS_SUB(HAS_SUB), .HAS_MUL(HAS_MUL), .HAS_DIV(HAS_DIV), .HAS_SQRT(HAS_SQRT),
             .HAS_SIGN(HAS_SIGN), .WB_PORTS(WB_PORTS), .CTX_CHECKED(CTX_CHECKED),
             .HOST_WSEL(HOST_WSEL)) u_host (
    .clk_i          (clk_i),
    .rst_i          (rst_i),
    .host_we_i      (host_we_i),
    .host_addr_i    (host_addr_i),
    .host_wdata_i   (host_wdata_i),
    .host_wsel_i    (host_wsel_i),
    .host_rdata_o   (host_rdata_o),
    .imem_we_o      (imem_we),
    .imem_waddr_o   (imem_idx),
    .imem_wdata_o   (imem_wdata),
    .start_o        (start),
    .clear_o        (clear),
    .steps_o        (steps),
    .steps_zero_o   (steps_zero),
    .steps_one_o    (steps_one),
    .steps_last2_o  (steps_last2),
    .contexts_bad_o (contexts_bad),
    .contexts_run_o (contexts_run),
    .sel_ctx_o      (ctx_sch),
    .running_i      (running),
    .done_i         (done),
    .any_error_i    (any_error),
    .error_i        (error),
    .fault_pc_i     (fault_pc),
    .steps_done_i   (steps_done),
    .cycles_i       (cycles),
    .issued_i       (issued),
    .stalls_i       (stalls),
    .reg_we_o       (host_reg_we),
    .reg_idx_o      (host_reg_idx),
    .reg_rdata_i    (ra_data_l),
    .flags_clr_o    (fclr),
    .flags_ctx_o    (ctx_flg),
    .flags_i        (flags_ctx)
  );
`ifndef FP3_SCHED_CHECK
  wire unused_steps = &{1'b0, steps};   // (STEPS as written: the checker's)
`endif

  // ---- scheduler -----------------------------------------------------------
  wire [XW-1:0] ra, rb, rd;
  wire [CW-1:0] issue_ctx;
  wire          idle;
  wire          issue, issue_sub, issue_imm, endi, beq;
  wire [2:0]    issue_sop;                // sign group: {abs/neg/min/max, fp_sign op}
  wire          br_taken;               // beq resolution (fp3_simd)
  wire [NUM_CONTEXTS-1:0] br;           // ... its context, one-hot (none: no beq)
  wire [AW-1:0] br_target;
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
    .steps_zero_i     (steps_zero),
    .steps_one_i      (steps_one),
    .steps_last2_i    (steps_last2),
    .contexts_bad_i   (contexts_bad),
    .contexts_run_i   (contexts_run),
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
    .br_i             (br),
    .br_taken_i       (br_taken),
    .br_target_i      (br_target),
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

  // ---- lanes ---------------------------------------------------------------
  // NUM_LANES register banks and arithmetic units under the one
  // scheduler, the issued operation's read stages, beq's resolution, the
  // sticky flags (fp3_simd).  Tag line ports {div/sqrt, move, mul, add}.
  wire [32*NL-1:0] add_data_l, mul_data_l, mov_data_l, div_data_l;   // lane l in [32l +: 32]
  wire [3:0]       lt_valid;          // the write-backs in the lanes' time (LD cycles late)
  wire [4*XW-1:0]  lt_idx;
  fp3_simd #(.NUM_CONTEXTS(NUM_CONTEXTS), .CW(CW), .NUM_LANES(NUM_LANES), .IW(IW), .AW(AW),
             .READ_STAGES(READ), .FLAGS_AHEAD(FMAX_PIPE), .BCAST(BC), .WB_PORTS(WB_PORTS),
             .ADD_LATENCY(ADD_LATENCY), .MUL_LATENCY(MUL_LATENCY), .MUL_FEED(MUL_FEED),
             .MOV_LATENCY(MOV_LATENCY), .DIV_LATENCY(DIV_LATENCY), .ROUND(ROUND), .FTZ(FTZ),
             .HAS_ADD(HAS_ADD), .HAS_SUB(HAS_SUB), .HAS_MUL(HAS_MUL), .HAS_DIV(HAS_DIV),
             .HAS_SQRT(HAS_SQRT), .HAS_SIGN(HAS_SIGN)) u_lanes (
    .clk_i         (clk_i),
    .rst_i         (rst_i),
    .issue_i       (issue),
    .issue_ctx_i   (issue_ctx),
    .ra_i          (ra),
    .rb_i          (rb),
    .issue_unit_i  (issue_unit),
    .issue_sub_i   (issue_sub),
    .issue_sop_i   (issue_sop),
    .issue_imm_i   (issue_imm),
    .imm_i         (imm),
    .beq_i         (beq),
    .pick_wr_i     (pick_wr),
    .pick_rd_i     (pick_rd),
    .busy_o        (busy),
    .idle_o        (idle),
    .ahead_valid_i ({diva_valid, mova_valid, mula_valid, adda_valid}),
    .ahead_idx_i   ({diva_idx, mova_idx, mula_idx, adda_idx}),
    .early_valid_i ({dive_valid, move_valid, mule_valid, adde_valid}),
    .early_idx_i   ({dive_idx, move_idx, mule_idx, adde_idx}),
    .next2_valid_i ({divn_valid, movn_valid, muln_valid, addn_valid}),
    .next2_idx_i   ({divn_idx, movn_idx, muln_idx, addn_idx}),
    .wb_valid_i    ({div_valid, mov_valid, mul_valid, add_valid}),
    .wb_idx_i      ({div_idx, mov_idx, mul_idx, add_idx}),
    .br_o          (br),
    .br_taken_o    (br_taken),
    .br_target_o   (br_target),
    .run_i         (run_l),
    .host_we_i     (host_reg_we),
    .host_idx_i    (host_reg_idx),
    .host_wdata_i  (host_wdata_i),
    .host_rdata_o  (ra_data_l),
    .flags_clr_i   (fclr),
    .flags_ctx_i   (ctx_flg),
    .flags_o       (flags_ctx),
    .lt_valid_o    (lt_valid),
    .lt_idx_o      (lt_idx),
    .add_data_o    (add_data_l),
    .mul_data_o    (mul_data_l),
    .mov_data_o    (mov_data_l),
    .div_data_o    (div_data_l)
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

  // ---- trace port ----------------------------------------------------------
  // The issue in the scheduler's time; the write-backs in the lanes' time,
  // beside their results.
  wire [XW-1:0] lt_add_idx = lt_idx[0 +: XW];
  wire [XW-1:0] lt_mul_idx = lt_idx[XW +: XW];
  wire [XW-1:0] lt_mov_idx = lt_idx[2*XW +: XW];
  wire [XW-1:0] lt_div_idx = lt_idx[3*XW +: XW];
  assign running_o       = running;
  assign done_o          = done;
  assign tr_issue_o      = issue;
  assign tr_issue_ctx_o  = {{(6-CW){1'b0}}, issue_ctx};
  assign tr_issue_unit_o = issue_unit;
  assign tr_endi_o       = endi;
  assign tr_add_valid_o  = lt_valid[0];
  assign tr_add_ctx_o    = {{(6-CW){1'b0}}, lt_add_idx[XW-1:IW]};
  assign tr_add_reg_o    = {{(8-IW){1'b0}}, lt_add_idx[IW-1:0]};
  assign tr_add_data_o   = add_data_l;
  assign tr_mul_valid_o  = lt_valid[1];
  assign tr_mul_ctx_o    = {{(6-CW){1'b0}}, lt_mul_idx[XW-1:IW]};
  assign tr_mul_reg_o    = {{(8-IW){1'b0}}, lt_mul_idx[IW-1:0]};
  assign tr_mul_data_o   = mul_data_l;
  assign tr_mov_valid_o  = lt_valid[2];
  assign tr_mov_ctx_o    = {{(6-CW){1'b0}}, lt_mov_idx[XW-1:IW]};
  assign tr_mov_reg_o    = {{(8-IW){1'b0}}, lt_mov_idx[IW-1:0]};
  assign tr_mov_data_o   = mov_data_l;
  assign tr_div_valid_o  = lt_valid[3];
  assign tr_div_ctx_o    = {{(6-CW){1'b0}}, lt_div_idx[XW-1:IW]};
  assign tr_div_reg_o    = {{(8-IW){1'b0}}, lt_div_idx[IW-1:0]};
  assign tr_div_data_o   = div_data_l;
`ifdef FP3_SCHED_CHECK
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
    .contexts_run_i   (contexts_run),
    .steps_i          (steps),
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
    .br_i             (br),
    .br_taken_i       (br_taken)
  );
`endif
endmodule
`default_nettype wire
