// fp3_spatial_mem -- one bank of a spatial frame's object memory: ROWS
// rows (objects) of WORDS 32-bit words, one block RAM (fp3_ram,
// registered read) per word, so that a write may store one word of a row
// (the host's) or every word (a pipeline's write-back) and a read returns
// a whole row (a pipeline's operands) in one cycle.
//
// Cost: WORDS fp3_ram of 32 x ROWS bits; on the ECP5 one DP16KD (512 x 36)
// per word up to 512 rows.
//
// Parameters
//   WORDS  32-bit words per row, >= 1
//   ROWS   rows, >= 2
//   RW     row address bits, clog2(ROWS) at least (and at least 1)
// Ports
//   we_i[k]             store wdata_i's word k at row waddr_i at the edge
//   raddr_i (cycle t) -> rdata_o (cycle t + 1), read-first: a read and a
//                        write of one row at one edge return the old row
`default_nettype none
module fp3_spatial_mem #(
  parameter integer WORDS = 1,
  parameter integer ROWS  = 2,
  parameter integer RW    = 1
) (
  input  wire                  clk_i,
  input  wire [WORDS-1:0]      we_i,
  input  wire [RW-1:0]         waddr_i,
  input  wire [32*WORDS-1:0]   wdata_i,
  input  wire [RW-1:0]         raddr_i,
  output wire [32*WORDS-1:0]   rdata_o
);
  genvar k;
  generate
    for (k = 0; k < WORDS; k = k + 1) begin : g_word
      fp3_ram #(.DEPTH(ROWS), .AW(RW), .WIDTH(32), .READ_STAGES(1)) u_ram (
        .clk_i   (clk_i),
        .we_i    (we_i[k]),
        .waddr_i (waddr_i),
        .wdata_i (wdata_i[32*k +: 32]),
        .raddr_i (raddr_i),
        .rdata_o (rdata_o[32*k +: 32])
      );
    end
  endgenerate
endmodule
`default_nettype wire
