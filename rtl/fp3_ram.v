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
//                    leaves a flip-flop (a block RAM's own output, without
//                    its register, 5.8 ns after the clock on the ECP5).
//                    The write is registered per lane too, and lands a
//                    cycle late: the word read is the one after the
//                    writes of cycles up to t - 1.
//                    In ECP5 synthesis (FP3_ECP5_EBR, set by
//                    scripts/synth.sh) and up to 512 words: block RAM
//                    with its output register instead, the same read
//                    (g_any below; tests/test_ram_ebr.sh checks it).
//
// Parameters
//   DEPTH        words, >= 2; AW address width, clog2(DEPTH) at least
//   WIDTH        bits per word
//   READ_STAGES  1 or 2, see above
// Ports
//   we_i/waddr_i/wdata_i  write at the rising edge
//   raddr_i (cycle t) -> rdata_o (cycle t + READ_STAGES)
// The words as written are g_any.mem[] in every simulated form (a
// testbench's view of the contents; sim/tb_fp3.v reads the register
// file's).
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
  output wire [WIDTH-1:0] rdata_o
);
  integer i;

  generate
    if (READ_STAGES == 1) begin : g_any
      reg [WIDTH-1:0] mem [0:DEPTH-1];
      reg [WIDTH-1:0] rd_q;
      initial begin
        for (i = 0; i < DEPTH; i = i + 1) mem[i] = {WIDTH{1'b0}};
        rd_q = {WIDTH{1'b0}};
      end
      always @(posedge clk_i) begin
        if (we_i) mem[waddr_i] <= wdata_i;
        rd_q <= mem[raddr_i];
      end
      assign rdata_o = rd_q;
`ifdef FP3_ECP5_EBR
    end else if (READ_STAGES == 2 && DEPTH <= 512) begin : g_any
      // ECP5 synthesis only (scripts/synth.sh defines FP3_ECP5_EBR; no
      // simulator sees this form): block RAM with its output register,
      // which Yosys does not infer, instantiated: one PDPW16KD (512 x 36
      // pseudo-dual-port, Lattice FPGA-TN-02204 "ECP5 and ECP5-5G Memory
      // Usage Guide") per 36 bits of the word, REGMODE "OUTREG".  The
      // block registers the read address at the edge ending cycle t and
      // the word in its output register at the next, so the word leaves
      // a register (0.97 ns after the clock in nextpnr's model, against
      // 5.83 ns without it) in cycle t + 2, as in the LUT-RAM form.  The
      // write lands at the edge ending its own cycle, a cycle earlier than
      // the LUT RAM's, so a read of cycle t has the writes up to t - 1 in
      // both; for a write and a read of one address in the same cycle the
      // block gives no promise, and neither form's word is used then (the
      // register file bypasses the writes of the read's cycle; the
      // instruction memory is written only while stopped).  Contents
      // start at zero (INITVAL).
      localparam integer BLOCKS = (WIDTH + 35) / 36;
      wire [36*BLOCKS-1:0] di = wdata_i;  // (zero-extended)
      wire [36*BLOCKS-1:0] dq;
      wire [8:0]  wa = waddr_i;
      wire [13:0] ra = {raddr_i, 5'd0};   // 36 bits wide: word address in ADR[13:5]
      genvar b;
      for (b = 0; b < BLOCKS; b = b + 1) begin : g_ebr
        wire [35:0] d = di[36*b +: 36];
        wire [35:0] q;
        PDPW16KD #(
          .DATA_WIDTH_W(36), .DATA_WIDTH_R(36), .REGMODE("OUTREG"), .RESETMODE("SYNC"),
          .GSR("DISABLED"), .CSDECODE_W("0b000"), .CSDECODE_R("0b000"),
          .CLKWMUX("CLKW"), .CLKRMUX("CLKR")
        ) u_ebr (
          .DI0(d[0]),   .DI1(d[1]),   .DI2(d[2]),   .DI3(d[3]),   .DI4(d[4]),   .DI5(d[5]),
          .DI6(d[6]),   .DI7(d[7]),   .DI8(d[8]),   .DI9(d[9]),   .DI10(d[10]), .DI11(d[11]),
          .DI12(d[12]), .DI13(d[13]), .DI14(d[14]), .DI15(d[15]), .DI16(d[16]), .DI17(d[17]),
          .DI18(d[18]), .DI19(d[19]), .DI20(d[20]), .DI21(d[21]), .DI22(d[22]), .DI23(d[23]),
          .DI24(d[24]), .DI25(d[25]), .DI26(d[26]), .DI27(d[27]), .DI28(d[28]), .DI29(d[29]),
          .DI30(d[30]), .DI31(d[31]), .DI32(d[32]), .DI33(d[33]), .DI34(d[34]), .DI35(d[35]),
          .ADW0(wa[0]), .ADW1(wa[1]), .ADW2(wa[2]), .ADW3(wa[3]), .ADW4(wa[4]), .ADW5(wa[5]),
          .ADW6(wa[6]), .ADW7(wa[7]), .ADW8(wa[8]),
          .BE0(1'b1), .BE1(1'b1), .BE2(1'b1), .BE3(1'b1),
          .CEW(we_i), .CLKW(clk_i), .CSW0(1'b0), .CSW1(1'b0), .CSW2(1'b0),
          .ADR0(ra[0]),   .ADR1(ra[1]),   .ADR2(ra[2]),   .ADR3(ra[3]),   .ADR4(ra[4]),
          .ADR5(ra[5]),   .ADR6(ra[6]),   .ADR7(ra[7]),   .ADR8(ra[8]),   .ADR9(ra[9]),
          .ADR10(ra[10]), .ADR11(ra[11]), .ADR12(ra[12]), .ADR13(ra[13]),
          .CER(1'b1), .OCER(1'b1), .CLKR(clk_i), .CSR0(1'b0), .CSR1(1'b0), .CSR2(1'b0),
          .RST(1'b0),
          .DO0(q[0]),   .DO1(q[1]),   .DO2(q[2]),   .DO3(q[3]),   .DO4(q[4]),   .DO5(q[5]),
          .DO6(q[6]),   .DO7(q[7]),   .DO8(q[8]),   .DO9(q[9]),   .DO10(q[10]), .DO11(q[11]),
          .DO12(q[12]), .DO13(q[13]), .DO14(q[14]), .DO15(q[15]), .DO16(q[16]), .DO17(q[17]),
          .DO18(q[18]), .DO19(q[19]), .DO20(q[20]), .DO21(q[21]), .DO22(q[22]), .DO23(q[23]),
          .DO24(q[24]), .DO25(q[25]), .DO26(q[26]), .DO27(q[27]), .DO28(q[28]), .DO29(q[29]),
          .DO30(q[30]), .DO31(q[31]), .DO32(q[32]), .DO33(q[33]), .DO34(q[34]), .DO35(q[35]));
        assign dq[36*b +: 36] = q;
      end
      assign rdata_o = dq[WIDTH-1:0];
`endif
`ifdef VERILATOR
    end else if (READ_STAGES == 2) begin : g_any
      // For Verilator: the LUT-RAM form below with its lanes merged.  The
      // lanes' copies of the address and write registers hold equal
      // values and their LUT RAMs equal nibbles of one word, so one copy
      // of each and one array of whole words read and write the same words
      // in the same cycles.  The lanes are there for placement only; a
      // Verilated model evaluates every lane's registers and array every
      // cycle, which made them a sixth of the chip build's simulation time
      // (docs/lanes.md "Simulation speed").  Icarus, Yosys and the formal
      // tools see the lanes.
      // The words as written, for a testbench (as below); the LUT RAMs'.
      /* verilator lint_off UNUSEDSIGNAL */
      reg [WIDTH-1:0] mem [0:DEPTH-1];
      /* verilator lint_on UNUSEDSIGNAL */
      reg [WIDTH-1:0] words [0:DEPTH-1];
      reg             we_q;
      reg [AW-1:0]    raddr_q, waddr_q;
      reg [WIDTH-1:0] wdata_q, rd_q;
      initial begin
        for (i = 0; i < DEPTH; i = i + 1) begin
          mem[i]  = {WIDTH{1'b0}};
          words[i] = {WIDTH{1'b0}};
        end
        we_q    = 1'b0;
        raddr_q = {AW{1'b0}};
        waddr_q = {AW{1'b0}};
        wdata_q = {WIDTH{1'b0}};
        rd_q    = {WIDTH{1'b0}};
      end
      always @(posedge clk_i) begin
        if (we_i) mem[waddr_i] <= wdata_i;
        raddr_q <= raddr_i;
        we_q    <= we_i;
        waddr_q <= waddr_i;
        wdata_q <= wdata_i;
        if (we_q) words[waddr_q] <= wdata_q;
        rd_q <= words[raddr_q];
      end
      assign rdata_o = rd_q;
`endif
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
      reg [WIDTH-1:0] rd_q;
      initial rd_q = {WIDTH{1'b0}};
      assign rdata_o = rd_q;
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
          rd_q[4*l +: LW] <= lane[raddr_q];
        end
      end
    end else begin : g_bad_read_stages
      // Elaboration error on purpose: READ_STAGES must be 1 or 2.
      fp3_ram_error_READ_STAGES_must_be_1_or_2 u_error ();
    end
  endgenerate
endmodule
`default_nettype wire
