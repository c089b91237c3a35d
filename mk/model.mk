# model.mk -- the model language (sw/model/, models/*.fp3m): its test.
#
# sw/model/*.c reach libfp3.a through mk/sw.mk's wildcard.  test_model
# links the RTL model (RTL_OBJS) to run the compiled models on it, and the
# test builds (RTL_TEST_OBJS, mk/rtl.mk) for a model scene on lanes (l4).
$(BUILD)/tests/test_model: tests/test_model.c $(BUILD)/sw-san/libfp3.a $(RTL_DEPS) $(RTL_TEST_OBJS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(BUILD)/sw-san/libfp3.a $(RTL_OBJS) $(RTL_TEST_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_model

# tests/test_model_cli.sh runs build/fp3 (FP3_BIN, mk/sw.mk).
TEST_SCRIPTS += tests/test_model_cli.sh

# tests/test_mscene.sh: model scenes through build/fp3 (run, compile,
# configure, frames, bench --model; bad scenes).
TEST_SCRIPTS += tests/test_mscene.sh

# make bench-model: the work-precision sweep and the stability bounds of
# models/spring.fp3m and models/oscillator.fp3m (fp3 bench --model; CSV
# and PNG in build/bench/: work-precision, error against h).
.PHONY: bench-model
## bench-model: models' work-precision sweep (fp3 bench --model; CSV, PNG in build/bench)
bench-model: $(BUILD)/fp3
	@mkdir -p $(BUILD)/bench
	$(BUILD)/fp3 bench --model models/spring.fp3m --set h=0.015625 --set k=40 --set c=0.8 \
	  --set m=2 --set x=0.5 --set v=-0.25 --points 8 -o $(BUILD)/bench/model-spring.csv \
	  --stability $(BUILD)/bench/model-spring-stability.csv
	$(BUILD)/fp3 bench --model models/oscillator.fp3m --set h=0.015625 --set w=3 \
	  --set x=0.75 --set v=-0.5 --t-end 100 --points 8 -o $(BUILD)/bench/model-oscillator.csv \
	  --stability $(BUILD)/bench/model-oscillator-stability.csv
	for m in spring oscillator; do gnuplot -e "csv='$(BUILD)/bench/model-$$m.csv'; \
	  png='$(BUILD)/bench/model-$$m.png'; hpng='$(BUILD)/bench/model-$$m-h.png'" \
	  scripts/plot-bench.gp || exit 1; done
