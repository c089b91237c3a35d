// fp3_rr_fair -- formal harness of fp3_rr_arbiter in the discipline of the
// scheduler's fetch arbiter (rtl/fp3_sched_fetch.v; bind-free: it drives
// the arbiter's ports the way the fetch step does, from free requests):
// the last grant (last_q) is masked behind the pick; a grant is taken in
// the cycle of the pick, and the position moves there.  (The issue
// arbiter is proved inside its module, rtl/fp3_sched_issue.v:
// formal/fp3_issue_fair.v.)
//
// Properties, for every context f_c (a free constant):
//   F1  the grant is a requester, at most one per cycle;
//   F2  fairness: a context that keeps requesting (its request, not masked
//       as the last grant, stays high until it is granted) is granted
//       within BOUND = N cycles, counted from its first cycle of request
//       (formal/fp3_fair_wait.v);
//   C1  (cover) a grant after exactly N - 1 cycles of waiting, and a grant
//       while others request too.
// The arbiter's own assertions (rtl/fp3_rr_arbiter.v) are proved with
// them.
//
// Parameters: N requesters; BOUND of F2, cycles.
`default_nettype none
module fp3_rr_fair #(
  parameter integer N      = 8,
  parameter integer BOUND  = N
) (
  input  wire         clk_i,
  input  wire         rst_i,
  input  wire [N-1:0] req_i
);
  localparam integer CW = (N <= 2) ? 1 : $clog2(N);
  initial assume (rst_i);

  wire [N-1:0] pick;
  wire [N-1:0] arb_req;
  wire         take;
  wire [N-1:0] taken;
  wire [N-1:0] granted;       // the context granted this cycle (one-hot or 0)
  wire [N-1:0] masked;        // requests not counted: the last grant
  reg  [N-1:0] last_q;        // the last cycle's grant (fp3_keep: no reset)
  initial last_q = {N{1'b0}};
  always @(posedge clk_i) last_q <= granted;

  fp3_rr_arbiter #(.N(N)) u_arb (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .req_i   (arb_req),
    .pick_o  (pick),
    .take_i  (take),
    .taken_i (taken)
  );

  assign arb_req = req_i;
  assign take    = |(req_i & ~last_q);
  assign taken   = pick & ~last_q;
  assign granted = rst_i ? {N{1'b0}} : taken;
  assign masked  = last_q;
  always @(*) if (!rst_i) f1_granted_req: assert ((granted & ~req_i) == {N{1'b0}});
  always @(*) if (!rst_i) f1_one_grant: assert ($onehot0(granted));

  // ---- F2: fairness for the context f_c -----------------------------------------
  (* anyconst *) reg [CW-1:0] f_c;
  always @(*) assume (f_c < N);
  wire f_req  = req_i[f_c] && !masked[f_c];
  wire f_gnt  = granted[f_c];
  wire [7:0] f_wait;          // cycles f_c has requested without a grant
  wire       f_waiting;       // ... and it requested in the last cycle
  fp3_fair_wait #(.BOUND(BOUND)) u_wait (
    .clk_i (clk_i), .rst_i (rst_i), .req_i (f_req), .gnt_i (f_gnt),
    .wait_o (f_wait), .waiting_o (f_waiting)
  );
  // It keeps requesting: once it has requested, its request stays until
  // the grant (a reset, !RUNNING in the scheduler, ends the wait).
  always @(*) if (f_waiting && !rst_i) assume (req_i[f_c]);

  // ---- C1 ------------------------------------------------------------------------
  always @(*) if (!rst_i) begin
    c_grant_after_n_minus_1: cover (f_gnt && f_wait == N - 1);
    c_grant_contended:       cover (f_gnt && (req_i & ~(1 << f_c)) != {N{1'b0}});
  end
endmodule
`default_nettype wire
