// fp_mul.v -- pipelined IEEE 754 binary32 multiplier.
//
// Computes a * b with the exception flags, bit for bit equal to sw/ref/fpref.h
// (x86 SSE results, explicit NaN rules).
//
// Parameters:
//   LATENCY  rising clock edges from the operands being sampled to the
//            result on the outputs; >= 1 (default 3).  The datapath has
//            ten places for a register (| below) besides the output
//            register; LATENCY picks which hold one:
//              L = 1:  m1a m1b m2a m2b m2c m3a m3b m4a m4b | out
//              L = 2:  m1a m1b m2a m2b m2c | m3a m3b m4a m4b | out
//              L = 3:  m1a m1b | m2a m2b m2c | m3a m3b m4a m4b | out
//              L = 4:  in | m1a m1b | m2a m2b m2c | m3a m3b m4a m4b | out
//              L = 5:  in | m1a m1b | m2a m2b m2c | m3a m3b | m4a m4b | out
//              L = 6:  in | m1a m1b | m2a | m2b m2c | m3a m3b | m4a m4b | out
//              L = 7:  in | m1a | m1b | m2a | m2b m2c | m3a m3b | m4a m4b
//                      | out
//              L = 8:  in | m1a | m1b | m2a | m2b m2c | m3a m3b | m4a
//                      | m4b | out
//              L = 9:  in | m1a | m1b | m2a | m2b | m2c | m3a m3b | m4a
//                      | m4b | out
//              L = 10: in | m1a | m1b | m2a | m2b | m2c | m2d | m3a
//                      | m3b m4a | m4b | out
//              L >= 11: in | m1a | m1b | m2a | m2b | m2c | m2d | m3a
//                      | m3b | m4a | m4b | out, plus L-11 delay stages
//            where in = operand registers;
//              m1a = unpack, the fields' tests for the special cases,
//                    leading zeros of subnormal significands
//                    (fp_mul_unpack_norm), exponent sum;
//              m1b = normalising shift of the significands, the exponent
//                    less the shifts, the special case decided;
//              m2a = from the exponent (it alone decides them): the result
//                    exponent for either position of the product's
//                    leading one and the denormalisation shift; the
//                    special result; the first step of the product;
//              m2b, m2c (and m2d) = the further steps of the 48-bit
//                    product, of which the top 27 bits and a sticky bit
//                    go on (fp_mul_prod: for L <= 9 four 12 x 12-bit
//                    partial products in DSP blocks, no m2d, for
//                    L = 6 to 9 the registers m1b | m2a and m2a | m2b of
//                    the product are the blocks' own (fp_dsp_mul; Yosys
//                    maps `*` without them, under 150 MHz on the ECP5);
//                    for L >= 10 an AND array and carry-chain adders, no
//                    DSP block);
//              m3a = one-place normalisation and the denormalisation of
//                    tiny results, shifts of 2 to 30 places with sticky
//                    (fp_norm_shift);
//              m3b = the remaining one-place shift with sticky;
//              m4a = rounding increment and overflow (fp_round);
//              m4b = flush to zero, flags, special result
//                    (fp_round_pack).
//   FEED     0: as the table above
//            1: one more register, in the fabric, between m1b and the DSP
//            blocks' input registers: the places of LATENCY - 1 (which
//            must be 7 to 10 here, so that the table's LATENCY - 1 is 6 to
//            9: the DSP product with the blocks' own registers) plus this
//            one, e.g. LATENCY 10:
//              in | m1a | m1b | feed | m2a | m2b | m2c | m3a m3b | m4a
//              | m4b | out
//            Why: with many lanes on one chip the route from m1b's shift to
//            a lane's MULT18X18D crosses much of the device (8 to 11 ns of
//            routing on the 16-lane LFE5U-85F build, docs/lanes.md); the
//            feed register splits it in two cycles.  It costs 67 flip-flops
//            (the significands and what rides beside them) and a cycle.
//   MULT_BLOCKS  the DSP product's blocks (LATENCY - FEED <= 9):
//            4: four 12 x 12-bit partial products, one MULT18X18D each
//            3: the operands cut at bit 6: three MULT18X18D (18 x 18 and
//            two 18 x 6) and the 6 x 6-bit low product in the fabric
//            (fp_mul_prod BLOCKS), 150 to 172 LUT4s and 51 flip-flops
//            more (latency 9, 10 with FEED; alone, spatial-core-area.sh);
//            same latency, same results.  For chips whose multiplier
//            blocks run out first (the literal ship pipeline: 56 of the
//            LFE5U-85F's 156 with 4, 42 with 3)
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
  parameter integer FEED    = 0, // 1: a fabric register in front of the DSP blocks
  parameter integer MULT_BLOCKS = 4, // MULT18X18D per product, 4 or 3
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
  localparam [31:0] DEFAULT_NAN = 32'hFFC0_0000;
  localparam [30:0] MAG_INF     = 31'h7F80_0000;

  // Register places, in datapath order (bit k of BND: place k holds one).
  localparam integer B_IN  = 0; // in  | m1a : operand registers
  localparam integer B_M1B = 1; // m1a | m1b
  localparam integer B_M2  = 2; // m1b | m2a : product operands
  localparam integer B_M2B = 3; // m2a | m2b
  localparam integer B_M2C = 4; // m2b | m2c
  localparam integer B_M2D = 5; // m2c | m2d (LUT product only)
  localparam integer B_M3  = 6; // m2d | m3a : the product
  localparam integer B_M3B = 7; // m3a | m3b
  localparam integer B_M4  = 8; // m3b | m4a : before rounding
  localparam integer B_M4B = 9; // m4a | m4b
  localparam integer N_LUT  = 10; // LATENCY from which the product is LUTs
  localparam integer N_FULL = 11; // LATENCY with every place registered

  // The header's table; LATENCY >= N_FULL adds output delay stages.
  function [9:0] bounds(input integer lat);
    begin
      case (lat)
        1:       bounds = 10'b00_0000_0000;
        2:       bounds = 10'b00_0100_0000;
        3:       bounds = 10'b00_0100_0100;
        4:       bounds = 10'b00_0100_0101;
        5:       bounds = 10'b01_0100_0101;
        6:       bounds = 10'b01_0100_1101;
        7:       bounds = 10'b01_0100_1111;
        8:       bounds = 10'b11_0100_1111;
        9:       bounds = 10'b11_0101_1111;
        10:      bounds = 10'b10_1111_1111;
        default: bounds = 10'b11_1111_1111;
      endcase
    end
  endfunction

  // The table's row: that of LATENCY less the feed register.
  localparam integer LAT_T    = LATENCY - ((FEED != 0) ? 1 : 0);
  localparam [9:0]   BND      = bounds(LAT_T);
  localparam integer DEPTH_O  = (LAT_T > N_FULL) ? LAT_T - N_FULL + 1 : 1;
  localparam integer LUT_PROD = (LAT_T >= N_LUT) ? 1 : 0;
  // The DSP product with a register in front (m1b | m2a) and one after
  // (m2a | m2b), L = 6 to 9: both are the DSP blocks' own (fp_mul_prod
  // PRE = 1), which take the significands a cycle early, from m1b.
  localparam integer DSP_REG  = ((LUT_PROD == 0) && BND[B_M2] && BND[B_M2B]) ? 1 : 0;

  generate
    if (LATENCY < 1) begin : g_bad_latency
      // Elaboration error on purpose: LATENCY must be at least 1.
      fp_mul_error_LATENCY_must_be_at_least_1 u_error ();
    end
    if ((FEED != 0) && ((FEED != 1) || (DSP_REG == 0))) begin : g_bad_feed
      // Elaboration error on purpose: the feed register stands in front
      // of the DSP blocks' input registers, LATENCY 7 to 10.
      fp_mul_error_FEED_needs_LATENCY_7_to_10 u_error ();
    end
  endgenerate

  // ---------------------------------------------------------------------
  // in: operand registers
  // ---------------------------------------------------------------------
  wire        s0_valid;
  wire [31:0] a_in, b_in;
  // (HOLD: the operand registers load with valid_i only, so that the add
  // and multiply cores' registers, which have the same inputs, stay
  // apart, each beside its own core.)
  fp_pipe #(.WIDTH(64), .DEPTH(BND[B_IN] ? 1 : 0), .HOLD(1)) u_pipe_in (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({a_i, b_i}),
    .valid_o (s0_valid),
    .data_o  ({a_in, b_in})
  );

  // ---------------------------------------------------------------------
  // m1a: unpack, special cases, leading zeros, exponent sum
  // ---------------------------------------------------------------------
  wire       a_sign = a_in[31];
  wire       b_sign = b_in[31];
  wire [7:0] a_exp  = a_in[30:23];
  wire [7:0] b_exp  = b_in[30:23];
  // The fields' tests for the special cases (combined in m1b).
  wire [5:0] c1_cls = {a_exp == EXP_MAX, a_exp == 8'd0, |a_in[22:0],
                       b_exp == EXP_MAX, b_exp == 8'd0, |b_in[22:0]};

  // Significands (with the weight of the exponent fields) and their
  // leading-zero counts.
  wire [23:0] c1_aman, c1_bman;
  wire [4:0]  c1_alz, c1_blz;
  fp_mul_unpack_norm #(.FTZ(FTZ)) u_unpack_a (
    .exp_i  (a_exp),
    .frac_i (a_in[22:0]),
    .man_o  (c1_aman),
    .lz_o   (c1_alz)
  );
  fp_mul_unpack_norm #(.FTZ(FTZ)) u_unpack_b (
    .exp_i  (b_exp),
    .frac_i (b_in[22:0]),
    .man_o  (c1_bman),
    .lz_o   (c1_blz)
  );

  // Biased exponent of the product taken as a value in [1, 2) times 2
  // (the product of two significands in [1, 2) lies in [1, 4)), before
  // the normalising shifts; 10-bit two's complement.  The fields as they
  // are: fp_mul_unpack_norm gives a subnormal significand the weight of
  // the field 0.
  wire [9:0] c1_exp = {2'd0, a_exp} + {2'd0, b_exp} - EXP_BIAS_M1;

  // The special case: in m1b the fields' tests and the operand signs, in
  // m2a spec, spec_nv, nan, nan_b, dnan, inf and the signs; from m2a on
  // what m4b needs of it: spec, spec_y, spec_nv and the product's sign.
  localparam integer WQ = 6 + 2;
  localparam integer WR = 1 + 1 + 1 + 1 + 1 + 1 + 2;
  localparam integer WS = 1 + 32 + 1 + 1;

  localparam integer W1 = WQ + 10 + 24 + 24 + 5 + 5;
  wire          s1_valid;
  wire [W1-1:0] s1_data;
  fp_pipe #(.WIDTH(W1), .DEPTH(BND[B_M1B] ? 1 : 0)) u_pipe1 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s0_valid),
    .data_i  ({c1_cls, a_sign, b_sign, c1_exp,
               c1_aman, c1_bman, c1_alz, c1_blz}),
    .valid_o (s1_valid),
    .data_o  (s1_data)
  );

  wire          s1_amax, s1_azero, s1_anz, s1_bmax, s1_bzero, s1_bnz;
  wire          s1_asign, s1_bsign;
  wire [9:0]    s1_exp;
  wire [23:0]   s1_aman, s1_bman;
  wire [4:0]    s1_alz, s1_blz;
  assign {s1_amax, s1_azero, s1_anz, s1_bmax, s1_bzero, s1_bnz, s1_asign,
          s1_bsign, s1_exp, s1_aman, s1_bman, s1_alz, s1_blz} = s1_data;

  // ---------------------------------------------------------------------
  // m1b: normalise the significands (leading one at bit 23); the exponent
  // of the normalised significands
  // ---------------------------------------------------------------------
  wire [23:0] c1b_aman = s1_aman << s1_alz;
  wire [23:0] c1b_bman = s1_bman << s1_blz;
  wire [9:0]  c1b_exp  = s1_exp - {5'd0, s1_alz} - {5'd0, s1_blz};

  // The special case: NaN (a quiet one has fraction bit 22 set, the
  // significand's bit 22), infinity, zero (or subnormal read as zero
  // under FTZ: DAZ).  The special result, built in m2a: the first NaN
  // operand quieted (nan; nan_b: it is b), else the default NaN for
  // 0 * inf (dnan; an infinity and a zero leave no NaN operand), else
  // infinity (inf), else zero.
  wire a_nan  = s1_amax & s1_anz;
  wire b_nan  = s1_bmax & s1_bnz;
  wire a_inf  = s1_amax & ~s1_anz;
  wire b_inf  = s1_bmax & ~s1_bnz;
  wire a_zero = s1_azero & ((FTZ != 0) | ~s1_anz);
  wire b_zero = s1_bzero & ((FTZ != 0) | ~s1_bnz);
  wire c1b_spec    = a_nan | b_nan | a_inf | b_inf | a_zero | b_zero;
  wire c1b_nan     = a_nan | b_nan;
  wire c1b_nan_b   = ~a_nan;
  wire c1b_dnan    = (a_inf & b_zero) | (a_zero & b_inf);
  wire c1b_inf     = a_inf | b_inf;
  wire c1b_spec_nv = (a_nan & ~s1_aman[22]) | (b_nan & ~s1_bman[22]) | c1b_dnan;

  localparam integer W2 = WR + 10 + 24 + 24;

  // feed (FEED = 1): m1b's results once more, in the fabric; the DSP
  // blocks take their significands from here.
  wire          sf_valid;
  wire [W2-1:0] sf_data;
  fp_pipe #(.WIDTH(W2), .DEPTH((FEED != 0) ? 1 : 0)) u_pipe_feed (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s1_valid),
    .data_i  ({c1b_spec, c1b_spec_nv, c1b_nan, c1b_nan_b, c1b_dnan, c1b_inf,
               s1_asign, s1_bsign, c1b_exp, c1b_aman, c1b_bman}),
    .valid_o (sf_valid),
    .data_o  (sf_data)
  );
  wire [23:0] sf_aman = sf_data[47:24];
  wire [23:0] sf_bman = sf_data[23:0];

  wire          s2_valid;
  wire [W2-1:0] s2_data;
  fp_pipe #(.WIDTH(W2), .DEPTH(BND[B_M2] ? 1 : 0)) u_pipe2 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (sf_valid),
    .data_i  (sf_data),
    .valid_o (s2_valid),
    .data_o  (s2_data)
  );

  wire          s2_spec, s2_spec_nv, s2_nan, s2_nan_b, s2_dnan, s2_inf;
  wire          s2_asign, s2_bsign;
  wire [9:0]    s2_exp;
  wire [23:0]   s2_aman, s2_bman;
  assign {s2_spec, s2_spec_nv, s2_nan, s2_nan_b, s2_dnan, s2_inf, s2_asign,
          s2_bsign, s2_exp, s2_aman, s2_bman} = s2_data;

  // ---------------------------------------------------------------------
  // m2a: the special result.  A NaN operand has a normal significand
  // {1, fraction}, so its payload is the significand's low 22 bits.
  // ---------------------------------------------------------------------
  wire        c2_sign = s2_asign ^ s2_bsign;
  reg  [31:0] c2_spec_y;
  always @* begin
    if (s2_nan) begin
      c2_spec_y = s2_nan_b ? {s2_bsign, EXP_MAX, 1'b1, s2_bman[21:0]}
                           : {s2_asign, EXP_MAX, 1'b1, s2_aman[21:0]};
    end else if (s2_dnan) begin
      c2_spec_y = DEFAULT_NAN;
    end else if (s2_inf) begin
      c2_spec_y = {c2_sign, MAG_INF};
    end else begin
      c2_spec_y = {c2_sign, 31'd0};
    end
  end

  // ---------------------------------------------------------------------
  // m2a: from the exponent e alone, for either position of the product's
  // leading one (p47 = product bit 47):
  //   result exponent  p47: max(e, 1)   else: max(e - 1, 1)
  //   right shift of the product's top 27 bits (normalisation and
  //   denormalisation in one): e >= 2: p47 (0 or 1 place), e <= 1:
  //   2 - e places either way, at most 31 (all bits go to sticky)
  // so that m3 only picks by p47: shift = c2_shift | (p47 & c2_ge2)
  // (fp_norm_exp).
  // ---------------------------------------------------------------------
  wire [9:0]  c2_exp_a, c2_exp_b;
  wire        c2_ge2;
  wire [4:0]  c2_shift;
  fp_norm_exp u_norm_exp (
    .exp_i   (s2_exp),
    .exp_a_o (c2_exp_a),
    .exp_b_o (c2_exp_b),
    .ge2_o   (c2_ge2),
    .shift_o (c2_shift)
  );

  // ---------------------------------------------------------------------
  // m2a-m2d: the product prod = aman * bman, in [2^46, 2^48): its top 27
  // bits and the OR of the 21 below; the rest rides along
  // ---------------------------------------------------------------------
  localparam integer WP = WS + 10 + 10 + 1 + 5;
  wire          sp_valid;
  wire [WP-1:0] sp_side;
  wire [26:0]   c2_top;
  wire          c2_st;
  fp_mul_prod #(
    .LUT    (LUT_PROD),
    .BND    ({BND[B_M2D], BND[B_M2C], BND[B_M2B]}),
    .PRE    (DSP_REG),
    .BLOCKS (MULT_BLOCKS),
    .SIDE_W (WP)
  ) u_prod (
    .clk_i    (clk_i),
    .rst_i    (rst_i),
    .valid_i  (s2_valid),
    .a_i      ((DSP_REG != 0) ? sf_aman : s2_aman),
    .b_i      ((DSP_REG != 0) ? sf_bman : s2_bman),
    .side_i   ({s2_spec, c2_spec_y, s2_spec_nv, c2_sign, c2_exp_a, c2_exp_b,
                c2_ge2, c2_shift}),
    .valid_o  (sp_valid),
    .top_o    (c2_top),
    .sticky_o (c2_st),
    .side_o   (sp_side)
  );

  localparam integer W5 = WP + 27 + 1;
  wire          s5_valid;
  wire [W5-1:0] s5_data;
  fp_pipe #(.WIDTH(W5), .DEPTH(BND[B_M3] ? 1 : 0)) u_pipe5 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (sp_valid),
    .data_i  ({sp_side, c2_top, c2_st}),
    .valid_o (s5_valid),
    .data_o  (s5_data)
  );

  wire [WS-1:0] s5_spec;
  wire [9:0]    s5_exp_a, s5_exp_b;
  wire          s5_ge2;
  wire [4:0]    s5_shift;
  wire [26:0]   s5_top;
  wire          s5_st;
  assign {s5_spec, s5_exp_a, s5_exp_b, s5_ge2, s5_shift, s5_top, s5_st} = s5_data;

  // ---------------------------------------------------------------------
  // m3a: pick the exponent by p47 (the product's bit 47, s5_top[26]); the
  // shift's even part (2 to 30 places); m3b: the shift's last place
  // (fp_norm_shift)
  // ---------------------------------------------------------------------
  wire          s6_valid;
  wire [WS-1:0] s6_spec;
  wire [9:0]    s6_exp;
  wire [25:0]   c3b_man;  // significand, guard and round bits
  wire          c3b_st;
  fp_norm_shift #(.SIDE_W(WS), .MID_DEPTH(BND[B_M3B] ? 1 : 0)) u_norm_shift (
    .clk_i    (clk_i),
    .rst_i    (rst_i),
    .valid_i  (s5_valid),
    .side_i   (s5_spec),
    .top_i    (s5_top),
    .sticky_i (s5_st),
    .exp_a_i  (s5_exp_a),
    .exp_b_i  (s5_exp_b),
    .ge2_i    (s5_ge2),
    .shift_i  (s5_shift),
    .valid_o  (s6_valid),
    .side_o   (s6_spec),
    .exp_o    (s6_exp),
    .man_o    (c3b_man),
    .sticky_o (c3b_st)
  );

  localparam integer W7 = WS + 10 + 26 + 1;
  wire          s7_valid;
  wire [W7-1:0] s7_data;
  fp_pipe #(.WIDTH(W7), .DEPTH(BND[B_M4] ? 1 : 0)) u_pipe7 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s6_valid),
    .data_i  ({s6_spec, s6_exp, c3b_man, c3b_st}),
    .valid_o (s7_valid),
    .data_o  (s7_data)
  );

  wire [WS-1:0] s7_spec;
  wire [9:0]    s7_exp;
  wire [25:0]   s7_man;   // significand, guard and round bits
  wire          s7_st;
  assign {s7_spec, s7_exp, s7_man, s7_st} = s7_data;

  // ---------------------------------------------------------------------
  // m4a: rounding increment; m4b: overflow, flush, flags, special result
  // ---------------------------------------------------------------------
  wire [30:0] c4_pack;
  wire        c4_overflow;
  wire        c4_inexact;
  wire        c4_tiny;
  fp_round #(.ROUND(ROUND)) u_round (
    .exp_i     (s7_exp),
    .mant_i    (s7_man[25:2]),
    .guard_i   (s7_man[1]),
    .round_i   (s7_man[0]),
    .sticky_i  (s7_st),
    .pack_o    (c4_pack),
    .overflow_o(c4_overflow),
    .inexact_o (c4_inexact),
    .tiny_o    (c4_tiny)
  );

  localparam integer W8 = WS + 31 + 1 + 1 + 1;
  wire          s8_valid;
  wire [W8-1:0] s8_data;
  fp_pipe #(.WIDTH(W8), .DEPTH(BND[B_M4B] ? 1 : 0)) u_pipe8 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s7_valid),
    .data_i  ({s7_spec, c4_pack, c4_overflow, c4_inexact, c4_tiny}),
    .valid_o (s8_valid),
    .data_o  (s8_data)
  );

  wire        s8_spec;
  wire [31:0] s8_spec_y;
  wire        s8_spec_nv;
  wire        s8_sign;
  wire [30:0] s8_pack;
  wire        s8_overflow;
  wire        s8_inexact;
  wire        s8_tiny;
  assign {s8_spec, s8_spec_y, s8_spec_nv, s8_sign, s8_pack, s8_overflow, s8_inexact,
          s8_tiny} = s8_data;

  wire [31:0] c4_y;
  wire [4:0]  c4_flags;
  fp_round_pack #(.ROUND(ROUND), .FTZ(FTZ)) u_pack (
    .sign_i    (s8_sign),
    .pack_i    (s8_pack),
    .overflow_i(s8_overflow),
    .inexact_i (s8_inexact),
    .tiny_i    (s8_tiny),
    .spec_i    (s8_spec),
    .spec_y_i  (s8_spec_y),
    .spec_nv_i (s8_spec_nv),
    .y_o       (c4_y),
    .flags_o   (c4_flags)
  );

  fp_pipe #(.WIDTH(32 + 5), .DEPTH(DEPTH_O)) u_pipe_out (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s8_valid),
    .data_i  ({c4_y, c4_flags}),
    .valid_o (valid_o),
    .data_o  ({y_o, flags_o})
  );

endmodule

`default_nettype wire
