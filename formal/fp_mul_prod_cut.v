// fp_mul_prod (cut point) -- a stand-in for rtl/fp_mul_prod.v in the
// multiplier's pipeline miter (formal/fp_miter.sby, tasks mul_pipe_*):
// same module name, parameters and ports, same latency for the valid bit
// and the side band (one cycle per register place BND sets), but the
// product is cut out: the operands leave on cut_in (read by the miter),
// and top_o, sticky_o come from cut_out (driven by the miter).  The .sby
// script flattens the miter and connects both wires of each build to the
// miter's cut_* wires (yosys connect), so that formal/fp_miter.v can
//   - assert that the two builds give the product the same operands in
//     the aligned cycles (everything of fp_mul in front of the product),
//   - and give both builds' products one free value, the deep build's
//     delayed by the difference of the latencies up to the product's
//     output (everything behind it, for every product value).
// Why: rtl/fp_mul_prod.v builds the 24 x 24 product as four DSP partial
// products (LUT = 0, fp_mul LATENCY <= 9) or as an AND array and an adder
// tree (LUT = 1, LATENCY >= 10), each split by BND: a miter of two builds
// with the real modules asks the solver to show two multipliers equal,
// which none decides.  What the cut leaves to fp_mul_prod: that each of
// its structures computes the top 27 bits and the sticky bit of a_i * b_i
// in popcount(BND) cycles (simulated: tests/test_fpu.c, every latency).
// Parameters and ports: as rtl/fp_mul_prod.v; cut_in = {valid_i, a_i,
// b_i}, cut_out = {top_o, sticky_o}.
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
  (* keep *) wire [48:0] cut_in = {valid_i, a_i, b_i};
  (* keep *) wire [27:0] cut_out;
  fp_pipe #(.WIDTH(SIDE_W), .DEPTH(LAT)) u_delay (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  (side_i),
    .valid_o (valid_o),
    .data_o  (side_o)
  );
  assign {top_o, sticky_o} = cut_out;
endmodule

`default_nettype wire
