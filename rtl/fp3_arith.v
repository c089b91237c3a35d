// fp3_arith -- the arithmetic unit (paper §4): one pipelined FP add/sub
// core, one pipelined FP mul core and a one-cycle move path, each with its
// own write-back port.
//
// One operation may enter per cycle (single issue).  Each unit carries the
// destination register index in a tag line (fp_pipe) beside its data path, so the
// index leaves with the result.  Write-back ports never collide on one
// register because the scheduler stalls WAW hazards.
//
// Parameters
//   ADD_LATENCY  cycles from operands to result of fp_add (a dependent
//                instruction issues one read-stage cycle more after its
//                producer, thanks to the register-file bypass)
//   MUL_LATENCY  the same for fp_mul
//   ROUND, FTZ   core options, see rtl/fp_add.v (0 = RNE, IEEE subnormals)
//   HAS_ADD, HAS_MUL  0: that core is not built (its port never writes);
//   HAS_SUB      0: the adder's subtract input is tied off (the scheduler
//                rejects the instructions these leave without a unit)
//   XW           width of the destination tag ({context, register})
// Ports
//   valid_i, unit_i (UNIT_ADD/MUL/MOV of rtl/fp3_isa.vh), sub_i, rd_i,
//   a_i, b_i: the operation issued in the previous cycle, with its operands
//   from the register file's read stage (for the move path a_i is
//   the value to write: the source register or the immediate).
//   {add,mul,mov}_{valid,reg,data}_o: write-back ports; add/mul flags_o are
//   the IEEE exception flags of the result on the same port.
//   {add,mul,mov}_next_{valid,reg}_o: the write-backs of the next cycle.
`default_nettype none
module fp3_arith #(
  parameter integer ADD_LATENCY = 4,
  parameter integer MUL_LATENCY = 3,
  parameter integer ROUND       = 0,
  parameter integer FTZ         = 0,
  parameter integer HAS_ADD     = 1,
  parameter integer HAS_SUB     = 1,
  parameter integer HAS_MUL     = 1,
  parameter integer XW          = 5
) (
  input  wire          clk_i,
  input  wire          rst_i,
  input  wire          valid_i,
  input  wire [1:0]    unit_i,
  input  wire          sub_i,
  input  wire [XW-1:0] rd_i,
  input  wire [31:0]   a_i,
  input  wire [31:0]   b_i,
  output wire          add_valid_o,
  output wire [XW-1:0] add_reg_o,
  output wire [31:0]   add_data_o,
  output wire [4:0]    add_flags_o,
  output wire          mul_valid_o,
  output wire [XW-1:0] mul_reg_o,
  output wire [31:0]   mul_data_o,
  output wire [4:0]    mul_flags_o,
  output reg           mov_valid_o,
  output wire          add_next_valid_o,  // tags written back next cycle
  output wire [XW-1:0] add_next_reg_o,
  output wire          mul_next_valid_o,
  output wire [XW-1:0] mul_next_reg_o,
  output wire          mov_next_valid_o,
  output wire [XW-1:0] mov_next_reg_o,
  output reg  [XW-1:0] mov_reg_o,
  output reg  [31:0]   mov_data_o
);
`include "fp3_isa.vh"

  wire add_go = valid_i && unit_i == UNIT_ADD && HAS_ADD != 0;
  wire mul_go = valid_i && unit_i == UNIT_MUL && HAS_MUL != 0;
  wire mov_go = valid_i && unit_i == UNIT_MOV;

  // ---- add/sub core and its tag line ---------------------------------------
  wire add_core_valid;
  generate
    if (HAS_ADD != 0) begin : g_add
      fp_add #(.LATENCY(ADD_LATENCY), .ROUND(ROUND), .FTZ(FTZ)) u_add (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (add_go),
        .sub_i   (HAS_SUB != 0 && sub_i),
        .a_i     (a_i),
        .b_i     (b_i),
        .valid_o (add_core_valid),
        .y_o     (add_data_o),
        .flags_o (add_flags_o)
      );
    end else begin : g_no_add
      assign add_core_valid = 1'b0;
      assign add_data_o     = 32'd0;
      assign add_flags_o    = 5'd0;
    end
  endgenerate
  // The tag line is split one stage before its end: the tag there is the
  // register written back in the next cycle (add_next_*), which lets the
  // scheduler decide one cycle ahead.
  fp_pipe #(.WIDTH(XW), .DEPTH(ADD_LATENCY - 1)) u_add_tag_pre (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (add_go),
    .data_i  (rd_i),
    .valid_o (add_next_valid_o),
    .data_o  (add_next_reg_o)
  );
  fp_pipe #(.WIDTH(XW), .DEPTH(1)) u_add_tag (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (add_next_valid_o),
    .data_i  (add_next_reg_o),
    .valid_o (add_valid_o),
    .data_o  (add_reg_o)
  );

  // ---- mul core and its tag line -------------------------------------------
  wire mul_core_valid;
  generate
    if (HAS_MUL != 0) begin : g_mul
      fp_mul #(.LATENCY(MUL_LATENCY), .ROUND(ROUND), .FTZ(FTZ)) u_mul (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (mul_go),
        .a_i     (a_i),
        .b_i     (b_i),
        .valid_o (mul_core_valid),
        .y_o     (mul_data_o),
        .flags_o (mul_flags_o)
      );
    end else begin : g_no_mul
      assign mul_core_valid = 1'b0;
      assign mul_data_o     = 32'd0;
      assign mul_flags_o    = 5'd0;
    end
  endgenerate
  fp_pipe #(.WIDTH(XW), .DEPTH(MUL_LATENCY - 1)) u_mul_tag_pre (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (mul_go),
    .data_i  (rd_i),
    .valid_o (mul_next_valid_o),
    .data_o  (mul_next_reg_o)
  );
  fp_pipe #(.WIDTH(XW), .DEPTH(1)) u_mul_tag (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (mul_next_valid_o),
    .data_i  (mul_next_reg_o),
    .valid_o (mul_valid_o),
    .data_o  (mul_reg_o)
  );

  // The cores' own valid bits equal the tag lines' (same depth, same input);
  // the tag lines' are used, the cores' are checked under FORMAL only.
  wire unused_core_valid = add_core_valid ^ mul_core_valid ^ sub_i;
`ifdef FORMAL
  always @(*) begin
    assert (add_core_valid == add_valid_o);
    assert (mul_core_valid == mul_valid_o);
  end
`endif

  // ---- move path: one register stage ---------------------------------------
  assign mov_next_valid_o = mov_go;
  assign mov_next_reg_o   = rd_i;
  always @(posedge clk_i) begin
    if (rst_i) mov_valid_o <= 1'b0;
    else       mov_valid_o <= mov_go;
    mov_reg_o  <= rd_i;
    mov_data_o <= a_i;
  end
endmodule
`default_nettype wire
