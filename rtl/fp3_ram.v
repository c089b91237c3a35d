// fp3_ram -- simple dual-port RAM: one write port, one read port whose
// word leaves a register.  Contents start at zero.
//
//   READ_STAGES = 1  registered read (read-first: a read and a write of
//                    one address at the same edge return the old word).
//                    The shape of FPGA block RAM (Xilinx RAMB16, Lattice
//                    DP16KD) and LUT RAM with an output register; Yosys
//                    infers either.  The default.
//   READ_STAGES = 2  for clock rate: LUT RAM (ECP5 TRELLIS_DPR16X4, 16
//                    words x 4 bits), in lanes of 4 bits.  Cycle t: the
//                    read address is registered, one copy per lane (so
//                    that it does not fan out to every LUT-RAM cell of the
//                    word from one flip-flop); cycle t + 1: each lane's
//                    LUT RAM is read at its copy (the bank of 16 words
//                    chosen by the high bits) and the word registered: it
//                    leaves a flip-flop (a block RAM's leaves it 5.8 ns
//                    after the clock on the ECP5).  The write is
//                    registered per lane too, and lands a cycle late: the
//                    word read is the one after the writes of cycles up
//                    to t - 1.
//
// Parameters
//   DEPTH        words, >= 2; AW address width, clog2(DEPTH) at least
//   WIDTH        bits per word
//   READ_STAGES  1 or 2, see above
// Ports
//   we_i/waddr_i/wdata_i  write at the rising edge
//   raddr_i (cycle t) -> rdata_o (cycle t + READ_STAGES)
// The words as written are g_any.mem[] in every form (a testbench's view
// of the contents; sim/tb_fp3.v reads the register file's).
`default_nettype none
module fp3_ram #(
  parameter integer DEPTH = 32,
  parameter integer AW    = 5,
  parameter integer WIDTH = 32,
  parameter integer READ_STAGES = 1
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
    if (READ_STAGES == 1) begin : g_any
      reg [WIDTH-1:0] mem [0:DEPTH-1];
      initial for (i = 0; i < DEPTH; i = i + 1) mem[i] = {WIDTH{1'b0}};
      always @(posedge clk_i) begin
        if (we_i) mem[waddr_i] <= wdata_i;
        rdata_o <= mem[raddr_i];
      end
    end else if (READ_STAGES == 2) begin : g_any
      // The whole words, for a testbench only: nothing reads them, and
      // synthesis removes them.  (The blocks of one conditional generate
      // may share a name, IEEE 1364-2005 12.4.3: g_any.mem in either form.)
      /* verilator lint_off UNUSEDSIGNAL */
      reg [WIDTH-1:0] mem [0:DEPTH-1];
      /* verilator lint_on UNUSEDSIGNAL */
      initial for (i = 0; i < DEPTH; i = i + 1) mem[i] = {WIDTH{1'b0}};
      always @(posedge clk_i) if (we_i) mem[waddr_i] <= wdata_i;
      localparam integer LANES = (WIDTH + 3) / 4;
      genvar l;
      for (l = 0; l < LANES; l = l + 1) begin : g_lane
        localparam integer LW = (WIDTH - 4 * l < 4) ? WIDTH - 4 * l : 4;
        // The lanes' copies of the address are equal registers, which
        // Yosys would merge into one (and hang every lane on it): the
        // process is kept, and the initial value keeps the copies apart
        // from equal registers without one elsewhere.
        // The write's copies likewise.
        reg              we_q;
        reg [AW-1:0]     raddr_q, waddr_q;
        reg [LW-1:0]     wdata_q;
        (* ram_style = "distributed" *) reg [LW-1:0] lane [0:DEPTH-1];
        initial begin
          we_q    = 1'b0;
          raddr_q = {AW{1'b0}};
          waddr_q = {AW{1'b0}};
          wdata_q = {LW{1'b0}};
          for (i = 0; i < DEPTH; i = i + 1) lane[i] = {LW{1'b0}};
        end
        (* keep *) always @(posedge clk_i) begin
          raddr_q <= raddr_i;
          we_q    <= we_i;
          waddr_q <= waddr_i;
          wdata_q <= wdata_i[4*l +: LW];
        end
        always @(posedge clk_i) begin
          if (we_q) lane[waddr_q] <= wdata_q;
          rdata_o[4*l +: LW] <= lane[raddr_q];
        end
      end
    end else begin : g_bad_read_stages
      // Elaboration error on purpose: READ_STAGES must be 1 or 2.
      fp3_ram_error_READ_STAGES_must_be_1_or_2 u_error ();
    end
  endgenerate
endmodule
`default_nettype wire
