# rtl.mk -- the Verilated processor model, lint and synthesis.
#
# Exports RTL_OBJS (what an executable links to use sim/fp3_model.h: the
# models of all four FP core configurations) and RTL_DEPS.  NUM_CONTEXTS,
# NUM_LANES, NUM_REGS, IMEM_DEPTH, ADD_LATENCY, MUL_LATENCY, HAS_ADD,
# HAS_SUB, HAS_MUL, HAS_DIV, HAS_SQRT, HAS_SIGN, DIV_LATENCY, FMAX_PIPE,
# WB_PORTS and MUL_FEED on the make command line override the defaults of sw/isa/fp3_isa.h
# (e.g. `make sim ADD_LATENCY=6`); the C side reads the values back from
# the model's INFO registers.

RTL_TOP      := fp3_top
RTL_PARAMS   := $(foreach p,NUM_CONTEXTS NUM_LANES NUM_REGS IMEM_DEPTH ADD_LATENCY MUL_LATENCY HAS_ADD HAS_SUB HAS_MUL HAS_DIV HAS_SQRT HAS_SIGN DIV_LATENCY FMAX_PIPE \
                  WB_PORTS MUL_FEED,$(if $($(p)),-G$(p)=$($(p))))
RTL_VFLAGS   := $(VFLAGS) --trace -MAKEFLAGS OPT_FAST=-O2 --top-module $(RTL_TOP) $(RTL_PARAMS)

