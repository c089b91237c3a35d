// fp_round.v -- rounding, overflow/underflow handling and packing of a
// binary32 result (combinational), shared by fp_add and fp_mul.
//
// Parameters:
//   ROUND  0: round to nearest, ties to even (RNE); 1: toward zero (RTZ)
//   FTZ    1: a tiny result is flushed to a zero of the same sign
//
// Ports (input is the exact result, normalised, with its low bits kept as
// guard, round and sticky):
//   sign_i    sign of the result
//   exp_i     biased exponent, >= 1 (may exceed 254: overflow)
//   mant_i    24-bit significand incl. the hidden bit; mant_i[23] == 0 only
//             if exp_i == 1 (subnormal before rounding) or the value is 0
//   guard_i   first bit below mant_i[0]
//   round_i   second bit below mant_i[0]
//   sticky_i  OR of all lower bits
//   y_o       binary32 result
//   flags_o   {invalid(0), infinite(0), overflow, underflow, inexact}
//
// Standards: IEEE 754-2008 §4.3 (roundTiesToEven, roundTowardZero), §7.4
// overflow (RNE: infinity, RTZ: largest finite, both with inexact), §7.5
// underflow with tininess detected after rounding (as x86 and TestFloat
// -tininessafter): the result is tiny when rounding the exact value to 24
// bits with an unbounded exponent gives a magnitude below 2^-126; the
// underflow flag is raised when tiny and inexact.  FTZ (not IEEE, matches
// x86 MXCSR.FTZ): a tiny nonzero result becomes +-0 with underflow and
// inexact.
`default_nettype none

module fp_round #(
  parameter integer ROUND = 0, // 0 RNE, 1 RTZ
  parameter integer FTZ   = 0  // 1: flush tiny results to zero
) (
  input  wire        sign_i,
  input  wire [9:0]  exp_i,
  input  wire [23:0] mant_i,
  input  wire        guard_i,
  input  wire        round_i,
  input  wire        sticky_i,
  output reg  [31:0] y_o,
  output reg  [4:0]  flags_o
);

  localparam integer ROUND_RNE = 0;
  localparam [9:0]   EXP_ONE   = 10'd1;
  localparam [9:0]   EXP_INF   = 10'd255;
  localparam [30:0]  MAG_INF   = 31'h7F80_0000;
  localparam [30:0]  MAG_MAX   = 31'h7F7F_FFFF;
  localparam [23:0]  MANT_TOP  = 24'h7F_FFFF; // largest subnormal significand
  localparam [4:0]   FLAG_NX   = 5'b00001;
  localparam [4:0]   FLAG_UF   = 5'b00010;
  localparam [4:0]   FLAG_OF   = 5'b00100;

  wire inexact = guard_i | round_i | sticky_i;

  // Round up by one ulp?
  wire round_up = (ROUND == ROUND_RNE) ? (guard_i & (mant_i[0] | round_i | sticky_i))
                                       : 1'b0;

  wire [24:0] mant_rnd = {1'b0, mant_i} + {24'd0, round_up};

  // Packing: the hidden bit (and a carry out of the significand) add into
  // the exponent field, so a subnormal that rounds up to 2^-126 and a
  // significand that rounds up to 2^24 both come out right.
  wire [9:0]  exp_m1 = exp_i - EXP_ONE;
  wire [32:0] pack_sum = {exp_m1, 23'd0} + {8'd0, mant_rnd};
  wire        overflow = (pack_sum[32:23] >= EXP_INF);

  // Tiny after rounding: below 2^-126 before rounding, and not rounding up
  // to 2^-126 with an unbounded exponent (RNE: 0x7FFFFF.11b and above).
  wire is_sub  = (exp_i == EXP_ONE) & ~mant_i[23];
  wire nonzero = (|mant_i) | inexact;
  wire rnd_out = (ROUND == ROUND_RNE) & (mant_i == MANT_TOP) & guard_i & round_i;
  wire tiny    = is_sub & nonzero & ~rnd_out;

  always @* begin
    if (overflow) begin
      y_o     = {sign_i, (ROUND == ROUND_RNE) ? MAG_INF : MAG_MAX};
      flags_o = FLAG_OF | FLAG_NX;
    end else if ((FTZ != 0) && tiny) begin
      y_o     = {sign_i, 31'd0};
      flags_o = FLAG_UF | FLAG_NX;
    end else begin
      y_o     = {sign_i, pack_sum[30:0]};
      flags_o = (inexact ? FLAG_NX : 5'd0) | ((tiny & inexact) ? FLAG_UF : 5'd0);
    end
  end

endmodule

`default_nettype wire
