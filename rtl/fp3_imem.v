// fp3_imem -- instruction memory: one write port for the host, one
// synchronous read port for instruction fetch (a block RAM on an FPGA).
//
// The read port is the first pipeline stage of the workload scheduler
// (paper §4): the address presented in cycle t is read at the edge ending
// cycle t, and the instruction is on insn_o during cycle t + 1.
//
// Parameters
//   DEPTH   entries (instructions), a power of two is not required
//   AW      address width, clog2(DEPTH) at least
//   WIDTH   instruction width in bits (64, sw/fp3_isa.h)
`default_nettype none
module fp3_imem #(
  parameter integer DEPTH = 256,
  parameter integer AW    = 8,
  parameter integer WIDTH = 64
) (
  input  wire             clk_i,
  // host write port
  input  wire             we_i,
  input  wire [AW-1:0]    waddr_i,
  input  wire [WIDTH-1:0] wdata_i,
  // fetch read port
  input  wire [AW-1:0]    raddr_i,
  output reg  [WIDTH-1:0] insn_o
);
  reg [WIDTH-1:0] mem [0:DEPTH-1];

  // Entries never written read as zero, the nop.
  integer i;
  initial begin
    for (i = 0; i < DEPTH; i = i + 1) mem[i] = {WIDTH{1'b0}};
  end

  always @(posedge clk_i) begin
    if (we_i) mem[waddr_i] <= wdata_i;
    insn_o <= mem[raddr_i];
  end
endmodule
`default_nettype wire