# One model per FP core configuration (FP3_MODEL_CONFIGS of
# sim/fp3_model.h): name := ROUND FTZ [NUM_CONTEXTS [ADD_LATENCY
# MUL_LATENCY [NUM_REGS HAS_ADD HAS_SUB HAS_MUL [FMAX_PIPE [NUM_LANES [HAS_DIV
# HAS_SQRT HAS_SIGN [WB_PORTS [MUL_FEED]]]]]]]].  The test
# programs also get models with 1 and 3 contexts, with other core latencies
# (shortest add, and no div/sqrt unit: HAS_DIV = HAS_SQRT = 0, the build a
# program with div or sqrt is refused on; FMAX_PIPE, the build for clock
# rate, with the shortest latencies it takes, whose write-back tag lines
# are too short for the full announcement lead: fp3_wb_tag).  The 3-context
# build also has NUM_REGS=40, the fewest registers that hold every shipped
# model's program (3-D rk4comp, folded, needs 40; tests/test_model.c runs
# the four that need more than 32 on it), and not a power of two, so the
# register check is a compare (r < NUM_REGS), not the index's high bits.
RTL_CONFIGS     := rne rtz ftz rtz_ftz
RTL_CFG_rne     := 0 0
RTL_CFG_rtz     := 1 0
RTL_CFG_ftz     := 0 1
RTL_CFG_rtz_ftz := 1 1
RTL_CFG_nc1     := 0 0 1 1 2 32 1 1 1 0 1 0 0
RTL_CFG_nc3     := 0 0 3 4 3 40 1 1 1 1
# ... and with lanes: 8 contexts of 4 lanes each (32 objects in flight).
RTL_CFG_l4      := 0 0 8 4 3 32 1 1 1 0 4
# ... and lanes in the build for clock rate: the chip build (CHIP_PARAMS
# below) in small, 4 contexts x 3 lanes, with its latencies and multiplier
# (the feed register in front of the DSP blocks), one write-back port,
# broadcast stages and split host read.
RTL_CFG_lf      := 0 0 4 10 10 32 1 1 1 1 3 0 0 1 1 1
RTL_TEST_CONFIGS := nc1 nc3 l4 lf
# ... and the throughput benchmark with 16, 32 and 64.
RTL_CFG_nc16    := 0 0 16
RTL_CFG_nc32    := 0 0 32
RTL_CFG_nc64    := 0 0 64
RTL_BENCH_CONFIGS := nc16 nc32 nc64
# ... and one build sized to a scene (tests/test_configure.c):
# words 4-5 are ADD_LATENCY MUL_LATENCY, 6-9 NUM_REGS HAS_ADD HAS_SUB HAS_MUL,
# 10 FMAX_PIPE, 11 NUM_LANES, 12-14 HAS_DIV HAS_SQRT HAS_SIGN, 15 WB_PORTS
# (one write-back port: both latencies 4).  `build/fp3 configure scenes/drift.scene`
# derives exactly these parameters (the test checks it).
RTL_CFG_drift   := 1 1 4 4 4 11 1 0 1 0 2 0 0 0 1
RTL_SCENE_CONFIGS := drift
# ... and the build for clock rate (docs/fpga.md), the processor inside the
# AXI4-Lite wrapper's build of the same parameters (mk/axil.mk), which
# tests/test_axil.c compares with it.
RTL_CFG_fmax    := 0 0 8 9 10 32 1 1 1 1
RTL_AXIL_CONFIGS := fmax
# ... and the lanes benchmark (make bench-chip, docs/lanes.md): 8 contexts
# of 2, 8 and 16 lanes (1 and 4: rne, l4), and the chip build, the build
# for clock rate with CHIP_CONTEXTS contexts of CHIP_LANES lanes sized to
# the LFE5U-85F (mk/pnr.mk CHIP=ecp5-85 places the same parameters).  16
# contexts hide the build for clock rate's latencies (8 leave the issue
# slot idle: 1.23 times the issue bound; f16 below).  Its multiplier is in
# MULT18X18D with the blocks' own input and output registers (fp_mul_prod
# LUT = 0, PRE = 1; fp_mul alone 162 MHz), which saves about 1,050 LUT4s a
# lane against the LUT product, and a fabric register in front of them
# (MUL_FEED: MUL_LATENCY 10 is the DSP product of 9 and that register):
# the route from a lane's logic to its blocks, across a full chip, gets a
# cycle of its own.  One write-back port
# (WB_PORTS=1: the move path delayed to the add's 10 cycles, no live value
# table) makes a lane about two thirds as large: 16 lanes are 58,968 LUT4s
# (70.5 %) and route (docs/lanes.md "Chip build").
# The chip build and f16 leave out the
# div/sqrt unit (HAS_DIV = HAS_SQRT = 0): at DIV_LATENCY 8 fp_div and
# fp_sqrt place at about 50-60 MHz, at 34 (every register place) above
# 165 MHz alone (docs/fp-cores.md), for about 4,500 LUT4s a lane and, at
# 34, 6,400 flip-flops; the ship's programs do not use them.
CHIP_CONTEXTS   := 16
CHIP_LANES      := 16
CHIP_PARAMS     := NUM_CONTEXTS=$(CHIP_CONTEXTS) NUM_LANES=$(CHIP_LANES) ADD_LATENCY=10 MUL_LATENCY=10 \
                   MUL_FEED=1 FMAX_PIPE=1 HAS_DIV=0 HAS_SQRT=0 WB_PORTS=1
RTL_CFG_l2      := 0 0 8 4 3 32 1 1 1 0 2
RTL_CFG_l8      := 0 0 8 4 3 32 1 1 1 0 8
RTL_CFG_l16     := 0 0 8 4 3 32 1 1 1 0 16
RTL_CFG_chip    := 0 0 $(CHIP_CONTEXTS) 10 10 32 1 1 1 1 $(CHIP_LANES) 0 0 1 1 1
# ... and the build for clock rate with 16 contexts, one lane: whether
# twice the contexts hide its latencies (a context's timing does not
# depend on its lanes).
RTL_CFG_f16     := 0 0 16 9 10 32 1 1 1 1 1 0 0 1
RTL_CHIP_CONFIGS := l2 l8 l16 chip f16

# The -G flags of configuration $(1): the words of RTL_CFG_$(1), in order.
RTL_CFG_PARAMS := ROUND FTZ NUM_CONTEXTS ADD_LATENCY MUL_LATENCY NUM_REGS HAS_ADD HAS_SUB HAS_MUL FMAX_PIPE \
                  NUM_LANES HAS_DIV HAS_SQRT HAS_SIGN WB_PORTS MUL_FEED
