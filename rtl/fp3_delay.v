// fp3_delay -- a fixed delay line: a valid bit and a data word delayed by
// exactly DEPTH clock edges.
//
// Used by the arithmetic unit to carry the destination register of each
// operation alongside an FP core, so the tag leaves the unit in the same
// cycle as the core's result.  Fully pipelined: a new entry every cycle.
//
// Parameters
//   WIDTH  width of the data word (bits), >= 1
//   DEPTH  delay in clock cycles, >= 1
// Ports
//   clk_i, rst_i   clock; synchronous active-high reset (clears valid bits)
//   valid_i/data_i entry presented in cycle t
//   valid_o/data_o the same entry in cycle t + DEPTH
`default_nettype none
module fp3_delay #(
  parameter integer WIDTH = 8,
  parameter integer DEPTH = 4
) (
  input  wire             clk_i,
  input  wire             rst_i,
  input  wire             valid_i,
  input  wire [WIDTH-1:0] data_i,
  output wire             valid_o,
  output wire [WIDTH-1:0] data_o
);
  reg             valid_q [0:DEPTH-1];
  reg [WIDTH-1:0] data_q  [0:DEPTH-1];

  // Stage 0 takes the input; stage s takes stage s-1.
  genvar s;
  generate
    for (s = 0; s < DEPTH; s = s + 1) begin : g_stage
      wire             valid_d = (s == 0) ? valid_i : valid_q[(s == 0) ? 0 : s-1];
      wire [WIDTH-1:0] data_d  = (s == 0) ? data_i  : data_q[(s == 0) ? 0 : s-1];
      always @(posedge clk_i) begin
        if (rst_i) valid_q[s] <= 1'b0;
        else       valid_q[s] <= valid_d;
        data_q[s] <= data_d;
      end
    end
  endgenerate

  assign valid_o = valid_q[DEPTH-1];
  assign data_o  = data_q[DEPTH-1];
endmodule
`default_nettype wire
