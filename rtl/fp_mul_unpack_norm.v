// fp_mul_unpack_norm.v -- significand and exponent of a finite binary32
// operand for fp_mul, subnormals normalised (combinational).
//
// Parameters:
//   FTZ  1: subnormals are read as zero by the caller; the normalising
//        shifter is left out
//
// Ports:
//   exp_i   biased exponent field (0 for zero/subnormal)
//   frac_i  fraction field
//   man_o   significand with the leading one at bit 23 (0 for zero)
//   exp_o   exponent of man_o, 10-bit two's complement: exp_i for normals,
//           1 - (leading zeros of {0, frac_i}) for subnormals
//
// Normalising subnormal inputs here keeps the product in [2^46, 2^48), so
// the multiplier output needs at most a one-place normalisation (IEEE
// 754-2008 §3.4 encoding of subnormals).
`default_nettype none

module fp_mul_unpack_norm #(
  parameter integer FTZ = 0 // 1: no subnormal support needed
) (
  input  wire [7:0]  exp_i,
  input  wire [22:0] frac_i,
  output wire [23:0] man_o,
  output wire [9:0]  exp_o
);

  wire normal = (exp_i != 8'd0);

  // Leading-zero count by binary search, shifting as it goes.
  reg [23:0] v;
  reg [4:0]  n;
  always @* begin
    v = {1'b0, frac_i};
    n = 5'd0;
    if (v[23:8] == 16'd0) begin v = v << 16; n = n + 5'd16; end
    if (v[23:16] == 8'd0) begin v = v << 8;  n = n + 5'd8;  end
    if (v[23:20] == 4'd0) begin v = v << 4;  n = n + 5'd4;  end
    if (v[23:22] == 2'd0) begin v = v << 2;  n = n + 5'd2;  end
    if (v[23] == 1'b0)    begin v = v << 1;  n = n + 5'd1;  end
  end

  generate
    if (FTZ != 0) begin : g_ftz
      assign man_o = {normal, frac_i};
      assign exp_o = {2'd0, exp_i};
      wire unused_norm = &{1'b0, v, n, 1'b0};
    end else begin : g_ieee
      assign man_o = normal ? {1'b1, frac_i} : v;
      assign exp_o = normal ? {2'd0, exp_i} : (10'd1 - {5'd0, n});
    end
  endgenerate

endmodule

`default_nettype wire
