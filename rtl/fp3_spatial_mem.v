// fp3_spatial_mem -- one bank of a spatial frame's object memory: ROWS
// rows (objects) of WORDS words of WIDTH bits, one block RAM (fp3_ram)
// per word, so that a write may store one word of a row (the host's) or
// every word (a pipeline's write-back) and a read returns a whole row (a
// pipeline's operands) in one cycle.
//
// The read takes two cycles and its word leaves a register, so that a
// block RAM's slow clock-to-output (5.83 ns on the ECP5 without its
// output register, nextpnr's model) never starts a path through logic:
//   - up to 512 rows, fp3_ram's READ_STAGES 2 (in ECP5 synthesis the
//     block's own output register, 0.97 ns; no fabric cost);
//   - above 512 rows, fp3_ram's registered read into a flip-flop per bit
//     (fp3_ram's two-stage form would be LUT RAM there).
// Both read, in cycle t, the words written up to cycle t - 1; a read and
// a write of one row in the same cycle give no promise (the frame never
// does both).
//
// Cost: WORDS fp3_ram of WIDTH x ROWS bits; on the ECP5 one block RAM
// (512 x 36) per word up to 512 rows.
//
// Parameters
//   WORDS  words per row, >= 1
//   WIDTH  bits per word, 1 .. 36 (32: a binary32 value)
//   ROWS   rows, >= 2
//   RW     row address bits, clog2(ROWS) at least (and at least 1)
// Ports
//   we_i[k]             store wdata_i's word k at row waddr_i at the edge
//   raddr_i (cycle t) -> rdata_o (cycle t + 2)
`default_nettype none
module fp3_spatial_mem #(
  parameter integer WORDS = 1,
  parameter integer WIDTH = 32,
  parameter integer ROWS  = 2,
  parameter integer RW    = 1
) (
  input  wire                   clk_i,
  input  wire [WORDS-1:0]       we_i,
  input  wire [RW-1:0]          waddr_i,
  input  wire [WIDTH*WORDS-1:0] wdata_i,
  input  wire [RW-1:0]          raddr_i,
  output wire [WIDTH*WORDS-1:0] rdata_o
);
  // fp3_ram's read stages: its two-stage form up to 512 rows (one block
  // with its output register), else its registered read and a flip-flop
  localparam integer RS = ROWS <= 512 ? 2 : 1;
  genvar k;
  generate
    for (k = 0; k < WORDS; k = k + 1) begin : g_word
      wire [WIDTH-1:0] rd;
      fp3_ram #(.DEPTH(ROWS), .AW(RW), .WIDTH(WIDTH), .READ_STAGES(RS)) u_ram (
        .clk_i   (clk_i),
        .we_i    (we_i[k]),
        .waddr_i (waddr_i),
        .wdata_i (wdata_i[WIDTH*k +: WIDTH]),
        .raddr_i (raddr_i),
        .rdata_o (rd)
      );
      if (RS == 2) begin : g_outreg
        assign rdata_o[WIDTH*k +: WIDTH] = rd;
      end else begin : g_fabric
        reg [WIDTH-1:0] rd_q;
        always @(posedge clk_i) rd_q <= rd;
        assign rdata_o[WIDTH*k +: WIDTH] = rd_q;
      end
    end
  endgenerate
endmodule
`default_nettype wire
