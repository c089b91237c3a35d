// fp3_sched_issue -- the scheduler's issue step (paper §4, the workload
// scheduler's dispatch; one arithmetic unit shared by the contexts, §6.3):
// a round-robin arbiter grants one context whose head was ready, and the
// granted head's fields go to the register file and the arithmetic unit.
//
// Round robin (fp3_rr_arbiter) among the ready heads (ready_i, a
// register: the pick starts at flip-flops); the granted context has the
// lowest priority next, so no context with ready work starves.  The
// context granted in the last cycle is no candidate: its ready bit
// belonged to the instruction that left.  It is masked behind the carry
// chain (gl_q, a copy of the last grant for this mask), as in the fetch
// arbiter, so that the ready step's next state does not wait for the
// grant: the pick starts after the last grant, so it is that context only
// when no other is ready, and masking it then leaves no grant, as it
// should.  One context issues at most every other cycle (PICK_STAGES = 2:
// every third); two or more keep the arithmetic unit busy every cycle.
//
// The granted head's fields are picked from the heads' fields (selected
// by the head pointers beside the arbiter, from registers only) by the
// one-hot grant.  The instruction, as it issues: {valid, context, ra, rb,
// rd (register indices {context, register}), unit, sub, li, immediate,
// endi, beq}.
//
// Generate branches (PICK_STAGES, set by fp3_top's FMAX_PIPE):
//   g_grant_reg / g_grant_now  PICK_STAGES = 2 registers the arbiter's
//       decision (dec_q) before it is the grant (gone_o), so that the loop
//       from ready_i through the arbiter's carry chain ends at a register
//       of its own.  The context decided in the last cycle and the one
//       granted before it are no candidates (the ready step heard of
//       neither when it made ready_i), so a context is granted at most
//       every third cycle.  The round-robin position moves with the
//       decision.
//   g_pick0 / g_pick2  PICK_STAGES = 2 registers the grant (the pick
//       selects by copies of it, gpi_q, gpf_q, and picks the last heads'
//       fields: the granted word stays in its slot for a cycle), picks the
//       fields and registers them (is_q) before they issue: so neither the
//       arbiter nor a wide multiplexer sits in front of the register file,
//       and no multiplexer behind the arbiter.  Costs two cycles from the
//       grant to the issue (the dependent-issue distances are kept by the
//       tag lines' earlier announcements, fp3_wb_tag, fp3_regfile's
//       bypass).  PICK_STAGES = 0: the granted instruction issues in the
//       cycle of the grant.  (g_bad_pick_stages: any other value does not
//       elaborate.)
//
// Parameters
//   NUM_CONTEXTS  contexts, >= 1; CW = clog2, >= 1 (NC below)
//   IW            register index width; XW = CW + IW
//   PICK_STAGES   0 or 2: cycles from the grant to the issue (above)
// Ports (one-hot vectors: bit c for context c)
//   clk_i, rst_i      clock (rising edge), synchronous reset
//   running_i         a run is in progress (the arbiter restarts at
//                     context 0 and the issue register is clear while not)
//   ready_i [NC]      the heads found ready in the last cycle (fp3_sched_queue)
//   hp_i [NC]         the queues' head slots
//   fields_i [2*NC*SCH_FW]  every slot's issue fields (rtl/fp3_sched.vh)
//   gone_o [NC]       the head granted now (leaves its queue)
//   grant_o           a context is granted now
//   gone_q_o [NC]     the grant of the last cycle, while running
//   grant_q_o         ... whether there was one
//   issue_o, issue_ctx_o [CW], ra_o, rb_o, rd_o [XW], issue_unit_o [3],
//   issue_sub_o, issue_imm_o, imm_o [32], endi_o, beq_o  the instruction
//                     issuing now (fp3_scheduler's ports of the same names)
//   pick_wr_o, pick_rd_o [XW], pick_unit_o [3]  the instruction picked,
//                     which issues in the next cycle (PICK_STAGES = 2; with
//                     0, the one issuing now): it writes a register, which,
//                     and its unit
// Errors: none (PICK_STAGES other than 0 or 2 fails elaboration).
//
// Formal: formal/rr_arbiter.sby proves this module's grants and fairness
// in both builds (formal/fp3_issue_fair.v).  The define
// FP3_MUTANT_ISSUE_POS_LATE is a deliberately broken copy for the mutation
// test (tests/test_formal_mutant.sh): with PICK_STAGES = 2 the arbiter's
// position moves with the grant, a cycle after the decision, so a waiting
// context can be passed over for up to 2 NUM_CONTEXTS - 3 cycles; the
// fairness proof must fail.
`default_nettype none
module fp3_sched_issue #(
  parameter integer NUM_CONTEXTS = 1,
  parameter integer CW           = 1,
  parameter integer IW           = 5,
  parameter integer PICK_STAGES  = 0
) (
  input  wire                    clk_i,
  input  wire                    rst_i,
  input  wire                    running_i,
  input  wire [NUM_CONTEXTS-1:0] ready_i,
  input  wire [NUM_CONTEXTS-1:0] hp_i,
  input  wire [2*NUM_CONTEXTS*(3*IW+42)-1:0] fields_i,   // 2 * NC * SCH_FW
  output wire [NUM_CONTEXTS-1:0] gone_o,
  output wire                    grant_o,
  output wire [NUM_CONTEXTS-1:0] gone_q_o,
  output wire                    grant_q_o,
  output wire                    issue_o,
  output wire [CW-1:0]           issue_ctx_o,
  output wire [CW+IW-1:0]        ra_o,
  output wire [CW+IW-1:0]        rb_o,
  output wire [CW+IW-1:0]        rd_o,
  output wire [2:0]              issue_unit_o,
  output wire                    issue_sub_o,
  output wire [2:0]              issue_sop_o,   // sign group: {abs/neg/min/max, fp_sign op}
  output wire                    issue_imm_o,
  output wire [31:0]             imm_o,
  output wire                    endi_o,
  output wire                    beq_o,
  output wire                    pick_wr_o,
  output wire [CW+IW-1:0]        pick_rd_o,
  output wire [2:0]              pick_unit_o
);
`include "fp3_isa.vh"
  localparam integer NC = NUM_CONTEXTS;
  localparam integer XW = CW + IW;
