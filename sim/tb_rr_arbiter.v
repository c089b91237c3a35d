// tb_rr_arbiter -- self-checking Icarus testbench of fp3_rr_arbiter
// (tests/test_rr_arbiter.sh): random requests for +cycles=C cycles
// (default 20000) from +seed=S (default 1), the pick compared every cycle
// with a reference written differently (a loop from the requester after
// the last grant taken, wrapping around), in two uses, a thousand cycles
// each in turn:
//   plain   the pick is taken whenever there is one (take = |req);
//   masked  the grant taken in the last cycle is masked behind the
//           pick (taken = pick & ~last) and taken if any is left: the
//           scheduler's issue and fetch arbiters.  Their claim that this
//           takes a grant exactly when a requester other than the last
//           grant asks (fp3_sched_issue: grant; fp3_sched_fetch: fetch) is checked too.
// A random reset now and then starts the round at requester 0 again.
// Prints "PASS: tb_rr_arbiter N=... " or "FAIL: ..." lines and finishes.
`default_nettype none
module tb_rr_arbiter;
  parameter integer N = 8;

  reg          clk = 1'b0;
  reg          rst = 1'b1;
  reg  [N-1:0] req = {N{1'b0}};
  reg  [N-1:0] last = {N{1'b0}};   // the grant taken in the last cycle (masked use)
  reg          masked = 1'b0;
  wire [N-1:0] pick;
  wire [N-1:0] taken = masked ? pick & ~last : pick;
  wire         take  = |taken;

  fp3_rr_arbiter #(.N(N)) dut (
    .clk_i   (clk),
    .rst_i   (rst),
    .req_i   (req),
    .pick_o  (pick),
    .take_i  (take),
    .taken_i (taken)
  );

  integer cycles, seed, cyc, errors, k, after, picks;
  integer ref_last;                // reference: the last grant taken (N - 1 after reset)
  reg [N-1:0] want;

  initial begin
    if (!$value$plusargs("cycles=%d", cycles)) cycles = 20000;
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    errors = 0;
    picks  = 0;
    ref_last = N - 1;
    @(posedge clk);
    #1 rst = 1'b0;
    for (cyc = 0; cyc < cycles; cyc = cyc + 1) begin
      // New inputs after the edge: dense requests mostly, some sparse.
      req = $random(seed);
      if (($random(seed) & 3) == 0) req = req & $random(seed);
      masked = (cyc / 1000) % 2 == 1;
      #1;
      // The reference pick: the first requester after ref_last.
      want = {N{1'b0}};
      for (k = N; k >= 1; k = k - 1) begin
        after = (ref_last + k) % N;
        if (req[after]) begin
          want = {N{1'b0}};
          want[after] = 1'b1;
        end
      end
      if (pick !== want) begin
        errors = errors + 1;
        if (errors <= 10)
          $display("FAIL: tb_rr_arbiter N=%0d cycle %0d: requests %b, last grant %0d: pick %b, want %b",
                   N, cyc, req, ref_last, pick, want);
      end
      if (masked && take !== |(req & ~last)) begin
        errors = errors + 1;
        if (errors <= 10)
          $display("FAIL: tb_rr_arbiter N=%0d cycle %0d: masked use takes %b with requests %b, last %b",
                   N, cyc, take, req, last);
      end
      @(posedge clk);
      last = taken;                // zero after a cycle without a grant
      if (take) begin
        picks = picks + 1;
        for (k = 0; k < N; k = k + 1) if (taken[k]) ref_last = k;
      end
      // A reset now and then: the round starts at requester 0 again.
      if (($random(seed) & 255) == 0) begin
        #1 rst = 1'b1;
        @(posedge clk);
        #1 rst = 1'b0;
        ref_last = N - 1;
        last = {N{1'b0}};
      end
    end
    if (errors == 0)
      $display("PASS: tb_rr_arbiter N=%0d: %0d cycles, %0d grants taken, every pick as the reference",
               N, cycles, picks);
    else
      $display("FAIL: tb_rr_arbiter N=%0d: %0d mismatches", N, errors);
    $finish;
  end

  always #5 clk = ~clk;
endmodule
`default_nettype wire
