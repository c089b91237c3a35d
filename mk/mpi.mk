# mpi.mk -- build/fp3-mpi, the command line on MPI (docs/cluster.md):
# `mpirun -np N build/fp3-mpi run|frames ...` shards a scene's objects
# across N ranks (sw/cli/mpishard.h); the MPI co-simulation campaign
# (make bench-cosim MPI_NP=N); the MPI tests and make bench-mpi.
#
# build/fp3-mpi is build/fp3's library with the MPI forms of fp3.c,
# cmd_run.c and cmd_frames.c (-DFP3_MPI) and sw/cli/mpishard.c, compiled
# with Open MPI's flags (mpicc --showme); build/fp3 stays MPI-free.  `make`
# builds it when mpicc is there (scripts/setup.sh installs openmpi-bin
# and libopenmpi-dev); make test always does.

MPICC     ?= mpicc
MPIRUN    ?= mpirun
# recursive: read when a recipe runs, after scripts/setup.sh installed MPI
MPI_CFLAGS = $(shell $(MPICC) --showme:compile)
MPI_LIBS   = $(shell $(MPICC) --showme:link)
MPI_SRCS  := sw/cli/fp3.c sw/cli/cmd_run.c sw/cli/cmd_frames.c $(SW_MPI_SRCS)
MPI_OBJS  := $(patsubst sw/%.c,$(BUILD)/mpi/%.o,$(MPI_SRCS))

$(BUILD)/mpi/%.o: sw/%.c | $(SETUP_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SW_CPPFLAGS) $(MPI_CFLAGS) -DFP3_MPI -MMD -MP -c $< -o $@

-include $(MPI_OBJS:.o=.d)

# MPI's objects first: the archive's one-process fp3_cmd_run and
# fp3_cmd_frames are then never pulled in.
$(BUILD)/fp3-mpi: $(MPI_OBJS) $(SW_LIB) $(RTL_OBJS) $(FPU_DEPS)
	$(CXX) -o $@ $(MPI_OBJS) $(SW_LIB) $(RTL_OBJS) $(FPU_OBJS) \
	  $(RTL_LIBS) $(FPU_LIBS) $(VERILATOR_LDLIBS) $(LDLIBS_SW) $(MPI_LIBS)

ifneq ($(shell command -v $(MPICC) 2>/dev/null),)
all: $(BUILD)/fp3-mpi
endif
test-build: $(BUILD)/fp3-mpi
export FP3_MPI_BIN := $(abspath $(BUILD)/fp3-mpi)

# ---- the co-simulation campaign on MPI ----------------------------------------
# tests/test_engines.c's random programs (RTL = ISS on the default build
# and every lanes build), its range split across the ranks, the seed
# digests added by MPI_Reduce.  Built without the sanitizers (a campaign
# of hours; make test runs the sanitized test_engines).
$(BUILD)/tests/test_engines-mpi: tests/test_engines.c $(SW_LIB) $(RTL_DEPS) $(RTL_ENGINE_OBJS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SW_CPPFLAGS) $(MPI_CFLAGS) -DFP3_MPI -c $< -o $@.o
	$(CXX) -o $@ $@.o $(SW_LIB) $(RTL_OBJS) $(RTL_ENGINE_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS) $(MPI_LIBS)
test-build: $(BUILD)/tests/test_engines-mpi

# mpirun's options for every MPI target: more ranks than cores on one
# machine (--oversubscribe); MPI_HOSTFILE=FILE runs them on the machines
# it lists (docs/cluster.md).  The campaign's range goes to every rank
# (-x, also to other machines).
MPI_HOSTFILE ?=
MPI_RUN_FLAGS ?= --oversubscribe $(if $(MPI_HOSTFILE),--hostfile $(MPI_HOSTFILE))
COSIM_MPI = FP3_RANDOM_FIRST=$(COSIM_FIRST) FP3_RANDOM_PROGRAMS=$(COSIM_PROGRAMS) \
  $(MPIRUN) -np $(MPI_NP) $(MPI_RUN_FLAGS) -x FP3_RANDOM_FIRST -x FP3_RANDOM_PROGRAMS \
  $(BUILD)/tests/test_engines-mpi

# tests/test_mpi.sh: fp3-mpi on 1, 2 and 3 ranks = fp3 (run, --json, frames),
# the co-simulation digest of a range, faults (docs/cluster.md).
TEST_SCRIPTS += tests/test_mpi.sh
export FP3_COSIM_MPI_BIN := $(abspath $(BUILD)/tests/test_engines-mpi)
export FP3_COSIM_BIN := $(abspath $(BUILD)/tests/test_engines)

# ---- scaling (make bench-mpi) ---------------------------------------------------
# Object-steps per second of fp3-mpi on BENCH_MPI_NP ranks (default 1 and
# 2, this machine's cores), speed-up and parallel efficiency
# (scripts/bench-mpi.sh): the default build on BENCH_MPI_ARGS (about 21 s
# of one core: 192 ships, 24 batches of 8 contexts, 1,200 integrations),
# then, with BENCH_MPI_CHIP=1, the chip build (CHIP_PARAMS: 16 contexts x
# 16 lanes, a build of its own in $(BUILD)-chip, long to Verilate) on
# BENCH_MPI_CHIP_ARGS (1,024 ships, 4 batches of 256, 800 integrations:
# about 21 s of one core).
BENCH_MPI_NP   ?= 1 2
BENCH_MPI_ARGS ?= run --model models/ship.fp3m --objects 192 --steps 1200
BENCH_MPI_CHIP ?=
BENCH_MPI_CHIP_ARGS ?= run --model models/ship.fp3m --objects 1024 --steps 800
.PHONY: bench-mpi
## bench-mpi: fp3-mpi object-steps per second on 1 and 2 ranks, speed-up and parallel efficiency (BENCH_MPI_NP=, BENCH_MPI_ARGS=, BENCH_MPI_CHIP=1, MPI_HOSTFILE=)
bench-mpi: $(BUILD)/fp3-mpi
	MPI_RUN_FLAGS="$(MPI_RUN_FLAGS)" bash scripts/bench-mpi.sh --np "$(BENCH_MPI_NP)" --label "default build" \
	  $(BUILD)/fp3-mpi $(BENCH_MPI_ARGS)
	$(if $(BENCH_MPI_CHIP),$(MAKE) --no-print-directory BUILD=$(BUILD)-chip $(CHIP_PARAMS) $(BUILD)-chip/fp3-mpi && \
	  MPI_RUN_FLAGS="$(MPI_RUN_FLAGS)" bash scripts/bench-mpi.sh --np "$(BENCH_MPI_NP)" --label "chip build" \
	  $(BUILD)-chip/fp3-mpi $(BENCH_MPI_CHIP_ARGS))