rtl_gparams = $(join $(patsubst %,-G%=,$(wordlist 1,$(words $(RTL_CFG_$(1))),$(RTL_CFG_PARAMS))),$(RTL_CFG_$(1)))

rtl_objdir  = $(BUILD)/obj_fp3_$(1)
rtl_archive = $(call rtl_objdir,$(1))/Vfp3_top_$(1)__ALL.a
rtl_shim    = $(BUILD)/sim/fp3_shim_$(1).o

RTL_OBJS := $(foreach c,$(RTL_CONFIGS),$(call rtl_shim,$(c)) $(call rtl_archive,$(c))) \
            $(VERILATED_OBJS) $(BUILD)/verilated/verilated_vcd_c.o
RTL_DEPS := $(RTL_OBJS)

# Rebuild the models when the sources, the parameters or the flags change.
RTL_PARAM_STAMP := $(BUILD)/obj_fp3.params.$(shell echo '$(RTL_VFLAGS)' | md5sum | cut -c1-8)

$(RTL_PARAM_STAMP):
	@mkdir -p $(BUILD)
	@rm -f $(BUILD)/obj_fp3.params.*
	@touch $@

# ... and when a configuration's words change (one stamp per configuration).
rtl_cfg_stamp = $(BUILD)/obj_fp3_$(1).cfg.$(shell echo '$(RTL_CFG_$(1))' | md5sum | cut -c1-8)

define RTL_MODEL_RULES
$(call rtl_cfg_stamp,$(1)):
	@mkdir -p $(BUILD)
	@rm -f $(BUILD)/obj_fp3_$(1).cfg.*
	@touch $$@

$(call rtl_archive,$(1)): $(RTL_SRC) $(RTL_INC) $(RTL_PARAM_STAMP) $(call rtl_cfg_stamp,$(1)) | $(SETUP_STAMP)
	@mkdir -p $(call rtl_objdir,$(1))
	$(VERILATOR) --cc --build -j 2 $(RTL_VFLAGS) $(call rtl_gparams,$(1)) \
	  --prefix Vfp3_top_$(1) --Mdir $(call rtl_objdir,$(1)) $(RTL_SRC) \
	  >$(call rtl_objdir,$(1))/build.log 2>&1 || { tail -40 $(call rtl_objdir,$(1))/build.log; exit 1; }

$(call rtl_shim,$(1)): sim/fp3_shim.cpp sim/fp3_model.h sim/vmodel.h $(call rtl_archive,$(1))
	@mkdir -p $$(dir $$@)
	$(CXX) $(VERILATOR_CXXFLAGS) -Isim -I$(call rtl_objdir,$(1)) -DFP3_CFG=$(1) -c $$< -o $$@
endef
$(foreach c,$(RTL_CONFIGS) $(RTL_TEST_CONFIGS) $(RTL_BENCH_CONFIGS) $(RTL_SCENE_CONFIGS) \
                  $(RTL_AXIL_CONFIGS) $(RTL_CHIP_CONFIGS),$(eval $(call RTL_MODEL_RULES,$(c))))
RTL_TEST_OBJS := $(foreach c,$(RTL_TEST_CONFIGS),$(call rtl_shim,$(c)) $(call rtl_archive,$(c)))

# rtl/fp3_isa.vh and the tables of docs/isa.md are generated from
# sw/isa/fp3_isa.h (and committed; tests/test_isa_sync.sh checks both).
$(BUILD)/gen_isa: sw/isa/gen_isa.c sw/isa/fp3_isa.h
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(CWARN) -Isw/isa $< -o $@

.PHONY: isa
## isa: regenerate rtl/fp3_isa.vh and the generated ISA tables from sw/isa/fp3_isa.h
isa: $(BUILD)/gen_isa
	$(BUILD)/gen_isa > rtl/fp3_isa.vh
	python3 scripts/isa-tables.py $(BUILD)/gen_isa docs/isa.md

