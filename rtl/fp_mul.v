// fp_mul.v -- pipelined IEEE 754 binary32 multiplier.
//
// Computes a * b with the exception flags, bit for bit equal to sw/fpref.h
// (x86 SSE results, explicit NaN rules).
//
// Parameters:
//   LATENCY  rising clock edges from the operands being sampled to the
//            result on the outputs; >= 1 (default 3).  Stage boundaries:
//              L = 1: m1 m2 m3 | out
//              L = 2: m1 m2 | m3 | out
//              L = 3: m1 | m2 | m3 | out
//              L = 4: in | m1 | m2 | m3 | out
//              L >= 5: in | m1 | m2 | m3a | m3b | out, plus L-5 delay
//              stages (in = operand registers; m3a = normalisation and
//              denormalisation, m3b = rounding)
//            where m1 = unpack, special cases, normalisation of subnormal
//            significands, exponent sum; m2 = 24 x 24 bit product (the
//            registers around it map to the DSP input/output registers);
//            m3 = normalisation, denormalisation of tiny results with
//            sticky, rounding and packing (fp_round).
//   ROUND    0: round to nearest, ties to even; 1: round toward zero
//   FTZ      0: IEEE subnormals; 1: subnormal inputs read as zero (sign
//            kept, no flag: x86 DAZ) and tiny results flushed to +-0 with
//            underflow and inexact (x86 FTZ, tininess after rounding)
//
// Ports:
//   clk_i    clock, rising edge
//   rst_i    synchronous reset, active high; clears the valid bits only
//   valid_i  an operation is presented this cycle
//   a_i      operand a (binary32 bit pattern)
//   b_i      operand b
//   valid_o  a result is presented this cycle
//   y_o      result
//   flags_o  {invalid, infinite (always 0), overflow, underflow, inexact},
//            the Berkeley SoftFloat bit order (bit 0 inexact)
//
// Timing contract: every path from the inputs to the outputs crosses exactly
// LATENCY registers; if valid_i is high in cycle t (sampled by the rising
// edge that ends cycle t), valid_o is high with y_o and flags_o valid in
// cycle t + LATENCY, i.e. LATENCY = cycles from issue to the issue of a
// dependent operation that takes the result from y_o.  Fully pipelined:
// one operation per cycle (initiation interval 1), results in order.
//
// Standards followed (IEEE 754-2008): §4.3 rounding (roundTiesToEven,
// roundTowardZero); §5.4.1 multiplication; §6.2 NaN propagation (a NaN
// operand is returned quieted, a before b), the invalid result is the x86
// default NaN 0xFFC00000; §6.3 the sign of a product (also zero or
// infinite) is the XOR of the operand signs; §7.2 invalid (0 * inf, any
// signalling NaN operand), §7.4 overflow, §7.5 underflow with tininess
// detected after rounding (see fp_round).
`default_nettype none

module fp_mul #(
  parameter integer LATENCY = 3, // issue to result, rising edges, >= 1
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

  localparam [7:0]  EXP_MAX     = 8'hFF;
  localparam [9:0]  EXP_BIAS_M1 = 10'd126; // bias - 1: product in [1, 4)
  localparam [31:0] QNAN_BIT    = 32'h0040_0000;
  localparam [31:0] DEFAULT_NAN = 32'hFFC0_0000;
  localparam [30:0] MAG_INF     = 31'h7F80_0000;
  localparam [4:0]  FLAG_NV     = 5'b10000;
  localparam [9:0]  SHIFT_MAX   = 10'd31; // right shifts >= 26 leave sticky

  // Stage boundaries: register stages at the inputs, after m1, after m2,
  // inside m3 (before rounding) and at the output.
  localparam integer DEPTH_I = (LATENCY >= 4) ? 1 : 0;
  localparam integer DEPTH1  = (LATENCY >= 3) ? 1 : 0;
  localparam integer DEPTH2  = (LATENCY >= 2) ? 1 : 0;
  localparam integer DEPTH3  = (LATENCY >= 5) ? 1 : 0;
  localparam integer DEPTH_O = (LATENCY >= 5) ? LATENCY - 4 : 1;

  generate
    if (LATENCY < 1) begin : g_bad_latency
      // Elaboration error on purpose: LATENCY must be at least 1.
      fp_mul_error_LATENCY_must_be_at_least_1 u_error ();
    end
  endgenerate

  // ---------------------------------------------------------------------
  // operand registers (LATENCY >= 4)
  // ---------------------------------------------------------------------
  wire        s0_valid;
  wire [31:0] a_in, b_in;
  fp_pipe #(.WIDTH(64), .DEPTH(DEPTH_I)) u_pipe_in (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({a_i, b_i}),
    .valid_o (s0_valid),
    .data_o  ({a_in, b_in})
  );

  // ---------------------------------------------------------------------
  // m1: unpack, special cases, normalise subnormal significands
  // ---------------------------------------------------------------------
  wire       a_sign = a_in[31];
  wire       b_sign = b_in[31];
  wire [7:0] a_exp  = a_in[30:23];
  wire [7:0] b_exp  = b_in[30:23];
  wire       a_nan  = (a_exp == EXP_MAX) & (|a_in[22:0]);
  wire       b_nan  = (b_exp == EXP_MAX) & (|b_in[22:0]);
  wire       a_snan = a_nan & ~a_in[22];
  wire       b_snan = b_nan & ~b_in[22];
  wire       a_inf  = (a_exp == EXP_MAX) & ~(|a_in[22:0]);
  wire       b_inf  = (b_exp == EXP_MAX) & ~(|b_in[22:0]);
  // Zero, or subnormal read as zero under FTZ (DAZ).
  wire       a_zero = (a_exp == 8'd0) & ((FTZ != 0) | ~(|a_in[22:0]));
  wire       b_zero = (b_exp == 8'd0) & ((FTZ != 0) | ~(|b_in[22:0]));
  wire       c1_sign = a_sign ^ b_sign;

  reg        c1_spec;
  reg [31:0] c1_spec_y;
  reg        c1_spec_nv;
  always @* begin
    c1_spec    = a_nan | b_nan | a_inf | b_inf | a_zero | b_zero;
    c1_spec_nv = 1'b0;
    if (a_nan) begin
      c1_spec_y  = a_in | QNAN_BIT;
      c1_spec_nv = a_snan | b_snan;
    end else if (b_nan) begin
      c1_spec_y  = b_in | QNAN_BIT;
      c1_spec_nv = b_snan;
    end else if ((a_inf & b_zero) | (a_zero & b_inf)) begin
      c1_spec_y  = DEFAULT_NAN;
      c1_spec_nv = 1'b1;
    end else if (a_inf | b_inf) begin
      c1_spec_y  = {c1_sign, MAG_INF};
    end else begin
      c1_spec_y  = {c1_sign, 31'd0};
    end
  end

  // Significands with the leading one at bit 23, exponents (10-bit two's
  // complement) lowered by the normalising shift.
  wire [23:0] a_man;
  wire [23:0] b_man;
  wire [9:0]  a_expn;
  wire [9:0]  b_expn;
  fp_mul_unpack_norm #(.FTZ(FTZ)) u_norm_a (
    .exp_i  (a_exp),
    .frac_i (a_in[22:0]),
    .man_o  (a_man),
    .exp_o  (a_expn)
  );
  fp_mul_unpack_norm #(.FTZ(FTZ)) u_norm_b (
    .exp_i  (b_exp),
    .frac_i (b_in[22:0]),
    .man_o  (b_man),
    .exp_o  (b_expn)
  );

  // Biased exponent of the product taken as a value in [1, 2) times 2:
  // the product of two significands in [1, 2) lies in [1, 4).
  wire [9:0] c1_exp = a_expn + b_expn - EXP_BIAS_M1;

  localparam integer W1 = 1 + 32 + 1 + 1 + 10 + 24 + 24;
  wire          s1_valid;
  wire [W1-1:0] s1_data;
  fp_pipe #(.WIDTH(W1), .DEPTH(DEPTH1)) u_pipe1 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s0_valid),
    .data_i  ({c1_spec, c1_spec_y, c1_spec_nv, c1_sign, c1_exp, a_man, b_man}),
    .valid_o (s1_valid),
    .data_o  (s1_data)
  );

  wire        s1_spec;
  wire [31:0] s1_spec_y;
  wire        s1_spec_nv;
  wire        s1_sign;
  wire [9:0]  s1_exp;
  wire [23:0] s1_aman;
  wire [23:0] s1_bman;
  assign {s1_spec, s1_spec_y, s1_spec_nv, s1_sign, s1_exp, s1_aman,
          s1_bman} = s1_data;

  // ---------------------------------------------------------------------
  // m2: the significand product, in [2^46, 2^48)
  // ---------------------------------------------------------------------
  wire [47:0] c2_prod = s1_aman * s1_bman;

  localparam integer W2 = 1 + 32 + 1 + 1 + 10 + 48;
  wire          s2_valid;
  wire [W2-1:0] s2_data;
  fp_pipe #(.WIDTH(W2), .DEPTH(DEPTH2)) u_pipe2 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s1_valid),
    .data_i  ({s1_spec, s1_spec_y, s1_spec_nv, s1_sign, s1_exp, c2_prod}),
    .valid_o (s2_valid),
    .data_o  (s2_data)
  );

  wire        s2_spec;
  wire [31:0] s2_spec_y;
  wire        s2_spec_nv;
  wire        s2_sign;
  wire [9:0]  s2_exp;
  wire [47:0] s2_prod;
  assign {s2_spec, s2_spec_y, s2_spec_nv, s2_sign, s2_exp, s2_prod} = s2_data;

  // ---------------------------------------------------------------------
  // m3: normalise (at most one place left), shift tiny results right into
  // the subnormal range keeping a sticky bit, round and pack
  // ---------------------------------------------------------------------
  wire [47:0] norm_p   = s2_prod[47] ? s2_prod : {s2_prod[46:0], 1'b0};
  wire [9:0]  norm_e   = s2_prod[47] ? s2_exp : (s2_exp - 10'd1);
  // Exponent below 1 (two's complement: negative or zero)?
  wire        is_low   = norm_e[9] | (norm_e == 10'd0);
  wire [9:0]  rs_full  = 10'd1 - norm_e;
  wire [4:0]  rs       = !is_low ? 5'd0
                       : ((rs_full > SHIFT_MAX) ? SHIFT_MAX[4:0] : rs_full[4:0]);
  wire [47:0] den_p    = norm_p >> rs;
  wire [47:0] lost     = norm_p & ~({48{1'b1}} << rs);
  wire [9:0]  c3_exp   = is_low ? 10'd1 : norm_e;
  wire        c3_sticky = (|den_p[21:0]) | (|lost);

  // LATENCY >= 5: a register stage between the shifts and the rounding.
  localparam integer W3 = 1 + 32 + 1 + 1 + 10 + 26 + 1;
  wire          s3_valid;
  wire [W3-1:0] s3_data;
  fp_pipe #(.WIDTH(W3), .DEPTH(DEPTH3)) u_pipe3 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s2_valid),
    .data_i  ({s2_spec, s2_spec_y, s2_spec_nv, s2_sign, c3_exp, den_p[47:22], c3_sticky}),
    .valid_o (s3_valid),
    .data_o  (s3_data)
  );

  wire        s3_spec;
  wire [31:0] s3_spec_y;
  wire        s3_spec_nv;
  wire        s3_sign;
  wire [9:0]  s3_exp;
  wire [25:0] s3_man;    // significand, guard and round bits
  wire        s3_sticky;
  assign {s3_spec, s3_spec_y, s3_spec_nv, s3_sign, s3_exp, s3_man, s3_sticky} = s3_data;

  wire [31:0] rnd_y;
  wire [4:0]  rnd_flags;
  fp_round #(.ROUND(ROUND), .FTZ(FTZ)) u_round (
    .sign_i   (s3_sign),
    .exp_i    (s3_exp),
    .mant_i   (s3_man[25:2]),
    .guard_i  (s3_man[1]),
    .round_i  (s3_man[0]),
    .sticky_i (s3_sticky),
    .y_o      (rnd_y),
    .flags_o  (rnd_flags)
  );

  wire [31:0] c3_y     = s3_spec ? s3_spec_y : rnd_y;
  wire [4:0]  c3_flags = s3_spec ? (s3_spec_nv ? FLAG_NV : 5'd0) : rnd_flags;

  fp_pipe #(.WIDTH(32 + 5), .DEPTH(DEPTH_O)) u_pipe_out (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s3_valid),
    .data_i  ({c3_y, c3_flags}),
    .valid_o (valid_o),
    .data_o  ({y_o, flags_o})
  );

endmodule

`default_nettype wire
