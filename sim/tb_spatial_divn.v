// tb_spatial_divn.v -- exhaustive test of rtl/fp3_spatial_divn.v: for
// every dividend x < 2^W, x / N and x mod N, started back to back and
// after idle cycles, and each again at once (the result kept).  Prints "PASS N=.. W=.." or the first mismatches
// and "FAIL"; tests/test_spatial_chip.sh runs it (iverilog) for several N.
`default_nettype none
module tb_spatial_divn;
  parameter integer N = 3;
  parameter integer W = 10;
  localparam integer NB = N <= 2 ? 1 : $clog2(N);
  reg clk = 1'b0, rst = 1'b1, start = 1'b0;
  reg [W-1:0] x = {W{1'b0}};
  wire ready;
  wire [W-1:0] q;
  wire [NB-1:0] r;
  integer v, errors = 0, idle;
  fp3_spatial_divn #(.N(N), .W(W), .NB(NB)) dut (
    .clk_i (clk), .rst_i (rst), .start_i (start), .x_i (x),
    .ready_o (ready), .q_o (q), .r_o (r)
  );
  always #5 clk = !clk;
  initial begin
    @(negedge clk) rst = 1'b0;
    for (v = 0; v < (1 << W); v = v + 1) begin
      @(negedge clk);
      if (!ready) begin errors = errors + 1; $display("not ready before x=%0d", v); end
      x = v; start = 1'b1;
      @(negedge clk) start = 1'b0;
      while (!ready) @(negedge clk);
      if (q != v / N || r != v % N) begin
        errors = errors + 1;
        if (errors < 10) $display("x=%0d: q=%0d r=%0d, want %0d %0d", v, q, r, v / N, v % N);
      end
      // the same dividend again: its result at once
      start = 1'b1;
      @(negedge clk) start = 1'b0;
      if (!ready || q != v / N || r != v % N) begin
        errors = errors + 1;
        if (errors < 10) $display("x=%0d again: ready=%0d q=%0d r=%0d", v, ready, q, r);
      end
      for (idle = 0; idle < v % 3; idle = idle + 1) @(negedge clk);
    end
    if (errors) $display("FAIL N=%0d W=%0d: %0d errors", N, W, errors);
    else $display("PASS N=%0d W=%0d: every x < %0d", N, W, 1 << W);
    $finish;
  end
endmodule
`default_nettype wire
