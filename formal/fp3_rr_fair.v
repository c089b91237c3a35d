// fp3_rr_fair -- formal harness of fp3_rr_arbiter in the disciplines of its
// two callers in fp3_scheduler (bind-free: it drives the arbiter's ports
// the way the scheduler does, from free requests).
//
//   STAGED = 0  the issue arbiter with PICK_STAGES = 0, and the fetch
//               arbiter: the last grant (last_q) is masked behind the pick;
//               a grant is taken in the cycle of the pick, and the
//               position moves there.
//   STAGED = 1  the issue arbiter with PICK_STAGES = 2 (the build for clock
//               rate, FMAX_PIPE): the candidates exclude the context
//               decided in the last cycle (dec_q) and the one granted
//               (last_q); the pick is registered as the decision, which is
//               the grant of the next cycle; the position moves with the
//               decision.
//
// Properties, for every context f_c (a free constant):
//   F1  the grant is a requester (a candidate), at most one per cycle;
//   F2  fairness: a context that keeps requesting (its request, not masked
//       as the last grant or decision, stays high until it is granted) is
//       granted within BOUND cycles, counted from its first cycle of
//       request: N in both disciplines (tight for STAGED = 1: N - 1
//       fails, a counterexample for N = 8; formal/rr_arbiter.sby);
//   C1  (cover) a grant after exactly N - 1 cycles of waiting, and a grant
//       while others request too.
// The arbiter's own assertions (rtl/fp3_rr_arbiter.v) are proved with
// them.  The scheduler's requests (ready heads, fetch requests) come from
// its internals, so this harness takes them free: whatever the requests,
// the arbiter and its masking serve every requester within N cycles.
//
// Parameters: N requesters; STAGED 0 or 1 (above); BOUND of F2, cycles.
`default_nettype none
module fp3_rr_fair #(
  parameter integer N      = 8,
  parameter integer STAGED = 0,
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
  wire [N-1:0] masked;        // requests not counted: last grant / decision
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

  generate
    if (STAGED != 0) begin : g_staged
      reg [N-1:0] dec_q;
      reg         dec_any_q;
      wire [N-1:0] cand = req_i & ~last_q & ~dec_q;
      always @(posedge clk_i) begin
        if (rst_i) begin
          dec_q     <= {N{1'b0}};
          dec_any_q <= 1'b0;
        end else begin
          dec_q     <= pick;
          dec_any_q <= |cand;
        end
      end
      assign arb_req = cand;
      assign take    = |cand;
      assign taken   = pick;
      assign granted = dec_q;
      assign masked  = last_q | dec_q;
      // F1: the decision was a candidate when it was made
      reg [N-1:0] cand_q;     // the last cycle's candidates
      always @(posedge clk_i) cand_q <= rst_i ? {N{1'b0}} : cand;
      always @(*) if (!rst_i) f1_granted_cand: assert ((granted & ~cand_q) == {N{1'b0}});
    end else begin : g_now
      assign arb_req = req_i;
      assign take    = |(req_i & ~last_q);
      assign taken   = pick & ~last_q;
      assign granted = rst_i ? {N{1'b0}} : taken;
      assign masked  = last_q;
      always @(*) if (!rst_i) f1_granted_req: assert ((granted & ~req_i) == {N{1'b0}});
    end
  endgenerate
  always @(*) if (!rst_i) f1_one_grant: assert ($onehot0(granted));

  // ---- F2: fairness for the context f_c -----------------------------------------
  (* anyconst *) reg [CW-1:0] f_c;
  always @(*) assume (f_c < N);
  wire f_req  = req_i[f_c] && !masked[f_c];
  wire f_gnt  = granted[f_c];
  reg  [7:0] f_wait;          // cycles f_c has requested without a grant
  reg        f_waiting;       // ... and it requested in the last cycle
  always @(posedge clk_i) begin
    if (rst_i || f_gnt || !f_req) begin
      f_wait    <= 8'd0;
      f_waiting <= 1'b0;
    end else begin
      f_wait    <= f_wait + 8'd1;
      f_waiting <= 1'b1;
    end
  end
  // It keeps requesting: once it has requested, its request stays until
  // the grant (a reset, !RUNNING in the scheduler, ends the wait).
  always @(*) if (f_waiting && !rst_i) assume (req_i[f_c]);
  always @(*) if (!rst_i && f_req) f2_served_within_n: assert (f_wait < BOUND);

  // ---- C1 ------------------------------------------------------------------------
  always @(*) if (!rst_i) begin
    c_grant_after_n_minus_1: cover (f_gnt && f_wait == N - 1);
    c_grant_contended:       cover (f_gnt && (req_i & ~(1 << f_c)) != {N{1'b0}});
  end
endmodule
`default_nettype wire
