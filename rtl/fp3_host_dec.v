// fp3_host_dec -- the host port's address decode: which writable register
// or window of the host-port map (HR_* in rtl/fp3_isa.vh, generated from
// sw/isa/fp3_isa.h) a 12-bit word address names.  Combinational.
//
// fp3_top decodes its host address with it; fp3_axil decodes a write's
// address as it is captured from the bus, holds the result with it and
// hands it to fp3_top (HOST_WSEL = 1), so that the host's write
// strobes reach the core's register enables from flip-flops through one
// gate instead of a 12-bit compare (the host address -> a host
// register's enable is otherwise a critical path of the build for clock
// rate).
//
// Parameters
//   NUM_REGS    registers per context; IW = clog2(NUM_REGS)
//   IMEM_DEPTH  instruction memory entries; AW = clog2(IMEM_DEPTH)
// Ports
//   addr_i   host word address, 12 bits
//   wsel_o   one-hot (or zero: no writable register), 8 bits:
//            0 CTRL, 1 STEPS, 2 CONTEXTS, 3 CTX,
//            4 the register window, register index < NUM_REGS,
//            5 the program window, a low word (any index: the core
//              stores it only with its high word),
//            6 the program window, a high word, index < IMEM_DEPTH,
//            7 LANE
//   imem_ok_o  addr_i[10:1], as a program window's index, is below
//            IMEM_DEPTH (whatever the window; fp3_axil's check of a low
//            word)
`default_nettype none
module fp3_host_dec #(
  parameter integer NUM_REGS   = 32,
  parameter integer IW         = 5,
  parameter integer IMEM_DEPTH = 256,
  parameter integer AW         = 8
) (
  input  wire [11:0] addr_i,
  output wire [7:0]  wsel_o,
  output wire        imem_ok_o
);
`include "fp3_isa.vh"
  wire       win_reg  = addr_i[11:8] == HR_REG_BASE[11:8];
  wire       win_imem = addr_i[11] == HR_IMEM_BASE[11];
  wire [9:0] imem_idx = addr_i[10:1];
  // (compares with a constant as high bits zero when it is a power of
  // two: Yosys maps such a compare to a carry chain, which was on a
  // critical path, the host's write -> the register file)
  wire       reg_ok   = (addr_i[7:0] >> IW) == 8'd0 &&
                        (NUM_REGS == (1 << IW) || {24'd0, addr_i[7:0]} < NUM_REGS);
  wire       imem_ok  = (imem_idx >> AW) == 10'd0 &&
                        (IMEM_DEPTH == (1 << AW) || {22'd0, imem_idx} < IMEM_DEPTH);
  assign imem_ok_o = imem_ok;
  assign wsel_o = {addr_i == HR_LANE,
                   win_imem && imem_ok && addr_i[0], win_imem && !addr_i[0],
                   win_reg && reg_ok, addr_i == HR_CTX, addr_i == HR_CONTEXTS,
                   addr_i == HR_STEPS, addr_i == HR_CTRL};
endmodule
`default_nettype wire
