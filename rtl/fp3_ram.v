// fp3_ram -- simple dual-port RAM: one write port, one read port with a
// registered read (read-first: a read and a write of one address at the
// same edge return the old word).  The shape of FPGA block RAM (Xilinx
// RAMB16, Lattice DP16KD) and LUT RAM with an output register; Yosys
// infers either (LUT_RAM = 0), or LUT RAM only (LUT_RAM = 1: the data
// leave a flip-flop, where a block RAM's leave it 5.8 ns after the clock
// on the ECP5).  Contents start at zero.
//
// Parameters
//   DEPTH    words, >= 2; AW address width, clog2(DEPTH) at least
//   WIDTH    bits per word
//   LUT_RAM  0: block or LUT RAM, the synthesis tool's choice; 1: LUT RAM
//            (the attribute ram_style = "distributed")
// Ports
//   we_i/waddr_i/wdata_i  write at the rising edge
//   raddr_i (cycle t) -> rdata_o (cycle t + 1)
`default_nettype none
module fp3_ram #(
  parameter integer DEPTH = 32,
  parameter integer AW    = 5,
  parameter integer WIDTH = 32,
  parameter integer LUT_RAM = 0
) (
  input  wire             clk_i,
  input  wire             we_i,
  input  wire [AW-1:0]    waddr_i,
  input  wire [WIDTH-1:0] wdata_i,
  input  wire [AW-1:0]    raddr_i,
  output reg  [WIDTH-1:0] rdata_o
);
  integer i;
  initial rdata_o = {WIDTH{1'b0}};

  generate
    if (LUT_RAM == 0) begin : g_any
      reg [WIDTH-1:0] mem [0:DEPTH-1];
      initial for (i = 0; i < DEPTH; i = i + 1) mem[i] = {WIDTH{1'b0}};
      always @(posedge clk_i) begin
        if (we_i) mem[waddr_i] <= wdata_i;
        rdata_o <= mem[raddr_i];
      end
    end else begin : g_lut
      // (The same as g_any but for the attribute: Verilog-2005 has no
      // attribute that depends on a parameter.)
      (* ram_style = "distributed" *) reg [WIDTH-1:0] mem [0:DEPTH-1];
      initial for (i = 0; i < DEPTH; i = i + 1) mem[i] = {WIDTH{1'b0}};
      always @(posedge clk_i) begin
        if (we_i) mem[waddr_i] <= wdata_i;
        rdata_o <= mem[raddr_i];
      end
    end
  endgenerate
endmodule
`default_nettype wire
