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
//   in           the operand registers (HOLD: each core keeps its own)
//   u1           unpack: the operands' classes, the leading-zero counts
//                of subnormal significands (fp_recur_unpack), Ea - Eb +
//                127 from the fields
//   u2           the normalising shifts, the exponent less them (10-bit
//                two's complement), the special case and result
//   r1 .. r27    one quotient bit each (the recurrence above); beside r1,
//                from the exponent alone, the result exponent for either
//                q_0 and the denormalising shift of a tiny quotient
//                (fp_norm_exp)
//   n1           normalisation by q_0 and the denormalisation, its even
//                part: right shift of 0 to 30 places with sticky
//   n2           its last place (n1, n2: fp_norm_shift)
//   n3           rounding increment (fp_round, in fp_recur_out)
//   n4           overflow, flush to zero, flags, special result
//                (fp_round_pack, in fp_recur_out); then the output
//                register
// The places, as rtl/fp_recur.vh numbers them: 30 base places, u2 | r1
// (base place 0), r_s | r_s+1 (s = 1 .. 26), r27 | n1, n3 | n4 and the
// output register, filled first; then 4 extra places, in this order:
// n2 | n3, u1 | u2, n1 | n2, in | u1.  With L = min(LATENCY, 30) >= 2,
// one register at u2 | r1 (the unpack takes about as long as four
// recurrence steps, so it gets a stage of its own), and the other L - 2
// spread evenly over the 28 base places after r1 .. r27 and n3: base
// place s holds one iff floor(s (L - 1) / 29) differs from
// floor((s - 1) (L - 1) / 29), so every later stage has about 29 / (L - 1)
// steps (L = 8: the unpack, then stages of 5, 4, 4, 4, 4, 4 recurrence
// steps, and a last one of 2 steps with the normalisation and rounding,
// and the pack).  L = 1: no register but the output one.  LATENCY 31 to
// 34 fill the extra places; at 34 (every place) no stage is longer than
// one recurrence step.  LATENCY > 34 adds output delay stages.
//
// Parameters:
//   LATENCY  rising clock edges from the operands being sampled to the
//            result on the outputs; >= 1 (default 8; 34: every place)
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
// in the recurrence holds the remainder (25 bits), the divisor (24), the
// quotient bits so far and the special result and exponents (62 bits):
// about 140 flip-flops per stage.
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
  localparam [7:0]   EXP_MAX     = 8'hFF;
  localparam [31:0]  DEFAULT_NAN = 32'hFFC0_0000;
  localparam [30:0]  MAG_INF     = 31'h7F80_0000;
  localparam integer NITER       = 27;     // quotient bits
  localparam integer NBASE       = 30;     // base places, incl. out
  localparam integer NEXTRA      = 4;      // extra places
  // The extra places, in the order they fill.
  localparam integer X_N3 = 0;             // n2 | n3
  localparam integer X_U2 = 1;             // u1 | u2
  localparam integer X_N2 = 2;             // n1 | n2
  localparam integer X_IN = 3;             // in | u1

  // NPLACE, LC, DEPTH_O, the check of LATENCY, the registers after base
  // step s (regs_after) and at extra place k (extra_reg): the header's
  // rule.
