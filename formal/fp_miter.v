// fp_miter -- miter of two builds of one binary32 core (formal only): the
// shortest latency (LAT_S, every register place empty) and a deeper one
// (LAT_D; the deepest build, every place registered, is fp_add 9, fp_mul
// 11, fp_div 34 and fp_sqrt 32), fed the same operands every cycle.  The short build's
// outputs are delayed by LAT_D - LAT_S cycles and compared with the deep
// build's:
//   M1  valid_o agree in every cycle after reset;
//   M2  when valid, the results y_o and the flags flags_o agree bit for bit.
// So every latency option computes what the TestFloat vectors checked on
// the default build (tests/test_fpu.c), for every operand pair: both
// pipelines are feed-forward, so k-induction of depth LAT_D + 1 closes.
// Covers: a valid result, an inexact result, an invalid operation, and
// (FTZ = 0) a subnormal result, so the compare is not vacuous.
//
// Parameters
//   CORE     0 fp_add (valid_i with sub_i), 1 fp_mul, 2 fp_div, 3 fp_sqrt
//            (b_i unused)
//   LAT_S    the short build's LATENCY (1)
//   LAT_D    the deep build's LATENCY (> LAT_S)
//   ROUND    0 RNE, 1 RTZ;  FTZ 0 IEEE subnormals, 1 flush (DAZ + FTZ)
//   CUT      1 (CORE = 1): the product cut out of both builds (below)
//   CUT_FRONT, CUT_PROD  with CUT: how many more registers the deep build
//            has than the short one in front of the product and inside it
//
// The product cut (CUT = 1): the .sby script makes the outputs of both
// builds' fp_mul_prod (top_o, sticky_o) free values (yosys cutpoint) and
// connects its operands and outputs to g_cut's wires.  Asserted besides
// M1, M2:
//   M0  the product's operands agree: the short build's valid bit and
//       significands, CUT_FRONT cycles later, equal the deep build's;
// assumed: the deep build's product equals the short build's
// CUT_FRONT + CUT_PROD cycles earlier.  So M1, M2 hold for every value
// the product may have (what is behind it), and M0 checks what is in
// front of it; what is left is that fp_mul_prod computes the product
// (a multiplier equivalence).
`default_nettype none
module fp_miter #(
  parameter integer CORE  = 0,
  parameter integer LAT_S = 1,
  parameter integer LAT_D = 9,
  parameter integer ROUND = 0,
  parameter integer FTZ   = 0,
  parameter integer CUT       = 0,
  parameter integer CUT_FRONT = 0,
  parameter integer CUT_PROD  = 0
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        valid_i,
  input  wire        sub_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i
);
  initial assume (rst_i);
  localparam integer GAP = LAT_D - LAT_S;

  wire        vs, vd;
  wire [31:0] ys, yd;
  wire [4:0]  fs, fd;
  generate
    if (CORE == 0) begin : g_add
      fp_add #(.LATENCY(LAT_S), .ROUND(ROUND), .FTZ(FTZ)) u_s (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (valid_i), .sub_i (sub_i),
        .a_i (a_i), .b_i (b_i), .valid_o (vs), .y_o (ys), .flags_o (fs));
      fp_add #(.LATENCY(LAT_D), .ROUND(ROUND), .FTZ(FTZ)) u_d (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (valid_i), .sub_i (sub_i),
        .a_i (a_i), .b_i (b_i), .valid_o (vd), .y_o (yd), .flags_o (fd));
    end else if (CORE == 1) begin : g_mul
      fp_mul #(.LATENCY(LAT_S), .ROUND(ROUND), .FTZ(FTZ)) u_s (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (valid_i),
        .a_i (a_i), .b_i (b_i), .valid_o (vs), .y_o (ys), .flags_o (fs));
      fp_mul #(.LATENCY(LAT_D), .ROUND(ROUND), .FTZ(FTZ)) u_d (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (valid_i),
        .a_i (a_i), .b_i (b_i), .valid_o (vd), .y_o (yd), .flags_o (fd));
      wire unused_sub = sub_i;
    end else if (CORE == 2) begin : g_div
      fp_div #(.LATENCY(LAT_S), .ROUND(ROUND), .FTZ(FTZ)) u_s (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (valid_i),
        .a_i (a_i), .b_i (b_i), .valid_o (vs), .y_o (ys), .flags_o (fs));
      fp_div #(.LATENCY(LAT_D), .ROUND(ROUND), .FTZ(FTZ)) u_d (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (valid_i),
        .a_i (a_i), .b_i (b_i), .valid_o (vd), .y_o (yd), .flags_o (fd));
      wire unused_sub = sub_i;
    end else begin : g_sqrt
      fp_sqrt #(.LATENCY(LAT_S), .ROUND(ROUND), .FTZ(FTZ)) u_s (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (valid_i),
        .a_i (a_i), .valid_o (vs), .y_o (ys), .flags_o (fs));
      fp_sqrt #(.LATENCY(LAT_D), .ROUND(ROUND), .FTZ(FTZ)) u_d (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (valid_i),
        .a_i (a_i), .valid_o (vd), .y_o (yd), .flags_o (fd));
      wire unused_ops = &{1'b0, sub_i, b_i};
    end
  endgenerate

  // The short build's outputs, GAP cycles later (valid cleared by reset,
  // as the cores clear theirs).
  reg [GAP-1:0] vq;
  reg [31:0]    yq [0:GAP-1];
  reg [4:0]     fq [0:GAP-1];
  integer k;
  always @(posedge clk_i) begin
    vq <= rst_i ? {GAP{1'b0}} : {vq, vs} & {GAP{1'b1}};
    yq[0] <= ys;
    fq[0] <= fs;
    for (k = 1; k < GAP; k = k + 1) begin
      yq[k] <= yq[k-1];
      fq[k] <= fq[k-1];
    end
  end
  wire        v_ref = vq[GAP-1];
  wire [31:0] y_ref = yq[GAP-1];
  wire [4:0]  f_ref = fq[GAP-1];

  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;

  generate
    if (CUT != 0) begin : g_cut
      // (connected by the .sby script to each build's fp_mul_prod, whose
      // outputs top_o, sticky_o it cuts: free values)
      (* keep *) wire [48:0] cut_in_s, cut_in_d;     // {valid_i, a_i, b_i} of each product
      (* keep *) wire [27:0] cut_out_s, cut_out_d;   // {top_o, sticky_o} of each product
      wire        fv;
      wire [47:0] fab;
      fp_pipe #(.WIDTH(48), .DEPTH(CUT_FRONT)) u_front (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (cut_in_s[48]), .data_i (cut_in_s[47:0]),
        .valid_o (fv), .data_o (fab));
      wire        pv_unused;
      wire [27:0] prod_s;   // the short build's product, as late as the deep build's
      fp_pipe #(.WIDTH(28), .DEPTH(CUT_FRONT + CUT_PROD)) u_prod (
        .clk_i (clk_i), .rst_i (rst_i), .valid_i (1'b0), .data_i (cut_out_s),
        .valid_o (pv_unused), .data_o (prod_s));
      always @(*) begin
        assume (cut_out_d == prod_s);
        if (f_past_valid && !rst_i) begin
          m0_prod_valid_agree: assert (cut_in_d[48] == fv);
          if (fv) m0_prod_operands_agree: assert (cut_in_d[47:0] == fab);
        end
      end
    end
  endgenerate
  always @(*) if (f_past_valid && !rst_i) begin
    m1_valid_agree: assert (vd == v_ref);
    if (vd) begin
      m2_result_agree: assert (yd == y_ref);
      m2_flags_agree:  assert (fd == f_ref);
    end
  end
  always @(*) if (f_past_valid && !rst_i) begin
    c_valid:     cover (vd);
    c_inexact:   cover (vd && fd[0]);
    c_invalid:   cover (vd && fd[4]);
    if (FTZ == 0) c_subnormal: cover (vd && yd[30:23] == 8'd0 && yd[22:0] != 23'd0);
  end
endmodule
`default_nettype wire
