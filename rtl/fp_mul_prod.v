// fp_mul_prod.v -- the 24 x 24-bit significand product of fp_mul, pipelined:
// the top 27 of its 48 bits and the OR of the 21 below (sticky), in one of
// two structures, with a side-band word carried along the same registers.
//
// Parameters:
//   LUT     0: partial products in DSP blocks (`*` where the flow maps
//              them; BLOCKS says which) summed in two steps: m2a
//              products, m2b the two middle ones summed, m2c the 48-bit
//              sum
//           1: no multiplier: an AND array and a tree of carry-chain
//              adders (m2a rows a * b[2j] + 2 a * b[2j+1], 12 of 26 bits;
//              m2b pairs of those, 6 of 28 bits; m2c pairs again, 3 of 32
//              bits; m2d the last three summed through one carry-save
//              level (3:2 compressor) and one 40-bit adder); the sticky
//              bit from the lowest ones of a and b (m2a finds them with
//              the carry chain and pairs them, m2b ORs), beside the adders
//   BND     register places (bit k set: a register): bit 0 after m2a,
//           bit 1 after m2b, bit 2 after m2c (LUT = 1 only)
//   PRE     0: a_i and b_i come with valid_i and side_i
//           1 (LUT = 0 and BND bit 0 set): a_i and b_i come one cycle
//              ahead of valid_i and side_i, and the partial products are
//              fp_dsp_mul blocks registered at their inputs and outputs:
//              the input registers stand for the register that the
//              caller would put in front of this module, the output
//              registers for BND bit 0.  On the ECP5 both are the
//              MULT18X18D's own, so that no routing hop shares a cycle
//              with the block's 3.93 ns.
//   BLOCKS  (LUT = 0) the DSP blocks per product, with the operands cut
//           at bit H (a = aH * 2^H + aL, b likewise):
//           4: H = 12, four 12 x 12-bit products aH bH, aH bL, aL bH,
//              aL bL, one MULT18X18D each
//           3: H = 6, three in MULT18X18D (aH bH 18 x 18, aH bL and
//              aL bH 18 x 6) and aL bL (6 x 6) in the fabric: m2a sums
//              its rows in pairs (3 of 8 bits, an AND level and one carry
//              chain), m2b sums the pairs (two carry chains of 12 bits,
//              beside the middle sum).  The sticky bit comes from the
//              operands' trailing zeros (sticky_terms: m2a the terms,
//              m2b their OR), beside the products, so that m2c's 42-bit
//              sum ends at the top bits only (the OR of its low bits
//              after the carry chain was a placed chip's worst path).  It
//              frees a quarter of the multiplier blocks for 150 to 172
//              LUT4s and, at fp_mul latency 9 (10 with FEED), 51
//              flip-flops (alone, scripts/spatial-core-area.sh), for
//              chips whose multiplier blocks run out first
//              (docs/spatial.md)
//   SIDE_W  bits of the side-band word (>= 1)
//
// Ports:
//   clk_i     clock, rising edge
//   rst_i     synchronous reset, active high; clears the valid bits only
//   valid_i   valid bit entering with the operands
//   a_i, b_i  the significands (any 24-bit values); with PRE = 1 one
//             cycle before the valid_i and side_i that they belong to
//   side_i    side-band word, delayed like the product
//   valid_o   valid_i delayed
//   top_o     bits 47:21 of a_i * b_i
//   sticky_o  OR of bits 20:0 of a_i * b_i
//   side_o    side_i delayed
//
// Timing: combinational from the inputs to the outputs apart from the
// registers BND asks for: latency = number of bits set in BND (from
// valid_i and side_i; from a_i and b_i one more with PRE = 1).
//
// Why two structures, and PRE: Yosys 0.23 maps `*` for the ECP5 to a
// MULT18X18D without its internal registers, 3.93 ns from A/B to P in
// nextpnr's speed-6 model; with clock-to-out and the two routing hops to
// and from the block, a lone registered 12 x 12 multiply places at
// 141-148 MHz (LFE5U-85F-6, 6 seeds), fp_mul with it at 133-140 MHz.
// With PRE = 1 the blocks' own registers take the routing hops apart
// (fp_dsp_mul): fp_mul at latency 9 places at 162.3 MHz (seed 1; its
// critical path is then the operands' unpacking, not the product).  The
// LUT structure puts one carry chain in each stage (the AND gates in
// front of the first: a LUT level); with every register place it takes
// 654 LUT4s, 318 CCU2C carry cells and 591 flip-flops on the ECP5 (Yosys
// 0.23), against 7, 31, 162 and four DSP blocks.
//
// The carry-save level (LUT = 1, m2d): three addends x, y, z give
// s = x ^ y ^ z and c = majority(x, y, z) with x + y + z = s + 2c (the
// standard 3:2 compressor), so the three partial sums need one adder.
`default_nettype none

module fp_mul_prod #(
  parameter integer   LUT    = 0,      // 0: DSP partial products, 1: LUT tree
  parameter [2:0]     BND    = 3'b000, // register after m2a, m2b, m2c
  parameter integer   PRE    = 0,      // 1: operands a cycle early, DSP registers
  parameter integer   BLOCKS = 4,      // DSP blocks per product, 4 or 3 (LUT = 0)
  parameter integer   SIDE_W = 1       // side-band bits
) (
  input  wire              clk_i,
  input  wire              rst_i,
  input  wire              valid_i,
  input  wire [23:0]       a_i,
  input  wire [23:0]       b_i,
  input  wire [SIDE_W-1:0] side_i,
  output wire              valid_o,
  output wire [26:0]       top_o,
  output wire              sticky_o,
  output wire [SIDE_W-1:0] side_o
);

  // BLOCKS = 3: the 6 x 6-bit product a b as its row pairs,
  // {r2, r1, r0} with rk = a b[2k] + 2 a b[2k+1] (8 bits), so that
  // a b = r0 + 4 r1 + 16 r2 (written with AND and +: no `*` for the flow
  // to map to a DSP block).
  function [23:0] ll_rows(input [5:0] a, input [5:0] b);
    integer k;
    begin
      ll_rows = 24'd0;
      for (k = 0; k < 3; k = k + 1)
        ll_rows[8 * k +: 8] = {2'd0, a & {6{b[2 * k]}}} + {1'b0, a & {6{b[2 * k + 1]}}, 1'b0};
    end
  endfunction

  // The sticky bit's terms: a product's trailing zeros are those of a and
  // b together (the product of two odd numbers is odd; a zero factor gives
  // a zero product), so its low 21 bits hold a one exactly when a's
  // lowest one (bit i) and b's (bit j) have i + j <= 20.  With the carry
  // chain: a & ~(a - 1) is a's lowest one alone, ~b & (b - 1) the bits
  // below b's lowest one (all of them for b = 0), and term i holds when
  // a's lowest one is bit i and b has a one at or below bit 20 - i.  Only
  // bits 20:0 of a and b count (bit i of a - 1 depends on bits i:0).
  // The sticky bit is the OR of the 21 terms.
  function [20:0] sticky_terms(input [20:0] a, input [20:0] b);
    reg [20:0] a_low, b_below;
    integer i;
    begin
      a_low   = a & ~(a - 21'd1);
      b_below = ~b & (b - 21'd1);
      for (i = 0; i < 21; i = i + 1)
        sticky_terms[i] = a_low[i] & ~b_below[20 - i];
    end
  endfunction

  generate
    if ((LUT == 0) && BND[2]) begin : g_bad_bnd
      // Elaboration error on purpose: the DSP structure has no m2d.
      fp_mul_prod_error_BND2_needs_LUT u_error ();
    end
    if ((PRE != 0) && ((LUT != 0) || !BND[0])) begin : g_bad_pre
      // Elaboration error on purpose: the registered blocks are the DSP
      // structure's m2a with the register after it.
      fp_mul_prod_error_PRE_needs_LUT0_and_BND0 u_error ();
    end
    if ((BLOCKS != 3) && (BLOCKS != 4)) begin : g_bad_blocks
      // Elaboration error on purpose: the product is cut for 4 or 3 blocks.
      fp_mul_prod_error_BLOCKS_must_be_3_or_4 u_error ();
    end

    if (LUT == 0) begin : g_dsp
      // -----------------------------------------------------------------
      // m2a: partial products of the operands cut at bit H: hh = aH bH
      // (2 (24 - H) bits), lh = aL bH and hl = aH bL (24 bits), and the
      // low product aL bL as llp: BLOCKS = 4 the product itself (24 bits),
      // BLOCKS = 3 its three row pairs (8 bits each), summed in m2b
      // -----------------------------------------------------------------
      localparam integer H  = (BLOCKS == 3) ? 6 : 12;
      localparam integer WH = 2 * (24 - H);
      wire [SIDE_W-1:0] sa;
      wire [WH-1:0]     hh;
      wire [23:0]       lh, hl, llp;
      wire              va;
      // BLOCKS = 3: the sticky bit's terms (sticky_terms) from the
      // operands, beside the products (with the blocks' input registers,
      // on PRE's registered copies), ORed in m2b; the sticky bit then
      // does not wait for m2c's 42-bit sum.  BLOCKS = 4: unused.
      wire [20:0]       stt;
      if (PRE != 0) begin : g_pre
        // The products in registered blocks (latency 2 from a_i, b_i;
        // 1 from valid_i, side_i), the side band in one fabric register.
        if (BLOCKS == 4) begin : g_b4
          fp_dsp_mul #(.W(12)) u_ll (.clk_i(clk_i), .a_i(a_i[11:0]),  .b_i(b_i[11:0]),  .p_o(llp));
          fp_dsp_mul #(.W(12)) u_lh (.clk_i(clk_i), .a_i(a_i[11:0]),  .b_i(b_i[23:12]), .p_o(lh));
          fp_dsp_mul #(.W(12)) u_hl (.clk_i(clk_i), .a_i(a_i[23:12]), .b_i(b_i[11:0]),  .p_o(hl));
          fp_dsp_mul #(.W(12)) u_hh (.clk_i(clk_i), .a_i(a_i[23:12]), .b_i(b_i[23:12]), .p_o(hh));
          assign stt = 21'd0;
        end else begin : g_b3
          // 18 x 6 in an 18 x 18 block: the 6-bit operand zero-extended,
          // the product's top 12 bits zero.
          wire [35:0] lh36, hl36;
          fp_dsp_mul #(.W(18)) u_lh (.clk_i(clk_i), .a_i({12'd0, a_i[5:0]}), .b_i(b_i[23:6]),
                                     .p_o(lh36));
          fp_dsp_mul #(.W(18)) u_hl (.clk_i(clk_i), .a_i(a_i[23:6]), .b_i({12'd0, b_i[5:0]}),
                                     .p_o(hl36));
          fp_dsp_mul #(.W(18)) u_hh (.clk_i(clk_i), .a_i(a_i[23:6]), .b_i(b_i[23:6]), .p_o(hh));
          assign lh = lh36[23:0];
          assign hl = hl36[23:0];
          wire unused_hi = &{1'b0, lh36[35:24], hl36[35:24]};
          // aL bL and the sticky bit's terms in the fabric with the
          // blocks' two registers: the operands, then the row pairs and
          // the terms (no reset: data only).
          reg [20:0] cp_a, cp_b;
          reg [23:0] ll_r;
          reg [20:0] st_r;
          always @(posedge clk_i) begin
            cp_a <= a_i[20:0];
            cp_b <= b_i[20:0];
            ll_r <= ll_rows(cp_a[5:0], cp_b[5:0]);
            st_r <= sticky_terms(cp_a, cp_b);
          end
          assign llp = ll_r;
          assign stt = st_r;
        end
        fp_pipe #(.WIDTH(SIDE_W), .DEPTH(1)) u_pipe_a (
          .clk_i   (clk_i),
          .rst_i   (rst_i),
          .valid_i (valid_i),
          .data_i  (side_i),
          .valid_o (va),
          .data_o  (sa)
        );
      end else begin : g_comb
        wire [WH-1:0] c_hh = a_i[23:H] * b_i[23:H];
        wire [23:0]   c_lh = a_i[H-1:0] * b_i[23:H];
        wire [23:0]   c_hl = a_i[23:H] * b_i[H-1:0];
        wire [23:0]   c_llp;
        wire [20:0]   c_stt;
        if (BLOCKS == 4) begin : g_b4
          assign c_llp = a_i[11:0] * b_i[11:0];
          assign c_stt = 21'd0;
        end else begin : g_b3
          assign c_llp = ll_rows(a_i[5:0], b_i[5:0]);
          assign c_stt = sticky_terms(a_i[20:0], b_i[20:0]);
        end

        localparam integer WA = SIDE_W + 21 + WH + 3 * 24;
        fp_pipe #(.WIDTH(WA), .DEPTH(BND[0] ? 1 : 0)) u_pipe_a (
          .clk_i   (clk_i),
          .rst_i   (rst_i),
          .valid_i (valid_i),
          .data_i  ({side_i, c_stt, c_llp, c_lh, c_hl, c_hh}),
          .valid_o (va),
          .data_o  ({sa, stt, llp, lh, hl, hh})
        );
      end

      // -----------------------------------------------------------------
      // m2b: the two middle partial products summed; aL bL (2H bits)
      // whole (BLOCKS = 3: from its row pairs); lo: BLOCKS = 4 the OR of
      // aL bL's low 12 bits (the sticky bit's part below m2c's sum),
      // BLOCKS = 3 the sticky bit itself, the OR of its terms
      // -----------------------------------------------------------------
      wire [24:0]    c_mid = {1'b0, lh} + {1'b0, hl};
      wire [2*H-1:0] c_ll;
      wire           c_lo;
      if (BLOCKS == 4) begin : g_ll4
        assign c_ll = llp;
        assign c_lo = |c_ll[11:0];
        wire unused_stt = &{1'b0, stt, 1'b0};
      end else begin : g_ll3
        // aL bL = r0 + 4 r1 + 16 r2 (< 2^12); its low H bits count only
        // in the sticky bit, which the terms give
        wire [11:0] r01 = {4'd0, llp[7:0]} + {2'd0, llp[15:8], 2'd0};
        assign c_ll = r01 + {llp[23:16], 4'd0};
        assign c_lo = |stt;
        wire unused_ll_lo = &{1'b0, c_ll[H-1:0], 1'b0};
      end

      localparam integer WB = SIDE_W + WH + H + 25 + 1;
      wire          vb;
      wire [WB-1:0] db;
      fp_pipe #(.WIDTH(WB), .DEPTH(BND[1] ? 1 : 0)) u_pipe_b (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (va),
        .data_i  ({sa, hh, c_ll[2*H-1:H], c_mid, c_lo}),
        .valid_o (vb),
        .data_o  (db)
      );

      wire [SIDE_W-1:0] sb;
      wire [WH-1:0]     hh_b;
      wire [H-1:0]      ll_hi;
      wire [24:0]       mid;
      wire              lo;
      assign {sb, hh_b, ll_hi, mid, lo} = db;

      // -----------------------------------------------------------------
      // m2c: prod = hh * 2^(2H) + mid * 2^H + ll; bits 47:H by one adder
      // (BLOCKS = 3: only its top 27 bits are used)
      // -----------------------------------------------------------------
      wire [47-H:0] c_hi = {hh_b, ll_hi} + {{(23-H){1'b0}}, mid};
      wire          hi_st = |c_hi[20-H:0];
      assign valid_o  = vb;
      assign top_o    = c_hi[47-H:21-H];
      assign sticky_o = (BLOCKS == 3) ? lo : (lo | hi_st);
      assign side_o   = sb;
    end else begin : g_lut
      // -----------------------------------------------------------------
      // m2a: row pairs, r1[26j +: 26] = a * b[2j] + 2 * a * b[2j+1]
      // (the sum of rows 2j and 2j+1, weight 2^(2j)); the sticky bit's
      // terms (below)
      // -----------------------------------------------------------------
      wire [12*26-1:0] c_r1;
      genvar j;
      for (j = 0; j < 12; j = j + 1) begin : g_r1
        wire [23:0] x = a_i & {24{b_i[2 * j]}};
        wire [23:0] y = a_i & {24{b_i[2 * j + 1]}};
        wire [24:0] s = {1'b0, y} + {2'b0, x[23:1]};
        assign c_r1[26 * j +: 26] = {s, x[0]};
      end

      // The sticky bit's terms (sticky_terms), registered here and ORed
      // in m2b.
      wire [20:0] c_stt = sticky_terms(a_i[20:0], b_i[20:0]);

      localparam integer WA = SIDE_W + 21 + 12 * 26;
      wire          va;
      wire [WA-1:0] da;
      fp_pipe #(.WIDTH(WA), .DEPTH(BND[0] ? 1 : 0)) u_pipe_a (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (valid_i),
        .data_i  ({side_i, c_stt, c_r1}),
        .valid_o (va),
        .data_o  (da)
      );

      wire [SIDE_W-1:0] sa;
      wire [20:0]       stt;
      wire [12*26-1:0]  r1;
      assign {sa, stt, r1} = da;

      // -----------------------------------------------------------------
      // m2b: r2[j] = r1[2j] + 4 * r1[2j+1] (rows 4j to 4j+3, < 2^28);
      // the sticky bit, the OR of m2a's terms
      // -----------------------------------------------------------------
      wire       c_st = |stt;
      wire [6*28-1:0] c_r2;
      for (j = 0; j < 6; j = j + 1) begin : g_r2
        wire [25:0] x = r1[26 * (2 * j) +: 26];
        wire [25:0] y = r1[26 * (2 * j + 1) +: 26];
        wire [25:0] s = y + {2'b0, x[25:2]};
        assign c_r2[28 * j +: 28] = {s, x[1:0]};
      end

      localparam integer WB = SIDE_W + 1 + 6 * 28;
      wire          vb;
      wire [WB-1:0] db;
      fp_pipe #(.WIDTH(WB), .DEPTH(BND[1] ? 1 : 0)) u_pipe_b (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (va),
        .data_i  ({sa, c_st, c_r2}),
        .valid_o (vb),
        .data_o  (db)
      );

      wire [SIDE_W-1:0] sb;
      wire              st_b;
      wire [6*28-1:0]   r2;
      assign {sb, st_b, r2} = db;

      // -----------------------------------------------------------------
      // m2c: r3[j] = r2[2j] + 16 * r2[2j+1] (rows 8j to 8j+7, < 2^32)
      // -----------------------------------------------------------------
      wire [3*32-1:0] c_r3;
      for (j = 0; j < 3; j = j + 1) begin : g_r3
        wire [27:0] x = r2[28 * (2 * j) +: 28];
        wire [27:0] y = r2[28 * (2 * j + 1) +: 28];
        wire [27:0] s = y + {4'b0, x[27:4]};
        assign c_r3[32 * j +: 32] = {s, x[3:0]};
      end

      localparam integer WC = SIDE_W + 1 + 3 * 32;
      wire          vc;
      wire [WC-1:0] dc;
      fp_pipe #(.WIDTH(WC), .DEPTH(BND[2] ? 1 : 0)) u_pipe_c (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (vb),
        .data_i  ({sb, st_b, c_r3}),
        .valid_o (vc),
        .data_o  (dc)
      );

      wire [SIDE_W-1:0] sc;
      wire              st_c;
      wire [31:0]       x3, y3, z3; // weights 2^0, 2^8, 2^16
      assign {sc, st_c, z3, y3, x3} = dc;

      // -----------------------------------------------------------------
      // m2d: prod = x3 + y3 * 2^8 + z3 * 2^16.  Columns 16-47 hold all
      // three (x3[31:16], y3[31:8], z3): carry-save them; then bits 47:8
      // by one adder, with columns 8-15 (x3[15:8], y3[7:0]) beneath.
      // Bits 7:0 (x3[7:0]) and 20:8 are only needed for the sticky bit,
      // which is known already.  A carry out of column 47 cannot occur
      // (the product is below 2^48), so the carries stop at column 47.
      // -----------------------------------------------------------------
      wire [31:0] xh = {16'd0, x3[31:16]};
      wire [31:0] yh = {8'd0, y3[31:8]};
      wire [31:0] cs_s = xh ^ yh ^ z3;                                // columns 16-47
      wire [30:0] cs_c = (xh[30:0] & yh[30:0]) | (xh[30:0] & z3[30:0])
                       | (yh[30:0] & z3[30:0]);                       // columns 17-47
      wire [39:0] p_hi = {cs_s, x3[15:8]} + {cs_c, 1'b0, y3[7:0]};   // prod[47:8]

      wire unused_lo = &{1'b0, x3[7:0], p_hi[12:0], 1'b0};

      assign valid_o  = vc;
      assign top_o    = p_hi[39:13];
      assign sticky_o = st_c;
      assign side_o   = sc;
    end
  endgenerate

endmodule

`default_nettype wire
