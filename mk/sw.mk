# sw.mk -- the C library, the CLI build/fp3 and the software tests.
#
# Exports:
#   SW_LIB_OBJS             objects of sw/*.c except the mains (fp3.c,
#                           gen_isa.c), built with CFLAGS into $(BUILD)/sw/
#   $(BUILD)/sw/libfp3.a    the same objects as an archive
#   $(BUILD)/sw-san/libfp3.a  the same, built with $(SAN_FLAGS), for tests
# An archive only pulls in what a program uses: a program that never calls
# fp3_cmd_testfloat() links without the Verilated FP-core models.
#
# build/fp3 links the RTL and FPU models exported by mk/rtl.mk and
# mk/fpu.mk (RTL_OBJS/RTL_LIBS, FPU_OBJS/FPU_LIBS), with $(CXX) since they
# are C++.

SW_MAINS     := sw/cli/fp3.c sw/isa/gen_isa.c sw/bench/bench_parallel.c sw/bench/bench_chip.c \
                sw/bench/cpu_ship.c
# sw/cli/mpishard.c needs MPI: it goes into build/fp3-mpi alone (mk/mpi.mk)
SW_MPI_SRCS  := sw/cli/mpishard.c
SW_LIB_SRCS  := $(filter-out $(SW_MAINS) $(SW_MPI_SRCS),$(wildcard sw/*/*.c))
SW_LIB_OBJS  := $(patsubst sw/%.c,$(BUILD)/sw/%.o,$(SW_LIB_SRCS))
SW_SAN_OBJS  := $(patsubst sw/%.c,$(BUILD)/sw-san/%.o,$(SW_LIB_SRCS))
SW_LIB       := $(BUILD)/sw/libfp3.a
SW_SAN_LIB   := $(BUILD)/sw-san/libfp3.a
# sim/*_model.h: the C views of the Verilated models (engine_rtl.c, testfloat.c)
SW_CPPFLAGS  := -Isim

$(BUILD)/sw/%.o: sw/%.c | $(SETUP_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SW_CPPFLAGS) -MMD -MP -c $< -o $@

$(BUILD)/sw-san/%.o: sw/%.c | $(SETUP_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SW_CPPFLAGS) $(SAN_FLAGS) -MMD -MP -c $< -o $@

$(SW_LIB): $(SW_LIB_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

$(SW_SAN_LIB): $(SW_SAN_OBJS)
	@rm -f $@
	$(AR) rcs $@ $^

-include $(SW_LIB_OBJS:.o=.d) $(SW_SAN_OBJS:.o=.d) $(BUILD)/sw/cli/fp3.d

# ---- the CLI -----------------------------------------------------------------
$(BUILD)/fp3: $(BUILD)/sw/cli/fp3.o $(SW_LIB) $(RTL_OBJS) $(FPU_DEPS)
	$(CXX) -o $@ $(BUILD)/sw/cli/fp3.o $(SW_LIB) $(RTL_OBJS) $(FPU_OBJS) \
	  $(RTL_LIBS) $(FPU_LIBS) $(VERILATOR_LDLIBS) $(LDLIBS_SW)

# ---- tests -------------------------------------------------------------------
$(BUILD)/tests/test_sw: tests/test_sw.c $(SW_SAN_LIB) $(RTL_DEPS) | $(SETUP_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(SW_SAN_LIB) $(RTL_OBJS) $(LDLIBS_SW) $(CMOCKA_LIB) \
	  $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_sw

# tests/test_cli.sh and tests/test_trace.sh run the CLI named by $FP3_BIN.
TEST_SCRIPTS += tests/test_cli.sh tests/test_trace.sh
# tests/test_progress.sh: the progress line of long runs on a (pseudo-)
# terminal, none with stderr to a file or --json ($FP3_BIN).
TEST_SCRIPTS += tests/test_progress.sh
# tests/test_json.sh: every subcommand's --json against docs/fp3.schema.json
# (Python's jsonschema; $FP3_BIN).
TEST_SCRIPTS += tests/test_json.sh
export FP3_BIN := $(abspath $(BUILD)/fp3)
test-build: $(BUILD)/fp3
