// fp_norm_exp.v -- the exponent half of the final normalisation of a
// significand whose leading one may sit in either of two places
// (combinational): fp_mul's product in [1, 4), fp_div's quotient in
// (1/2, 2).  From the exponent alone, before the significand is known,
// it gives the result exponent for either place of the leading one and
// the right shift that normalises and denormalises in one, so that the
// significand's stage (fp_norm_shift) only picks by its top bit.
//
// With e the biased exponent that goes with the leading one at the
// higher place (top bit set):
//   result exponent  top bit set: max(e, 1);  clear: max(e - 1, 1)
//   right shift of the significand's top 27 bits: e >= 2: the top bit
//   (0 or 1 place, the one-place normalisation, added by fp_norm_shift);
//   e <= 1: 2 - e places either way (a tiny result denormalised), at most
//   SHIFT_MAX, which sends every bit to sticky
//
// Ports:
//   exp_i    e, 10-bit two's complement (may be negative or above 254)
//   exp_a_o  result exponent if the top bit is set, >= 1
//   exp_b_o  result exponent if it is clear, >= 1
//   ge2_o    e >= 2: the shift is the top bit alone (fp_norm_shift adds
//            it)
//   shift_o  the shift without the top bit's place: 0 if ge2_o, else
//            min(2 - e, 31)
//
// Standards: IEEE 754-2019 §3.4 (a subnormal has the exponent of the
// smallest normal, 1 biased, and no hidden bit).
`default_nettype none

module fp_norm_exp (
  input  wire [9:0] exp_i,
  output wire [9:0] exp_a_o,
  output wire [9:0] exp_b_o,
  output wire       ge2_o,
  output wire [4:0] shift_o
);

  localparam [9:0] SHIFT_MAX = 10'd31; // right shifts >= 27 leave sticky

  wire       ge1    = ~exp_i[9] & (exp_i != 10'd0);
  wire       ge2    = ge1 & (exp_i != 10'd1);
  wire [9:0] exp_m1 = exp_i - 10'd1;
  wire [9:0] rs     = 10'd2 - exp_i;

  assign ge2_o   = ge2;
  assign exp_a_o = ge1 ? exp_i : 10'd1;
  assign exp_b_o = ge2 ? exp_m1 : 10'd1;
  // (rs > SHIFT_MAX written as bits: no comparator chain)
  assign shift_o = ge2 ? 5'd0 : ((|rs[9:5]) ? SHIFT_MAX[4:0] : rs[4:0]);

endmodule

`default_nettype wire
