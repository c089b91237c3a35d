// fp_mul_unpack_norm.v -- significand and normalising shift of a finite
// binary32 operand for fp_mul (combinational).
//
// Parameters:
//   FTZ  1: subnormals are read as zero by the caller; no leading-zero
//        count is needed (lz_o = 0)
//
// Ports:
//   exp_i   biased exponent field (0 for zero/subnormal)
//   frac_i  fraction field
//   man_o   significand with the weight of the exponent field exp_i:
//           {1, frac_i} for a normal operand, {frac_i, 0} for a
//           subnormal one (its value 2^-126 * 0.frac_i is 2^(0-127) times
//           frac_i / 2^22, so that its exponent is the field itself, 0,
//           and not 1); FTZ: {1, frac_i} (a subnormal is the caller's
//           special case)
//   lz_o    leading zeros of man_o (0 for normals, 0 to 22 for
//           subnormals, 24 for zero): man_o << lz_o has its leading one
//           at bit 23, with the exponent exp_i - lz_o
//
// fp_mul adds the exponent fields as they are, shifts the significand by
// lz_o in the next stage (m1b) and subtracts lz_o from the exponent there,
// so that the product lies in [2^46, 2^48) and needs at most a one-place
// normalisation (IEEE 754-2008 §3.4 encoding of subnormals).  The
// exponent sum does not wait for the exponent-is-zero test.
`default_nettype none

module fp_mul_unpack_norm #(
  parameter integer FTZ = 0 // 1: no subnormal support needed
) (
  input  wire [7:0]  exp_i,
  input  wire [22:0] frac_i,
  output wire [23:0] man_o,
  output wire [4:0]  lz_o
);

  generate
    if (FTZ != 0) begin : g_ftz
      assign man_o = {1'b1, frac_i};
      assign lz_o  = 5'd0;
      // The exponent only decides normal or not, which the caller does.
      wire unused_exp = &{1'b0, exp_i, 1'b0};
    end else begin : g_ieee
      wire normal = (exp_i != 8'd0);
      assign man_o = normal ? {1'b1, frac_i} : {frac_i, 1'b0};
      // Leading zeros of {frac_i, 0}, the subnormal significand, counted
      // beside the exponent-is-zero test.
      wire [4:0] lz_sub;
      fp_lzc #(.WIDTH(24)) u_lzc (
        .v_i ({frac_i, 1'b0}),
        .n_o (lz_sub)
      );
      assign lz_o = normal ? 5'd0 : lz_sub;
    end
  endgenerate

endmodule

`default_nettype wire
