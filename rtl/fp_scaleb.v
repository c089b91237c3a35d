// fp_scaleb.v -- pipelined binary32 multiply by a power of two, a * b with
// b = +-2^k a normal number, as an exponent adjustment (IEEE 754-2019
// §5.3.3 scaleB, with b's sign): no multiplier, so the spatial back end
// (sw/compiler/spatial.h) uses it for a multiply by a constant such as
// 0.5 or 2 and saves fp_mul's MULT18X18D blocks.
//
// Result and flags equal fp_mul's (and sw/ref/fpref.h fpref_mul's) for the
// same a and b, bit for bit, in every ROUND and FTZ:
//   - a NaN: a quieted (bit 22 set, sign and payload kept); invalid if a
//     is signalling (IEEE 754-2019 §6.2, §7.2);
//   - a infinite: infinity of sign a XOR b, no flag;
//   - a zero (or, with FTZ, subnormal: read as zero, x86 DAZ, no flag):
//     zero of sign a XOR b, no flag;
//   - otherwise the exact product a * 2^k = M * 2^E (M the 24-bit
//     significand of a, normalised if a is subnormal) is
//       normal if its biased exponent is 1 to 254: exact, no flag;
//       above (§7.4 overflow): RNE infinity, RTZ the largest finite
//         number, with overflow and inexact;
//       below 1 (tiny; the exact product has at most 24 significant bits,
//         so tininess before and after rounding agree, §7.5): FTZ: zero
//         of the sign with underflow and inexact (x86 FTZ); else
//         denormalised and rounded (RNE: ties to even; RTZ: truncated),
//         which may round up to the smallest normal number, with
//         underflow and inexact if any bit was lost, no flag if none.
// b must be a normal power of two (fraction 0, exponent field 1 to 254);
// for any other b the result is not specified (the generator passes only
// such constants).
//
// Parameters:
//   LATENCY  rising edges from the operands being sampled to the result,
//            >= 1.  The register places, added in this order:
//              1: the output register;
//              2: the register between the two halves below (the
//                 exponent sum, which special case applies and the shift
//                 amounts | the shifts beside the special case's result,
//                 rounding and packing);
//              3: the operand register, in front of the first half
//                 (a and b's sign and exponent);
//              4: a register inside the second half, after the shifts
//                 (before the rounding increment and the packing);
//              >= 5: LATENCY - 4 delay stages after the output register.
//            1 and 2 suit a core beside others of a few stages; 4 is for
//            a chip's clock rate: the route from the core that computes a
//            (on a full chip often placed far away) ends at the operand
//            register, then each stage is short (side-by-side chains on
//            a's exponent and the selects after them | the masked shifts
//            | a 23-bit increment).  With the constant b of the spatial
//            back end the first half folds to a few LUT levels: a multiply
//            by 2 has no tiny path, one by 0.5 no left shift.
//   ROUND    0: round to nearest, ties to even; 1: round toward zero
//   FTZ      1: subnormal a read as zero, tiny results flushed to zero
//
// Ports (as fp_mul's):
//   clk_i    clock, rising edge
//   rst_i    synchronous reset, active high; clears the valid bits only
//   valid_i  an operation is presented this cycle
//   a_i      operand a (binary32 bit pattern)
//   b_i      b = +-2^k, k = -126 to 127 (binary32 bit pattern)
//   valid_o  a result is presented this cycle (LATENCY after valid_i)
//   y_o      result
//   flags_o  {invalid, infinite (always 0), overflow, underflow, inexact}
`default_nettype none

module fp_scaleb #(
  parameter integer LATENCY = 1, // issue to result, rising edges, >= 1
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

  localparam [4:0] FLAG_NV = 5'b10000;
  localparam [4:0] FLAG_OF = 5'b00100;
  localparam [4:0] FLAG_UF = 5'b00010;
  localparam [4:0] FLAG_NX = 5'b00001;

  generate
    if (LATENCY < 1) begin : g_bad_latency
      // Elaboration error on purpose: LATENCY must be at least 1.
      fp_scaleb_error_LATENCY_must_be_at_least_1 u_error ();
    end
  endgenerate

  // ---- first half: special cases, the exponent sum, the shift amounts ----
  // Written so that a constant b (the spatial back end's case) folds in
  // synthesis: k's sign decides which paths exist, and each shift amount
  // is masked to the bits its bound under that k needs, so a multiply by
  // 0.5 or 2 keeps a one-place shifter, not a barrel shifter.
  // Place 3 (LATENCY >= 3) is the operand register in front of this
  // half.  Everything that needs a carry chain on a's exponent is
  // computed side by side straight from the exponent field ea, with no
  // select in front: the exponent sum t, the overflow and tiny decisions
  // (t compared through its bounds moved onto ea), the tiny path's shift
  // 1 - t and its bound (for a normal and a subnormal a, selected after),
  // and the leading-zero count lz.  With the spatial back end's constant
  // b each decision is a compare of ea against a constant.
  // k = eb - 127 (-126 to 127) and a's significand m, not normalised (its
  // exponent E: ea, 1 for a subnormal a): a * 2^k = m * 2^(E + k - 150),
  // so t = E + k is the result's biased exponent while m's top bit is set.
  wire [40:0] p3_q;
  wire        p3_valid;
  // (HOLD: kept apart from the operand registers of other cores that
  // take the same a, as fp_mul's and fp_add's are; b's constant bits
  // still fold.)
  fp_pipe #(.WIDTH(41), .DEPTH(LATENCY >= 3 ? 1 : 0), .HOLD(1)) u_p3 (
    .clk_i(clk_i), .rst_i(rst_i), .valid_i(valid_i),
    .data_i({a_i, b_i[31:23]}),
    .valid_o(p3_valid), .data_o(p3_q)
  );
  wire [31:0] r_a;
  wire [8:0]  r_b;
  assign {r_a, r_b} = p3_q;
  // b's fraction is 0 by the contract: only its sign and exponent count.
  wire unused_b_fraction = &{1'b0, b_i[22:0], 1'b0};

  wire              sign  = r_a[31] ^ r_b[8];
  wire [7:0]        ea    = r_a[30:23];
  wire [22:0]       fa    = r_a[22:0];
  wire              a_sub = ea == 8'h00;
  wire [23:0]       m     = {~a_sub, fa};
  wire signed [9:0] k     = $signed({2'b00, r_b[7:0]}) - 10'sd127;
  wire              k_neg = k < 10'sd0;
  wire signed [9:0] e10   = $signed({2'b00, ea});
  wire [7:0]        t     = ea + k[7:0]; // t's low 8 bits, the normal path's field (a normal)
  wire [4:0]        lz;
  fp_lzc #(.WIDTH(24)) u_lzc (.v_i(m), .n_o(lz));
  // the paths of a finite nonzero a
  //   normal: a normal, 1 <= t <= 254: {sign, t, fa}, exact
  //   ovf:    a normal, t >= 255 (then k > 0)
  //   left:   a subnormal, k >= 0: m shifted left by d = min(lz, k) (lz
  //           its leading zeros, 1 to 23): normal with exponent
  //           1 + k - lz if the shift reached the hidden bit, else still
  //           subnormal; exact either way
  //   tiny:   t <= 0 (then k < 0): m shifted right by 1 - t, 1 to -k,
  //           rounded
  // t > 254 is E > 254 - k and t < 1 is E < 1 - k (10-bit signed, exact).
  // Both hold for ea in place of E: a subnormal a (ea = 0, E = 1) never
  // overflows (0 > 254 - k needs k > 254), and for k < 0 both 0 and 1
  // are below 1 - k, so a subnormal a is tiny exactly when k < 0.
  wire ovf  = e10 > 10'sd254 - k;
  wire tiny = k_neg && e10 < 10'sd1 - k;

  // masks: the bits a shift amount needs when it is at most k (left) or
  // at most min(-k, 26) (tiny; from 26 places on only the sticky remains)
  function [4:0] span(input [4:0] v);
    begin
      span = v >= 5'd16 ? 5'd31 : v >= 5'd8 ? 5'd15 : v >= 5'd4 ? 5'd7 : v >= 5'd2 ? 5'd3 :
             v >= 5'd1 ? 5'd1 : 5'd0;
    end
  endfunction
  // the tiny path's shift: 1 - t = (1 - k) - E, bounded by min(-k, 26)
  // (1 - t > bound is E < (1 - k) - bound)
  // (a subnormal a, E = 1: 1 - t = -k, beyond the bound iff -k > 26)
  wire signed [9:0] nk     = -k;
  wire              nk_big = nk > 10'sd26;
  wire [4:0]        sh_lim = nk_big ? 5'd26 : nk[4:0];
  // (only its low 5 bits are kept, so a 5-bit difference gives them)
  wire [4:0]        sh_w   = a_sub ? nk[4:0] : 5'd1 - k[4:0] - ea[4:0];
  wire              sh_big = a_sub ? nk_big : e10 < 10'sd1 - k - $signed({5'd0, sh_lim});
  wire [4:0]        sh     = (sh_big ? sh_lim : sh_w) & span(sh_lim);

  wire        a_max  = ea == 8'hFF;
  wire        a_zero = a_sub && (fa == 23'd0 || FTZ != 0);
  wire              left  = a_sub && !k_neg;
  wire [4:0] k_lo    = (k > 10'sd23) ? 5'd23 : k[4:0];       // k for the left shift, bounded
  wire [4:0] d       = ((lz < k_lo) ? lz : k_lo) & span(k_lo);
  wire [7:0] e_left  = k[7:0] + 8'd1 - {3'b000, lz};        // when the shift reached bit 23

  // the decided results: NaN, infinity, zero, overflow.  Only which one
  // (spec_k) crosses the register between the halves; the result and
  // flags are built after it, beside the shifts, so that the first half
  // ends at a few decision bits instead of a 32-bit multiplexer.
  localparam [1:0] SK_NAN = 2'd0, SK_INF = 2'd1, SK_ZERO = 2'd2, SK_OVF = 2'd3;
  wire       fa_zero = fa == 23'd0;
  wire       spec    = a_max || a_zero || ovf;
  wire [1:0] spec_k  = a_max ? (fa_zero ? SK_INF : SK_NAN) : (a_zero ? SK_ZERO : SK_OVF);

  // ---- the register between the halves (LATENCY >= 2) ----
  localparam integer MID_W = 1 + 2 + 1 + 1 + 2 + 8 + 24 + 5 + 8 + 5;
  wire [MID_W-1:0] mid_d = {spec, spec_k, r_a[31], sign, left, tiny, t, m, d, e_left, sh};
  wire [MID_W-1:0] mid_q;
  wire             mid_valid;
  fp_pipe #(.WIDTH(MID_W), .DEPTH(LATENCY >= 2 ? 1 : 0)) u_mid (
    .clk_i(clk_i), .rst_i(rst_i), .valid_i(p3_valid), .data_i(mid_d),
    .valid_o(mid_valid), .data_o(mid_q)
  );
  wire        q_spec, q_a_sign, q_sign, q_left, q_tiny;
  wire [1:0]  q_spec_k;
  wire [4:0]  q_d, q_sh;
  wire [7:0]  q_t, q_e_left;
  wire [23:0] q_m;
  assign {q_spec, q_spec_k, q_a_sign, q_sign, q_left, q_tiny, q_t, q_m, q_d, q_e_left, q_sh} = mid_q;

  // the decided result and flags: a NaN keeps a's sign and payload (q_m's
  // fraction, a's exponent all ones), quieted
  reg [31:0] q_spec_y;
  reg [4:0]  q_spec_f;
  always @* begin
    q_spec_y = {q_sign, 31'd0};
    q_spec_f = 5'd0;
    case (q_spec_k)
      SK_NAN: begin
        q_spec_y = {q_a_sign, 8'hFF, 1'b1, q_m[21:0]};
        q_spec_f = q_m[22] ? 5'd0 : FLAG_NV;
      end
      SK_INF:  q_spec_y = {q_sign, 8'hFF, 23'd0};
      SK_ZERO: q_spec_y = {q_sign, 31'd0};
      default: begin
        q_spec_y = ROUND != 0 ? {q_sign, 31'h7F7F_FFFF} : {q_sign, 31'h7F80_0000};
        q_spec_f = FLAG_OF | FLAG_NX;
      end
    endcase
  end

  // ---- second half: shift | round, pack ----
  // left: exact
  wire [23:0] x_mm    = q_m << q_d;
  // tiny: q_m * 2^(t - 1) units of 2^-149, i.e. q_m shifted right by sh
  wire [49:0] ext     = {q_m, 26'd0} >> q_sh;
  wire unused_ext_top = ext[49];           // 0: sh >= 1 on the tiny path
  wire        x_guard = ext[25];
  wire        x_stick = |ext[24:0];

  // ---- place 4 (LATENCY >= 4): after the shifts ----
  localparam integer P4_W = 1 + 32 + 5 + 1 + 2 + 8 + 23 + 8 + 24 + 23 + 2;
  wire [P4_W-1:0] p4_q;
  wire            p4_valid;
  fp_pipe #(.WIDTH(P4_W), .DEPTH(LATENCY >= 4 ? 1 : 0)) u_p4 (
    .clk_i(clk_i), .rst_i(rst_i), .valid_i(mid_valid),
    .data_i({q_spec, q_spec_y, q_spec_f, q_sign, q_left, q_tiny, q_t, q_m[22:0], q_e_left,
             x_mm, ext[48:26], x_guard, x_stick}),
    .valid_o(p4_valid), .data_o(p4_q)
  );
  wire        s_spec, s_sign, s_left, s_tiny, guard, stick;
  wire [31:0] s_spec_y;
  wire [4:0]  s_spec_f;
  wire [7:0]  s_t, s_e_left;
  wire [22:0] s_f, sub_q;
  wire [23:0] mm;
  assign {s_spec, s_spec_y, s_spec_f, s_sign, s_left, s_tiny, s_t, s_f, s_e_left, mm, sub_q,
          guard, stick} = p4_q;

  wire        inexact = guard | stick;
  wire        up      = ROUND == 0 && guard && (stick || sub_q[0]);
  // a carry out of the fraction makes the smallest normal number
  wire [30:0] sub_mag = {8'd0, sub_q} + {30'd0, up};

  reg [31:0] y_d;
  reg [4:0]  f_d;
  always @* begin
    if (s_spec) begin
      y_d = s_spec_y;
      f_d = s_spec_f;
    end else if (s_left) begin
      y_d = {s_sign, mm[23] ? s_e_left : 8'd0, mm[22:0]};
      f_d = 5'd0;
    end else if (!s_tiny) begin
      y_d = {s_sign, s_t, s_f};
      f_d = 5'd0;
    end else if (FTZ != 0) begin
      y_d = {s_sign, 31'd0};
      f_d = FLAG_UF | FLAG_NX;
    end else begin
      y_d = {s_sign, sub_mag};
      f_d = inexact ? (FLAG_UF | FLAG_NX) : 5'd0;
    end
  end

  // ---- the output register and any delay stages after it ----
  localparam integer PLACES = LATENCY >= 4 ? 3 : LATENCY - 1;  // places 2 .. 4 in use
  fp_pipe #(.WIDTH(37), .DEPTH(LATENCY - PLACES)) u_out (
    .clk_i(clk_i), .rst_i(rst_i), .valid_i(p4_valid), .data_i({y_d, f_d}),
    .valid_o(valid_o), .data_o({y_o, flags_o})
  );

endmodule

`default_nettype wire
