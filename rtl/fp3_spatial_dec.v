// fp3_spatial_dec -- the address decode of a spatial chip's AXI slave
// (sw/isa/fp3_spatial_regs.h): a word address, decoded as it is captured
// into the slave's holding register (take_i), to its region, its offset
// and, for a window, the bank, row and word it names and whether they are
// in range; all held until the next capture.  The slave has one for its
// write address and one for its read address, so that its checks at the
// access are a few flip-flops.
//
// The word address's bits [21:20] name the region (0 the scalar
// registers, 1 the awake list, 2 the state window, 3 the input window),
// bits [19:0] the offset in it.  An awake-list offset is the entry's
// number i; a state (input) offset is o * 2^SLOG + w (o * 2^ILOG + k).
// The object or entry number n is in bank n mod N at row n / N (a
// division by the constant N: shifts when N is a power of two, else a
// constant divider of 20 bits, ceil(log2 M) after synthesis trims it).
//
// Parameters
//   PIPELINES  N; MAXOBJ M (a multiple of N, at most 2^20)
//   CARRIED, INPUTS  words per object in the state, input window
//   SLOG, ILOG  log2 of the windows' object strides (2^SLOG >= CARRIED)
//   RW, BW      row and bank bits (as fp3_spatial_frame's)
// Ports (the outputs registered, loaded when take_i is 1)
//   addr_i   word address (byte address bits [23:2])
//   sel_o    region, as above
//   off_o    the offset in the region (a scalar register's address)
//   ok_o     a window address whose number is < M and whose word is < the
//            object's words (0 in the scalar region)
//   bank_o, row_o, word_o   the bank, row and word it names
`default_nettype none
module fp3_spatial_dec #(
  parameter integer PIPELINES = 1,
  parameter integer MAXOBJ    = 2,
  parameter integer CARRIED   = 1,
  parameter integer INPUTS    = 1,
  parameter integer SLOG      = 0,
  parameter integer ILOG      = 0,
  parameter integer RW        = 1,
  parameter integer BW        = 1
) (
  input  wire          clk_i,
  input  wire          take_i,
  input  wire [21:0]   addr_i,
  output reg  [1:0]    sel_o,
  output reg  [19:0]   off_o,
  output reg           ok_o,
  output reg  [BW-1:0] bank_o,
  output reg  [RW-1:0] row_o,
  output reg  [7:0]    word_o
);
  localparam [1:0]  SEL_AWAKE = 2'd1;
  localparam [1:0]  SEL_STATE = 2'd2;
  localparam [19:0] N20   = PIPELINES[19:0];
  localparam [19:0] M20   = MAXOBJ[19:0];
  localparam [7:0]  NC8   = CARRIED[7:0];
  localparam [7:0]  NI8   = INPUTS[7:0];
  localparam [19:0] SMASK = (20'd1 << SLOG) - 20'd1;
  localparam [19:0] IMASK = (20'd1 << ILOG) - 20'd1;

  wire [19:0] off = addr_i[19:0];
  wire [1:0]  sel = addr_i[21:20];

  // the entry's or object's number, and the word in the object's stride
  wire [19:0] num  = sel == SEL_AWAKE ? off : sel == SEL_STATE ? off >> SLOG : off >> ILOG;
  wire [19:0] w20  = sel == SEL_AWAKE ? 20'd0 : sel == SEL_STATE ? off & SMASK : off & IMASK;
  wire [7:0]  nw   = sel == SEL_AWAKE ? 8'd1 : sel == SEL_STATE ? NC8 : NI8;
  wire [19:0] row  = num / N20;
  wire [19:0] bank = num % N20;

  always @(posedge clk_i) begin
    if (take_i) begin
      sel_o  <= sel;
      off_o  <= off;
      ok_o   <= sel != 2'd0 && num < M20 && w20 < {12'd0, nw};
      bank_o <= bank[BW-1:0];
      row_o  <= row[RW-1:0];
      word_o <= w20[7:0];
    end
  end

  // Above the row and bank fields: zero for a number below M (ok_o).
  wire unused = &{1'b0, row, bank, w20[19:8]};
endmodule
`default_nettype wire
