# bench.mk -- the ship integrators: their test, the CLI checks,
# and the work-precision benchmark.
#
#   make bench    build/fp3 bench: sweep, stability, long runs -> build/bench/
#                 (CSV, Markdown tables, PNG plots); the plots docs/numerics.md
#                 shows are copied to docs/.  BENCH_ARGS passes options
#                 (e.g. BENCH_ARGS='--long-steps 1000000').
#
# The library sources (sw/ref/integrators.c, sw/ref/gslref.c, sw/bench/bench.c) reach
# libfp3.a through mk/sw.mk's wildcard.

$(BUILD)/tests/test_integrators: tests/test_integrators.c $(BUILD)/sw-san/libfp3.a $(RTL_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(BUILD)/sw-san/libfp3.a $(RTL_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_integrators

# tests/test_bench_cli.sh runs $FP3_BIN (exported by mk/sw.mk).
TEST_SCRIPTS += tests/test_bench_cli.sh

BENCH_DIR  := $(BUILD)/bench
BENCH_ARGS ?=
BENCH_PLOTS := work-precision.png error-vs-h.png

.PHONY: bench
## bench: integrators: work-precision sweep, stability bounds, long runs (CSV, Markdown, PNG in build/bench)
bench: $(BUILD)/fp3
	@mkdir -p $(BENCH_DIR) docs
	{ $(BUILD)/fp3 bench --out $(BENCH_DIR) $(BENCH_ARGS); echo $$? >$(BENCH_DIR)/.rc; } \
	  | tee $(BENCH_DIR)/bench.txt; exit $$(cat $(BENCH_DIR)/.rc)
	gnuplot -e "dir='$(BENCH_DIR)'" scripts/plot-bench.gp
	cp $(addprefix $(BENCH_DIR)/,$(BENCH_PLOTS)) docs/
	@echo "bench: results in $(BENCH_DIR)/, plots copied to docs/"