# ---- lint ------------------------------------------------------------------
# The processor in the default build (every unit, the div/sqrt unit
# included), with lanes, without the div/sqrt unit and in the build for
# clock rate (its div/sqrt unit at DIV_LATENCY 34, every register place of
# fp_div), and the chip build (CHIP_PARAMS: lanes in the build for clock
# rate); the wrapper's variants: lint-axil (mk/axil.mk).
LINT_PARAMS := "" "-GNUM_LANES=4" "-GHAS_DIV=0 -GHAS_SQRT=0" "-GHAS_DIV=1 -GHAS_SQRT=0" \
               "-GFMAX_PIPE=1 -GADD_LATENCY=9 -GMUL_LATENCY=10 -GDIV_LATENCY=34" \
               "-GWB_PORTS=1 -GADD_LATENCY=4 -GMUL_LATENCY=4 -GHAS_DIV=0 -GHAS_SQRT=0" \
               "$(foreach p,$(CHIP_PARAMS),-G$(p))"
## lint: verilator --lint-only -Wall on the whole RTL, every top: zero warnings
lint: $(SETUP_STAMP)
	@set -e; for p in $(LINT_PARAMS); do \
	  echo "$(VERILATOR) --lint-only -Wall -Irtl --top-module $(RTL_TOP) $$p"; \
	  $(VERILATOR) --lint-only -Wall -Irtl --top-module $(RTL_TOP) $$p $(RTL_SRC); done
	@echo "lint: verilator -Wall clean"

# ---- synthesis -------------------------------------------------------------
# FPGA hand-off (docs/fpga.md): in each flow of SYNTH_FLOWS, one netlist of
# the AXI4-Lite wrapper fp3_axil with the processor $(RTL_TOP) kept as a
# level of hierarchy (area reported for both), `stat` and a summary
# (constraints/ has the clock of each flow); then the area of each FP core
# (fp_add, fp_mul, fp_div, fp_sqrt at their default latencies) in each
# ROUND/FTZ configuration on xc2v, xc7 and ECP5, as a table in
# $(SYNTH_DIR)/fp_cores_area.{md,csv}.  scripts/synth.sh fails on any latch
# or combinational loop.  `make synth SYNTH_FLOWS=ecp5` for one flow;
# SYNTH_PARAMS="NUM_CONTEXTS=1" overrides parameters of fp3_axil.  Last,
# the processor's area for 1, 8 and 32 contexts (synth-contexts).
SYNTH_DIR    := $(BUILD)/synth
SYNTH_FLOWS  ?= xc2v xc7 ecp5
SYNTH_PARAMS ?=
SYNTH_CORES  := fp_add fp_mul fp_div fp_sqrt
## synth: Yosys synthesis for xc2v, xc7 and ECP5: netlists, area, the FP-core area table
synth: $(SETUP_STAMP)
	@echo "synth: Yosys $(SYNTH_FLOWS) for fp3_axil/$(RTL_TOP) $(SYNTH_PARAMS), FP cores on xc2v/xc7/ecp5; results in $(SYNTH_DIR)/"
	@set -e; for flow in $(SYNTH_FLOWS); do \
	  bash scripts/synth.sh $(SYNTH_DIR) fp3_axil $$flow $(SYNTH_PARAMS) -keep $(RTL_TOP) \
	    $(RTL_SRC); done
	@set -e; for core in $(SYNTH_CORES); do for r in 0 1; do for f in 0 1; do \
	  for flow in xc2v xc7 ecp5; do \
	    bash scripts/synth.sh $(SYNTH_DIR) $$core $$flow ROUND=$$r FTZ=$$f $(RTL_SRC); \
	  done; done; done; done
	@echo "FP core area (default latencies), $(SYNTH_DIR)/fp_cores_area.md:"
	@bash scripts/synth-report.sh --table $(SYNTH_DIR)
	@$(MAKE) --no-print-directory synth-contexts

