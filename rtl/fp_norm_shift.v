// fp_norm_shift.v -- the significand half of the final normalisation of
// fp_mul's product and fp_div's quotient: the top 27 bits of the exact
// result (leading one at bit 26 or 25) shifted right to a normalised or
// denormalised significand with guard, round and sticky bits, and the
// result exponent picked, by the shift and exponents of fp_norm_exp.
// Two steps with a register place between them (MID_DEPTH):
//   a  pick the exponent by the top bit; the shift's even part, 0 to 30
//      places, with sticky (fp_shr_sticky)
//   b  the shift's last place: shift_i[0], or the one-place
//      normalisation of a top bit set with ge2_i
// Side bits ride along for the caller.
//
// Parameters:
//   SIDE_W     bits of side_i (>= 1)
//   MID_DEPTH  registers between steps a and b (0 or 1)
//
// Ports:
//   clk_i, rst_i  clock (rising edge), synchronous reset of the valid bit
//   valid_i       the inputs hold an operation this cycle
//   side_i        carried to side_o beside the result
//   top_i         the top 27 bits of the exact significand
//   sticky_i      OR of the bits below top_i
//   exp_a_i, exp_b_i, ge2_i, shift_i  fp_norm_exp's outputs
//   valid_o       valid_i delayed by MID_DEPTH
//   side_o        side_i delayed by MID_DEPTH
//   exp_o         biased result exponent, >= 1 (fp_round exp_i)
//   man_o         significand (bits 25:2, hidden bit at 25), guard (1),
//                 round (0)
//   sticky_o      sticky bit
// Combinational from the register place to the outputs: the caller
// registers them in its next place.
//
// Cost: two fp_shr_sticky shifters of 27 bits (the even one of four
// levels, the last of one) and, with MID_DEPTH 1, 39 + SIDE_W flip-flops.
`default_nettype none

module fp_norm_shift #(
  parameter integer SIDE_W    = 1, // side bits
  parameter integer MID_DEPTH = 0  // registers between steps a and b
) (
  input  wire              clk_i,
  input  wire              rst_i,
  input  wire              valid_i,
  input  wire [SIDE_W-1:0] side_i,
  input  wire [26:0]       top_i,
  input  wire              sticky_i,
  input  wire [9:0]        exp_a_i,
  input  wire [9:0]        exp_b_i,
  input  wire              ge2_i,
  input  wire [4:0]        shift_i,
  output wire              valid_o,
  output wire [SIDE_W-1:0] side_o,
  output wire [9:0]        exp_o,
  output wire [25:0]       man_o,
  output wire              sticky_o
);

  // a: the exponent by the top bit; the shift's even part.
  wire        top     = top_i[26];
  wire [9:0]  a_exp   = top ? exp_a_i : exp_b_i;
  wire        a_one   = shift_i[0] | (top & ge2_i);
  wire [26:0] a_top;
  wire        a_st;
  fp_shr_sticky #(.WIDTH(27)) u_shift_even (
    .v_i      (top_i),
    .amt_i    ({shift_i[4:1], 1'b0}),
    .sticky_i (sticky_i),
    .v_o      (a_top),
    .sticky_o (a_st)
  );

  localparam integer WM = SIDE_W + 10 + 1 + 27 + 1;
  wire [9:0]  b_exp;
  wire        b_one;
  wire [26:0] b_top;
  wire        b_st;
  fp_pipe #(.WIDTH(WM), .DEPTH(MID_DEPTH)) u_pipe_mid (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({side_i, a_exp, a_one, a_top, a_st}),
    .valid_o (valid_o),
    .data_o  ({side_o, b_exp, b_one, b_top, b_st})
  );

  // b: the last place.  The top 27 bits shifted right leave the
  // significand, guard and round bits in bits 25:0 (bit 26 is then 0).
  wire [26:0] b_sh;
  fp_shr_sticky #(.WIDTH(27)) u_shift_one (
    .v_i      (b_top),
    .amt_i    ({4'd0, b_one}),
    .sticky_i (b_st),
    .v_o      (b_sh),
    .sticky_o (sticky_o)
  );
  wire unused_top = &{1'b0, b_sh[26], 1'b0};

  assign exp_o = b_exp;
  assign man_o = b_sh[25:0];

endmodule

`default_nettype wire
