// fpu_top.v -- Verilator test top: one fp_add and one fp_mul side by side,
// driven from C through sim/fpu_shim.cpp (sim/fpu_model.h).
//
// Parameters (passed through to the cores):
//   ADD_LATENCY  fp_add LATENCY (issue to result, rising edges)
//   MUL_LATENCY  fp_mul LATENCY
//   ROUND        0 RNE, 1 RTZ (both cores)
//   FTZ          1: flush-to-zero / denormals-are-zero (both cores)
//
// Ports: clk_i, rst_i, then the add core's ports with prefix add_ and the
// mul core's with prefix mul_ (see rtl/fp_add.v, rtl/fp_mul.v for the
// timing contract).
`default_nettype none

module fpu_top #(
  parameter integer ADD_LATENCY = 4, // fp_add LATENCY
  parameter integer MUL_LATENCY = 3, // fp_mul LATENCY
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
  output wire [4:0]  mul_flags_o
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

endmodule

`default_nettype wire
