# bench.mk -- the ship integrators: their test, the CLI checks,
# and the integrator benchmark.
#
#   make bench    build/fp3 bench on the ship (models/ship.fp3m) -> build/bench/:
#                 the sweep (h = 4 s .. 4/2^14 s, h/tau = 2 .. 1.2e-4, to 12 s =
#                 6 tau), its Pareto table, the stability bounds, the long runs
#                 on the RTL (build/bench/), far out (s = 2^24 m, far-out/) and
#                 10^7 integrations on the ISS (iss/); CSV, Markdown, PNG.  The
#                 plots docs/numerics.md shows are copied to docs/.  BENCH_ARGS
#                 passes options to the first run (BENCH_ARGS='--only sweep':
#                 the sweep alone, seconds; '--long-steps 1000000').
#
# fp3 bench is sw/cli/cmd_bench.c; test_integrators runs the paper's
# programs bound to models/ship.fp3m.

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
BENCH_SWEEP := --h-max 4 --points 15 --t-end 12
# the far-out and ISS long runs, unless BENCH_ARGS asks for another part
BENCH_MORE := $(if $(filter sweep stability,$(BENCH_ARGS)),,yes)

.PHONY: bench
## bench: the ship's integrators: sweep, Pareto, stability, long runs (CSV, Markdown, PNG in build/bench)
bench: $(BUILD)/fp3
	@mkdir -p $(BENCH_DIR) docs
	{ $(BUILD)/fp3 bench --out $(BENCH_DIR) $(BENCH_SWEEP) $(BENCH_ARGS) && \
	  if [ -n "$(BENCH_MORE)" ]; then \
	    $(BUILD)/fp3 bench --out $(BENCH_DIR)/far-out --only long --set s=16777216 && \
	    $(BUILD)/fp3 bench --out $(BENCH_DIR)/iss --only long --engine iss \
	      --long-steps 10000000 --integrator rk4se,rk4vscomp; fi; \
	  echo $$? >$(BENCH_DIR)/.rc; } | tee $(BENCH_DIR)/bench.txt; exit $$(cat $(BENCH_DIR)/.rc)
	if [ -s $(BENCH_DIR)/sweep.csv ]; then \
	  gnuplot -e "dir='$(BENCH_DIR)'" scripts/plot-bench.gp && \
	  cp $(addprefix $(BENCH_DIR)/,$(BENCH_PLOTS)) docs/; fi
	@echo "bench: results in $(BENCH_DIR)/, plots copied to docs/"
