# wave.mk -- make wave: the RTL in Icarus Verilog with a self-checking
# testbench (sim/tb_fp3.v) and a waveform for GTKWave (sim/fp3.gtkw).
#
#   make wave [PROGRAM=programs/ship_rk4.s] [MODEL=models/ship.fp3m] [STEPS=10]
#             [WAVE_FORMAT=vcd|fst] [SET='T=0 v0=0']
#             [WAVE_ARGS='+dump_load +watchdog=N ...']
#
# PROGRAM: a model's hand-written program (fp3 run --program: .model,
# .integrator, .in/.out by the model's names); MODEL: its model when the
# program has no .model line.  SET: values NAME=VALUE of the model's
# object (fp3 run --set: h, params, NAME or NAME0 of a state variable),
# e.g. a ship at rest.
#
# 1. build/fp3 tbgen assembles PROGRAM, binds it to its model and writes
#    program.hex, init.hex, run.hex and expected.hex (ISS results checked
#    against the golden model, Verilator cycle counts) into $(WAVE_DIR);
#    an assembler, model or binding error stops make here.
# 2. iverilog -g2005 compiles the testbench and the modules it needs from
#    rtl/ (a library directory, -y), with the model parameters
#    NUM_CONTEXTS NUM_LANES NUM_REGS ... FTZ HAS_ADD HAS_SUB HAS_MUL of mk/rtl.mk when given
#    (with NUM_LANES every lane runs the object and is checked).
# 3. vvp runs it: PASS or FAIL, the watchdog ends a hung run; make fails
#    unless the last word is PASS.  The waveform is $(WAVE_DIR)/fp3.vcd
#    (or .fst): gtkwave $(WAVE_DIR)/fp3.vcd sim/fp3.gtkw
#
# tests/test_wave.sh runs it on the ship program and a spring program, and
# its negative cases.

WAVE_DIR     ?= $(BUILD)/wave
WAVE_FORMAT  ?= vcd
WAVE_ARGS    ?=
# the RTL to simulate (another tree, e.g. a candidate fix: WAVE_RTL_DIR=dir)
WAVE_RTL_DIR ?= rtl
IVERILOG     ?= iverilog
VVP          ?= vvp
WAVE_PROGRAM  = $(or $(PROGRAM),programs/ship_rk4.s)
WAVE_STEPS    = $(or $(STEPS),10)
WAVE_PARAMS  := $(foreach p,NUM_CONTEXTS NUM_LANES NUM_REGS IMEM_DEPTH ADD_LATENCY MUL_LATENCY ROUND FTZ HAS_ADD HAS_SUB HAS_MUL HAS_DIV HAS_SQRT FMAX_PIPE WB_PORTS,\
                  $(if $($(p)),-Ptb_fp3.$(p)=$($(p))))
# Every module gets 1 ns units (neither the RTL nor the testbench has a
# `timescale); Icarus takes that from a command file.
WAVE_IVFLAGS := -g2005 -Wall -I$(WAVE_RTL_DIR) -y $(WAVE_RTL_DIR) -s tb_fp3 $(WAVE_PARAMS)
WAVE_VVPFMT  := $(if $(filter fst,$(WAVE_FORMAT)),-fst,)

.PHONY: wave
## wave: the self-checking Icarus testbench and its waveform (GTKWave save file sim/fp3.gtkw)
wave: $(BUILD)/fp3 | $(SETUP_STAMP)
	@mkdir -p $(WAVE_DIR)
	$(BUILD)/fp3 tbgen $(WAVE_PROGRAM) -o $(WAVE_DIR) --steps $(WAVE_STEPS) \
	  $(if $(MODEL),--model $(MODEL)) $(foreach s,$(SET),--set $(s)) \
	  $(if $(filter 1,$(ROUND)),--round rtz) $(if $(filter 1,$(FTZ)),--ftz)
	@printf '+timescale+1ns/1ns\n' > $(WAVE_DIR)/iverilog.cmd
	$(IVERILOG) $(WAVE_IVFLAGS) -c $(WAVE_DIR)/iverilog.cmd -o $(WAVE_DIR)/tb_fp3.vvp \
	  sim/tb_fp3.v
	@rm -f $(WAVE_DIR)/fp3.vcd $(WAVE_DIR)/fp3.fst
	@$(VVP) -n $(WAVE_DIR)/tb_fp3.vvp $(WAVE_VVPFMT) +dir=$(WAVE_DIR) \
	  +wave=$(WAVE_DIR)/fp3.$(WAVE_FORMAT) $(WAVE_ARGS) >$(WAVE_DIR)/tb_fp3.log 2>&1; \
	  rc=$$?; cat $(WAVE_DIR)/tb_fp3.log; \
	  if [ $$rc -ne 0 ] || [ "$$(tail -n 1 $(WAVE_DIR)/tb_fp3.log | cut -d: -f1)" != PASS ]; then \
	    echo "make wave: FAIL (vvp exit $$rc; log $(WAVE_DIR)/tb_fp3.log)"; exit 1; fi
	@echo "wave: $(WAVE_DIR)/fp3.$(WAVE_FORMAT) ($$(du -h $(WAVE_DIR)/fp3.$(WAVE_FORMAT) | cut -f1));" \
	  "view: gtkwave $(WAVE_DIR)/fp3.$(WAVE_FORMAT) sim/fp3.gtkw"

TEST_SCRIPTS += tests/test_wave.sh

# FuseSoC: fp3.core's lint, sim and synth targets through `fusesoc`
TEST_SCRIPTS += tests/test_fusesoc.sh
