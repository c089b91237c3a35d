// fpu_top.v -- Verilator test top: one fp_add, fp_mul, fp_div, fp_sqrt
// and fp_sign (latency 1, the move path's) side by side, driven from C through sim/fpu_shim.cpp (sim/fpu_model.h).
//
// Parameters (passed through to the cores):
//   ADD_LATENCY  fp_add LATENCY (issue to result, rising edges)
//   MUL_LATENCY  fp_mul LATENCY
//   MUL_FEED     fp_mul FEED (1: the fabric register in front of its DSP blocks)
//   MUL_BLOCKS   fp_mul MULT_BLOCKS (4 or 3: its product's DSP blocks)
//   DIV_LATENCY  fp_div and fp_sqrt LATENCY (the processor's div/sqrt
//                unit: both on one write-back port, one latency)
//   ROUND        0 RNE, 1 RTZ (every core)
//   FTZ          1: flush-to-zero / denormals-are-zero (every core)
//
// Ports: clk_i, rst_i, then each core's ports with prefix add_, mul_,
// div_, sqrt_ and sign_ (see rtl/fp_add.v, rtl/fp_mul.v, rtl/fp_div.v,
// rtl/fp_sqrt.v, rtl/fp_sign.v for the timing contract).
`default_nettype none

module fpu_top #(
  parameter integer ADD_LATENCY = 4, // fp_add LATENCY
  parameter integer MUL_LATENCY = 3, // fp_mul LATENCY
  parameter integer MUL_FEED    = 0, // fp_mul FEED
  parameter integer MUL_BLOCKS  = 4, // fp_mul MULT_BLOCKS
  parameter integer DIV_LATENCY = 8, // fp_div, fp_sqrt LATENCY
  parameter integer ROUND       = 0, // 0 RNE, 1 RTZ
  parameter integer FTZ         = 0  // 1: FTZ/DAZ
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        add_valid_i,
  input  wire        add_sub_i,
  input  wire [31:0] add_a_i,
  input  wire [31:0] add_b_i,
  output wire        add_valid_o,
  output wire [31:0] add_y_o,
  output wire [4:0]  add_flags_o,
  input  wire        mul_valid_i,
  input  wire [31:0] mul_a_i,
  input  wire [31:0] mul_b_i,
  output wire        mul_valid_o,
  output wire [31:0] mul_y_o,
  output wire [4:0]  mul_flags_o,
  input  wire        div_valid_i,
  input  wire [31:0] div_a_i,
  input  wire [31:0] div_b_i,
  output wire        div_valid_o,
  output wire [31:0] div_y_o,
  output wire [4:0]  div_flags_o,
  input  wire        sqrt_valid_i,
  input  wire [31:0] sqrt_a_i,
  output wire        sqrt_valid_o,
  output wire [31:0] sqrt_y_o,
  output wire [4:0]  sqrt_flags_o,
  input  wire        sign_valid_i,
  input  wire [1:0]  sign_op_i,
  input  wire [31:0] sign_a_i,
  input  wire [31:0] sign_b_i,
  output wire        sign_valid_o,
  output wire [31:0] sign_y_o,
  output wire [4:0]  sign_flags_o
);

  fp_add #(
    .LATENCY (ADD_LATENCY),
    .ROUND   (ROUND),
    .FTZ     (FTZ)
  ) u_add (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (add_valid_i),
    .sub_i   (add_sub_i),
    .a_i     (add_a_i),
    .b_i     (add_b_i),
    .valid_o (add_valid_o),
    .y_o     (add_y_o),
    .flags_o (add_flags_o)
  );

  fp_mul #(
    .LATENCY (MUL_LATENCY),
    .FEED    (MUL_FEED),
    .MULT_BLOCKS (MUL_BLOCKS),
    .ROUND   (ROUND),
    .FTZ     (FTZ)
  ) u_mul (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (mul_valid_i),
    .a_i     (mul_a_i),
    .b_i     (mul_b_i),
    .valid_o (mul_valid_o),
    .y_o     (mul_y_o),
    .flags_o (mul_flags_o)
  );

  fp_div #(
    .LATENCY (DIV_LATENCY),
    .ROUND   (ROUND),
    .FTZ     (FTZ)
  ) u_div (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (div_valid_i),
    .a_i     (div_a_i),
    .b_i     (div_b_i),
    .valid_o (div_valid_o),
    .y_o     (div_y_o),
    .flags_o (div_flags_o)
  );

  fp_sqrt #(
    .LATENCY (DIV_LATENCY),
    .ROUND   (ROUND),
    .FTZ     (FTZ)
  ) u_sqrt (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (sqrt_valid_i),
    .a_i     (sqrt_a_i),
    .valid_o (sqrt_valid_o),
    .y_o     (sqrt_y_o),
    .flags_o (sqrt_flags_o)
  );

  fp_sign #(
    .LATENCY (1)
  ) u_sign (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (sign_valid_i),
    .op_i    (sign_op_i),
    .a_i     (sign_a_i),
    .b_i     (sign_b_i),
    .valid_o (sign_valid_o),
    .y_o     (sign_y_o),
    .flags_o (sign_flags_o)
  );

endmodule

`default_nettype wire
