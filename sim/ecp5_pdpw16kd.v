// ecp5_pdpw16kd.v -- a simulation model of the part of Lattice's ECP5
// PDPW16KD block RAM (512 x 36 pseudo-dual-port) that fp3_ram's ECP5 form
// uses (rtl/fp3_ram.v, FP3_ECP5_EBR), for the post-synthesis check of that
// form (tests/test_ram_ebr.sh).  Written from the ECP5 memory usage guide
// (Lattice FPGA-TN-02204): Yosys's own model of the block is a blackbox.
//
// Modelled: 36-bit write and read ports on one clock, chip selects against
// CSDECODE_W/CSDECODE_R, byte enables BE0..3 (9 bits each), CEW, CER;
// the read address's word in ADR[13:5] (36 bits wide), the write's in
// ADW[8:0]; REGMODE "NOREG" (the word read at a rising CLKR edge with CER
// is on DO after it) or "OUTREG" (it passes the output register, with
// OCER, at the next edge: one cycle more); RST clears the output (SYNC).
// Contents start at zero.  A read and a write of one word at the same
// edge give the old word here; the block promises neither, and the
// check does not use such reads.
// Any other configuration stops the simulation with an error.
`default_nettype none
module PDPW16KD #(
  parameter integer DATA_WIDTH_W = 36,
  parameter integer DATA_WIDTH_R = 36,
  parameter GSR                  = "ENABLED",
  parameter REGMODE              = "NOREG",
  parameter RESETMODE            = "SYNC",
  parameter ASYNC_RESET_RELEASE  = "SYNC",
  parameter CSDECODE_W           = "0b000",
  parameter CSDECODE_R           = "0b000",
  parameter INIT_DATA            = "STATIC",
  parameter CLKWMUX              = "CLKW",
  parameter CLKRMUX              = "CLKR"
) (
  input  wire DI35, DI34, DI33, DI32, DI31, DI30, DI29, DI28, DI27, DI26, DI25, DI24,
  input  wire DI23, DI22, DI21, DI20, DI19, DI18, DI17, DI16, DI15, DI14, DI13, DI12,
  input  wire DI11, DI10, DI9, DI8, DI7, DI6, DI5, DI4, DI3, DI2, DI1, DI0,
  input  wire ADW8, ADW7, ADW6, ADW5, ADW4, ADW3, ADW2, ADW1, ADW0,
  input  wire BE3, BE2, BE1, BE0, CEW, CLKW, CSW2, CSW1, CSW0,
  input  wire ADR13, ADR12, ADR11, ADR10, ADR9, ADR8, ADR7, ADR6, ADR5, ADR4, ADR3,
  input  wire ADR2, ADR1, ADR0,
  input  wire CER, OCER, CLKR, CSR2, CSR1, CSR0, RST,
  output wire DO35, DO34, DO33, DO32, DO31, DO30, DO29, DO28, DO27, DO26, DO25, DO24,
  output wire DO23, DO22, DO21, DO20, DO19, DO18, DO17, DO16, DO15, DO14, DO13, DO12,
  output wire DO11, DO10, DO9, DO8, DO7, DO6, DO5, DO4, DO3, DO2, DO1, DO0
);
  // "0b101" -> 3'b101
  function [2:0] cs_bits;
    input [8*5-1:0] s;
    begin
      cs_bits = {s[16] , s[8], s[0]};   // the last three characters, '0' or '1'
    end
  endfunction
  initial begin
    if (DATA_WIDTH_W != 36 || DATA_WIDTH_R != 36 ||
        (REGMODE != "NOREG" && REGMODE != "OUTREG") || RESETMODE != "SYNC" ||
        CLKWMUX != "CLKW" || CLKRMUX != "CLKR") begin
      $display("PDPW16KD model: configuration not modelled (widths %0d/%0d, REGMODE %0s)",
               DATA_WIDTH_W, DATA_WIDTH_R, REGMODE);
      $finish;
    end
  end
  wire [35:0] di = {DI35, DI34, DI33, DI32, DI31, DI30, DI29, DI28, DI27, DI26, DI25, DI24,
                    DI23, DI22, DI21, DI20, DI19, DI18, DI17, DI16, DI15, DI14, DI13, DI12,
                    DI11, DI10, DI9, DI8, DI7, DI6, DI5, DI4, DI3, DI2, DI1, DI0};
  wire [8:0]  wa = {ADW8, ADW7, ADW6, ADW5, ADW4, ADW3, ADW2, ADW1, ADW0};
  wire [8:0]  ra = {ADR13, ADR12, ADR11, ADR10, ADR9, ADR8, ADR7, ADR6, ADR5};
  wire [3:0]  be = {BE3, BE2, BE1, BE0};
  wire        wsel = {CSW2, CSW1, CSW0} == cs_bits(CSDECODE_W);
  wire        rsel = {CSR2, CSR1, CSR0} == cs_bits(CSDECODE_R);
  reg  [35:0] mem [0:511];
  reg  [35:0] lat, out;
  integer i;
  initial begin
    for (i = 0; i < 512; i = i + 1) mem[i] = 36'd0;
    lat = 36'd0;
    out = 36'd0;
  end
  always @(posedge CLKW)
    if (CEW && wsel)
      for (i = 0; i < 4; i = i + 1)
        if (be[i]) mem[wa][9*i +: 9] <= di[9*i +: 9];
  always @(posedge CLKR) begin
    if (RST)              lat <= 36'd0;
    else if (CER && rsel) lat <= mem[ra];
    if (RST)              out <= 36'd0;
    else if (OCER)        out <= lat;
  end
  wire [35:0] dq = REGMODE == "OUTREG" ? out : lat;
  assign {DO35, DO34, DO33, DO32, DO31, DO30, DO29, DO28, DO27, DO26, DO25, DO24,
          DO23, DO22, DO21, DO20, DO19, DO18, DO17, DO16, DO15, DO14, DO13, DO12,
          DO11, DO10, DO9, DO8, DO7, DO6, DO5, DO4, DO3, DO2, DO1, DO0} = dq;
endmodule
`default_nettype wire
