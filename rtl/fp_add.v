// fp_add.v -- pipelined IEEE 754 binary32 adder/subtractor.
//
// Computes a + b (sub_i = 0) or a - b (sub_i = 1) with the exception flags,
// bit for bit equal to sw/ref/fpref.h (x86 SSE results, explicit NaN rules).
//
// Parameters:
//   LATENCY  rising clock edges from the operands being sampled to the
//            result on the outputs; >= 1 (default 4).  The datapath has
//            eight places for a register (| below) besides the output
//            register; LATENCY picks which hold one:
//              L = 1:  c1a c1b c2a c2b c3a c3b c4a c4b | out
//              L = 2:  c1a c1b c2a c2b | c3a c3b c4a c4b | out
//              L = 3:  c1a c1b c2a c2b | c3a c3b | c4a c4b | out
//              L = 4:  c1a c1b | c2a c2b | c3a c3b | c4a c4b | out
//              L = 5:  in | c1a c1b | c2a c2b | c3a c3b | c4a c4b | out
//              L = 6:  in | c1a c1b | c2a c2b | c3a | c3b | c4a c4b | out
//              L = 7:  in | c1a c1b | c2a | c2b | c3a | c3b | c4a c4b | out
//              L = 8:  in | c1a | c1b | c2a | c2b | c3a | c3b | c4a c4b
//                      | out
//              L >= 9: in | c1a | c1b | c2a | c2b | c3a | c3b | c4a | c4b
//                      | out, plus L-9 delay stages
//            where in = operand registers;
//              c1a = unpack, special cases, magnitude compare, each
//                    significand's lowest one (for c2a's sticky bit);
//              c1b = swap (x = the operand of larger magnitude), exponent
//                    difference (alignment shift, saturated), the
//                    position of y's lowest one (its sticky limit);
//              c2a = alignment shift of y, its sticky bit (the sticky
//                    limit against the shift), the
//                    normalisation limit from the exponent;
//              c2b = add/subtract (one carry chain), ORed with the
//                    normalisation limit for c3a;
//              c3a = leading-zero count (fp_lzc), limited so that the
//                    exponent stays >= 1;
//              c3b = normalising shift and exponent;
//              c4a = rounding increment and overflow (fp_round);
//              c4b = flush to zero, flags, special result
//                    (fp_round_pack).
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
  localparam [31:0] QNAN_BIT    = 32'h0040_0000;
  localparam [31:0] DEFAULT_NAN = 32'hFFC0_0000;
  localparam [30:0] MAG_INF     = 31'h7F80_0000;

  // For the alignment's sticky bit (c2a), in two steps.  c1a: the lowest
  // one of a significand m = {norm, f}, one-hot (zero for m = 0): that of
  // the fraction f, f & ~(f - 1) (a carry chain from the operand register,
  // no logic in front of it), else the hidden bit; none for a subnormal
  // read as zero (daz: FTZ).
  function [23:0] lowest_one(input [22:0] f, input norm, input daz);
    reg [23:0] d;
    begin
      d          = {1'b0, f} - 24'd1;   // d[23]: f = 0 (the borrow)
      lowest_one = {d[23] & norm, f & ~d[22:0]} & {24{~daz}};
    end
  endfunction
  // c1b: the sticky limit, the position of that one in {m, 00} (m's
  // trailing zeros + 2), 31 for m = 0, so that a right shift of {m, 00} by
  // s (0 to 31) drops a one exactly when s > the limit.  Encoded by ORs.
  function [4:0] sticky_limit(input [23:0] low);
    integer k;
    begin
      sticky_limit = {5{~|low}};
      for (k = 0; k < 24; k = k + 1)
        sticky_limit = sticky_limit | ({5{low[k]}} & (k[4:0] + 5'd2));
    end
  endfunction

  // Register places, in datapath order (bit k of BND: place k holds one).
  localparam integer B_IN  = 0; // in  | c1a : operand registers
  localparam integer B_C1B = 1; // c1a | c1b
  localparam integer B_C2  = 2; // c1b | c2a
  localparam integer B_C2B = 3; // c2a | c2b
  localparam integer B_C3  = 4; // c2b | c3a : the sum
  localparam integer B_C3B = 5; // c3a | c3b
  localparam integer B_C4  = 6; // c3b | c4a : before rounding
  localparam integer B_C4B = 7; // c4a | c4b
  localparam integer N_FULL = 9; // LATENCY with every place registered

  // The header's table; LATENCY >= N_FULL adds output delay stages.
  function [7:0] bounds(input integer lat);
    begin
      case (lat)
        1:       bounds = 8'b0000_0000;
        2:       bounds = 8'b0001_0000;
        3:       bounds = 8'b0101_0000;
        4:       bounds = 8'b0101_0100;
        5:       bounds = 8'b0101_0101;
        6:       bounds = 8'b0111_0101;
        7:       bounds = 8'b0111_1101;
        8:       bounds = 8'b0111_1111;
        default: bounds = 8'b1111_1111;
      endcase
    end
  endfunction

  localparam [7:0]   BND     = bounds(LATENCY);
  localparam integer DEPTH_O = (LATENCY > N_FULL) ? LATENCY - N_FULL + 1 : 1;

  generate
    if (LATENCY < 1) begin : g_bad_latency
      // Elaboration error on purpose: LATENCY must be at least 1.
      fp_add_error_LATENCY_must_be_at_least_1 u_error ();
    end
  endgenerate

  // ---------------------------------------------------------------------
  // in: operand registers
  // ---------------------------------------------------------------------
  wire        s0_valid;
  wire        sub_in;
  wire [31:0] a_in, b_in;
  // (HOLD: the operand registers load with valid_i only, so that the add
  // and multiply cores' registers, which have the same inputs, stay
  // apart, each beside its own core.)
  fp_pipe #(.WIDTH(65), .DEPTH(BND[B_IN] ? 1 : 0), .HOLD(1)) u_pipe_in (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({sub_i, a_i, b_i}),
    .valid_o (s0_valid),
    .data_o  ({sub_in, a_in, b_in})
  );

  // ---------------------------------------------------------------------
  // c1a: unpack, special cases, compare, exponent differences
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

  // The special case is classified here and its result built in c1b from
  // the registered fields (a NaN's payload is its significand: its
  // exponent is not 0, so FTZ leaves it): which operand's NaN is quieted
  // (c1_spa, c1_spb), the default NaN (c1_sdn), else an infinity; and the
  // result's sign.  (The 32-bit result chosen here sat behind the operand
  // register's NaN and infinity tests, which Yosys made the result
  // register's synchronous set: a critical path on the ECP5.)
  wire       c1_spec    = a_nan | b_nan | a_inf | b_inf;
  wire       c1_spa     = a_nan;
  wire       c1_spb     = ~a_nan & b_nan;
  wire       c1_sdn     = ~a_nan & ~b_nan & a_inf & b_inf & (a_sign ^ b_sign);
  wire       c1_spec_nv = a_nan ? (a_snan | b_snan) : b_nan ? b_snan : c1_sdn;
  wire       c1_ssign   = a_nan  ? a_in[31] :
                          b_nan  ? b_in[31] :
                          c1_sdn ? DEFAULT_NAN[31] :
                          a_inf  ? a_sign : b_sign;

  // Significands, exponents (1 for subnormals) and the compare.
  wire        a_norm   = (a_mag[30:23] != 8'd0);
  wire        b_norm   = (b_mag[30:23] != 8'd0);
  wire [7:0]  a_e      = {a_mag[30:24], a_mag[23] | ~a_norm};
  wire [7:0]  b_e      = {b_mag[30:24], b_mag[23] | ~b_norm};
  wire [23:0] c1_aman  = {a_norm, a_mag[22:0]};
  wire [23:0] c1_bman  = {b_norm, b_mag[22:0]};
  // For the alignment's sticky bit (c2a): each significand's lowest one.
  wire [23:0] c1_alow  = lowest_one(a_in[22:0], a_norm, (FTZ != 0) && (a_exp == 8'd0));
  wire [23:0] c1_blow  = lowest_one(b_in[22:0], b_norm, (FTZ != 0) && (b_exp == 8'd0));
  wire        c1_swap  = (b_mag > a_mag);
  wire        c1_sub   = a_sign ^ b_sign;
  // Exact zero result: +0 for opposite signs (RNE, RTZ), else that sign.
  wire        c1_zsign = c1_sub ? 1'b0 : a_sign;

  // The special case as classified (c1a), and its result (from c1b on),
  // carried to c4b.
  localparam integer WC = 1 + 1 + 1 + 1 + 1 + 1; // spec, spa, spb, sdn, sign, spec_nv
  localparam integer WS = 1 + 32 + 1;            // spec, spec_y, spec_nv

  localparam integer W1 = WC + 1 + 1 + 1 + 1 + 1 + 8 + 8 + 24 + 24 + 24 + 24;
  wire          s1_valid;
  wire [W1-1:0] s1_data;
  fp_pipe #(.WIDTH(W1), .DEPTH(BND[B_C1B] ? 1 : 0)) u_pipe1 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s0_valid),
    .data_i  ({c1_spec, c1_spa, c1_spb, c1_sdn, c1_ssign, c1_spec_nv, a_sign, b_sign, c1_swap,
               c1_sub, c1_zsign, a_e, b_e, c1_aman, c1_bman, c1_alow, c1_blow}),
    .valid_o (s1_valid),
    .data_o  (s1_data)
  );

  wire          s1_sp, s1_spa, s1_spb, s1_sdn, s1_ssign, s1_snv;
  wire          s1_asign, s1_bsign, s1_swap, s1_sub, s1_zsign;
  wire [7:0]    s1_ae, s1_be;
  wire [23:0]   s1_aman, s1_bman;
  wire [23:0]   s1_alow, s1_blow;
  assign {s1_sp, s1_spa, s1_spb, s1_sdn, s1_ssign, s1_snv, s1_asign, s1_bsign, s1_swap,
          s1_sub, s1_zsign, s1_ae,
          s1_be, s1_aman, s1_bman, s1_alow, s1_blow} = s1_data;

  // ---------------------------------------------------------------------
  // c1b: swap: x is the operand of larger magnitude, y the other one; the
  // alignment shift x_e - y_e, from both differences (each a short carry
  // chain) saturated at 31 (any shift >= 26 leaves only the sticky bit)
  // and picked by swap.
  // ---------------------------------------------------------------------
  wire [7:0]  d_ab      = s1_ae - s1_be;  // used when a_e >= b_e
  wire [7:0]  d_ba      = s1_be - s1_ae;  // used when b_e >= a_e
  wire [4:0]  sh_ab     = d_ab[4:0] | {5{|d_ab[7:5]}};
  wire [4:0]  sh_ba     = d_ba[4:0] | {5{|d_ba[7:5]}};
  // The special result: a quiet NaN with an operand's payload or the
  // default NaN's, else an infinity (IEEE 754-2008 6.2.3, 7.2).
  wire [21:0] c1b_pay   = s1_spa ? s1_aman[21:0] : s1_spb ? s1_bman[21:0] : 22'd0;
  wire        c1b_nan   = s1_spa | s1_spb | s1_sdn;
  wire [31:0] c1b_spy   = {s1_ssign, MAG_INF} | (c1b_nan ? QNAN_BIT : 32'd0) | {10'd0, c1b_pay};
  wire [WS-1:0] s1_spec = {s1_sp, c1b_spy, s1_snv};
  wire        c1b_sign  = s1_swap ? s1_bsign : s1_asign;
  wire [7:0]  c1b_exp   = s1_swap ? s1_be    : s1_ae;
  wire [23:0] c1b_xman  = s1_swap ? s1_bman  : s1_aman;
  wire [23:0] c1b_yman  = s1_swap ? s1_aman  : s1_bman;
  wire [4:0]  c1b_shift = s1_swap ? sh_ba    : sh_ab;
  wire [4:0]  c1b_ylim  = sticky_limit(s1_swap ? s1_alow : s1_blow);

  localparam integer W2 = WS + 1 + 1 + 1 + 8 + 24 + 24 + 5 + 5;
  wire          s2_valid;
  wire [W2-1:0] s2_data;
  fp_pipe #(.WIDTH(W2), .DEPTH(BND[B_C2] ? 1 : 0)) u_pipe2 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s1_valid),
    .data_i  ({s1_spec, c1b_sign, s1_sub, s1_zsign, c1b_exp, c1b_xman,
               c1b_yman, c1b_shift, c1b_ylim}),
    .valid_o (s2_valid),
    .data_o  (s2_data)
  );

  wire [WS-1:0] s2_spec;
  wire          s2_sign, s2_sub, s2_zsign;
  wire [7:0]    s2_exp;
  wire [23:0]   s2_xman, s2_yman;
  wire [4:0]    s2_shift, s2_ylim;
  assign {s2_spec, s2_sign, s2_sub, s2_zsign, s2_exp, s2_xman, s2_yman,
          s2_shift, s2_ylim} = s2_data;

  // ---------------------------------------------------------------------
  // c2a: align y to x: 26 bits (significand, guard, round) and a sticky
  // bit; for c3a, the normalisation limit: a "stopper" one at bit
  // 27 - exp of the 28-bit sum bounds the left shift so that the exponent
  // stays >= 1 (none for exp >= 28).  The sticky bit is the OR of the
  // bits {y, 00} loses, set when y's lowest one sits below the shift:
  // shift > s2_ylim (sticky_limit, from c1b), one short carry chain
  // beside the shifter instead of an OR behind each of its levels.
  // ---------------------------------------------------------------------
  wire [25:0] y_sh = {s2_yman, 2'b00} >> s2_shift;
  wire        y_st = s2_shift > s2_ylim;
  wire [26:0] c2_x       = {s2_xman, 3'b000};
  wire [26:0] c2_y       = {y_sh, y_st};
  wire [27:0] c2_stopper = 28'h800_0000 >> s2_exp;

  localparam integer W3 = WS + 1 + 1 + 1 + 8 + 28 + 27 + 27;
  wire          s3_valid;
  wire [W3-1:0] s3_data;
  fp_pipe #(.WIDTH(W3), .DEPTH(BND[B_C2B] ? 1 : 0)) u_pipe3 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s2_valid),
    .data_i  ({s2_spec, s2_sign, s2_sub, s2_zsign, s2_exp, c2_stopper,
               c2_x, c2_y}),
    .valid_o (s3_valid),
    .data_o  (s3_data)
  );

  wire [WS-1:0] s3_spec;
  wire          s3_sign, s3_sub, s3_zsign;
  wire [7:0]    s3_exp;
  wire [27:0]   s3_stopper;
  wire [26:0]   s3_x, s3_y;
  assign {s3_spec, s3_sign, s3_sub, s3_zsign, s3_exp, s3_stopper, s3_x,
          s3_y} = s3_data;

  // ---------------------------------------------------------------------
  // c2b: x + y or x - y (x >= y, so the difference is not negative), one
  // carry chain: x + (y xor sub) + sub, the carry-in entering through an
  // extra low bit.
  // ---------------------------------------------------------------------
  wire [28:0] c2b_y    = {{1'b0, s3_y} ^ {28{s3_sub}}, s3_sub};
  wire [28:0] c2b_full = {1'b0, s3_x, s3_sub} + c2b_y;
  wire [27:0] c2b_sum  = c2b_full[28:1];
  wire unused_sum0 = &{1'b0, c2b_full[0], 1'b0};
  // What c3a counts the leading zeros of: the sum with the stopper.
  wire [27:0] c2b_lzv  = c2b_sum | s3_stopper;

  localparam integer W4 = WS + 1 + 1 + 8 + 28 + 28;
  wire          s4_valid;
  wire [W4-1:0] s4_data;
  fp_pipe #(.WIDTH(W4), .DEPTH(BND[B_C3] ? 1 : 0)) u_pipe4 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s3_valid),
    .data_i  ({s3_spec, s3_sign, s3_zsign, s3_exp, c2b_lzv, c2b_sum}),
    .valid_o (s4_valid),
    .data_o  (s4_data)
  );

  wire [WS-1:0] s4_spec;
  wire          s4_sign, s4_zsign;
  wire [7:0]    s4_exp;
  wire [27:0]   s4_lzv;
  wire [27:0]   s4_sum;
  assign {s4_spec, s4_sign, s4_zsign, s4_exp, s4_lzv, s4_sum} = s4_data;

  // ---------------------------------------------------------------------
  // c3a: leading zeros of the sum (0 on a carry out: a right shift by one
  // is the same as taking bits 27:4), at most exp thanks to the stopper;
  // the sign of an exact zero.
  // ---------------------------------------------------------------------
  wire [4:0] c3_lz;
  fp_lzc #(.WIDTH(28)) u_lzc (
    .v_i (s4_lzv),
    .n_o (c3_lz)
  );
  wire c3_sign = (s4_sum == 28'd0) ? s4_zsign : s4_sign;

  localparam integer W5 = WS + 1 + 8 + 5 + 28;
  wire          s5_valid;
  wire [W5-1:0] s5_data;
  fp_pipe #(.WIDTH(W5), .DEPTH(BND[B_C3B] ? 1 : 0)) u_pipe5 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s4_valid),
    .data_i  ({s4_spec, c3_sign, s4_exp, c3_lz, s4_sum}),
    .valid_o (s5_valid),
    .data_o  (s5_data)
  );

  wire [WS-1:0] s5_spec;
  wire          s5_sign;
  wire [7:0]    s5_exp;
  wire [4:0]    s5_lz;
  wire [27:0]   s5_sum;
  assign {s5_spec, s5_sign, s5_exp, s5_lz, s5_sum} = s5_data;

  // ---------------------------------------------------------------------
  // c3b: normalise: significand bits 27:4, guard 3, round 2, sticky 1:0;
  // exponent exp + 1 - lz (>= 1; a zero sum gives a zero significand,
  // which fp_round packs as a zero whatever the exponent)
  // ---------------------------------------------------------------------
  wire [27:0] c3b_w   = s5_sum << s5_lz;
  wire [9:0]  c3b_exp = {2'd0, s5_exp} + 10'd1 - {5'd0, s5_lz};

  localparam integer W6 = WS + 1 + 10 + 24 + 3;
  wire          s6_valid;
  wire [W6-1:0] s6_data;
  fp_pipe #(.WIDTH(W6), .DEPTH(BND[B_C4] ? 1 : 0)) u_pipe6 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s5_valid),
    .data_i  ({s5_spec, s5_sign, c3b_exp, c3b_w[27:2], |c3b_w[1:0]}),
    .valid_o (s6_valid),
    .data_o  (s6_data)
  );

  wire [WS-1:0] s6_spec;
  wire          s6_sign;
  wire [9:0]    s6_exp;
  wire [23:0]   s6_man;
  wire          s6_g, s6_r, s6_s;
  assign {s6_spec, s6_sign, s6_exp, s6_man, s6_g, s6_r, s6_s} = s6_data;

  // ---------------------------------------------------------------------
  // c4a: rounding increment; c4b: overflow, flush, flags, special result
  // ---------------------------------------------------------------------
  wire [30:0] c4_pack;
  wire        c4_overflow;
  wire        c4_inexact;
  wire        c4_tiny;
  fp_round #(.ROUND(ROUND)) u_round (
    .exp_i     (s6_exp),
    .mant_i    (s6_man),
    .guard_i   (s6_g),
    .round_i   (s6_r),
    .sticky_i  (s6_s),
    .pack_o    (c4_pack),
    .overflow_o(c4_overflow),
    .inexact_o (c4_inexact),
    .tiny_o    (c4_tiny)
  );

  localparam integer W7 = WS + 1 + 31 + 1 + 1 + 1;
  wire          s7_valid;
  wire [W7-1:0] s7_data;
  fp_pipe #(.WIDTH(W7), .DEPTH(BND[B_C4B] ? 1 : 0)) u_pipe7 (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s6_valid),
    .data_i  ({s6_spec, s6_sign, c4_pack, c4_overflow, c4_inexact, c4_tiny}),
    .valid_o (s7_valid),
    .data_o  (s7_data)
  );

  wire        s7_spec;
  wire [31:0] s7_spec_y;
  wire        s7_spec_nv;
  wire        s7_sign;
  wire [30:0] s7_pack;
  wire        s7_overflow;
  wire        s7_inexact;
  wire        s7_tiny;
  assign {s7_spec, s7_spec_y, s7_spec_nv, s7_sign, s7_pack, s7_overflow, s7_inexact,
          s7_tiny} = s7_data;

  wire [31:0] c4_y;
  wire [4:0]  c4_flags;
  fp_round_pack #(.ROUND(ROUND), .FTZ(FTZ)) u_pack (
    .sign_i    (s7_sign),
    .pack_i    (s7_pack),
    .overflow_i(s7_overflow),
    .inexact_i (s7_inexact),
    .tiny_i    (s7_tiny),
    .spec_i    (s7_spec),
    .spec_y_i  (s7_spec_y),
    .spec_nv_i (s7_spec_nv),
    .y_o       (c4_y),
    .flags_o   (c4_flags)
  );

  fp_pipe #(.WIDTH(32 + 5), .DEPTH(DEPTH_O)) u_pipe_out (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s7_valid),
    .data_i  ({c4_y, c4_flags}),
    .valid_o (valid_o),
    .data_o  ({y_o, flags_o})
  );

endmodule

`default_nettype wire