`include "fp3_sched.vh"
  localparam integer FW = SCH_FW;
  localparam [FW-1:0] IMM_BITS = SCH_IMM_BITS;

  wire [NC-1:0] ready_q = ready_i;
  wire [NC-1:0] hp_q = hp_i;
  wire [2*NC*FW-1:0] fields = fields_i;
  wire          running = running_i;

  // ---- the arbiter ---------------------------------------------------------
  // The copy of the last grant that masks it takes the grant as it is, not
  // gated with RUNNING as gone_q is: while stopped ready_q is clear (no
  // context is active in a run's last cycle, and the run state is held
  // clear), so a stale mask masks nothing, and the grant meets the
  // flip-flop with no gate between.
  wire [NC-1:0] gone;         // the head granted now
  wire [NC-1:0] gl_q;
  fp3_keep #(.W(NC)) u_gone_copy (
    .clk_i (clk_i),
    .d_i   (gone),
    .q_o   (gl_q)
  );
  wire [NC-1:0] ipick;
  wire          grant;        // a context is granted (one-hot: gone)
  wire [NC-1:0] arb_req;      // the arbiter's requests, ...
  wire          arb_take;     // ... whether its pick is taken, ...
  wire [NC-1:0] arb_taken;    // ... and which (its position moves there)
  fp3_rr_arbiter #(.N(NC)) u_issue_arb (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running),
    .req_i   (arb_req),
    .pick_o  (ipick),
    .take_i  (arb_take),
    .taken_i (arb_taken)
  );
  generate
    if (PICK_STAGES == 2) begin : g_grant_reg
      reg  [NC-1:0] dec_q;
      reg           dec_any_q;
      wire [NC-1:0] cand = ready_q & ~gl_q & ~dec_q;
      // (While stopped ready_q is clear, so cand and ipick are.)
      always @(posedge clk_i) begin
        if (rst_i) begin
          dec_q     <= {NC{1'b0}};
          dec_any_q <= 1'b0;
        end else begin
          dec_q     <= ipick;
          dec_any_q <= |cand;
        end
      end
      // The position moves with the decision, not a cycle later with the
      // grant: the next decision starts after this one, so a waiting
      // context is passed over at most once by each other context and is
      // granted within NUM_CONTEXTS cycles (formal/rr_arbiter.sby,
      // prove_staged_*).  Moving it with the grant would let the next
      // decision start from the old position and go to a context behind
      // the one just decided (2 NUM_CONTEXTS - 3 cycles in the worst
      // case).  Its cost: the position register loads from the carry
      // chain's pick, as dec_q does.
      assign arb_req   = cand;
`ifdef FP3_MUTANT_ISSUE_POS_LATE
      assign arb_take  = dec_any_q;
      assign arb_taken = dec_q;
