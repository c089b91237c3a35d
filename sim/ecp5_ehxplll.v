// ecp5_ehxplll.v -- a simulation model of the part of Lattice's ECP5
// EHXPLLL (phase-locked loop) that a board's generated PLL uses
// (boards/*/..._pll.v, yowasp-ecppll): CLKOP follows CLKI (the model does
// not multiply: a testbench drives CLKI at the output frequency it wants),
// LOCK rises after 16 cycles of CLKI.  For lint and simulation of a board
// top with its PLL in place; Yosys's own EHXPLLL is a blackbox, and
// nextpnr places the real block.  The other outputs are 0.
`default_nettype none
// The configuration is the real block's; the model does not use it.
/* verilator lint_off UNUSEDPARAM */
module EHXPLLL #(
  parameter PLLRST_ENA      = "DISABLED",
  parameter INTFB_WAKE      = "DISABLED",
  parameter STDBY_ENABLE    = "DISABLED",
  parameter DPHASE_SOURCE   = "DISABLED",
  parameter OUTDIVIDER_MUXA = "DIVA",
  parameter OUTDIVIDER_MUXB = "DIVB",
  parameter OUTDIVIDER_MUXC = "DIVC",
  parameter OUTDIVIDER_MUXD = "DIVD",
  parameter integer CLKI_DIV     = 1,
  parameter CLKOP_ENABLE    = "ENABLED",
  parameter integer CLKOP_DIV    = 8,
  parameter integer CLKOP_CPHASE = 0,
  parameter integer CLKOP_FPHASE = 0,
  parameter FEEDBK_PATH     = "CLKOP",
  parameter integer CLKFB_DIV    = 1
) (
  input  wire RST, STDBY, CLKI, CLKFB, PHASESEL0, PHASESEL1, PHASEDIR, PHASESTEP,
  input  wire PHASELOADREG, PLLWAKESYNC, ENCLKOP,
  output wire CLKOP, CLKINTFB, LOCK
);
/* verilator lint_on UNUSEDPARAM */
  reg [4:0] count_q = 5'd0;
  always @(posedge CLKI)
    if (RST) count_q <= 5'd0;
    else if (!count_q[4]) count_q <= count_q + 5'd1;
  assign CLKOP    = CLKI;
  assign CLKINTFB = 1'b0;
  assign LOCK     = count_q[4];
  // the configuration and the phase controls do not change the model
  wire unused = &{1'b0, STDBY, CLKFB, PHASESEL0, PHASESEL1, PHASEDIR, PHASESTEP,
                  PHASELOADREG, PLLWAKESYNC, ENCLKOP};
endmodule
`default_nettype wire
