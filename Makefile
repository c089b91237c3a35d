# FP3 -- Field-Programmable Physics Processor
#
#   make sim      build the Verilated RTL and run the default ship scene
#   make test     the whole test suite (installs what is missing first)
#   make lint     verilator --lint-only -Wall on the RTL
#   make synth    Yosys synthesis (xc2v, xc7, ECP5), area reports
#   make pnr      nextpnr place and route, Fmax (ECP5, iCE40); pnr-unit:
#                 one module alone (UNIT=, UNIT_PARAMS=)
#   make wave     Icarus testbench and waveform
#   make bench    benchmarks (also bench-fp, bench-parallel, bench-cosim,
#                 bench-compile, bench-sleep)
#   make help     every target with one line
#
# Missing tools are installed by scripts/setup.sh (Debian and PyPI packages).

BUILD      ?= build
CC         ?= cc
CXX        ?= g++
VERILATOR  ?= verilator
YOSYS      ?= yosys

# C that models hardware: no contraction into FMA, no fast-math (DESIGN.md).
CSTD       := -std=c11 -D_POSIX_C_SOURCE=200809L
CWARN      := -Wall -Wextra -Wshadow -Wstrict-prototypes -Wmissing-prototypes
CFLAGS     ?= -O2 -g
# sw/ is one folder per layer (README "Layout"); headers are included by
# bare name, so every layer's folder is on the include path.
SW_DIRS    := $(sort $(dir $(wildcard sw/*/*.c sw/*/*.h)))
SW_INC     := $(patsubst %/,-I%,$(SW_DIRS))
CFLAGS     += $(CSTD) $(CWARN) -ffp-contract=off -fno-fast-math -frounding-math $(SW_INC)
SAN_FLAGS  ?= -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined
LDLIBS_SW  := -lgsl -lgslcblas -lz -lm
CMOCKA_LIB := -lcmocka

VERILATOR_ROOT_INC := $(shell $(VERILATOR) --getenv VERILATOR_ROOT 2>/dev/null)/include
# --output-split-cfuncs: Verilator otherwise writes the whole clocked
# logic as one C++ function of thousands of lines, which g++ -O2 takes
# many minutes to compile (15 s split, measured on the processor model).
# --unroll-count 256: the scheduler's loops over the queue slots (two per
# context) must unroll for NUM_CONTEXTS up to 64; past Verilator's default
# of 64 iterations a loop of delayed assignments to an array is an error
# (BLKLOOPINIT), which stopped the 64-context build of make bench-parallel.
VFLAGS     := -Wall -O3 --x-assign fast --x-initial fast --noassert -Irtl --output-split-cfuncs 500 \
              --unroll-count 256
VERILATOR_CXXFLAGS := -O2 -std=c++17 -faligned-new -I$(VERILATOR_ROOT_INC) -I$(VERILATOR_ROOT_INC)/vltstd

# The Verilator runtime, compiled once and linked by every Verilated model.
VERILATED_OBJS := $(BUILD)/verilated/verilated.o $(BUILD)/verilated/verilated_threads.o
VERILATOR_LDLIBS := -pthread -latomic

RTL_SRC    := $(wildcard rtl/*.v)
RTL_INC    := rtl/fp3_isa.vh rtl/fp3_sched.vh rtl/fp_recur.vh

TEST_BINS    :=
TEST_SCRIPTS :=

.PHONY: all sim test test-build lint synth setup clean help
## all: build the command-line tool build/fp3 (the default goal)
all: $(BUILD)/fp3

## help: this list, generated from the "## target: text" lines of Makefile and mk/*.mk
# `make help` prints the "## target: text" line written above each
# target's rule in this file and in mk/*.mk, so the list cannot fall
# behind the targets (tests/test_make_help.sh checks every .PHONY target
# has one).
help:
	@echo "FP3 make targets (parameters as NAME=VALUE, e.g. make sim NUM_CONTEXTS=4;"
	@echo "see README.md, Parameters):"
	@awk '/^## [a-z0-9-]+: / { sub(/^## /, ""); t = $$0; sub(/:.*/, "", t); \
	  d = $$0; sub(/^[^:]*: /, "", d); printf "  make %-16s %s\n", t, d }' \
	  Makefile $(sort $(wildcard mk/*.mk))

# ---- one set-up script installs what is missing ----------------------------
SETUP_STAMP := $(BUILD)/.setup-ok
# The script checks each package and installs only the missing ones; it
# runs again whenever it changes (a new package).
## setup: install the missing Debian and PyPI packages (scripts/setup.sh); every target runs it first
setup $(SETUP_STAMP): scripts/setup.sh
	@mkdir -p $(BUILD)
	bash scripts/setup.sh
	@touch $(SETUP_STAMP)

$(BUILD)/verilated/%.o: $(VERILATOR_ROOT_INC)/%.cpp | $(SETUP_STAMP)
	@mkdir -p $(dir $@)
	$(CXX) $(VERILATOR_CXXFLAGS) -c $< -o $@

# The fragments that define the models and the library come first: the
# others name their variables in prerequisites, expanded when read.
MK_BASE := mk/rtl.mk mk/fpu.mk mk/sw.mk
include $(MK_BASE)
include $(filter-out $(MK_BASE),$(sort $(wildcard mk/*.mk)))

## clean: remove the build folder (BUILD, default build/)
clean:
	rm -rf $(BUILD)

# TEST_BINS / TEST_SCRIPTS are filled in by the mk/*.mk fragments, and so
# are test-build's other prerequisites.  make test builds them in a make of
# its own with TEST_JOBS recipes at once (default: one per CPU; the
# Verilated models and the C library compile side by side), then runs the
# tests one after another.  Only test-build is given -j: every other
# target, the benchmarks among them (they time themselves), runs one
# recipe at a time unless the command line asks for more.
TEST_JOBS ?= $(shell nproc)
## test: the whole test suite (installs what is missing first); closes with "tests: N passed, M failed"
test: $(SETUP_STAMP)
	@$(MAKE) --no-print-directory -j$(TEST_JOBS) test-build
	@bash scripts/run-tests.sh $(TEST_BINS) $(TEST_SCRIPTS)

## test-build: build what make test runs, TEST_JOBS recipes at once (default: one per CPU)
test-build: $(SETUP_STAMP) $(TEST_BINS)