`else
      assign arb_take  = |cand;
      assign arb_taken = ipick;
`endif
      assign gone      = dec_q;     // the head leaves its queue
      assign grant     = dec_any_q;
    end else begin : g_grant_now
      wire [NC-1:0] cand = ready_q & ~gl_q;   // (the ready step counts only active contexts)
      assign arb_req   = ready_q;
      assign arb_take  = grant;
      assign arb_taken = gone;
      assign grant     = |cand;
      assign gone      = ipick & ~gl_q;   // the head leaves its queue
    end
  endgenerate
  wire [CW-1:0] g     = sch_encode(gone);
  reg  [NC-1:0] gone_q;
  reg           grant_q;
  always @(posedge clk_i) begin
    gone_q  <= gone & {NC{running}};
    grant_q <= grant && running;
  end

  // ---- the pick ------------------------------------------------------------
  // The heads' fields, and the last heads' (hp_q has moved on if the head
  // was granted; the immediate's bits by hpi_q, hp_q a cycle late: the
  // slot the head was in, which for a context granted in the last cycle is
  // the last head's; for the others the pick does not read them).
  wire [NC-1:0]    hpi_q;
  wire [NC*FW-1:0] h_fields, l_fields;
  genvar c;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_heads
      wire [FW-1:0] f_e0 = fields[2*c*FW +: FW];
      wire [FW-1:0] f_e1 = fields[(2*c+1)*FW +: FW];
      assign h_fields[c*FW +: FW] = hp_q[c] ? f_e1 : f_e0;
      assign l_fields[c*FW +: FW] = (hp_q[c] ? f_e0 : f_e1) & ~IMM_BITS |
                                    (hpi_q[c] ? f_e1 : f_e0) & IMM_BITS;
    end
  endgenerate
  // hp_q's copy for the last heads' immediates (l_fields), the 32-bit half
  // of the pick's multiplexer (its grant from gpi_q), kept: placed beside
  // that multiplexer, not with the queues.  It is hp_q a cycle late, the
  // head's slot in the grant's cycle, not hp_q's next state (hp_q ^ gone),
  // so that the grant does not cross the die to it through a gate.
  fp3_keep #(.W(NC)) u_hp_imm (
    .clk_i (clk_i),
    .d_i   (hp_q),
    .q_o   (hpi_q)
  );
  // With PICK_STAGES = 2 the pick multiplexer takes the last grant from
  // copies of its own, one for the immediate (32 bits) and one for the
  // other fields: each drives some 30 LUTs beside the heads' fields
  // instead of one register driving 53 of them and the contexts' logic.
  // The copies take the grant as it is, not gated with RUNNING as gone_q
  // is: the pick's valid bit (grant_q) is gated, and fields picked while
  // stopped are not used (gated alike, the copies would share one AND
  // gate, which the placer puts between them).  The process is kept so
  // that Yosys does not merge the two equal copies (as fp3_keep); their
  // initial value only defines them in simulation before the first clock.
  reg [NC-1:0] gpi_q, gpf_q;
  initial begin
    gpi_q = {NC{1'b0}};
    gpf_q = {NC{1'b0}};
  end
  (* keep *) always @(posedge clk_i) begin
    gpi_q <= gone;
    gpf_q <= gone;
  end
  wire          two     = PICK_STAGES == 2;
  wire [NC-1:0] p_seli  = two ? gpi_q : gone;
  wire [NC-1:0] p_self  = two ? gpf_q : gone;
  wire          p_grant = two ? grant_q : grant;
  // The granted context's number, encoded from the grant's copy in the
  // pick cycle (not registered as encoded: Yosys would make the grant a
  // synchronous reset of that register, behind the arbiter).
  wire [CW-1:0] p_g     = two ? sch_encode(gpf_q) : g;
  reg  [FW-1:0] gf;
  integer q;
  always @(*) begin
    gf = {FW{1'b0}};
    for (q = 0; q < NC; q = q + 1)
      gf = gf | (({FW{p_seli[q]}} & IMM_BITS | {FW{p_self[q]}} & ~IMM_BITS) &
                 (two ? l_fields[q*FW +: FW] : h_fields[q*FW +: FW]));
  end

  wire [IW-1:0] g_ra, g_rb, g_rd;
  wire [2:0]    g_unit;
  wire          g_sub, g_li, g_endi, g_beq;
  wire [2:0]    g_sop;
  wire [31:0]   g_imm;
  assign {g_sop, g_ra, g_rb, g_rd, g_unit, g_sub, g_li, g_imm, g_endi, g_beq} = gf;

  // ---- the issue -----------------------------------------------------------
  // {valid, ctx, ra, rb, rd, unit, sub, sop, imm (li), immediate, endi, beq}
  localparam integer IS_W = 1 + CW + 3 * XW + 3 + 1 + 3 + 1 + 32 + 1 + 1;
  wire [IS_W-1:0] is_d = {p_grant, p_g, p_g, g_ra, p_g, g_rb, p_g, g_rd, g_unit, g_sub, g_sop, g_li,
                          g_imm, p_grant && g_endi, p_grant && g_beq};
  wire [IS_W-1:0] is_w;
  // (The issue register is cleared while stopped, below.)
  assign pick_wr_o = p_grant && g_unit != UNIT_NONE &&
                     (PICK_STAGES == 0 || (!rst_i && running));
  assign pick_rd_o = {p_g, g_rd};
  assign pick_unit_o = g_unit;
  generate
    if (PICK_STAGES == 0) begin : g_pick0
      assign is_w = is_d;
    end else if (PICK_STAGES == 2) begin : g_pick2
      reg [IS_W-1:0] is_q;
      always @(posedge clk_i) begin
        if (rst_i || !running) is_q <= {IS_W{1'b0}};
        else                   is_q <= is_d;
      end
      assign is_w = is_q;
    end else begin : g_bad_pick_stages
      // Elaboration error on purpose: PICK_STAGES must be 0 or 2.
      fp3_scheduler_error_PICK_STAGES_must_be_0_or_2 u_error ();
    end
  endgenerate
  assign {issue_o, issue_ctx_o, ra_o, rb_o, rd_o, issue_unit_o, issue_sub_o, issue_sop_o, issue_imm_o,
          imm_o, endi_o, beq_o} = is_w;

  assign gone_o    = gone;
  assign grant_o   = grant;
  assign gone_q_o  = gone_q;
  assign grant_q_o = grant_q;

`ifdef FORMAL
  // The arbiter picks only among its requests, the candidates (on the
  // default build ready_q, of which gone masks gl_q: so the grant is a
  // candidate).  (That the granted context is active is asserted in
  // fp3_scheduler, where the active contexts are in sight.)
  always @(*) assert ((ipick & ~arb_req) == {NC{1'b0}});
`endif
endmodule
`default_nettype wire
