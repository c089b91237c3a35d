// fp3_issue_fair -- formal harness of the scheduler's issue step,
// rtl/fp3_sched_issue.v itself (its arbiter, the masks of the last grant
// and decision, PICK_STAGES' registered decision), with free inputs:
// whichever heads are ready, whatever their fields.  Bind-free: it drives
// the module's ports as fp3_scheduler does.
//
// Assumptions (the scheduler's side of the contract): every trace starts
// with a reset; after a cycle in reset or with no run in progress no
// head is ready (the queue step's ready register, fp3_sched_queue's
// ready_q, is cleared then).
//
// Properties, for every context f_c (a free constant):
//   G1  at most one context is granted per cycle, and grant_o says whether
//       one is;
//   G2  the grant is a candidate: with PICK_STAGES = 0 a head ready now
//       and not granted in the last cycle; with PICK_STAGES = 2 a head
//       that was ready in the last cycle and was then neither the
//       decision nor the grant before it;
//   F   fairness: a context that keeps requesting (its head ready, not
//       masked as the last grant or, with PICK_STAGES = 2, as the current
//       decision, until it is granted) is granted within BOUND cycles,
//       counted from its first cycle of request.  NUM_CONTEXTS in both
//       builds (formal/rr_arbiter.sby, tasks issue_*); the bound is tight
//       (BOUND = N - 1 fails: task issue_staged_8_tight);
//   C   (cover) a grant after exactly N - 1 cycles of waiting, and a grant
//       while other heads are ready too.
//
// Parameters: N contexts; STAGES, the module's PICK_STAGES (0 or 2); BOUND
// of F, cycles.
`default_nettype none
module fp3_issue_fair #(
  parameter integer N      = 8,
  parameter integer STAGES = 0,
  parameter integer BOUND  = N
) (
  input  wire                  clk_i,
  input  wire                  rst_i,
  input  wire                  running_i,
  input  wire [N-1:0]          ready_i,
  input  wire [N-1:0]          hp_i,
  input  wire [2*N*(3*2+42)-1:0] fields_i   // 2 * N * SCH_FW with IW = 2
);
  localparam integer CW = (N <= 2) ? 1 : $clog2(N);
  initial assume (rst_i);
  reg f_stop_q = 1'b1;          // the last cycle was in reset or stopped
  always @(posedge clk_i) f_stop_q <= rst_i || !running_i;
  always @(*) if (f_stop_q) assume (ready_i == {N{1'b0}});

  wire [N-1:0] gone, gone_q;
  wire         grant, grant_q;
  fp3_sched_issue #(
    .NUM_CONTEXTS (N),
    .CW           (CW),
    .IW           (2),
    .PICK_STAGES  (STAGES)
  ) u_issue (
    .clk_i (clk_i), .rst_i (rst_i), .running_i (running_i),
    .ready_i (ready_i), .hp_i (hp_i), .fields_i (fields_i),
    .gone_o (gone), .grant_o (grant), .gone_q_o (gone_q), .grant_q_o (grant_q),
    .issue_o (), .issue_ctx_o (), .ra_o (), .rb_o (), .rd_o (), .issue_unit_o (),
    .issue_sub_o (), .issue_sop_o (), .issue_imm_o (), .imm_o (), .endi_o (), .beq_o (),
    .pick_wr_o (), .pick_rd_o (), .pick_unit_o ()
  );

  reg f_past = 1'b0;
  always @(posedge clk_i) f_past <= 1'b1;
  reg [N-1:0] last_q;          // the last cycle's grant
  reg [N-1:0] cand_q;          // the last cycle's candidates (PICK_STAGES = 2)
  initial last_q = {N{1'b0}};
  initial cand_q = {N{1'b0}};
  wire [N-1:0] masked = last_q | (STAGES != 0 ? gone : {N{1'b0}});
  always @(posedge clk_i) begin
    last_q <= gone;
    cand_q <= rst_i ? {N{1'b0}} : ready_i & ~masked;
  end

  // ---- G1, G2 --------------------------------------------------------------------
  always @(*) if (f_past && !rst_i) begin
    g1_one_grant: assert ($onehot0(gone));
    g1_grant_flag: assert (grant == (gone != {N{1'b0}}));
    if (STAGES != 0) g2_granted_cand: assert ((gone & ~cand_q) == {N{1'b0}});
    else             g2_granted_ready: assert ((gone & ~(ready_i & ~last_q)) == {N{1'b0}});
  end

  // ---- F: fairness for the context f_c -------------------------------------------
  (* anyconst *) reg [CW-1:0] f_c;
  always @(*) assume (f_c < N);
  wire f_req = running_i && ready_i[f_c] && !masked[f_c];
  wire f_gnt = gone[f_c];
  wire [7:0] f_wait;           // cycles f_c has requested without a grant
  wire       f_waiting;        // ... and it requested in the last cycle
  fp3_fair_wait #(.BOUND(BOUND)) u_wait (
    .clk_i (clk_i), .rst_i (rst_i), .req_i (f_req), .gnt_i (f_gnt),
    .wait_o (f_wait), .waiting_o (f_waiting)
  );
  // It keeps requesting until the grant; a reset or the end of the run
  // (running_i low) ends the wait.
  always @(*) if (f_waiting && !rst_i && running_i) assume (ready_i[f_c]);

  // ---- C -------------------------------------------------------------------------
  always @(*) if (!rst_i) begin
    c_grant_after_n_minus_1: cover (f_gnt && f_wait == N - 1);
    c_grant_contended:       cover (f_gnt && (ready_i & ~(1 << f_c)) != {N{1'b0}});
  end
endmodule
`default_nettype wire
