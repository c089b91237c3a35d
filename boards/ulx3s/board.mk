# boards/ulx3s/board.mk -- the ULX3S 85F (Radiona): everything of this
# board that mk/board.mk's make bitstream, make prog and the simulated
# board need.  A second board is a folder like this one (docs/board.md
# "Adding a board").
#
#   ULX3S_REV  the board's revision: wifi_gpio0 (the ESP32's GPIO0, held
#              high) is on L2 on v2.x and v3.0.x boards, on F1 from v3.1.

BOARD_NAME        := ULX3S 85F (LFE5U-85F-6 CABGA381)
BOARD_TOP         := fp3_ulx3s
BOARD_SRC         := boards/ulx3s/fp3_ulx3s.v boards/ulx3s/ulx3s_pll.v
BOARD_LPF         := boards/ulx3s/ulx3s.lpf
BOARD_NEXTPNR     := --85k --package CABGA381 --speed 6
# The system clock (the PLL's output, boards/ulx3s/ulx3s_pll.v) and the
# serial line's rate: CLKS_PER_BIT = round(100 MHz / 3 Mbaud) = 33
# (docs/board.md "Clock and baud rate").
BOARD_CLOCK_MHZ   := 100
BOARD_BAUD        := 3000000
BOARD_PROG        := openFPGALoader --board ulx3s
# The top's parameters in simulation (sim/board_sim.cpp): the PLL bypassed
# (the harness drives the system clock itself), 4 clocks a bit, frames
# dropped after 65,536 idle cycles, a heartbeat that toggles every 1,024.
BOARD_SIM_PARAMS  := -GPLL_BYPASS=1 -GCLKS_PER_BIT=4 -GTIMEOUT=65536 -GHEARTBEAT_BIT=10
BOARD_SIM_CLKS_PER_BIT := 4

ULX3S_REV ?= 3.0
ifeq ($(ULX3S_REV),3.1)
BOARD_LPF_EXTRA   := LOCATE COMP "wifi_gpio0" SITE "F1";
else
BOARD_LPF_EXTRA   := LOCATE COMP "wifi_gpio0" SITE "L2";
endif
BOARD_LPF_EXTRA   += IOBUF PORT "wifi_gpio0" PULLMODE=UP IO_TYPE=LVCMOS33 DRIVE=4;
