// tb_dsp_mul.v -- fp_dsp_mul's ECP5 netlist (module fp_dsp_mul_ecp5, a
// MULT18X18D: tests/test_dsp_mul.sh) against its behavioural form (the RTL
// without FP3_ECP5_DSP), both fed the same operands every cycle: random
// ones, and in one cycle of eight the extremes 0, 1 and 2^W - 1 mixed in.
// Every cycle's product compared from the third on (the latency is 2).
// Plusargs: +cycles=N (default 20000), +seed=S.  Prints PASS or FAIL.
`default_nettype none
module tb_dsp_mul;
  parameter integer W = 12;
  reg              clk = 1'b0;
  reg  [W-1:0]     a = {W{1'b0}}, b = {W{1'b0}};
  wire [2*W-1:0]   p_rtl, p_net;
  fp_dsp_mul      #(.W(W)) u_rtl (.clk_i(clk), .a_i(a), .b_i(b), .p_o(p_rtl));
  fp_dsp_mul_ecp5          u_net (.clk_i(clk), .a_i(a), .b_i(b), .p_o(p_net));
  // The operands set two falling edges before: the expected product.
  reg  [W-1:0]     a1 = {W{1'b0}}, b1 = {W{1'b0}};
  integer t, cycles, seed, bad;
  always #5 clk = !clk;
  function [W-1:0] pick(input integer r, input integer sel);
    begin
      case (sel & 3)
        0: pick = {W{1'b0}};
        1: pick = {{(W-1){1'b0}}, 1'b1};
        2: pick = {W{1'b1}};
        default: pick = r[W-1:0];
      endcase
    end
  endfunction
  initial begin
    if (!$value$plusargs("cycles=%d", cycles)) cycles = 20000;
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    bad = 0;
    for (t = 0; t < cycles; t = t + 1) begin
      @(negedge clk);
      if (t >= 2 && (p_rtl !== a1 * b1 || p_net !== p_rtl)) begin
        if (bad < 5)
          $display("cycle %0d: %0d * %0d: behavioural %0d, netlist %0d", t, a1, b1, p_rtl, p_net);
        bad = bad + 1;
      end
      a1 = a; b1 = b;
      if (($random(seed) & 7) == 0) begin
        a = pick($random(seed), $random(seed));
        b = pick($random(seed), $random(seed));
      end else begin
        a = $random(seed);
        b = $random(seed);
      end
    end
    if (bad == 0) $display("PASS: W = %0d, %0d cycles", W, cycles);
    else          $display("FAIL: %0d of %0d products differ", bad, cycles);
    $finish;
  end
endmodule
`default_nettype wire
