// fp3_arith -- the arithmetic unit (paper §4): one pipelined FP add/sub
// core, one pipelined FP mul core, a move path of MOV_LATENCY cycles
// (copies, immediates and the sign group abs, neg, min, max: fp_sign) and
// a div/sqrt unit of DIV_LATENCY cycles (fp_div and fp_sqrt side by side),
// each with its own write-back port.
//
// The div/sqrt unit: fp_div and fp_sqrt have the same latency and at most
// one operation enters either per cycle (single issue), so their results
// never leave in the same cycle and share one write-back port (a
// multiplexer on the valid bit of fp_sqrt's result) and one tag line.
// Both are fully pipelined (initiation interval 1): no structural hazard,
// the scheduler issues a div or sqrt in any cycle.
//
// One operation may enter per cycle (single issue).  The destination
// register indices travel beside the data path in fp3_top's tag lines
// (fp3_wb_tag), which announce each write-back ahead of time for the
// scoreboard.  Write-back ports never collide on one register because the
// scheduler stalls WAW hazards.
//
// Parameters
//   ADD_LATENCY  cycles from operands to result of fp_add (a dependent
//                instruction issues one read-stage cycle more after its
//                producer, thanks to the register-file bypass)
//   MUL_LATENCY  the same for fp_mul
//   MUL_FEED     fp_mul FEED: 1 puts a fabric register in front of its DSP
//                blocks (MUL_LATENCY 7 to 10; rtl/fp_mul.v)
//   MOV_LATENCY  the same for the move path, >= 1
//   DIV_LATENCY  the same for fp_div and fp_sqrt (their LATENCY), >= 1
//   ROUND, FTZ   core options, see rtl/fp_add.v (0 = RNE, IEEE subnormals)
//   HAS_ADD, HAS_MUL  0: that core is not built (its port never writes);
//   HAS_SUB      0: the adder's subtract input is tied off (the scheduler
//                rejects the instructions these leave without a unit)
//   HAS_DIV, HAS_SQRT  0: fp_div / fp_sqrt not built (div / sqrt illegal;
//                with neither the div/sqrt port never writes)
//   HAS_SIGN     0: no fp_sign on the move path (abs, neg, min, max are
//                illegal); 1 costs a 31-bit comparator, NaN tests and a
//                32-bit 2:1 multiplexer after the path's registers (fp_sign)
// Ports
//   sop_i: for the move path, {sign group, fp_sign op_i}: 0xx a copy of
//   a_i, 1xx fp_sign's abs (00), neg (01), min (10), max (11) of a_i, b_i.
//   valid_i, unit_i (UNIT_ADD/MUL/MOV/DIV of rtl/fp3_isa.vh), sub_i, a_i,
//   b_i: an issued operation with its operands from the register file's
//   read stage (for the move path a_i is the value to write: the source
//   register or the immediate; sub_i: a sub on the add/sub core, a sqrt
//   of a_i on the div/sqrt unit, else a_i / b_i).
//   {add,mul,mov,div}_{valid,data}_o: results, ADD_LATENCY, MUL_LATENCY,
//   MOV_LATENCY and DIV_LATENCY cycles after valid_i; *_flags_o are the
//   IEEE exception flags of the result (the move path's: invalid for a min
//   or max of a signalling NaN, else 0).
`default_nettype none
module fp3_arith #(
  parameter integer ADD_LATENCY = 4,
  parameter integer MUL_LATENCY = 3,
  parameter integer MUL_FEED    = 0,
  parameter integer ROUND       = 0,
  parameter integer FTZ         = 0,
  parameter integer MOV_LATENCY = 1,
  parameter integer DIV_LATENCY = 8,
  parameter integer HAS_ADD     = 1,
  parameter integer HAS_SUB     = 1,
  parameter integer HAS_MUL     = 1,
  parameter integer HAS_DIV     = 1,
  parameter integer HAS_SQRT    = 1,
  parameter integer HAS_SIGN    = 1
) (
  input  wire          clk_i,
  input  wire          rst_i,
  input  wire          valid_i,
  input  wire [2:0]    unit_i,
  input  wire          sub_i,
  input  wire [2:0]    sop_i,
  input  wire [31:0]   a_i,
  input  wire [31:0]   b_i,
  output wire          add_valid_o,
  output wire [31:0]   add_data_o,
  output wire [4:0]    add_flags_o,
  output wire          mul_valid_o,
  output wire [31:0]   mul_data_o,
  output wire [4:0]    mul_flags_o,
  output wire          mov_valid_o,
  output wire [31:0]   mov_data_o,
  output wire [4:0]    mov_flags_o,
  output wire          div_valid_o,
  output wire [31:0]   div_data_o,
  output wire [4:0]    div_flags_o
);
`include "fp3_isa.vh"

  wire add_go = valid_i && unit_i == UNIT_ADD && HAS_ADD != 0;
  wire mul_go = valid_i && unit_i == UNIT_MUL && HAS_MUL != 0;
  wire mov_go = valid_i && unit_i == UNIT_MOV;

  // ---- add/sub core --------------------------------------------------------
  generate
    if (HAS_ADD != 0) begin : g_add
      fp_add #(.LATENCY(ADD_LATENCY), .ROUND(ROUND), .FTZ(FTZ)) u_add (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (add_go),
        .sub_i   (HAS_SUB != 0 && sub_i),
        .a_i     (a_i),
        .b_i     (b_i),
        .valid_o (add_valid_o),
        .y_o     (add_data_o),
        .flags_o (add_flags_o)
      );
    end else begin : g_no_add
      assign add_valid_o = 1'b0;
      assign add_data_o  = 32'd0;
      assign add_flags_o = 5'd0;
    end
  endgenerate
  // ---- mul core ------------------------------------------------------------
  generate
    if (HAS_MUL != 0) begin : g_mul
      fp_mul #(.LATENCY(MUL_LATENCY), .FEED(MUL_FEED), .ROUND(ROUND), .FTZ(FTZ)) u_mul (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (mul_go),
        .a_i     (a_i),
        .b_i     (b_i),
        .valid_o (mul_valid_o),
        .y_o     (mul_data_o),
        .flags_o (mul_flags_o)
      );
    end else begin : g_no_mul
      assign mul_valid_o = 1'b0;
      assign mul_data_o  = 32'd0;
      assign mul_flags_o = 5'd0;
    end
  endgenerate

  // ---- div/sqrt unit: one write-back port ---------------------------------
  wire        dq_valid, sq_valid;
  wire [31:0] dq_data, sq_data;
  wire [4:0]  dq_flags, sq_flags;
  generate
    if (HAS_DIV != 0) begin : g_div
      wire div_go = valid_i && unit_i == UNIT_DIV && !sub_i;
      fp_div #(.LATENCY(DIV_LATENCY), .ROUND(ROUND), .FTZ(FTZ)) u_div (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (div_go),
        .a_i     (a_i),
        .b_i     (b_i),
        .valid_o (dq_valid),
        .y_o     (dq_data),
        .flags_o (dq_flags)
      );
    end else begin : g_no_div
      assign dq_valid = 1'b0;
      assign dq_data  = 32'd0;
      assign dq_flags = 5'd0;
    end
    if (HAS_SQRT != 0) begin : g_sqrt
      wire sqrt_go = valid_i && unit_i == UNIT_DIV && sub_i;
      fp_sqrt #(.LATENCY(DIV_LATENCY), .ROUND(ROUND), .FTZ(FTZ)) u_sqrt (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (sqrt_go),
        .a_i     (a_i),
        .valid_o (sq_valid),
        .y_o     (sq_data),
        .flags_o (sq_flags)
      );
    end else begin : g_no_sqrt
      assign sq_valid = 1'b0;
      assign sq_data  = 32'd0;
      assign sq_flags = 5'd0;
    end
  endgenerate
  // At most one of them has a result in a cycle (same latency, one issue
  // per cycle).
  assign div_valid_o = dq_valid || sq_valid;
  assign div_data_o  = sq_valid ? sq_data : dq_data;
  assign div_flags_o = sq_valid ? sq_flags : dq_flags;

  // ---- move path: MOV_LATENCY register stages ------------------------------
  // A copy goes through fp_pipe, a sign-group operation through fp_sign,
  // both MOV_LATENCY stages; at most one of them holds a result in a stage.
  wire        copy_valid;
  wire [31:0] copy_data;
  fp_pipe #(.WIDTH(32), .DEPTH(MOV_LATENCY)) u_mov (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (mov_go && !(HAS_SIGN != 0 && sop_i[2])),
    .data_i  (a_i),
    .valid_o (copy_valid),
    .data_o  (copy_data)
  );
  generate
    if (HAS_SIGN != 0) begin : g_sign
      wire        sign_valid;
      wire [31:0] sign_data;
      wire [4:0]  sign_flags;
      fp_sign #(.LATENCY(MOV_LATENCY)) u_sign (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (mov_go && sop_i[2]),
        .op_i    (sop_i[1:0]),
        .a_i     (a_i),
        .b_i     (b_i),
        .valid_o (sign_valid),
        .y_o     (sign_data),
        .flags_o (sign_flags)
      );
      assign mov_valid_o = copy_valid || sign_valid;
      assign mov_data_o  = sign_valid ? sign_data : copy_data;
      assign mov_flags_o = sign_valid ? sign_flags : 5'd0;
    end else begin : g_no_sign
      wire unused_sop = &{1'b0, sop_i};
      assign mov_valid_o = copy_valid;
      assign mov_data_o  = copy_data;
      assign mov_flags_o = 5'd0;
    end
  endgenerate
endmodule
`default_nettype wire
