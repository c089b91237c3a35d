// fp3_regfile -- register file with one busy flag per register (the
// scoreboard of paper §4), write-back bypass, and a host port.
//
// Busy flags: an issued instruction marks its destination busy (set_i);
// the unit that computes the result clears the flag when it writes back.
// The scheduler stalls an instruction while a source is busy (RAW) or its
// destination is busy (WAW), so at most one result per register is in
// flight and write-backs to one register happen in program order.
//
// No whole-pipeline stall on write-back (the paper has one; DESIGN.md):
// each unit has its own write port, and a result on a write-back port is
// forwarded to the read ports in the same cycle (bypass), so a dependent
// instruction issues in the cycle its operand is written.
//
// Parameters
//   NUM_REGS  registers (2 .. 256)
//   IW        register index width, clog2(NUM_REGS)
// Ports (all indices IW bits wide, data 32 bits)
//   ra_i/rb_i -> ra_data_o/rb_data_o, ra_ready_o/rb_ready_o: combinational
//     reads with bypass; ready = not busy, or being written this cycle.
//   rd_i -> rd_busy_o: destination busy and not being written this cycle
//     (WAW check): a new write lands at least one cycle after the old one.
//   set_i/set_reg_i: mark a destination busy (issue of add/mul/move).
//   wb{0,1,2}_*: write-back ports (add core, mul core, move path); each
//     write clears the register's busy flag.
//   host_we_i/host_reg_i/host_wdata_i: host write (only while stopped);
//     host_rdata_o reads host_reg_i.
//   idle_o: no busy flag set (nothing in flight).
`default_nettype none
module fp3_regfile #(
  parameter integer NUM_REGS = 32,
  parameter integer IW       = 5    // index width, clog2(NUM_REGS)
) (
  input  wire          clk_i,
  input  wire          rst_i,
  input  wire [IW-1:0] ra_i,
  input  wire [IW-1:0] rb_i,
  input  wire [IW-1:0] rd_i,
  output wire [31:0]   ra_data_o,
  output wire [31:0]   rb_data_o,
  output wire          ra_ready_o,
  output wire          rb_ready_o,
  output wire          rd_busy_o,
  input  wire          set_i,
  input  wire [IW-1:0] set_reg_i,
  input  wire          wb0_valid_i,
  input  wire [IW-1:0] wb0_reg_i,
  input  wire [31:0]   wb0_data_i,
  input  wire          wb1_valid_i,
  input  wire [IW-1:0] wb1_reg_i,
  input  wire [31:0]   wb1_data_i,
  input  wire          wb2_valid_i,
  input  wire [IW-1:0] wb2_reg_i,
  input  wire [31:0]   wb2_data_i,
  input  wire          host_we_i,
  input  wire [IW-1:0] host_reg_i,
  input  wire [31:0]   host_wdata_i,
  output wire [31:0]   host_rdata_o,
  output wire          idle_o
);
  reg [31:0]         regs_q [0:NUM_REGS-1];
  reg [NUM_REGS-1:0] busy_q;

  // ---- reads with bypass (indices are < NUM_REGS: the scheduler decodes
  // ---- only legal instructions, the host port checks its address) -------
  function written;  // a write-back port writes r in this cycle
    input [IW-1:0] r;
    begin
      written = (wb0_valid_i && wb0_reg_i == r) || (wb1_valid_i && wb1_reg_i == r) ||
                (wb2_valid_i && wb2_reg_i == r);
    end
  endfunction

  function [31:0] read_port;  // the register's value, bypassed
    input [IW-1:0] r;
    begin
      if      (wb0_valid_i && wb0_reg_i == r) read_port = wb0_data_i;
      else if (wb1_valid_i && wb1_reg_i == r) read_port = wb1_data_i;
      else if (wb2_valid_i && wb2_reg_i == r) read_port = wb2_data_i;
      else                                    read_port = regs_q[r];
    end
  endfunction

  assign ra_data_o    = read_port(ra_i);
  assign rb_data_o    = read_port(rb_i);
  assign ra_ready_o   = !busy_q[ra_i] || written(ra_i);
  assign rb_ready_o   = !busy_q[rb_i] || written(rb_i);
  assign rd_busy_o    = busy_q[rd_i] && !written(rd_i);
  assign host_rdata_o = regs_q[host_reg_i];
  assign idle_o       = (busy_q == {NUM_REGS{1'b0}});

  // ---- writes and busy flags, one register at a time ----------------------
  // The WAW stall guarantees that the write ports name distinct registers,
  // so the write priority below never matters for a legal sequence.  A
  // register whose result is written back in the cycle a new instruction
  // claims it stays busy: the set wins over the clear.
  genvar r;
  generate
    for (r = 0; r < NUM_REGS; r = r + 1) begin : g_reg
      localparam [IW-1:0] IDX = r[IW-1:0];
      wire hit0 = wb0_valid_i && wb0_reg_i == IDX;
      wire hit1 = wb1_valid_i && wb1_reg_i == IDX;
      wire hit2 = wb2_valid_i && wb2_reg_i == IDX;
      always @(posedge clk_i) begin
        if      (hit0) regs_q[r] <= wb0_data_i;
        else if (hit1) regs_q[r] <= wb1_data_i;
        else if (hit2) regs_q[r] <= wb2_data_i;
        else if (host_we_i && host_reg_i == IDX) regs_q[r] <= host_wdata_i;
      end
      always @(posedge clk_i) begin
        if (rst_i)                               busy_q[r] <= 1'b0;
        else if (set_i && set_reg_i == IDX)      busy_q[r] <= 1'b1;
        else if (hit0 || hit1 || hit2)           busy_q[r] <= 1'b0;
      end
    end
  endgenerate

`ifdef FORMAL
  // Two write ports never name the same register in one cycle.
  always @(*) begin
    if (wb0_valid_i && wb1_valid_i) assert (wb0_reg_i != wb1_reg_i);
    if (wb0_valid_i && wb2_valid_i) assert (wb0_reg_i != wb2_reg_i);
    if (wb1_valid_i && wb2_valid_i) assert (wb1_reg_i != wb2_reg_i);
  end
`endif
endmodule
`default_nettype wire
