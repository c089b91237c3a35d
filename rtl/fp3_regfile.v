// fp3_regfile -- register banks, one per context, with one busy flag per
// register (the scoreboard of paper §4), write-back bypass and a host port.
//
// Every index is {context, register} (XW bits).  Busy flags: an issued
// instruction marks its destination busy (set_i); the unit that computes
// the result clears the flag when it writes back.  The scheduler reads the
// flags (busy_o) and stalls an instruction while a source is busy (RAW) or
// its destination is busy (WAW), unless that register is being written
// back in this very cycle; so at most one result per register is in flight
// and write-backs to one register happen in program order.
//
// No whole-pipeline stall on write-back (the paper has one; DESIGN.md):
// each unit has its own write port, and a result on a write-back port is
// forwarded to the read ports in the same cycle (bypass), so a dependent
// instruction issues in the cycle its operand is written.
//
// Parameters
//   ENTRIES  registers in all, 2**XW
//   XW       index width, clog2(NUM_CONTEXTS) + clog2(NUM_REGS)
// Ports (indices XW bits wide, data 32 bits)
//   ra_i/rb_i -> ra_data_o/rb_data_o: combinational reads with bypass.
//   busy_o: every busy flag; idle_o: none set (nothing in flight).
//   set_i/set_idx_i: mark a destination busy (issue of add/mul/move).
//   wb{0,1,2}_*: write-back ports (add core, mul core, move path); each
//     write clears the register's busy flag.  A register written back in
//     the cycle a new instruction claims it stays busy: the set wins.
//   host_we_i/host_idx_i/host_wdata_i: host write (only while stopped);
//     host_rdata_o reads host_idx_i.
`default_nettype none
module fp3_regfile #(
  parameter integer ENTRIES = 32,
  parameter integer XW      = 5
) (
  input  wire               clk_i,
  input  wire               rst_i,
  input  wire [XW-1:0]      ra_i,
  input  wire [XW-1:0]      rb_i,
  output wire [31:0]        ra_data_o,
  output wire [31:0]        rb_data_o,
  output wire [ENTRIES-1:0] busy_o,
  input  wire               set_i,
  input  wire [XW-1:0]      set_idx_i,
  input  wire               wb0_valid_i,
  input  wire [XW-1:0]      wb0_idx_i,
  input  wire [31:0]        wb0_data_i,
  input  wire               wb1_valid_i,
  input  wire [XW-1:0]      wb1_idx_i,
  input  wire [31:0]        wb1_data_i,
  input  wire               wb2_valid_i,
  input  wire [XW-1:0]      wb2_idx_i,
  input  wire [31:0]        wb2_data_i,
  input  wire               host_we_i,
  input  wire [XW-1:0]      host_idx_i,
  input  wire [31:0]        host_wdata_i,
  output wire [31:0]        host_rdata_o,
  output wire               idle_o
);
  reg [31:0]        regs_q [0:ENTRIES-1];
  reg [ENTRIES-1:0] busy_q;

  // A register's value, bypassed.  A plain expression, not a function: a
  // continuous assignment is re-evaluated only when its operands change,
  // and a function's body is not an operand (Icarus relies on that).
`define FP3_READ_PORT(x) \
  ((wb0_valid_i && wb0_idx_i == (x)) ? wb0_data_i : \
   (wb1_valid_i && wb1_idx_i == (x)) ? wb1_data_i : \
   (wb2_valid_i && wb2_idx_i == (x)) ? wb2_data_i : regs_q[x])
  assign ra_data_o    = `FP3_READ_PORT(ra_i);
  assign rb_data_o    = `FP3_READ_PORT(rb_i);
`undef FP3_READ_PORT
  assign busy_o       = busy_q;
  assign host_rdata_o = regs_q[host_idx_i];
  assign idle_o       = (busy_q == {ENTRIES{1'b0}});

  // ---- writes and busy flags, one register at a time ----------------------
  // The WAW stall guarantees that the write ports name distinct registers,
  // so the write priority below never matters for a legal sequence.
  genvar r;
  generate
    for (r = 0; r < ENTRIES; r = r + 1) begin : g_reg
      localparam [XW-1:0] IDX = r[XW-1:0];
      wire hit0 = wb0_valid_i && wb0_idx_i == IDX;
      wire hit1 = wb1_valid_i && wb1_idx_i == IDX;
      wire hit2 = wb2_valid_i && wb2_idx_i == IDX;
      always @(posedge clk_i) begin
        if      (hit0) regs_q[r] <= wb0_data_i;
        else if (hit1) regs_q[r] <= wb1_data_i;
        else if (hit2) regs_q[r] <= wb2_data_i;
        else if (host_we_i && host_idx_i == IDX) regs_q[r] <= host_wdata_i;
      end
      always @(posedge clk_i) begin
        if (rst_i)                               busy_q[r] <= 1'b0;
        else if (set_i && set_idx_i == IDX)      busy_q[r] <= 1'b1;
        else if (hit0 || hit1 || hit2)           busy_q[r] <= 1'b0;
      end
    end
  endgenerate

`ifdef FORMAL
  // Two write ports never name the same register in one cycle.
  always @(*) begin
    if (wb0_valid_i && wb1_valid_i) assert (wb0_idx_i != wb1_idx_i);
    if (wb0_valid_i && wb2_valid_i) assert (wb0_idx_i != wb2_idx_i);
    if (wb1_valid_i && wb2_valid_i) assert (wb1_idx_i != wb2_idx_i);
  end
`endif
endmodule
`default_nettype wire
