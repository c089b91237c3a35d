# model.mk -- the model language (sw/model/, models/*.fp3m): its test.
#
# sw/model/*.c reach libfp3.a through mk/sw.mk's wildcard.  test_model
# links the RTL model (RTL_OBJS) to run the compiled models on it.
$(BUILD)/tests/test_model: tests/test_model.c $(BUILD)/sw-san/libfp3.a $(RTL_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(BUILD)/sw-san/libfp3.a $(RTL_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_model

# tests/test_model_cli.sh runs build/fp3 (FP3_BIN, mk/sw.mk).
TEST_SCRIPTS += tests/test_model_cli.sh

# tests/test_mscene.sh: model scenes through build/fp3 (run, compile,
# configure, frames, bench --model; bad scenes).
TEST_SCRIPTS += tests/test_mscene.sh
