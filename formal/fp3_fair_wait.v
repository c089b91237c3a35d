// fp3_fair_wait -- the fairness check of the arbiter harnesses
// (formal/fp3_rr_fair.v, formal/fp3_issue_fair.v): counts the cycles one
// context has requested without a grant and asserts that the count stays
// below BOUND while it requests.
//
// Parameters: BOUND, cycles (at most 255).
// Ports:
//   clk_i, rst_i  clock (rising edge) and reset of the harness
//   req_i         the context requests this cycle (its request not masked
//                 as a last grant or decision)
//   gnt_i         it is granted this cycle
//   wait_o        cycles it has requested without a grant, before this one
//   waiting_o     it requested in the last cycle and was not granted (the
//                 harness then assumes that it keeps requesting)
`default_nettype none
module fp3_fair_wait #(
  parameter integer BOUND = 8
) (
  input  wire       clk_i,
  input  wire       rst_i,
  input  wire       req_i,
  input  wire       gnt_i,
  output reg  [7:0] wait_o,
  output reg        waiting_o
);
  always @(posedge clk_i) begin
    if (rst_i || gnt_i || !req_i) begin
      wait_o    <= 8'd0;
      waiting_o <= 1'b0;
    end else begin
      wait_o    <= wait_o + 8'd1;
      waiting_o <= 1'b1;
    end
  end
  always @(*) if (!rst_i && req_i) f_served_within_bound: assert (wait_o < BOUND);
endmodule
`default_nettype wire