# Area of the processor against NUM_CONTEXTS: xc2v, 1, 8 and 32
# contexts, as a table in $(SYNTH_DIR)/contexts_area.{md,csv}.  About 1, 2
# and 7 CPU minutes of Yosys.  `make synth` runs it last.
SYNTH_CONTEXTS ?= 1 8 32
.PHONY: synth-contexts
## synth-contexts: area of fp3_top (xc2v) against NUM_CONTEXTS (SYNTH_CONTEXTS, default 1 8 32)
synth-contexts: $(SETUP_STAMP)
	@set -e; for n in $(SYNTH_CONTEXTS); do \
	  bash scripts/synth.sh $(SYNTH_DIR)/contexts_$$n $(RTL_TOP) xc2v NUM_CONTEXTS=$$n $(RTL_SRC); \
	done
	@set -e; md=$(SYNTH_DIR)/contexts_area.md; csv=$(SYNTH_DIR)/contexts_area.csv; \
	  echo "num_contexts,luts,ffs,mult18x18,brams" > $$csv.tmp; \
	  { echo "| NUM_CONTEXTS | LUTs | flip-flops | MULT18X18 | block RAMs |"; \
	    echo "| ---: | ---: | ---: | ---: | ---: |"; } > $$md.tmp; \
	  for n in $(SYNTH_CONTEXTS); do \
	    set -- $$(bash scripts/synth-report.sh --fields --module $(RTL_TOP) \
	      $(SYNTH_DIR)/contexts_$$n/$(RTL_TOP)_NUM_CONTEXTS-$${n}_xc2v_stat.txt); \
	    echo "$$n,$$1,$$2,$$3,$$5" >> $$csv.tmp; \
	    echo "| $$n | $$1 | $$2 | $$3 | $$5 |" >> $$md.tmp; \
	  done; mv $$csv.tmp $$csv; mv $$md.tmp $$md; \
	  echo "synth-contexts: $(RTL_TOP) on xc2v against NUM_CONTEXTS ($$md):"; cat $$md

# ---- RTL against ISS and golden model (cmocka) ------------------------------
# (It also runs the build for clock rate, the fp3_top model test_axil
# compares its AXI4-Lite build with: RTL_AXIL_CONFIGS; and random programs
# on the scene-sized build: RTL_SCENE_CONFIGS.)
RTL_ENGINE_OBJS := $(RTL_TEST_OBJS) \
  $(foreach c,$(RTL_AXIL_CONFIGS) $(RTL_SCENE_CONFIGS),$(call rtl_shim,$(c)) $(call rtl_archive,$(c)))
