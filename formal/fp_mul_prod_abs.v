// fp_mul_prod (abstract) -- a stand-in for rtl/fp_mul_prod.v in the
// multiplier's pipeline miter (formal/fp_miter.sby, task mul_pipe): same
// module name, parameters and ports, same latency (one cycle per bit set
// in BND), but the product computed in one place, after the registers:
// top_o = bits 47:21 of a_i * b_i, sticky_o = the OR of bits 20:0.
//
// Why: rtl/fp_mul_prod.v builds the 24 x 24 product as four DSP partial
// products (LUT = 0, fp_mul LATENCY <= 9) or as an AND array and an adder
// tree (LUT = 1, LATENCY >= 10), each split by the register places BND
// picks.  A miter of two fp_mul builds with the real modules asks the
// solver to show two multiplier structures equal, which none decides.
// With this stand-in in both builds the product is the same expression of
// the same operands, so the miter proves everything of fp_mul but the
// product: the unpacking, the normalisation, the exponent, the special
// cases, the side band carried beside the product, rounding and the
// flags, and that the registers of every place carry exactly the
// combinational values.  What it assumes: each structure of fp_mul_prod
// computes a_i * b_i's top 27 bits and sticky bit, in popcount(BND)
// cycles (tests/test_fpu.c: 10^6 random operations and the TestFloat
// vectors on every latency; the miters mul_dsp_* and mul_lut_* prove the
// real modules within each structure).
// Parameters and ports: as rtl/fp_mul_prod.v.
`default_nettype none

module fp_mul_prod #(
  parameter integer   LUT    = 0,
  parameter [2:0]     BND    = 3'b000,
  parameter integer   SIDE_W = 1
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
  // the DSP structure has no third place (rtl/fp_mul_prod.v refuses it)
  localparam integer LAT = BND[0] + BND[1] + (LUT != 0 ? BND[2] : 1'b0);
  wire [23:0] a, b;
  fp_pipe #(.WIDTH(SIDE_W + 48), .DEPTH(LAT)) u_delay (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({side_i, a_i, b_i}),
    .valid_o (valid_o),
    .data_o  ({side_o, a, b})
  );
  wire [47:0] p = {24'd0, a} * {24'd0, b};
  assign top_o    = p[47:21];
  assign sticky_o = |p[20:0];
endmodule

`default_nettype wire
