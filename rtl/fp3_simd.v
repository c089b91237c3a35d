// fp3_simd -- the lanes of the FP3 processor and what fans out to them and
// back in: NUM_LANES fp3_lane instances (each a register bank and an
// arithmetic unit), the operand-read stages of the issued operation (one
// copy for all lanes), the write-back tag lines in the lanes' time (for
// the trace port), beq's resolution from every lane's compare, and the
// sticky exception flags of every lane, by context.  (Its name contains
// no other module's: scripts/synth.sh -keep and synth-report.sh --module
// select modules by substring, and the chip build keeps fp3_lane.)
//
// Every lane receives the same operation stream from the one scheduler
// (fp3_scheduler) and the one set of write-back tag lines (fp3_wb_tag, in
// fp3_top): the same read indices, unit, immediate and write-back
// indices, so each issue of context c runs on lane 0 .. NUM_LANES-1 of c
// in the same cycle.  Lane 0's busy flags are the scoreboard (busy_o,
// idle_o), and its live value table chooses the RAM of every lane's reads
// (lanes 1 .. have neither: fp3_lane CTRL).  A beq is taken only when its
// operands are bit-identical in every lane of its context (the lanes of a
// context share one PC); otherwise every lane falls through.
//
// Broadcast stages (BCAST = 1, the build with more than one lane): the
// scheduler drives every lane across the die, and lane 0's live value
// table chooses the RAM of every lane's reads.  So that each of those
// wires leaves a flip-flop and enters one, lane 0 takes the operation
// stream (read indices, write-back tags, operation) through one register
// of its own and the other lanes through two, lane 0's LVT choice reaches
// them through one more, and the lanes register their beq compare; lane
// 0's results wait a cycle, so that every lane's results (and the trace
// port's write-backs) come LD = 2 cycles after the tag lines name them.
// The scoreboard is unchanged: the busy flags take their set and clear in
// the scheduler's time, and each lane sees its reads and write-backs at
// the same distances as without the stages.  What they cost: a beq
// resolves FP3_LANES_BEQ_CYCLES (3) later, a run drains LD cycles longer
// (FP3_LANES_STAGE_CYCLES; fp3_top's DRAIN), host reads take
// FP3_LANES_HOST_READ_CYCLES (1) more (the other lanes see the host's
// address a cycle after lane 0, for the same LVT choice; fp3_host), and
// 140-180 flip-flops per stage and lane (fp3_lane).  A one-lane build
// (BCAST = 0) has none of them.
//
// Sticky exception flags: per context and lane, cleared by flags_clr_i
// (the run's first cycle), ORed with the flags of every write-back of
// their context.  Each lane keeps its flags in an array of its own,
// indexed by context, so that the host's selection is a context
// multiplexer in each lane and a lane multiplexer behind them (fp3_host;
// an index context * NUM_LANES + lane would make Yosys build a multiplier
// and an adder into the host's read path when NUM_LANES is not a power of
// two).  The flags take their inputs a cycle late (below); flags_o ORs
// that staged cycle back in, so the host sees every write-back up to the
// previous cycle.
//
// Parameters
//   NUM_CONTEXTS  contexts, >= 1; CW = clog2, >= 1 (fp3_top's)
//   NUM_LANES     lanes, 1 .. 64 (fp3_top MAX_LANES)
//   IW            register index width (clog2(NUM_REGS), fp3_top's);
//                 XW = CW + IW, the register file's {context, register}
//   AW            instruction address width (beq's target)
//   READ_STAGES   the register file's read stages (fp3_top READ): the
//                 operation waits as long beside its operands
//   FLAGS_AHEAD   0 or 1 (fp3_top FMAX_PIPE): the busy flags take their
//                 set (the pick) and clear (early_*_i instead of
//                 ahead_*_i) a cycle ahead (fp3_regfile FLAGS_AHEAD)
//   BCAST         0 or 1: the broadcast stages above (1 with lanes);
//                 LD = 2 BCAST
//   WB_PORTS, ADD_LATENCY, MUL_LATENCY, MUL_FEED, MOV_LATENCY,
//   DIV_LATENCY, ROUND, FTZ, HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV, HAS_SQRT,
//   HAS_SIGN      each lane's register file and arithmetic unit (fp3_lane,
//                 fp3_top's values; MOV_LATENCY as fp3_top derives it)
// Ports
//   issue_*, ra_i, rb_i, imm_i, beq_i, pick_*  the scheduler's issue
//                 (fp3_scheduler issue_o .. pick_unit_o: the issue cycle)
//   busy_o, idle_o  lane 0's busy flags: the scoreboard
//   {ahead,early,next2,wb}_{valid,idx}_i  the tag lines' write-backs,
//                 ports {div/sqrt, move, mul, add} (3 .. 0; fp3_wb_tag
//                 ahead_*, early_*, next2_*, wb_*)
//   br_o, br_taken_o, br_target_o  a beq resolved, READ_STAGES + 1 + LD +
//                 BCAST cycles after its issue: its context (one-hot; none
//                 if no beq), taken (equal in every lane), its target
//   run_i         RUNNING, one copy per lane (fp3_sched_loop): while it is
//                 0 the host owns the lane's read port A
//   host_we_i     per lane: the host's register write (fp3_host, gated by
//                 LANE); host_idx_i {context, register}, host_wdata_i
//   host_rdata_o  every lane's port A read of host_idx_i (lane l in
//                 [32l +: 32]), READ_STAGES + BCAST cycles after the
//                 address (lanes 1 .. register the address, lane 0 its
//                 answer: fp3_lane HOST_STAGES, OUT_STAGES)
//   flags_clr_i   clear every sticky flag (the run's first cycle)
//   flags_ctx_i   the context whose flags flags_o shows (fp3_host: CTX)
//   flags_o       lane l's sticky flags of context flags_ctx_i in [5l +: 5],
//                 as if they took every write-back up to the last cycle
//   lt_valid_o, lt_idx_o  the tag lines' write-backs LD cycles late, ports
//                 {div/sqrt, move, mul, add}: the cycle in which *_data_o
//                 are the results they name (the trace port)
//   add_data_o, mul_data_o, mov_data_o, div_data_o  every lane's results
//                 (lane l in [32l +: 32])
`default_nettype none
module fp3_simd #(
  parameter integer NUM_CONTEXTS = 8,
  parameter integer CW           = 3,
  parameter integer NUM_LANES    = 1,
  parameter integer IW           = 5,
  parameter integer AW           = 8,
  parameter integer READ_STAGES  = 1,
  parameter integer FLAGS_AHEAD  = 0,
  parameter integer BCAST        = 0,
  parameter integer WB_PORTS     = 4,
  parameter integer ADD_LATENCY  = 4,
  parameter integer MUL_LATENCY  = 3,
  parameter integer MUL_FEED     = 0,
  parameter integer MOV_LATENCY  = 1,
  parameter integer DIV_LATENCY  = 8,
  parameter integer ROUND        = 0,
  parameter integer FTZ          = 0,
  parameter integer HAS_ADD      = 1,
  parameter integer HAS_SUB      = 1,
  parameter integer HAS_MUL      = 1,
  parameter integer HAS_DIV      = 1,
  parameter integer HAS_SQRT     = 1,
  parameter integer HAS_SIGN     = 1
) (
  input  wire                        clk_i,
  input  wire                        rst_i,
  // the issue (fp3_scheduler)
  input  wire                        issue_i,
  input  wire [CW-1:0]               issue_ctx_i,
  input  wire [CW+IW-1:0]            ra_i,
  input  wire [CW+IW-1:0]            rb_i,
  input  wire [2:0]                  issue_unit_i,
  input  wire                        issue_sub_i,
  input  wire [2:0]                  issue_sop_i,   // sign group: {abs/neg/min/max, fp_sign op}
  input  wire                        issue_imm_i,   // the move path takes the immediate
  input  wire [31:0]                 imm_i,
  input  wire                        beq_i,         // the issued instruction is a beq
  input  wire                        pick_wr_i,     // the next issue writes a register,
  input  wire [CW+IW-1:0]            pick_rd_i,     // ... this one
  // the scoreboard: lane 0's busy flags
  output wire [(1<<(CW+IW))-1:0]     busy_o,
  output wire                        idle_o,        // no busy flag in the last cycle
  // the write-back tag lines, ports {div/sqrt, move, mul, add}
  input  wire [3:0]                  ahead_valid_i, // write-backs announced AHEAD cycles on
  input  wire [4*(CW+IW)-1:0]        ahead_idx_i,
  input  wire [3:0]                  early_valid_i, // ... and a cycle before that
  input  wire [4*(CW+IW)-1:0]        early_idx_i,
  input  wire [3:0]                  next2_valid_i, // write-backs in two cycles
  input  wire [4*(CW+IW)-1:0]        next2_idx_i,
  input  wire [3:0]                  wb_valid_i,    // write-backs now
  input  wire [4*(CW+IW)-1:0]        wb_idx_i,
  // a beq resolved
  output wire [NUM_CONTEXTS-1:0]     br_o,
  output wire                        br_taken_o,
  output wire [AW-1:0]               br_target_o,
  // host: the register window
  input  wire [NUM_LANES-1:0]        run_i,
  input  wire [NUM_LANES-1:0]        host_we_i,
  input  wire [CW+IW-1:0]            host_idx_i,
  input  wire [31:0]                 host_wdata_i,
  output wire [32*NUM_LANES-1:0]     host_rdata_o,
  // host: the sticky exception flags
  input  wire                        flags_clr_i,
  input  wire [CW-1:0]               flags_ctx_i,
  output wire [5*NUM_LANES-1:0]      flags_o,
  // the write-backs in the lanes' time, and their results
  output wire [3:0]                  lt_valid_o,
  output wire [4*(CW+IW)-1:0]        lt_idx_o,
  output wire [32*NUM_LANES-1:0]     add_data_o,
  output wire [32*NUM_LANES-1:0]     mul_data_o,
  output wire [32*NUM_LANES-1:0]     mov_data_o,
  output wire [32*NUM_LANES-1:0]     div_data_o
);
`include "fp3_isa.vh"
  localparam integer NL = NUM_LANES;
  localparam integer XW = CW + IW;
  localparam integer READ = READ_STAGES;
  localparam integer BC = BCAST;
  localparam integer LD = 2 * BC;

  // ---- lanes: register banks and arithmetic units -------------------------
  // Banks are indexed {context, register}: 2**XW entries; the banks of
  // contexts >= NUM_CONTEXTS are never written and synthesize away.
  // With the pick stages the busy flags take their set and clear a cycle
  // ahead (fp3_regfile FLAGS_AHEAD): the instruction picked and the tag
  // lines' early announcements.  Every lane sees the same indices; lane
  // 0's busy flags are the scoreboard, and its live value table chooses
  // the RAM of every lane's reads (fp3_lane; lanes 1 .. have neither).
  // The host writes the lane host_we_i names.
  wire [3:0]       clr_valid = FLAGS_AHEAD != 0 ? early_valid_i : ahead_valid_i;
  wire [4*XW-1:0]  clr_idx   = FLAGS_AHEAD != 0 ? early_idx_i   : ahead_idx_i;
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
      fp3_lane #(.ENTRIES(1 << XW), .XW(XW), .READ_STAGES(READ), .FLAGS_AHEAD(FLAGS_AHEAD),
                 .CTRL(ln == 0 ? 1 : 0), .HOST_ALL(NL > 1 ? 1 : 0), .WB_PORTS(WB_PORTS),
                 .ADD_LATENCY(ADD_LATENCY), .MUL_LATENCY(MUL_LATENCY), .MUL_FEED(MUL_FEED),
                 .MOV_LATENCY(MOV_LATENCY), .DIV_LATENCY(DIV_LATENCY), .ROUND(ROUND),
                 .FTZ(FTZ), .HAS_ADD(HAS_ADD), .HAS_SUB(HAS_SUB), .HAS_MUL(HAS_MUL),
                 .HAS_DIV(HAS_DIV), .HAS_SQRT(HAS_SQRT), .HAS_SIGN(HAS_SIGN),
                 .IN_STAGES(ln == 0 ? BC : 2 * BC), .OUT_STAGES(ln == 0 ? BC : 0),
                 .EQ_STAGE(BC), .HOST_STAGES(ln == 0 ? 0 : BC)) u_lane (
        .clk_i           (clk_i),
        .rst_i           (rst_i),
        .ra_i            (ra_i),
        .rb_i            (rb_i),
        .ra_data_o       (ra_data_l[32*ln +: 32]),
        .eq_o            (eq_l[ln]),
        .busy_o          (busy_l[(1<<XW)*ln +: (1<<XW)]),
        .set_i           (pick_wr_i),
        .set_idx_i       (pick_rd_i),
        .clr0_valid_i    (clr_valid[0]),
        .clr0_idx_i      (clr_idx[0 +: XW]),
        .clr1_valid_i    (clr_valid[1]),
        .clr1_idx_i      (clr_idx[XW +: XW]),
        .clr2_valid_i    (clr_valid[2]),
        .clr2_idx_i      (clr_idx[2*XW +: XW]),
        .clr3_valid_i    (clr_valid[3]),
        .clr3_idx_i      (clr_idx[3*XW +: XW]),
        .wb0_valid_i     (wb_valid_i[0]),
        .wb0_idx_i       (wb_idx_i[0 +: XW]),
        .wb1_valid_i     (wb_valid_i[1]),
        .wb1_idx_i       (wb_idx_i[XW +: XW]),
        .wb2_valid_i     (wb_valid_i[2]),
        .wb2_idx_i       (wb_idx_i[2*XW +: XW]),
        .wb3_valid_i     (wb_valid_i[3]),
        .wb3_idx_i       (wb_idx_i[3*XW +: XW]),
        .wb0_in2_valid_i (next2_valid_i[0]),
        .wb0_in2_idx_i   (next2_idx_i[0 +: XW]),
        .wb1_in2_valid_i (next2_valid_i[1]),
        .wb1_in2_idx_i   (next2_idx_i[XW +: XW]),
        .wb2_in2_valid_i (next2_valid_i[2]),
        .wb2_in2_idx_i   (next2_idx_i[2*XW +: XW]),
        .wb3_in2_valid_i (next2_valid_i[3]),
        .wb3_in2_idx_i   (next2_idx_i[3*XW +: XW]),
        .host_sel_i      (!run_i[ln]),
        .host_we_i       (host_we_i[ln]),
        .host_idx_i      (host_idx_i),
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
  assign busy_o       = busy_l[(1<<XW)-1:0];
  assign idle_o       = idle_l[0];
  assign host_rdata_o = ra_data_l;
  assign add_data_o   = add_data_l;
  assign mul_data_o   = mul_data_l;
  assign mov_data_o   = mov_data_l;
  assign div_data_o   = div_data_l;
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
    .valid_i (issue_i && issue_unit_i != UNIT_NONE),
    .data_i  ({issue_unit_i, issue_sub_i, issue_sop_i, issue_imm_i, imm_i, issue_ctx_i}),
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
    .valid_i (issue_i && beq_i),
    .data_i  (1'b0),
    .valid_o (rd_beq),
    .data_o  (rd_beq_nil)
  );

  // ---- the write-backs in the lanes' time --------------------------------
  // The tag lines LD cycles late: the cycle in which the lanes' results
  // (fp3_lane {add,mul,mov,div}_data_o) are those the tags name, for the
  // trace port and the sticky flags.
  wire          lt_add_valid, lt_mul_valid, lt_mov_valid, lt_div_valid;
  wire [XW-1:0] lt_add_idx, lt_mul_idx, lt_mov_idx, lt_div_idx;
  fp_pipe #(.WIDTH(XW), .DEPTH(LD)) u_lt_add (
    .clk_i (clk_i), .rst_i (rst_i), .valid_i (wb_valid_i[0]), .data_i (wb_idx_i[0 +: XW]),
    .valid_o (lt_add_valid), .data_o (lt_add_idx));
  fp_pipe #(.WIDTH(XW), .DEPTH(LD)) u_lt_mul (
    .clk_i (clk_i), .rst_i (rst_i), .valid_i (wb_valid_i[1]), .data_i (wb_idx_i[XW +: XW]),
    .valid_o (lt_mul_valid), .data_o (lt_mul_idx));
  fp_pipe #(.WIDTH(XW), .DEPTH(LD)) u_lt_mov (
    .clk_i (clk_i), .rst_i (rst_i), .valid_i (wb_valid_i[2]), .data_i (wb_idx_i[2*XW +: XW]),
    .valid_o (lt_mov_valid), .data_o (lt_mov_idx));
  fp_pipe #(.WIDTH(XW), .DEPTH(LD)) u_lt_div (
    .clk_i (clk_i), .rst_i (rst_i), .valid_i (wb_valid_i[3]), .data_i (wb_idx_i[3*XW +: XW]),
    .valid_o (lt_div_valid), .data_o (lt_div_idx));
  assign lt_valid_o = {lt_div_valid, lt_mov_valid, lt_mul_valid, lt_add_valid};
  assign lt_idx_o   = {lt_div_idx, lt_mov_idx, lt_mul_idx, lt_add_idx};

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
  reg                    br_taken_q;   // beq resolution: taken,
  reg [NUM_CONTEXTS-1:0] br_q;         // ... its context, one-hot (none: no beq),
  reg [AW-1:0]           br_target_q;  // ... its target
  integer bc;
  always @(posedge clk_i) begin
    for (bc = 0; bc < NUM_CONTEXTS; bc = bc + 1)
      br_q[bc] <= !rst_i && bq_beq && bq_ctx == bc[CW-1:0];
    br_taken_q  <= &eq_l;
    br_target_q <= bq_target;
  end
  assign br_o        = br_q;
  assign br_taken_o  = br_taken_q;
  assign br_target_o = br_target_q;

  // ---- sticky exception flags of the run, per context and lane -------------
  // Cleared in the run's first cycle (flags_clr_i, a cycle after its START,
  // in which nothing has issued yet: fp3_host).
  //
  // The flags take their inputs a cycle late: each lane registers the four
  // write-back tag lines' valid and context (copies of its own, fp3_keep,
  // so each is placed by its lane's flags and not by the tag line) and its
  // cores' flags, and decodes the context from those registers.  So the
  // route from the tag lines across the die to every lane has a cycle of
  // its own with no logic in it; it cost one flip-flop per bit (4 x (1 +
  // CW) + 20 a lane).  The host's FLAGS read ORs the staged cycle into the
  // array (flags_o), so it sees every write-back up to the previous
  // cycle, as if the flags took their inputs directly.
  wire [4*(1+CW)-1:0] wb_tags = {lt_div_valid, lt_div_idx[XW-1:IW], lt_mov_valid,
                                 lt_mov_idx[XW-1:IW], lt_mul_valid, lt_mul_idx[XW-1:IW],
                                 lt_add_valid, lt_add_idx[XW-1:IW]};
  wire [5*NL-1:0]     flags_ctx;  // lane l's flags of context flags_ctx_i in [5l +: 5]
  wire [CW-1:0]       ctx_flg = flags_ctx_i;
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
          if (rst_i || flags_clr_i) flags_q[fc] <= 5'd0;
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
  assign flags_o = flags_ctx;

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
      if (rst_i || flags_clr_i) fref_q[fk] <= {5*NL{1'b0}};
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
`endif
endmodule
`default_nettype wire
