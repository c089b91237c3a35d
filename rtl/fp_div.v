// fp_div.v -- pipelined IEEE 754 binary32 divider.
//
// Computes a / b, correctly rounded, with the exception flags, bit for bit
// equal to sw/ref/fpref.h fpref_div (x86 SSE divss results, explicit NaN
// rules).
//
// Algorithm: radix-2 restoring digit recurrence on the normalised
// significands, unrolled into a pipeline.  With Ma, Mb the 24-bit
// significands (leading one at bit 23; a subnormal one normalised by its
// leading-zero count, fp_recur_unpack), the partial remainder starts
// at r0 = Ma and each of 27 steps i = 0 .. 26 decides one quotient bit of
// weight 2^-i:
//     q_i = (r_i >= Mb);   r_{i+1} = 2 (r_i - q_i Mb)
// so Q = q_0 .. q_26 = floor(Ma / Mb * 2^26) and r_27 / 2 is the exact
// remainder (r_i < 2 Mb < 2^25: 25-bit remainders, one 25-bit subtractor
// and multiplexer per step).  Ma / Mb lies in (1/2, 2): q_0 = 1 gives the
// significand in Q[26:3], else in Q[25:2] with the exponent one lower,
// and the bits below it with the remainder's OR are guard, round and
// sticky.  The first step doubles as the comparison that picks this
// normalisation, so no 24-bit comparator precedes the recurrence.
//
// Datapath steps (the places for a register are between them):
//   s = 0        unpack: special cases, normalisation of subnormal
//                significands (lz count and shift), exponent difference
//                Ea - Eb + 127 (10-bit two's complement, Ea, Eb the
//                biased exponents of the normalised significands)
//   s = 1 .. 27  one quotient bit each (the recurrence above)
//   s = 28       normalisation by q_0, denormalisation of a tiny quotient
//                (right shift by 1 - e places with sticky, fp_shr_sticky),
//                rounding increment (fp_round, in fp_recur_out)
//   s = 29       overflow, flush to zero, flags, special result
//                (fp_round_pack, in fp_recur_out); then the output
//                register
// The LATENCY - 1 registers besides the output register: with L =
// min(LATENCY, 30) >= 2, one right after the unpack step (place 0: the
// leading-zero count, the normalising shift and the special cases take
// about as long as four recurrence steps, so they get a stage of their
// own), and the other L - 2 spread evenly over the 28 places after steps
// 1 .. 28: place s holds one iff floor(s (L - 1) / 29) differs from
// floor((s - 1) (L - 1) / 29), so every later stage has about 29 / (L - 1)
// steps (L = 8: the unpack step, then stages of 5, 4, 4, 4, 4, 4 steps and
// a last one of 2 steps, the rounding and the pack).  L = 1: no register
// but the output one (rtl/fp_recur.vh).  LATENCY > 30 adds output delay
// stages.
//
// Parameters:
//   LATENCY  rising clock edges from the operands being sampled to the
//            result on the outputs; >= 1 (default 8)
//   ROUND    0: round to nearest, ties to even; 1: round toward zero
//   FTZ      0: IEEE subnormals; 1: subnormal inputs read as zero (sign
//            kept, no flag: x86 DAZ; a subnormal divisor is then a zero
//            divisor) and tiny results flushed to +-0 with underflow and
//            inexact (x86 FTZ, tininess after rounding)
//
// Ports:
//   clk_i    clock, rising edge
//   rst_i    synchronous reset, active high; clears the valid bits only
//   valid_i  an operation is presented this cycle
//   a_i      dividend (binary32 bit pattern)
//   b_i      divisor
//   valid_o  a result is presented this cycle
//   y_o      quotient
//   flags_o  {invalid, infinite (divide by zero), overflow, underflow,
//            inexact}, the Berkeley SoftFloat bit order (bit 0 inexact)
//
// Timing contract (as fp_add and fp_mul): valid_i high in cycle t gives
// valid_o high with y_o and flags_o in cycle t + LATENCY.  Fully
// pipelined: initiation interval 1, results in order.
//
// Cost: 27 subtract-and-select steps of 25 bits; each pipeline register
// holds the remainder (25 bits), the divisor (24), the quotient bits so
// far and the special result and exponent (46 bits): about 120 flip-flops
// per stage.
//
// Standards followed (IEEE 754-2019): §4.3 rounding (roundTiesToEven,
// roundTowardZero); §5.4.1 division; §6.2 NaN propagation (a NaN operand
// is returned quieted, a before b; the invalid result is the x86 default
// NaN 0xFFC00000); §6.3 the sign of a quotient (also zero or infinite) is
// the XOR of the operand signs; §7.2 invalid (0 / 0, inf / inf, any
// signalling NaN operand); §7.3 division by zero (finite nonzero / zero:
// an infinity and the infinite flag); §7.4 overflow; §7.5 underflow with
// tininess detected after rounding (fp_round).
`default_nettype none

module fp_div #(
  parameter integer LATENCY = 8, // issue to result, rising edges, >= 1
  parameter integer ROUND   = 0, // 0 RNE, 1 RTZ
  parameter integer FTZ     = 0  // 1: flush subnormal inputs and results
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  output wire        valid_o,
  output wire [31:0] y_o,
  output wire [4:0]  flags_o
);

  localparam [9:0]   EXP_BIAS    = 10'd127;
  localparam [31:0]  DEFAULT_NAN = 32'hFFC0_0000;
  localparam [30:0]  MAG_INF     = 31'h7F80_0000;
  localparam [9:0]   SHIFT_MAX   = 10'd31; // right shifts >= 27 leave sticky
  localparam integer NITER       = 27;     // quotient bits
  localparam integer NPLACE      = 30;     // places for a register, incl. out

  // LC, DEPTH_O, the check of LATENCY, and the registers after step s
  // (0 .. NPLACE - 2): the header's rule.
`include "fp_recur.vh"

  // ---------------------------------------------------------------------
  // s = 0: unpack, special cases, normalisation, exponent
  // ---------------------------------------------------------------------
  wire       a_sign = a_i[31];
  wire       b_sign = b_i[31];
  wire [7:0] a_exp  = a_i[30:23];
  wire [7:0] b_exp  = b_i[30:23];

  // Classes (FTZ: a subnormal is a zero) and normalised significands.
  wire        a_nan, a_snan, a_inf, a_zero, b_nan, b_snan, b_inf, b_zero;
  wire [23:0] a_norm, b_norm;
  wire [4:0]  a_lz, b_lz;
  fp_recur_unpack #(.FTZ(FTZ)) u_unpack_a (
    .x_i(a_i[30:0]),
    .nan_o(a_nan), .snan_o(a_snan), .inf_o(a_inf), .zero_o(a_zero),
    .norm_o(a_norm), .lz_o(a_lz)
  );
  fp_recur_unpack #(.FTZ(FTZ)) u_unpack_b (
    .x_i(b_i[30:0]),
    .nan_o(b_nan), .snan_o(b_snan), .inf_o(b_inf), .zero_o(b_zero),
    .norm_o(b_norm), .lz_o(b_lz)
  );
  wire sign   = a_sign ^ b_sign;

  // The special result: the first NaN operand quieted, else the default
  // NaN (0 / 0, inf / inf), else infinity (inf / x, x / 0), else zero
  // (0 / x, x / inf).  Invalid for a signalling NaN operand and the
  // default NaN; divide by zero for a finite nonzero over a zero.
  wire        dnan    = (a_zero & b_zero) | (a_inf & b_inf);
  wire        spec    = a_nan | b_nan | a_inf | b_inf | a_zero | b_zero;
  wire        spec_nv = a_snan | b_snan | (~a_nan & ~b_nan & dnan);
  wire        spec_dz = ~a_nan & ~b_nan & ~a_inf & ~a_zero & b_zero;
  reg  [31:0] spec_y;
  always @* begin
    if (a_nan) begin
      spec_y = a_i | 32'h0040_0000;
    end else if (b_nan) begin
      spec_y = b_i | 32'h0040_0000;
    end else if (dnan) begin
      spec_y = DEFAULT_NAN;
    end else if (a_inf | b_zero) begin
      spec_y = {sign, MAG_INF};
    end else begin
      spec_y = {sign, 31'd0};
    end
  end

  // Biased exponent of the quotient for q_0 = 1: (fields less the
  // normalising shifts) Ea - Eb + 127.  A subnormal's field counts as 0
  // with fp_mul_unpack_norm's significand {frac, 0}.
  wire [9:0] exp_q = {2'd0, a_exp} - {5'd0, a_lz} - {2'd0, b_exp} +
                     {5'd0, b_lz} + EXP_BIAS;

  // ---------------------------------------------------------------------
  // The state between steps: side information, remainder, divisor,
  // quotient bits (q_i at bit 26 - i; the bits not yet decided are 0).
  // ---------------------------------------------------------------------
  localparam integer WSIDE = 1 + 32 + 1 + 1 + 1 + 10;
  localparam integer WST   = WSIDE + 25 + 24 + NITER;

  wire [NITER:0]           st_valid;
  wire [WST*(NITER+1)-1:0] st_data;

  fp_pipe #(.WIDTH(WST), .DEPTH(regs_after(0))) u_pipe_unpack (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({spec, spec_y, spec_nv, spec_dz, sign, exp_q,
               {1'b0, a_norm}, b_norm, {NITER{1'b0}}}),
    .valid_o (st_valid[0]),
    .data_o  (st_data[0 +: WST])
  );

  // ---------------------------------------------------------------------
  // s = 1 .. 27: the recurrence, one quotient bit per step
  // ---------------------------------------------------------------------
  genvar i;
  generate
    for (i = 0; i < NITER; i = i + 1) begin : g_step
      wire [WSIDE-1:0] side;
      wire [24:0]      r;
      wire [23:0]      d;
      wire [NITER-1:0] q;
      assign {side, r, d, q} = st_data[i*WST +: WST];

      wire [25:0] diff  = {1'b0, r} - {2'b0, d};
      wire        q_bit = ~diff[25];
      wire [24:0] r_sel = q_bit ? diff[24:0] : r;
      // r_sel < Mb < 2^24: the doubled remainder fits 25 bits.
      wire [24:0] r_next = {r_sel[23:0], 1'b0};
      wire [NITER-1:0] q_next = q | ({{(NITER-1){1'b0}}, q_bit} << (NITER - 1 - i));
      wire unused_r = &{1'b0, r_sel[24], 1'b0};

      fp_pipe #(.WIDTH(WST), .DEPTH(regs_after(i + 1))) u_pipe_step (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (st_valid[i]),
        .data_i  ({side, r_next, d, q_next}),
        .valid_o (st_valid[i+1]),
        .data_o  (st_data[(i+1)*WST +: WST])
      );
    end
  endgenerate

  // ---------------------------------------------------------------------
  // s = 28: normalisation by q_0, denormalisation
  // ---------------------------------------------------------------------
  wire [WSIDE-1:0] f_side;
  wire [24:0]      f_r;
  wire [23:0]      f_d;
  wire [NITER-1:0] f_q;
  assign {f_side, f_r, f_d, f_q} = st_data[NITER*WST +: WST];
  wire unused_d = &{1'b0, f_d, 1'b0};

  wire [9:0] f_exp_q = f_side[9:0];
  wire       q0      = f_q[NITER-1];
  // Significand, guard and round in bits 26:1, sticky bit 0 with the
  // remainder.
  wire [26:0] f_top  = q0 ? f_q : {f_q[25:0], 1'b0};
  wire        f_rem  = |f_r;
  wire [9:0]  f_exp  = q0 ? f_exp_q : f_exp_q - 10'd1;
  // Tiny before rounding (biased exponent <= 0): shift right 1 - e
  // places (at most SHIFT_MAX: all bits to sticky), exponent 1.
  wire        f_ge1  = ~f_exp[9] & (f_exp != 10'd0);
  wire [9:0]  f_rs   = 10'd1 - f_exp;
  wire [4:0]  f_shift = f_ge1 ? 5'd0
                      : ((|f_rs[9:5]) ? SHIFT_MAX[4:0] : f_rs[4:0]);
  wire [26:0] f_sh;
  wire        f_st;
  fp_shr_sticky #(.WIDTH(27)) u_denorm (
    .v_i      (f_top),
    .amt_i    (f_shift),
    .sticky_i (f_rem),
    .v_o      (f_sh),
    .sticky_o (f_st)
  );

  // The rounding increment (s = 28), its register place, overflow, flush,
  // flags and special result (s = 29) and the output register:
  // fp_recur_out.
  wire        f_spec, f_nv, f_dz, f_sign;
  wire [31:0] f_spec_y;
  assign {f_spec, f_spec_y, f_nv, f_dz, f_sign} = f_side[WSIDE-1:10];
  fp_recur_out #(.ROUND(ROUND), .FTZ(FTZ), .MID_DEPTH(regs_after(NITER + 1)),
                 .OUT_DEPTH(DEPTH_O)) u_out (
    .clk_i(clk_i), .rst_i(rst_i), .valid_i(st_valid[NITER]),
    .exp_i(f_ge1 ? f_exp : 10'd1), .mant_i(f_sh[26:3]),
    .guard_i(f_sh[2]), .round_i(f_sh[1]), .sticky_i(f_sh[0] | f_st),
    .sign_i(f_sign), .spec_i(f_spec), .spec_y_i(f_spec_y), .spec_nv_i(f_nv), .spec_dz_i(f_dz),
    .valid_o(valid_o), .y_o(y_o), .flags_o(flags_o)
  );

endmodule

`default_nettype wire
