// fp3_keep -- a register that copies a signal some other register also
// holds, kept apart in synthesis: a copy for a group of loads of its own,
// so that the placer can put it beside them (clock-rate builds).
//
// Yosys merges flip-flops with the same inputs into one (opt_merge); the
// process is kept so that it does not, and the copy is then placed by its
// own loads instead of among the original's.  The initial value only
// defines the register in simulation before the first clock edge (the
// copies in this design are either reset through d_i or not used before
// their first load).
//
// Parameters
//   W     bits (>= 1)
// Ports
//   clk_i  clock, rising edge
//   d_i    the value to register, W bits (fold any reset or enable into it)
//   q_o    d_i of the last rising edge, W bits
`default_nettype none
module fp3_keep #(
  parameter integer W = 1
) (
  input  wire         clk_i,
  input  wire [W-1:0] d_i,
  output wire [W-1:0] q_o
);
  reg [W-1:0] q;
  initial q = {W{1'b0}};
  (* keep *) always @(posedge clk_i) q <= d_i;
  assign q_o = q;
endmodule
`default_nettype wire
