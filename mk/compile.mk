# compile.mk -- the scene compiler: its test and its
# benchmark.
#
#   make bench-compile   scenes (all terms, no drag, no thrust, mixed) of
#                        BENCH_COMPILE_OBJECTS objects, BENCH_COMPILE_STEPS
#                        integrations each, on the RTL: literal vs compiled
#                        program; instructions per integration, cycles per
#                        object-step (measured), error of v and s against the
#                        exact solution -> build/bench/compile.{csv,md}
#
# sw/compiler/compile.c and sw/cli/cmd_compile.c reach libfp3.a through mk/sw.mk's
# wildcard.

# The test models (RTL_ENGINE_OBJS, mk/rtl.mk) give test_compile the build
# for clock rate twice (nc3 and fmax: FMAX_PIPE 1, short and long latencies).
$(BUILD)/tests/test_compile: tests/test_compile.c $(BUILD)/sw-san/libfp3.a $(RTL_DEPS) \
                             $(RTL_ENGINE_OBJS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(BUILD)/sw-san/libfp3.a $(RTL_OBJS) $(RTL_ENGINE_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_compile

BENCH_COMPILE_OBJECTS ?= 256
BENCH_COMPILE_STEPS   ?= 2000

.PHONY: bench-compile
## bench-compile: the scene compiler: literal against compiled program on four scenes (RTL)
bench-compile: $(BUILD)/fp3
	@mkdir -p $(BUILD)/bench
	bash scripts/bench-compile.sh $(BUILD)/fp3 $(BUILD)/bench $(BENCH_COMPILE_OBJECTS) \
	  $(BENCH_COMPILE_STEPS)
