// fp_dsp_mul.v -- an unsigned W x W-bit product registered at its inputs
// and at its output (latency 2), built so that both registers are a DSP
// block's own.
//
// Parameters:
//   W   operand width, 1 to 18 (the MULT18X18D's unsigned width)
//
// Ports:
//   clk_i   clock, rising edge
//   a_i     operand a, W bits, sampled every rising edge (no enable)
//   b_i     operand b, W bits, sampled every rising edge
//   p_o     a * b, 2W bits, of the operands sampled two rising edges
//           before: a_i, b_i in cycle t give p_o in cycle t + 2
//
// No reset: the registers hold data only (the valid bits that say which
// products count travel beside them, in fabric registers, fp_pipe).
//
// Two bodies, one behaviour:
//   FP3_ECP5_DSP defined (scripts/synth.sh for the ECP5): a MULT18X18D
//     instantiated with its input registers A and B and its output
//     register on CLK0 (REG_INPUTA_CLK, REG_INPUTB_CLK, REG_OUTPUT_CLK =
//     "CLK0"; the pipeline register bypassed), unsigned (SIGNEDA =
//     SIGNEDB = 0), operands on A and B from the fabric (SOURCEA =
//     SOURCEB = 0), CE0 high, RST0 low; the block's ports and parameters
//     are those of the Lattice ECP5 sysDSP usage guide (TN1267, the
//     MULT18X18D primitive).  Yosys 0.23 maps `*` to this block without
//     its registers, so that the product's 3.93 ns inside the block (the
//     speed-6 timing of nextpnr) adds to the routing before and after it
//     in one clock cycle; with the block's registers each routing hop has
//     a cycle of its own.
//   otherwise (simulation, other FPGA flows): `*` between two registers,
//     the same latency and the same product.
// tests/test_dsp_mul.sh checks that the two agree, the first against a
// model of the block's registered mode written from TN1267.
`default_nettype none

module fp_dsp_mul #(
  parameter integer W = 12 // operand width, 1..18
) (
  input  wire           clk_i,
  input  wire [W-1:0]   a_i,
  input  wire [W-1:0]   b_i,
  output wire [2*W-1:0] p_o
);

  generate
    if ((W < 1) || (W > 18)) begin : g_bad_w
      // Elaboration error on purpose: the block multiplies 18 x 18 bits.
      fp_dsp_mul_error_W_must_be_1_to_18 u_error ();
    end
  endgenerate

`ifdef FP3_ECP5_DSP
  // Zero-extended to the block's 18 bits (W = 18 included).
  wire [17+W:0] a_x = {18'd0, a_i};
  wire [17+W:0] b_x = {18'd0, b_i};
  wire [17:0]   a   = a_x[17:0];
  wire [17:0]   b   = b_x[17:0];
  wire [35:0] p;

  MULT18X18D #(
    .REG_INPUTA_CLK   ("CLK0"),
    .REG_INPUTB_CLK   ("CLK0"),
    .REG_PIPELINE_CLK ("NONE"),
    .REG_OUTPUT_CLK   ("CLK0"),
    .GSR              ("DISABLED"),
    .RESETMODE        ("SYNC")
  ) u_mult (
    .A0 (a[0]),  .A1 (a[1]),  .A2 (a[2]),  .A3 (a[3]),  .A4 (a[4]),
    .A5 (a[5]),  .A6 (a[6]),  .A7 (a[7]),  .A8 (a[8]),  .A9 (a[9]),
    .A10(a[10]), .A11(a[11]), .A12(a[12]), .A13(a[13]), .A14(a[14]),
    .A15(a[15]), .A16(a[16]), .A17(a[17]),
    .B0 (b[0]),  .B1 (b[1]),  .B2 (b[2]),  .B3 (b[3]),  .B4 (b[4]),
    .B5 (b[5]),  .B6 (b[6]),  .B7 (b[7]),  .B8 (b[8]),  .B9 (b[9]),
    .B10(b[10]), .B11(b[11]), .B12(b[12]), .B13(b[13]), .B14(b[14]),
    .B15(b[15]), .B16(b[16]), .B17(b[17]),
    .C0 (1'b0), .C1 (1'b0), .C2 (1'b0), .C3 (1'b0), .C4 (1'b0), .C5 (1'b0),
    .C6 (1'b0), .C7 (1'b0), .C8 (1'b0), .C9 (1'b0), .C10(1'b0), .C11(1'b0),
    .C12(1'b0), .C13(1'b0), .C14(1'b0), .C15(1'b0), .C16(1'b0), .C17(1'b0),
    .SIGNEDA (1'b0), .SIGNEDB (1'b0), .SOURCEA (1'b0), .SOURCEB (1'b0),
    .CLK0 (clk_i), .CLK1 (1'b0), .CLK2 (1'b0), .CLK3 (1'b0),
    .CE0  (1'b1),  .CE1  (1'b0), .CE2  (1'b0), .CE3  (1'b0),
    .RST0 (1'b0),  .RST1 (1'b0), .RST2 (1'b0), .RST3 (1'b0),
    .P0 (p[0]),  .P1 (p[1]),  .P2 (p[2]),  .P3 (p[3]),  .P4 (p[4]),
    .P5 (p[5]),  .P6 (p[6]),  .P7 (p[7]),  .P8 (p[8]),  .P9 (p[9]),
    .P10(p[10]), .P11(p[11]), .P12(p[12]), .P13(p[13]), .P14(p[14]),
    .P15(p[15]), .P16(p[16]), .P17(p[17]), .P18(p[18]), .P19(p[19]),
    .P20(p[20]), .P21(p[21]), .P22(p[22]), .P23(p[23]), .P24(p[24]),
    .P25(p[25]), .P26(p[26]), .P27(p[27]), .P28(p[28]), .P29(p[29]),
    .P30(p[30]), .P31(p[31]), .P32(p[32]), .P33(p[33]), .P34(p[34]),
    .P35(p[35])
  );

  assign p_o = p[2*W-1:0];
  // The product of two W-bit numbers has 2W bits: the block's upper ones
  // are zero.
  wire unused_p = &{1'b0, p, a_x, b_x};
`else
  reg [W-1:0]   a_q, b_q;
  reg [2*W-1:0] p_q;
  always @(posedge clk_i) begin
    a_q <= a_i;
    b_q <= b_i;
    p_q <= a_q * b_q;
  end
  assign p_o = p_q;
`endif

endmodule

`default_nettype wire