`include "fp_recur.vh"

  // ---------------------------------------------------------------------
  // in: operand registers
  // ---------------------------------------------------------------------
  wire        s0_valid;
  wire [31:0] a_in, b_in;
  fp_pipe #(.WIDTH(64), .DEPTH(extra_reg(X_IN)), .HOLD(1)) u_pipe_in (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({a_i, b_i}),
    .valid_o (s0_valid),
    .data_o  ({a_in, b_in})
  );

  // ---------------------------------------------------------------------
  // u1: classes (FTZ: a subnormal is a zero), significands and their
  // normalising shifts, exponent difference of the fields
  // ---------------------------------------------------------------------
  wire        a_nan, a_snan, a_inf, a_zero, b_nan, b_snan, b_inf, b_zero;
  wire [23:0] a_man, b_man;
  wire [4:0]  a_lz, b_lz;
  fp_recur_unpack #(.FTZ(FTZ)) u_unpack_a (
    .x_i(a_in[30:0]),
    .nan_o(a_nan), .snan_o(a_snan), .inf_o(a_inf), .zero_o(a_zero),
    .man_o(a_man), .lz_o(a_lz)
  );
  fp_recur_unpack #(.FTZ(FTZ)) u_unpack_b (
    .x_i(b_in[30:0]),
    .nan_o(b_nan), .snan_o(b_snan), .inf_o(b_inf), .zero_o(b_zero),
    .man_o(b_man), .lz_o(b_lz)
  );
  // Ea - Eb + 127 of the fields; a subnormal's field counts as 0 with
  // fp_mul_unpack_norm's significand {frac, 0}.
  wire [9:0] exp_f = {2'd0, a_in[30:23]} - {2'd0, b_in[30:23]} + EXP_BIAS;

  localparam integer W1 = 8 + 2 + 10 + 24 + 24 + 5 + 5;
  wire       s1_valid;
  wire       u_anan, u_asnan, u_ainf, u_azero, u_bnan, u_bsnan, u_binf, u_bzero;
  wire       u_asign, u_bsign;
  wire [9:0] u_exp;
  wire [23:0] u_aman, u_bman;
  wire [4:0]  u_alz, u_blz;
  fp_pipe #(.WIDTH(W1), .DEPTH(extra_reg(X_U2))) u_pipe_u2 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s0_valid),
    .data_i  ({a_nan, a_snan, a_inf, a_zero, b_nan, b_snan, b_inf, b_zero,
               a_in[31], b_in[31], exp_f, a_man, b_man, a_lz, b_lz}),
    .valid_o (s1_valid),
    .data_o  ({u_anan, u_asnan, u_ainf, u_azero, u_bnan, u_bsnan, u_binf, u_bzero,
               u_asign, u_bsign, u_exp, u_aman, u_bman, u_alz, u_blz})
  );

  // ---------------------------------------------------------------------
  // u2: normalisation, exponent, special case
  // ---------------------------------------------------------------------
  wire [23:0] a_norm = u_aman << u_alz;
  wire [23:0] b_norm = u_bman << u_blz;
  wire        sign   = u_asign ^ u_bsign;

  // The special result: the first NaN operand quieted (its payload is the
  // significand's low 22 bits), else the default NaN (0 / 0, inf / inf),
  // else infinity (inf / x, x / 0), else zero (0 / x, x / inf).  Invalid
  // for a signalling NaN operand and the default NaN; divide by zero for
  // a finite nonzero over a zero.
  wire        dnan    = (u_azero & u_bzero) | (u_ainf & u_binf);
  wire        spec    = u_anan | u_bnan | u_ainf | u_binf | u_azero | u_bzero;
  wire        spec_nv = u_asnan | u_bsnan | (~u_anan & ~u_bnan & dnan);
  wire        spec_dz = ~u_anan & ~u_bnan & ~u_ainf & ~u_azero & u_bzero;
  reg  [31:0] spec_y;
  always @* begin
    if (u_anan) begin
      spec_y = {u_asign, EXP_MAX, 1'b1, u_aman[21:0]};
    end else if (u_bnan) begin
      spec_y = {u_bsign, EXP_MAX, 1'b1, u_bman[21:0]};
    end else if (dnan) begin
      spec_y = DEFAULT_NAN;
    end else if (u_ainf | u_bzero) begin
      spec_y = {sign, MAG_INF};
    end else begin
      spec_y = {sign, 31'd0};
    end
  end

  // Biased exponent of the quotient for q_0 = 1: (fields less the
  // normalising shifts) Ea - Eb + 127.
  wire [9:0] exp_q = u_exp - {5'd0, u_alz} + {5'd0, u_blz};

  // ---------------------------------------------------------------------
  // The state between steps: side information, remainder, divisor,
  // quotient bits (q_i at bit 26 - i; the bits not yet decided are 0).
  // The side's exponent field X holds exp_q before r1 and fp_norm_exp's
  // {exp_a, exp_b, ge2, shift} after it.
  // ---------------------------------------------------------------------
  localparam integer WX    = 10 + 10 + 1 + 5;
  localparam integer WSPEC = 1 + 32 + 1 + 1 + 1;
  localparam integer WSIDE = WSPEC + WX;
  localparam integer WST   = WSIDE + 25 + 24 + NITER;

  wire [NITER:0]           st_valid;
  wire [WST*(NITER+1)-1:0] st_data;

  fp_pipe #(.WIDTH(WST), .DEPTH(regs_after(0))) u_pipe_unpack (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s1_valid),
    .data_i  ({spec, spec_y, spec_nv, spec_dz, sign, {(WX - 10){1'b0}}, exp_q,
               {1'b0, a_norm}, b_norm, {NITER{1'b0}}}),
    .valid_o (st_valid[0]),
    .data_o  (st_data[0 +: WST])
  );

  // ---------------------------------------------------------------------
  // r1 .. r27: the recurrence, one quotient bit per step
  // ---------------------------------------------------------------------
  genvar i;
  generate
    for (i = 0; i < NITER; i = i + 1) begin : g_step
      wire [WSPEC-1:0] spc;
      wire [WX-1:0]    x;
      wire [24:0]      r;
      wire [23:0]      d;
      wire [NITER-1:0] q;
      assign {spc, x, r, d, q} = st_data[i*WST +: WST];

      wire [25:0] diff  = {1'b0, r} - {2'b0, d};
      wire        q_bit = ~diff[25];
      wire [24:0] r_sel = q_bit ? diff[24:0] : r;
      // r_sel < Mb < 2^24: the doubled remainder fits 25 bits.
      wire [24:0] r_next = {r_sel[23:0], 1'b0};
      wire [NITER-1:0] q_next = q | ({{(NITER-1){1'b0}}, q_bit} << (NITER - 1 - i));
      wire unused_r = &{1'b0, r_sel[24], 1'b0};

      // Beside r1: the exponent's part of the normalisation.
      wire [WX-1:0] x_next;
      if (i == 0) begin : g_exp
        fp_norm_exp u_norm_exp (
          .exp_i   (x[9:0]),
          .exp_a_o (x_next[25:16]),
          .exp_b_o (x_next[15:6]),
          .ge2_o   (x_next[5]),
          .shift_o (x_next[4:0])
        );
        wire unused_x = &{1'b0, x[WX-1:10], 1'b0};
      end else begin : g_keep
        assign x_next = x;
      end

      fp_pipe #(.WIDTH(WST), .DEPTH(regs_after(i + 1))) u_pipe_step (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (st_valid[i]),
        .data_i  ({spc, x_next, r_next, d, q_next}),
        .valid_o (st_valid[i+1]),
        .data_o  (st_data[(i+1)*WST +: WST])
      );
    end
  endgenerate

  // ---------------------------------------------------------------------
  // n1, n2: normalisation by q_0 and denormalisation (fp_norm_shift): the
  // quotient bits Q = q_0 .. q_26 are its top 27 bits (q_0 = 1: the
  // leading one at bit 26, exponent exp_q; else at bit 25, exp_q - 1),
  // the remainder's OR the sticky bit below them
  // ---------------------------------------------------------------------
  wire [WSPEC-1:0] f_spc;
  wire [9:0]       f_exp_a, f_exp_b;
  wire             f_ge2;
  wire [4:0]       f_shift;
  wire [24:0]      f_r;
  wire [23:0]      f_d;
  wire [NITER-1:0] f_q;
  assign {f_spc, f_exp_a, f_exp_b, f_ge2, f_shift, f_r, f_d, f_q} = st_data[NITER*WST +: WST];
  wire unused_d = &{1'b0, f_d, 1'b0};

  wire             n_valid;
  wire [WSPEC-1:0] n_spc;
  wire [9:0]       n_exp;
  wire [25:0]      n_man;
  wire             n_st;
  fp_norm_shift #(.SIDE_W(WSPEC), .MID_DEPTH(extra_reg(X_N2))) u_norm_shift (
    .clk_i    (clk_i),
    .rst_i    (rst_i),
    .valid_i  (st_valid[NITER]),
    .side_i   (f_spc),
    .top_i    (f_q),
    .sticky_i (|f_r),
    .exp_a_i  (f_exp_a),
    .exp_b_i  (f_exp_b),
    .ge2_i    (f_ge2),
    .shift_i  (f_shift),
    .valid_o  (n_valid),
    .side_o   (n_spc),
    .exp_o    (n_exp),
    .man_o    (n_man),
    .sticky_o (n_st)
  );

  localparam integer W3 = WSPEC + 10 + 26 + 1;
  wire             g_valid;
  wire [WSPEC-1:0] g_spc;
  wire [9:0]       g_exp;
  wire [25:0]      g_man;
  wire             g_st;
  fp_pipe #(.WIDTH(W3), .DEPTH(extra_reg(X_N3))) u_pipe_n3 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (n_valid),
    .data_i  ({n_spc, n_exp, n_man, n_st}),
    .valid_o (g_valid),
    .data_o  ({g_spc, g_exp, g_man, g_st})
  );

  // n3: the rounding increment, its register place (base place 28), n4:
  // overflow, flush, flags and special result, and the output register:
  // fp_recur_out.
  wire        g_spec, g_nv, g_dz, g_sign;
  wire [31:0] g_spec_y;
  assign {g_spec, g_spec_y, g_nv, g_dz, g_sign} = g_spc;
  fp_recur_out #(.ROUND(ROUND), .FTZ(FTZ), .MID_DEPTH(regs_after(NITER + 1)),
                 .OUT_DEPTH(DEPTH_O)) u_out (
    .clk_i(clk_i), .rst_i(rst_i), .valid_i(g_valid),
    .exp_i(g_exp), .mant_i(g_man[25:2]),
    .guard_i(g_man[1]), .round_i(g_man[0]), .sticky_i(g_st),
    .sign_i(g_sign), .spec_i(g_spec), .spec_y_i(g_spec_y), .spec_nv_i(g_nv), .spec_dz_i(g_dz),
    .valid_o(valid_o), .y_o(y_o), .flags_o(flags_o)
  );

endmodule

`default_nettype wire
