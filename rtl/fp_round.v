// fp_round.v -- first half of rounding a binary32 result (combinational),
// shared by fp_add and fp_mul: the round-up decision and the increment of
// the packed exponent and fraction.  fp_round_pack finishes the result
// (overflow, flush to zero, flags); a core may put a register between the
// two.
//
// Parameters:
//   ROUND  0: round to nearest, ties to even (RNE); 1: toward zero (RTZ)
//
// Ports (input is the exact result, normalised, with its low bits kept as
// guard, round and sticky):
//   exp_i      biased exponent, >= 1 (may exceed 254: overflow)
//   mant_i     24-bit significand incl. the hidden bit; mant_i[23] == 0
//              only if exp_i == 1 (subnormal before rounding) or the value
//              is 0 (then any exp_i: the result is a zero)
//   guard_i    first bit below mant_i[0]
//   round_i    second bit below mant_i[0]
//   sticky_i   OR of all lower bits
//   pack_o     exponent and fraction fields of the rounded magnitude
//              (meaningless on overflow)
//   overflow_o the rounded exponent is >= 255 (found from the inputs,
//              beside the increment's carry chain)
//   inexact_o  the result is inexact (guard, round or sticky set)
//   tiny_o     the result is tiny (below 2^-126) after rounding
//
// Packing: the hidden bit selects the exponent field (exp_i for a normal
// significand, 0 for a subnormal one, since then exp_i == 1), and the
// round-up adds into the whole word, so a subnormal that rounds up to
// 2^-126 and a significand that rounds up to 2^24 both come out right:
// one 31-bit increment.
//
// Standards: IEEE 754-2008 §4.3 (roundTiesToEven, roundTowardZero); §7.5
// tininess detected after rounding (as x86 and TestFloat -tininessafter):
// the result is tiny when rounding the exact value to 24 bits with an
// unbounded exponent gives a magnitude below 2^-126.
`default_nettype none

module fp_round #(
  parameter integer ROUND = 0 // 0 RNE, 1 RTZ
) (
  input  wire [9:0]  exp_i,
  input  wire [23:0] mant_i,
  input  wire        guard_i,
  input  wire        round_i,
  input  wire        sticky_i,
  output wire [30:0] pack_o,
  output wire        overflow_o,
  output wire        inexact_o,
  output wire        tiny_o
);

  localparam integer ROUND_RNE = 0;
  localparam [23:0]  MANT_TOP  = 24'h7F_FFFF; // largest subnormal significand

  assign inexact_o = guard_i | round_i | sticky_i;

  // Round up by one ulp?
  wire round_up = (ROUND == ROUND_RNE) ? (guard_i & (mant_i[0] | round_i | sticky_i))
                                       : 1'b0;

  wire [9:0] exp_field = exp_i & {10{mant_i[23]}};
  assign pack_o = {exp_field[7:0], mant_i[22:0]} + {30'd0, round_up};

  // Overflow: the exponent field is >= 255 already, or 254 with a carry
  // out of the fraction (all ones, rounded up).
  assign overflow_o = exp_field[9] | exp_field[8] | (&exp_field[7:0])
                    | ((exp_field == 10'd254) & (&mant_i[22:0]) & round_up);

  // Tiny after rounding: below 2^-126 before rounding (a subnormal
  // significand), and not rounding up to 2^-126 with an unbounded
  // exponent (RNE: 0x7FFFFF.11b and above).
  wire nonzero = (|mant_i) | inexact_o;
  wire rnd_out = (ROUND == ROUND_RNE) & (mant_i == MANT_TOP) & guard_i & round_i;
  assign tiny_o = ~mant_i[23] & nonzero & ~rnd_out;

endmodule

`default_nettype wire
