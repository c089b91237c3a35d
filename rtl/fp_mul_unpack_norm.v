// fp_mul_unpack_norm.v -- significand, exponent and normalising shift of a
// finite binary32 operand for fp_mul (combinational).
//
// Parameters:
//   FTZ  1: subnormals are read as zero by the caller; no leading-zero
//        count is needed (lz_o = 0)
//
// Ports:
//   exp_i   biased exponent field (0 for zero/subnormal)
//   frac_i  fraction field
//   man_o   significand {hidden bit, frac_i} (not yet normalised)
//   exp_o   exponent of man_o: exp_i for normals, 1 for subnormals
//   lz_o    leading zeros of man_o (0 for normals, 1 to 23 for
//           subnormals, 24 for zero): man_o << lz_o has its leading one
//           at bit 23, with the exponent exp_o - lz_o
//
// fp_mul shifts the significand by lz_o in the next stage (m1b), so that
// the product lies in [2^46, 2^48) and needs at most a one-place
// normalisation (IEEE 754-2008 §3.4 encoding of subnormals).
`default_nettype none

module fp_mul_unpack_norm #(
  parameter integer FTZ = 0 // 1: no subnormal support needed
) (
  input  wire [7:0]  exp_i,
  input  wire [22:0] frac_i,
  output wire [23:0] man_o,
  output wire [7:0]  exp_o,
  output wire [4:0]  lz_o
);

  wire normal = (exp_i != 8'd0);

  assign man_o = {normal, frac_i};
  assign exp_o = {exp_i[7:1], exp_i[0] | ~normal};

  generate
    if (FTZ != 0) begin : g_ftz
      assign lz_o = 5'd0;
    end else begin : g_ieee
      fp_lzc #(.WIDTH(24)) u_lzc (
        .v_i (man_o),
        .n_o (lz_o)
      );
    end
  endgenerate

endmodule

`default_nettype wire
