// fp_add.v -- pipelined IEEE 754 binary32 adder/subtractor.
//
// Computes a + b (sub_i = 0) or a - b (sub_i = 1) with the exception flags,
// bit for bit equal to sw/fpref.h (x86 SSE results, explicit NaN rules).
//
// Parameters:
//   LATENCY  rising clock edges from the operands being sampled to the
//            result on the outputs; >= 1 (default 4).  Stage boundaries:
//              L = 1: c1 c2 c3 c4 | out
//              L = 2: c1 c2 | c3 c4 | out
//              L = 3: c1 c2 | c3 | c4 | out
//              L = 4: c1 | c2 | c3 | c4 | out
//              L = 5: in | c1 | c2 | c3 | c4 | out
//              L >= 6: in | c1 | c2a | c2b | c3 | c4 | out, plus L-6
//              delay stages (in = operand registers; c2a = alignment
//              shift, c2b = add/subtract)
//            where c1 = unpack, special cases, compare and swap, exponent
//            difference; c2 = alignment shift with sticky, add/subtract;
//            c3 = leading-zero count and normalisation; c4 = rounding and
//            packing (fp_round).
//   ROUND    0: round to nearest, ties to even; 1: round toward zero
//   FTZ      0: IEEE subnormals; 1: subnormal inputs read as zero (sign
//            kept, no flag: x86 DAZ) and tiny results flushed to +-0 with
//            underflow and inexact (x86 FTZ, tininess after rounding)
//
// Ports:
//   clk_i    clock, rising edge
//   rst_i    synchronous reset, active high; clears the valid bits only
//   valid_i  an operation is presented this cycle
//   sub_i    1: a - b, 0: a + b
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
// roundTowardZero); §5.4.1 addition; §6.2 NaN propagation (a NaN operand
// is returned quieted, a before b; b's sign is not flipped by sub), the
// invalid result is the x86 default NaN 0xFFC00000; §6.3 signs: an exact
// zero sum of opposite-signed operands is +0 (both rounding modes
// supported round neither toward -inf), x + x keeps the sign of x;
// §7.2 invalid (inf - inf, any signalling NaN operand), §7.4 overflow,
// §7.5 underflow (tininess after rounding; a sum is never both tiny and
// inexact, so add/sub raises underflow only when FTZ flushes).
`default_nettype none

module fp_add #(
  parameter integer LATENCY = 4, // issue to result, rising edges, >= 1
  parameter integer ROUND   = 0, // 0 RNE, 1 RTZ
  parameter integer FTZ     = 0  // 1: flush subnormal inputs and results
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        valid_i,
  input  wire        sub_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  output wire        valid_o,
  output wire [31:0] y_o,
  output wire [4:0]  flags_o
);

  localparam [7:0]  EXP_MAX     = 8'hFF;
  localparam [7:0]  EXP_ONE     = 8'd1;
  localparam [31:0] QNAN_BIT    = 32'h0040_0000;
  localparam [31:0] DEFAULT_NAN = 32'hFFC0_0000;
  localparam [30:0] MAG_INF     = 31'h7F80_0000;
  localparam [4:0]  FLAG_NV     = 5'b10000;
  localparam [4:0]  ALIGN_MAX   = 5'd27; // shifts >= 27 leave only sticky

  // Stage boundaries (register stages after c1, c2, c3, and at the output).
  localparam integer DEPTH_I  = (LATENCY >= 5) ? 1 : 0;
  localparam integer DEPTH1   = (LATENCY >= 4) ? 1 : 0;
  localparam integer DEPTH2A  = (LATENCY >= 6) ? 1 : 0;
  localparam integer DEPTH2   = (LATENCY >= 2) ? 1 : 0;
  localparam integer DEPTH3   = (LATENCY >= 3) ? 1 : 0;
  localparam integer DEPTH_O  = (LATENCY >= 6) ? LATENCY - 5 : 1;

  generate
    if (LATENCY < 1) begin : g_bad_latency
      // Elaboration error on purpose: LATENCY must be at least 1.
      fp_add_error_LATENCY_must_be_at_least_1 u_error ();
    end
  endgenerate

  // ---------------------------------------------------------------------
  // operand registers (LATENCY >= 5)
  // ---------------------------------------------------------------------
  wire        s0_valid;
  wire        sub_in;
  wire [31:0] a_in, b_in;
  fp_pipe #(.WIDTH(65), .DEPTH(DEPTH_I)) u_pipe_in (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({sub_i, a_i, b_i}),
    .valid_o (s0_valid),
    .data_o  ({sub_in, a_in, b_in})
  );

  // ---------------------------------------------------------------------
  // c1: unpack, special cases, compare and swap, exponent difference
  // ---------------------------------------------------------------------
  wire       a_sign = a_in[31];
  wire       b_sign = b_in[31] ^ sub_in; // effective sign of the addend
  wire [7:0] a_exp  = a_in[30:23];
  wire [7:0] b_exp  = b_in[30:23];
  wire       a_nan  = (a_exp == EXP_MAX) & (|a_in[22:0]);
  wire       b_nan  = (b_exp == EXP_MAX) & (|b_in[22:0]);
  wire       a_snan = a_nan & ~a_in[22];
  wire       b_snan = b_nan & ~b_in[22];
  wire       a_inf  = (a_exp == EXP_MAX) & ~(|a_in[22:0]);
  wire       b_inf  = (b_exp == EXP_MAX) & ~(|b_in[22:0]);

  // Magnitudes, subnormals read as zero under FTZ (DAZ).
  wire [30:0] a_mag = ((FTZ != 0) && (a_exp == 8'd0)) ? 31'd0 : a_in[30:0];
  wire [30:0] b_mag = ((FTZ != 0) && (b_exp == 8'd0)) ? 31'd0 : b_in[30:0];

  reg        c1_spec;
  reg [31:0] c1_spec_y;
  reg        c1_spec_nv;
  always @* begin
    c1_spec    = a_nan | b_nan | a_inf | b_inf;
    c1_spec_nv = 1'b0;
    if (a_nan) begin
      c1_spec_y  = a_in | QNAN_BIT;
      c1_spec_nv = a_snan | b_snan;
    end else if (b_nan) begin
      c1_spec_y  = b_in | QNAN_BIT;
      c1_spec_nv = b_snan;
    end else if (a_inf & b_inf & (a_sign ^ b_sign)) begin
      c1_spec_y  = DEFAULT_NAN;
      c1_spec_nv = 1'b1;
    end else if (a_inf) begin
      c1_spec_y  = {a_sign, MAG_INF};
    end else begin
      c1_spec_y  = {b_sign, MAG_INF};
    end
  end

  // x: the operand of larger magnitude, y: the other one.
  wire        swap      = (b_mag > a_mag);
  wire [30:0] x_mag     = swap ? b_mag : a_mag;
  wire [30:0] y_mag     = swap ? a_mag : b_mag;
  wire        c1_sign   = swap ? b_sign : a_sign;
  wire        c1_sub    = a_sign ^ b_sign;
  // Exact zero result: +0 for opposite signs (RNE, RTZ), else that sign.
  wire        c1_zsign  = c1_sub ? 1'b0 : a_sign;
  wire        x_norm    = (x_mag[30:23] != 8'd0);
  wire        y_norm    = (y_mag[30:23] != 8'd0);
  wire [7:0]  c1_exp    = x_norm ? x_mag[30:23] : EXP_ONE;
  wire [7:0]  y_exp     = y_norm ? y_mag[30:23] : EXP_ONE;
  wire [23:0] c1_xman   = {x_norm, x_mag[22:0]};
  wire [23:0] c1_yman   = {y_norm, y_mag[22:0]};
  wire [7:0]  exp_diff  = c1_exp - y_exp;
  wire [4:0]  c1_shift  = (exp_diff > {3'd0, ALIGN_MAX}) ? ALIGN_MAX : exp_diff[4:0];

  localparam integer W1 = 1 + 32 + 1 + 1 + 1 + 1 + 8 + 24 + 24 + 5;
  wire          s1_valid;
  wire [W1-1:0] s1_data;
  fp_pipe #(.WIDTH(W1), .DEPTH(DEPTH1)) u_pipe1 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s0_valid),
    .data_i  ({c1_spec, c1_spec_y, c1_spec_nv, c1_sign, c1_sub, c1_zsign,
               c1_exp, c1_xman, c1_yman, c1_shift}),
    .valid_o (s1_valid),
    .data_o  (s1_data)
  );

  wire        s1_spec;
  wire [31:0] s1_spec_y;
  wire        s1_spec_nv;
  wire        s1_sign;
  wire        s1_sub;
  wire        s1_zsign;
  wire [7:0]  s1_exp;
  wire [23:0] s1_xman;
  wire [23:0] s1_yman;
  wire [4:0]  s1_shift;
  assign {s1_spec, s1_spec_y, s1_spec_nv, s1_sign, s1_sub, s1_zsign,
          s1_exp, s1_xman, s1_yman, s1_shift} = s1_data;

  // ---------------------------------------------------------------------
  // c2: align y to x (3 extra bits: guard, round, sticky), add or subtract
  // ---------------------------------------------------------------------
  wire [53:0] y_wide   = {s1_yman, 3'd0, 27'd0} >> s1_shift;
  wire [26:0] y_align  = {y_wide[53:28], y_wide[27] | (|y_wide[26:0])};
  wire [26:0] x_align  = {s1_xman, 3'd0};

  // LATENCY >= 6: a register stage between the shift and the adder.
  localparam integer W2A = 1 + 32 + 1 + 1 + 1 + 1 + 8 + 27 + 27;
  wire          s2a_valid;
  wire [W2A-1:0] s2a_data;
  fp_pipe #(.WIDTH(W2A), .DEPTH(DEPTH2A)) u_pipe2a (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s1_valid),
    .data_i  ({s1_spec, s1_spec_y, s1_spec_nv, s1_sign, s1_sub, s1_zsign, s1_exp,
               x_align, y_align}),
    .valid_o (s2a_valid),
    .data_o  (s2a_data)
  );
  wire        s2a_spec;
  wire [31:0] s2a_spec_y;
  wire        s2a_spec_nv;
  wire        s2a_sign;
  wire        s2a_sub;
  wire        s2a_zsign;
  wire [7:0]  s2a_exp;
  wire [26:0] s2a_x;
  wire [26:0] s2a_y;
  assign {s2a_spec, s2a_spec_y, s2a_spec_nv, s2a_sign, s2a_sub, s2a_zsign, s2a_exp,
          s2a_x, s2a_y} = s2a_data;

  wire [27:0] c2_sum   = s2a_sub ? ({1'b0, s2a_x} - {1'b0, s2a_y})
                                 : ({1'b0, s2a_x} + {1'b0, s2a_y});

  localparam integer W2 = 1 + 32 + 1 + 1 + 1 + 8 + 28;
  wire          s2_valid;
  wire [W2-1:0] s2_data;
  fp_pipe #(.WIDTH(W2), .DEPTH(DEPTH2)) u_pipe2 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s2a_valid),
    .data_i  ({s2a_spec, s2a_spec_y, s2a_spec_nv, s2a_sign, s2a_zsign, s2a_exp,
               c2_sum}),
    .valid_o (s2_valid),
    .data_o  (s2_data)
  );

  wire        s2_spec;
  wire [31:0] s2_spec_y;
  wire        s2_spec_nv;
  wire        s2_sign;
  wire        s2_zsign;
  wire [7:0]  s2_exp;
  wire [27:0] s2_sum;
  assign {s2_spec, s2_spec_y, s2_spec_nv, s2_sign, s2_zsign, s2_exp,
          s2_sum} = s2_data;

  // ---------------------------------------------------------------------
  // c3: normalise.  A carry shifts right by one; otherwise shift left by
  // the leading-zero count, limited to exp - 1 so that the exponent stays
  // >= 1 (a "stopper" bit at that position bounds the count).
  // ---------------------------------------------------------------------
  wire [7:0]  lz_cap  = s2_exp - EXP_ONE;
  wire [26:0] stopper = (lz_cap < 8'd27) ? (27'h400_0000 >> lz_cap[4:0]) : 27'd0;

  reg [26:0] lz_v;  // value with stopper, drives the count
  reg [26:0] lz_w;  // value shifted alongside
  reg [4:0]  lz_n;  // shift count
  always @* begin
    lz_v = s2_sum[26:0] | stopper;
    lz_w = s2_sum[26:0];
    lz_n = 5'd0;
    if (lz_v[26:11] == 16'd0) begin lz_v = lz_v << 16; lz_w = lz_w << 16; lz_n = lz_n + 5'd16; end
    if (lz_v[26:19] == 8'd0)  begin lz_v = lz_v << 8;  lz_w = lz_w << 8;  lz_n = lz_n + 5'd8;  end
    if (lz_v[26:23] == 4'd0)  begin lz_v = lz_v << 4;  lz_w = lz_w << 4;  lz_n = lz_n + 5'd4;  end
    if (lz_v[26:25] == 2'd0)  begin lz_v = lz_v << 2;  lz_w = lz_w << 2;  lz_n = lz_n + 5'd2;  end
    if (lz_v[26] == 1'b0)     begin lz_v = lz_v << 1;  lz_w = lz_w << 1;  lz_n = lz_n + 5'd1;  end
  end

  reg        c3_sign;
  reg [9:0]  c3_exp;
  reg [23:0] c3_man;
  reg        c3_g;
  reg        c3_r;
  reg        c3_s;
  always @* begin
    c3_sign = s2_sign;
    if (s2_sum == 28'd0) begin
      c3_sign = s2_zsign;
      c3_exp  = 10'd1;
      c3_man  = 24'd0;
      c3_g    = 1'b0;
      c3_r    = 1'b0;
      c3_s    = 1'b0;
    end else if (s2_sum[27]) begin
      c3_exp  = {2'd0, s2_exp} + 10'd1;
      c3_man  = s2_sum[27:4];
      c3_g    = s2_sum[3];
      c3_r    = s2_sum[2];
      c3_s    = |s2_sum[1:0];
    end else begin
      c3_exp  = {2'd0, s2_exp} - {5'd0, lz_n};
      c3_man  = lz_w[26:3];
      c3_g    = lz_w[2];
      c3_r    = lz_w[1];
      c3_s    = lz_w[0];
    end
  end

  wire unused_lz = &{1'b0, lz_v, 1'b0};

  localparam integer W3 = 1 + 32 + 1 + 1 + 10 + 24 + 3;
  wire          s3_valid;
  wire [W3-1:0] s3_data;
  fp_pipe #(.WIDTH(W3), .DEPTH(DEPTH3)) u_pipe3 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s2_valid),
    .data_i  ({s2_spec, s2_spec_y, s2_spec_nv, c3_sign, c3_exp, c3_man,
               c3_g, c3_r, c3_s}),
    .valid_o (s3_valid),
    .data_o  (s3_data)
  );

  wire        s3_spec;
  wire [31:0] s3_spec_y;
  wire        s3_spec_nv;
  wire        s3_sign;
  wire [9:0]  s3_exp;
  wire [23:0] s3_man;
  wire        s3_g;
  wire        s3_r;
  wire        s3_s;
  assign {s3_spec, s3_spec_y, s3_spec_nv, s3_sign, s3_exp, s3_man,
          s3_g, s3_r, s3_s} = s3_data;

  // ---------------------------------------------------------------------
  // c4: round and pack, or the special result
  // ---------------------------------------------------------------------
  wire [31:0] rnd_y;
  wire [4:0]  rnd_flags;
  fp_round #(.ROUND(ROUND), .FTZ(FTZ)) u_round (
    .sign_i   (s3_sign),
    .exp_i    (s3_exp),
    .mant_i   (s3_man),
    .guard_i  (s3_g),
    .round_i  (s3_r),
    .sticky_i (s3_s),
    .y_o      (rnd_y),
    .flags_o  (rnd_flags)
  );

  wire [31:0] c4_y     = s3_spec ? s3_spec_y : rnd_y;
  wire [4:0]  c4_flags = s3_spec ? (s3_spec_nv ? FLAG_NV : 5'd0) : rnd_flags;

  fp_pipe #(.WIDTH(32 + 5), .DEPTH(DEPTH_O)) u_pipe_out (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s3_valid),
    .data_i  ({c4_y, c4_flags}),
    .valid_o (valid_o),
    .data_o  ({y_o, flags_o})
  );

endmodule

`default_nettype wire
