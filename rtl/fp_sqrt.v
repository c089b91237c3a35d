// fp_sqrt.v -- pipelined IEEE 754 binary32 square root.
//
// Computes sqrt(a), correctly rounded, with the exception flags, bit for
// bit equal to sw/ref/fpref.h fpref_sqrt (x86 SSE sqrtss results, explicit NaN
// rules).
//
// Algorithm: radix-2 restoring digit recurrence (the integer square root,
// two radicand bits per step), unrolled into a pipeline.  With Ma the
// 24-bit significand (leading one at bit 23; a subnormal one normalised by
// its leading-zero count, fp_recur_unpack) and E its biased exponent,
// a = Ma 2^(E - 150).  The radicand N = Ma 2^27 for an odd E, Ma 2^28 for
// an even one (so that the exponent left over is even), a 52-bit integer,
// and the root Q = floor(sqrt(N)) has 26 bits with the leading one at bit
// 25: the significand in Q[25:2], guard Q[1], round Q[0], sticky the
// remainder N - Q^2 being nonzero.  The biased result exponent is
// (E + 127) >> 1, between 52 and 190: a square root is never tiny and
// never overflows.  Step j = 0 .. 25 decides root bit 25 - j from the
// partial root P (j bits) and remainder R (at most 2P, j + 1 bits):
//     R' = 4R + (next two radicand bits);  T = 4P + 1
//     R' >= T:  R = R' - T, P = 2P + 1;   else  R = R', P = 2P
// (the remainder stays N_top - P^2).  Step j subtracts j + 2 bits; the
// widths grow with j and the bits above them are constant zeros.
//
// Datapath steps (the places for a register are between them):
//   in           the operand register (HOLD: the core keeps its own)
//   u1           unpack: the operand's class, the leading-zero count of
//                a subnormal significand (fp_recur_unpack)
//   u2           the normalising shift, result exponent, radicand
//                alignment, the special case and result
//   r1 .. r26    one root bit each (the recurrence above)
//   n2           the remainder's OR: the sticky bit
//   n3           rounding increment (fp_round, in fp_recur_out)
//   n4           flags, special result (fp_round_pack, in fp_recur_out);
//                then the output register
// The places, as fp_div's (rtl/fp_recur.vh): 29 base places, u2 | r1
// (base place 0), r_j | r_j+1 (j = 1 .. 25), r26 | n2, n3 | n4 and the
// output register, filled first; then 3 extra places, in this order:
// n2 | n3, u1 | u2, in | u1.  With L = min(LATENCY, 29) >= 2, one register at u2 | r1 (the
// unpack gets a stage of its own), and the other L - 2 spread evenly over
// the 27 base places after r1 .. r26 and n3: base place s holds one iff
// floor(s (L - 1) / 28) differs from floor((s - 1) (L - 1) / 28).  L = 1:
// no register but the output one.  LATENCY 30 to 32 fill the extra
// places; at 32 (every place) no stage is longer than one recurrence
// step.  LATENCY > 32 adds output delay stages (fp_div's 34, the
// processor's common DIV_LATENCY for both, gives two).
//
// Parameters:
//   LATENCY  rising clock edges from the operand being sampled to the
//            result on the outputs; >= 1 (default 8; 32: every place)
//   ROUND    0: round to nearest, ties to even; 1: round toward zero
//   FTZ      0: IEEE subnormals; 1: a subnormal operand reads as zero of
//            its sign, no flag (x86 DAZ; sqrt of a negative subnormal is
//            then -0).  No result is tiny, so nothing is flushed.
//
// Ports:
//   clk_i    clock, rising edge
//   rst_i    synchronous reset, active high; clears the valid bits only
//   valid_i  an operation is presented this cycle
//   a_i      operand (binary32 bit pattern)
//   valid_o  a result is presented this cycle
//   y_o      result
//   flags_o  {invalid, infinite (0), overflow (0), underflow (0),
//            inexact}, the Berkeley SoftFloat bit order
//
// Timing contract (as fp_add and fp_mul): valid_i high in cycle t gives
// valid_o high with y_o and flags_o in cycle t + LATENCY.  Fully
// pipelined: initiation interval 1, results in order.
//
// Standards followed (IEEE 754-2019): §4.3 rounding; §5.4.1 squareRoot:
// sqrt(-0) = -0, sqrt(+inf) = +inf, exact; §6.2 NaN propagation (a NaN
// operand quieted, sign and payload kept); §7.2 invalid: the operand is
// below zero (also -inf) or a signalling NaN; the result of a negative
// operand is the x86 default NaN 0xFFC00000.
`default_nettype none

module fp_sqrt #(
  parameter integer LATENCY = 8, // issue to result, rising edges, >= 1
  parameter integer ROUND   = 0, // 0 RNE, 1 RTZ
  parameter integer FTZ     = 0  // 1: subnormal operands read as zero
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        valid_i,
  input  wire [31:0] a_i,
  output wire        valid_o,
  output wire [31:0] y_o,
  output wire [4:0]  flags_o
);

  localparam [9:0]   EXP_BIAS    = 10'd127;
  localparam [7:0]   EXP_MAX     = 8'hFF;
  localparam [31:0]  DEFAULT_NAN = 32'hFFC0_0000;
  localparam integer NITER       = 26;     // root bits
  localparam integer NBASE       = 29;     // base places, incl. out
  localparam integer NEXTRA      = 3;      // extra places
  // The extra places, in the order they fill.
  localparam integer X_N3 = 0;             // n2 | n3
  localparam integer X_U2 = 1;             // u1 | u2
  localparam integer X_IN = 2;             // in | u1

  // NPLACE, LC, DEPTH_O, the check of LATENCY, the registers after base
  // step s (regs_after) and at extra place k (extra_reg): the header's
  // rule.
`include "fp_recur.vh"

  // ---------------------------------------------------------------------
  // in: operand register
  // ---------------------------------------------------------------------
  wire        s0_valid;
  wire [31:0] a_in;
  fp_pipe #(.WIDTH(32), .DEPTH(extra_reg(X_IN)), .HOLD(1)) u_pipe_in (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  (a_i),
    .valid_o (s0_valid),
    .data_o  (a_in)
  );

  // ---------------------------------------------------------------------
  // u1: class (FTZ: a subnormal is a zero), significand and its
  // normalising shift
  // ---------------------------------------------------------------------
  wire        a_nan, a_snan, a_inf, a_zero;
  wire [23:0] a_man;
  wire [4:0]  a_lz;
  fp_recur_unpack #(.FTZ(FTZ)) u_unpack (
    .x_i(a_in[30:0]),
    .nan_o(a_nan), .snan_o(a_snan), .inf_o(a_inf), .zero_o(a_zero),
    .man_o(a_man), .lz_o(a_lz)
  );

  localparam integer W1 = 4 + 1 + 8 + 24 + 5;
  wire        s1_valid;
  wire        u_nan, u_snan, u_inf, u_zero, u_sign;
  wire [7:0]  u_exp;
  wire [23:0] u_man;
  wire [4:0]  u_lz;
  fp_pipe #(.WIDTH(W1), .DEPTH(extra_reg(X_U2))) u_pipe_u2 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s0_valid),
    .data_i  ({a_nan, a_snan, a_inf, a_zero, a_in[31], a_in[30:23], a_man, a_lz}),
    .valid_o (s1_valid),
    .data_o  ({u_nan, u_snan, u_inf, u_zero, u_sign, u_exp, u_man, u_lz})
  );

  // ---------------------------------------------------------------------
  // u2: normalisation, special case, exponent, radicand
  // ---------------------------------------------------------------------
  wire [23:0] a_norm = u_man << u_lz;

  // The special result: a NaN quieted (its payload is the significand's
  // low 22 bits); +-0 itself; below zero (also -inf) the default NaN with
  // invalid; +inf itself.
  wire        spec    = u_nan | u_inf | u_zero | u_sign;
  wire        neg     = u_sign & ~u_nan & ~u_zero;
  wire        spec_nv = u_snan | neg;
  reg  [31:0] spec_y;
  always @* begin
    if (u_nan) begin
      spec_y = {u_sign, EXP_MAX, 1'b1, u_man[21:0]};
    end else if (neg) begin
      spec_y = DEFAULT_NAN;
    end else if (u_zero) begin
      spec_y = {u_sign, 31'd0};
    end else begin
      spec_y = {1'b0, EXP_MAX, 23'd0}; // +inf
    end
  end

  // E = field - lz (10-bit two's complement, >= -22); result (E + 127) >> 1;
  // the radicand's top 26 bits {Ma, 0} (E odd) or {0, Ma} shifted one
  // more place: N = top << 26.
  wire [9:0]  e_norm = {2'd0, u_exp} - {5'd0, u_lz};
  wire [9:0]  e_sum  = e_norm + EXP_BIAS;
  wire [7:0]  exp_r  = e_sum[8:1];
  // e_sum is 105 to 381: bit 9 is 0, bit 0 is the halving's remainder.
  wire unused_e = &{1'b0, e_sum[9], e_sum[0], 1'b0};
  wire [25:0] n_top  = e_norm[0] ? {1'b0, a_norm, 1'b0} : {a_norm, 2'b00};

  // ---------------------------------------------------------------------
  // The state between steps: side information, radicand bits not yet
  // used (top first), remainder (27 bits), partial root (26 bits).
  // ---------------------------------------------------------------------
  localparam integer WSIDE = 1 + 32 + 1 + 8;
  localparam integer WST   = WSIDE + 26 + 27 + NITER;

  wire [NITER:0]           st_valid;
  wire [WST*(NITER+1)-1:0] st_data;

  fp_pipe #(.WIDTH(WST), .DEPTH(regs_after(0))) u_pipe_unpack (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s1_valid),
    .data_i  ({spec, spec_y, spec_nv, exp_r, n_top, 27'd0, {NITER{1'b0}}}),
    .valid_o (st_valid[0]),
    .data_o  (st_data[0 +: WST])
  );

  // ---------------------------------------------------------------------
  // r1 .. r26: the recurrence, one root bit per step.  The radicand's
  // bits below n_top are zero, so step j >= 13 brings in two zero bits.
  // ---------------------------------------------------------------------
  genvar j;
  generate
    for (j = 0; j < NITER; j = j + 1) begin : g_step
      wire [WSIDE-1:0] side;
      wire [25:0]      n;
      wire [26:0]      r;
      wire [NITER-1:0] p;
      assign {side, n, r, p} = st_data[j*WST +: WST];

      // Widths at step j: P has j bits, R at most 2P: j + 1 bits;
      // R' = 4R + 2 bits and T = 4P + 1: j + 3 bits.
      localparam integer WT = j + 3;
      wire [WT-1:0] r_sh  = {r[WT-3:0], n[25:24]};
      wire [WT-1:0] t     = {p[WT-3:0], 2'b01};
      wire [WT:0]   diff  = {1'b0, r_sh} - {1'b0, t};
      wire          p_bit = ~diff[WT];
      wire [WT-1:0] r_sel = p_bit ? diff[WT-1:0] : r_sh;
      // R <= 2P after the step: j + 2 bits (the top bit of r_sel is 0).
      wire [27+WT-2:0] r_ext  = {27'd0, r_sel[WT-2:0]};
      wire [26:0]      r_next = r_ext[26:0];
      wire [NITER-1:0] p_next = {p[NITER-2:0], p_bit};
      wire unused_bits = &{1'b0, r[26:WT-2], p[NITER-1], r_sel[WT-1],
                           r_ext[27+WT-2:27], 1'b0};

      fp_pipe #(.WIDTH(WST), .DEPTH(regs_after(j + 1))) u_pipe_step (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (st_valid[j]),
        .data_i  ({side, n[23:0], 2'b00, r_next, p_next}),
        .valid_o (st_valid[j+1]),
        .data_o  (st_data[(j+1)*WST +: WST])
      );
    end
  endgenerate

  // ---------------------------------------------------------------------
  // n2: the root and the sticky bit, the remainder's OR
  // ---------------------------------------------------------------------
  wire [WSIDE-1:0] f_side;
  wire [25:0]      f_n;
  wire [26:0]      f_r;
  wire [NITER-1:0] f_p;
  assign {f_side, f_n, f_r, f_p} = st_data[NITER*WST +: WST];
  wire unused_n = &{1'b0, f_n, 1'b0};

  wire             g_valid;
  wire [WSIDE-1:0] g_side;
  wire [NITER-1:0] g_p;
  wire             g_st;
  fp_pipe #(.WIDTH(WSIDE + NITER + 1), .DEPTH(extra_reg(X_N3))) u_pipe_n3 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (st_valid[NITER]),
    .data_i  ({f_side, f_p, |f_r}),
    .valid_o (g_valid),
    .data_o  ({g_side, g_p, g_st})
  );

  // n3: the rounding increment, its register place (base place 27), n4:
  // flags and special result, and the output register: fp_recur_out (a root
  // is positive, never tiny, never overflows, never divides by zero).
  wire        g_spec, g_nv;
  wire [31:0] g_spec_y;
  assign {g_spec, g_spec_y, g_nv} = g_side[WSIDE-1:8];
  fp_recur_out #(.ROUND(ROUND), .FTZ(FTZ), .MID_DEPTH(regs_after(NITER + 1)),
                 .OUT_DEPTH(DEPTH_O)) u_out (
    .clk_i(clk_i), .rst_i(rst_i), .valid_i(g_valid),
    .exp_i({2'd0, g_side[7:0]}), .mant_i(g_p[25:2]),
    .guard_i(g_p[1]), .round_i(g_p[0]), .sticky_i(g_st),
    .sign_i(1'b0), .spec_i(g_spec), .spec_y_i(g_spec_y), .spec_nv_i(g_nv), .spec_dz_i(1'b0),
    .valid_o(valid_o), .y_o(y_o), .flags_o(flags_o)
  );

endmodule

`default_nettype wire