$(BUILD)/tests/test_engines: tests/test_engines.c $(BUILD)/sw-san/libfp3.a $(RTL_DEPS) $(RTL_ENGINE_OBJS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(BUILD)/sw-san/libfp3.a $(RTL_OBJS) $(RTL_ENGINE_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_engines

# ---- one source of truth, tool acceptance -----------------------------------
TEST_SCRIPTS += tests/test_isa_sync.sh tests/test_rtl_tools.sh tests/test_ram_ebr.sh tests/test_delay_ebr.sh tests/test_dsp_mul.sh tests/test_rr_arbiter.sh
test-build: $(BUILD)/gen_isa

# ---- make sim: the default ship scene on the RTL ----------------------------
SIM_STEPS ?= 10000
## sim: build the Verilated RTL and run the default ship scene (SIM_STEPS integrations; parameters as NAME=VALUE)
sim: $(BUILD)/fp3
	$(BUILD)/fp3 run --engine rtl --program programs/ship_rk4.s --steps $(SIM_STEPS)

# ---- 10^6 random programs, RTL against ISS (a benchmark, not a test) ---------
# Programs COSIM_FIRST .. COSIM_FIRST+COSIM_PROGRAMS-1 on the default build
# and every lanes build, in COSIM_JOBS ranges at once (scripts/bench-cosim.sh;
# logs in build/bench/cosim/).  Program p is the same in any split, so
# `make bench-cosim COSIM_FIRST=500000 COSIM_PROGRAMS=500000` and the same
# from 0 cover the 10^6 of one run.
COSIM_FIRST    ?= 0
COSIM_PROGRAMS ?= 1000000
COSIM_JOBS     ?= $(shell nproc)
.PHONY: bench-cosim
# With MPI_NP=N the range is split across N MPI ranks instead, their
# digests added by MPI_Reduce (mk/mpi.mk, docs/cluster.md; MPI_HOSTFILE=).
MPI_NP ?=
## bench-cosim: 10^6 random hazard-dense programs on every build, RTL against the ISS bit for bit (COSIM_FIRST=, COSIM_PROGRAMS=, COSIM_JOBS=; MPI_NP=N on MPI ranks)
bench-cosim: $(if $(MPI_NP),$(BUILD)/tests/test_engines-mpi,$(BUILD)/tests/test_engines)
	$(if $(MPI_NP),$(COSIM_MPI),bash scripts/bench-cosim.sh $(BUILD)/tests/test_engines $(COSIM_FIRST) $(COSIM_PROGRAMS) $(COSIM_JOBS) $(BUILD)/bench/cosim)
# tests/test_bench_cosim.sh: the ranges' split, sums and failures on a
# stand-in, and the same programs in any split on test_engines.
TEST_SCRIPTS += tests/test_bench_cosim.sh

# ---- throughput of many objects (make bench-parallel) -------------------------
RTL_BENCH_OBJS := $(foreach c,$(RTL_BENCH_CONFIGS),$(call rtl_shim,$(c)) $(call rtl_archive,$(c)))
$(BUILD)/bench_parallel: sw/bench/bench_parallel.c $(BUILD)/sw/libfp3.a $(RTL_DEPS) $(RTL_TEST_OBJS) $(RTL_BENCH_OBJS)
	$(CC) $(CFLAGS) $(SW_CPPFLAGS) -c $< -o $@.o
	$(CXX) -o $@ $@.o $(BUILD)/sw/libfp3.a $(RTL_OBJS) $(RTL_TEST_OBJS) $(RTL_BENCH_OBJS) \
	  $(LDLIBS_SW) $(VERILATOR_LDLIBS)

.PHONY: bench-parallel
# PARALLEL_ARGS: the model and program (default: the paper's
# programs/ship_rk4.s), e.g. PARALLEL_ARGS="--model models/spring.fp3m
# --integrator rk4".
PARALLEL_ARGS ?=
## bench-parallel: many-object throughput, cycles per object-step for 1 to 64 contexts (PARALLEL_ARGS: any model)
bench-parallel: $(BUILD)/bench_parallel
	@mkdir -p $(BUILD)/bench
	$(BUILD)/bench_parallel --steps 200 --csv $(BUILD)/bench/parallel.csv $(PARALLEL_ARGS)

# ---- lanes against the CPU (make bench-chip) ----------------------------------
# cpu_ship.c, the CPU reference, is built as the issue's comparison asks:
# -O3 -march=native, no contraction into fused multiply-adds.
CPU_SHIP_FLAGS := -O3 -march=native -ffp-contract=off
# BENCH_CHIP_MODELS: the lane builds bench_chip links (the chip's 24
# lanes take an hour and more to Verilate and compile on two cores); the
# others are reported as not linked.
BENCH_CHIP_MODELS ?= l2 l4 l8 l16 fmax f16 chip
RTL_CHIP_OBJS := $(foreach c,$(BENCH_CHIP_MODELS),$(call rtl_shim,$(c)) $(call rtl_archive,$(c)))
$(BUILD)/bench/cpu_ship.o: sw/bench/cpu_ship.c sw/bench/cpu_ship.h sw/model/model.h
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(CWARN) $(CPU_SHIP_FLAGS) -DCPU_SHIP_FLAGS='"$(CPU_SHIP_FLAGS)"' -Isw/model -c $< -o $@
BENCH_CHIP_STAMP = $(BUILD)/bench_chip.models.$(shell echo '$(BENCH_CHIP_MODELS)' | md5sum | cut -c1-8)
$(BENCH_CHIP_STAMP):
	@mkdir -p $(BUILD)
	@rm -f $(BUILD)/bench_chip.models.*
	@touch $@
$(BUILD)/bench_chip: sw/bench/bench_chip.c $(BUILD)/bench/cpu_ship.o $(BUILD)/sw/libfp3.a $(RTL_DEPS) \
                     $(RTL_CHIP_OBJS) $(BENCH_CHIP_STAMP)
	$(CC) $(CFLAGS) $(SW_CPPFLAGS) -c $< -o $@.o
	$(CXX) -o $@ $@.o $(BUILD)/bench/cpu_ship.o $(BUILD)/sw/libfp3.a $(RTL_OBJS) $(RTL_CHIP_OBJS) \
	  $(LDLIBS_SW) $(VERILATOR_LDLIBS)

# The chip build's median Fmax over the placement seeds, when make pnr
# CHIP=ecp5-85 PNR_SEEDS=... has measured it (else cycles only).
CHIP_FMAX ?= $(shell test -f $(BUILD)/pnr/chip_fmax_median.txt && cat $(BUILD)/pnr/chip_fmax_median.txt)
# The spatial chips' median Fmax, folded and literal, when make pnr-spatial
# MODEL=models/ship.fp3m INTEGRATOR=rk4se [LITERAL=1 MULT_BLOCKS=3]
# PNR_SEEDS=... (the shape bench_chip runs: the pipelines that fit,
# --clock-cores; three MULT18X18D a multiply have the same latency) has
# measured it (else their rows give cycles only).
SPATIAL_FMAX ?= $(shell cat $(BUILD)/pnr-spatial/ship-rk4se/fmax_median.txt 2>/dev/null)
SPATIAL_LITERAL_FMAX ?= $(shell cat $(BUILD)/pnr-spatial/ship-rk4se-literal-b3/fmax_median.txt 2>/dev/null)
.PHONY: bench-chip
## bench-chip: lanes 1-16, the chip build and the spatial chip: cycles per object-step, literal and compiled RK4, every object bit-exact; the CPU reference in the same run (BENCH_CHIP_MODELS=)
bench-chip: $(BUILD)/bench_chip
	@mkdir -p $(BUILD)/bench
	$(BUILD)/bench_chip --steps 200 --csv $(BUILD)/bench/chip.csv $(if $(CHIP_FMAX),--fmax-mhz $(CHIP_FMAX)) \
	  $(if $(SPATIAL_FMAX),--spatial-fmax-mhz $(SPATIAL_FMAX)) \
	  $(if $(SPATIAL_LITERAL_FMAX),--spatial-literal-fmax-mhz $(SPATIAL_LITERAL_FMAX))

# ---- simulation speed (make bench-simspeed) ----------------------------------
# The Verilated chip build on 256 ships against the default build on 64,
# and the spatial engine's folded ship chip against the chip build,
# object-steps per CPU second, median of SIMSPEED_ROUNDS runs of bench_chip
# linked with the chip build only (scripts/bench-simspeed.sh;
# docs/lanes.md "Simulation speed", docs/spatial.md "The spatial engine").  SIMSPEED_BEFORE=path/to/bench_chip,
# the same program built from another revision: both, alternating.
# SIMSPEED_BASELINE=path/to/fp3, build/fp3 of another revision: its
# default build's `fp3 run --objects 64` timed in the same rounds.
SIMSPEED_ROUNDS ?= 3
SIMSPEED_BEFORE ?=
SIMSPEED_BASELINE ?=
# tests/test_simspeed.sh: the script's arithmetic and bad input, on stand-ins.
TEST_SCRIPTS += tests/test_simspeed.sh
.PHONY: bench-simspeed
## bench-simspeed: Verilated model speed, chip build (256 ships) against the default build (64 ships), the spatial chip against the chip build: object-steps per CPU second and ratios (SIMSPEED_BEFORE=, SIMSPEED_BASELINE=)
bench-simspeed:
	$(MAKE) --no-print-directory $(BUILD)/bench_chip BENCH_CHIP_MODELS=chip
	bash scripts/bench-simspeed.sh --rounds $(SIMSPEED_ROUNDS) \
	  $(if $(SIMSPEED_BASELINE),--baseline $(SIMSPEED_BASELINE)) $(BUILD)/bench_chip $(SIMSPEED_BEFORE)
