// fp3_ulx3s -- the top of FP3 on the ULX3S (Radiona, LFE5U-85F-6
// CABGA381; pins from the board's public ulx3s_v20.lpf, the used ones in
// boards/ulx3s/ulx3s.lpf): the 25 MHz crystal through the PLL
// (ulx3s_pll, 100 MHz), fp3_board on the FT231X's serial line at
// CLKS_PER_BIT clocks a bit, its eight LEDs, the PWR button as a reset,
// and the ESP32's GPIO0 held high (else the ESP32 may take the
// configuration pins and reset the FPGA).
//
// Parameters
//   PLL_BYPASS    0: the system clock is the PLL's (the bitstream);
//                 1: clk_25mhz is the system clock itself and the clock is
//                 taken as locked (simulation: sim/board_sim.cpp drives
//                 clk_25mhz at whatever rate it likes)
//   CLKS_PER_BIT  clock cycles per UART bit: 33 for 3 Mbaud at 100 MHz
//                 (docs/board.md "Clock and baud rate")
//   TIMEOUT       cycles after which the bridge drops an unfinished frame:
//                 100 ms at 100 MHz, as LiteX's UART bridge
//   HEARTBEAT_BIT the heartbeat LED's counter bit
// Ports (the names of ulx3s_v20.lpf)
//   clk_25mhz     25 MHz crystal
//   ftdi_txd      serial data from the host (the FT231X's TXD): FPGA input
//   ftdi_rxd      serial data to the host (the FT231X's RXD): FPGA output
//   led           LEDs 0 .. 7 (fp3_board)
//   btn           btn[0], PWR, active low: reset
//   wifi_gpio0    driven high
`default_nettype none
module fp3_ulx3s #(
  parameter integer PLL_BYPASS    = 0,
  parameter integer CLKS_PER_BIT  = 33,
  parameter integer TIMEOUT       = 10_000_000,
  parameter integer HEARTBEAT_BIT = 26
) (
  input  wire       clk_25mhz,
  input  wire       ftdi_txd,
  output wire       ftdi_rxd,
  output wire [7:0] led,
  input  wire [0:0] btn,
  output wire       wifi_gpio0
);
  wire clk, locked;
  generate
    if (PLL_BYPASS != 0) begin : g_bypass
      assign clk    = clk_25mhz;
      assign locked = 1'b1;
    end else begin : g_pll
      ulx3s_pll u_pll (
        .clkin   (clk_25mhz),
        .clkout0 (clk),
        .locked  (locked)
      );
    end
  endgenerate

  fp3_board #(
    .CLKS_PER_BIT  (CLKS_PER_BIT),
    .TIMEOUT       (TIMEOUT),
    .HEARTBEAT_BIT (HEARTBEAT_BIT)
  ) u_board (
    .clk_i     (clk),
    .locked_i  (locked),
    .rst_btn_i (!btn[0]),
    .uart_rx_i (ftdi_txd),
    .uart_tx_o (ftdi_rxd),
    .led_o     (led)
  );

  assign wifi_gpio0 = 1'b1;
endmodule
`default_nettype wire
