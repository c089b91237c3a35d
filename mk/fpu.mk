# mk/fpu.mk -- the binary32 FP cores: Verilated models, C shim, tests, bench.
#
# Included by the top Makefile.  Exports, for any executable that uses
# sim/fpu_model.h (link with $(CXX)):
#   FPU_OBJS  objects to link (shim of each configuration + dispatcher)
#   FPU_LIBS  archives to link after them (models, Verilator runtime)
#   FPU_DEPS  prerequisites (= FPU_OBJS FPU_LIBS)
#   FPU_INC   -I flag for sim/fpu_model.h
# The CLI gets the four rounding configurations at the default latencies;
# tests/test_fpu additionally gets models at other latencies.
#
#   make bench-fp   10^8 random operations per operation and configuration

FPU_RTL := rtl/fp_add.v rtl/fp_mul.v rtl/fp_div.v rtl/fp_sqrt.v rtl/fp_sign.v \
           rtl/fp_pipe.v rtl/fp_round.v \
           rtl/fp_round_pack.v rtl/fp_lzc.v rtl/fp_shr_sticky.v \
           rtl/fp_mul_unpack_norm.v rtl/fp_mul_prod.v rtl/fp_dsp_mul.v rtl/fp_recur_unpack.v \
           rtl/fp_recur_out.v rtl/fp_norm_exp.v rtl/fp_norm_shift.v
FPU_RTL_INC := rtl/fp_recur.vh
FPU_DIR := $(BUILD)/fpu
FPU_INC := -Isim

# Default latencies: fp3_isa.h FP3_CONFIG (ADD_LATENCY 4, MUL_LATENCY 3).
FPU_ADD_LAT_DEF := $(shell sed -n 's/.*X(ADD_LATENCY, *\([0-9]*\)).*/\1/p' sw/isa/fp3_isa.h)
FPU_MUL_LAT_DEF := $(shell sed -n 's/.*X(MUL_LATENCY, *\([0-9]*\)).*/\1/p' sw/isa/fp3_isa.h)
# fp_div and fp_sqrt: the latency of the div/sqrt unit (docs/fp-cores.md).
FPU_DIV_LAT_DEF := 8

# name := ROUND FTZ ADD_LATENCY MUL_LATENCY DIV_LATENCY [MUL_FEED [MUL_BLOCKS]]
# (the names give the add and mul latencies; the variants also take the
# div/sqrt latencies 1 to 35: register counts over the 30 and 29 base
# places of fp_div and fp_sqrt, each of their extra places (31 to 34 and
# 30 to 32: every place), and output delay stages beyond)
FPU_CFG_rne      := 0 0 $(FPU_ADD_LAT_DEF) $(FPU_MUL_LAT_DEF) $(FPU_DIV_LAT_DEF)
FPU_CFG_rtz      := 1 0 $(FPU_ADD_LAT_DEF) $(FPU_MUL_LAT_DEF) $(FPU_DIV_LAT_DEF)
FPU_CFG_ftz      := 0 1 $(FPU_ADD_LAT_DEF) $(FPU_MUL_LAT_DEF) $(FPU_DIV_LAT_DEF)
FPU_CFG_rtz_ftz  := 1 1 $(FPU_ADD_LAT_DEF) $(FPU_MUL_LAT_DEF) $(FPU_DIV_LAT_DEF)
FPU_CFG_lat_1_2  := 0 0 1 2 1
FPU_CFG_lat_2_1  := 0 0 2 1 2
FPU_CFG_lat_3_8  := 0 0 3 8 3
FPU_CFG_lat_8_4  := 0 0 8 4 15
FPU_CFG_lat_5_6  := 0 0 5 6 5
# The fast latencies (150 MHz class on ECP5, docs/fpga.md: add 9, mul 10, the
# multiplier's LUT product, also in RTZ with FTZ), every register place of
# both cores, and output delay stages beyond them.
FPU_CFG_lat_9_7  := 0 0 9 7 29
FPU_CFG_lat_7_10 := 0 0 7 10 31
FPU_CFG_lat_6_9  := 0 0 6 9 30
FPU_CFG_lat_10_11 := 0 0 10 11 33
FPU_CFG_lat_8_12 := 0 0 8 12 32
FPU_CFG_lat_9_10 := 0 0 9 10 35
FPU_CFG_lat_9_10_rtz_ftz := 1 1 9 10 34
# The chip build's multiplier (mk/rtl.mk CHIP_PARAMS): the DSP product of
# latency 9 behind the feed register (fp_mul FEED), and in RTZ with FTZ at
# latency 8 (the DSP product of 7).
FPU_CFG_lat_10_10f := 0 0 10 10 9 1
FPU_CFG_lat_4_8f_rtz_ftz := 1 1 4 8 4 1
# The multiplier of three DSP blocks (fp_mul MULT_BLOCKS 3; the spatial
# chips, docs/spatial.md): behind the feed register as --clock-cores has
# it, in RTZ with FTZ, and at latency 3 (the product without the blocks'
# registers).
FPU_CFG_lat_10_10f3 := 0 0 10 10 9 1 3
FPU_CFG_lat_4_8f3_rtz_ftz := 1 1 4 8 4 1 3
FPU_CFG_lat_4_3b3_rtz := 1 0 4 3 8 0 3

FPU_MODELS_MAIN := rne rtz ftz rtz_ftz
FPU_MODELS_LAT  := lat_1_2 lat_2_1 lat_3_8 lat_8_4 lat_5_6 lat_9_7 lat_7_10 \
                   lat_6_9 lat_10_11 lat_8_12 lat_9_10 lat_9_10_rtz_ftz lat_10_10f \
                   lat_4_8f_rtz_ftz lat_10_10f3 lat_4_8f3_rtz_ftz lat_4_3b3_rtz
FPU_MODELS_ALL  := $(FPU_MODELS_MAIN) $(FPU_MODELS_LAT)

fpu_model_lib  = $(FPU_DIR)/obj_$(1)/Vfpu_$(1)__ALL.a
fpu_shim_obj   = $(FPU_DIR)/shim_$(1).o
FPU_RUNTIME    := $(FPU_DIR)/libfpu_verilated.a

# Verilated model + shim object of one configuration.
define FPU_MODEL_RULES
$(call fpu_model_lib,$(1)): $(FPU_RTL) $(FPU_RTL_INC) sim/fpu_top.v mk/fpu.mk | $(SETUP_STAMP)
	@mkdir -p $(FPU_DIR)
	$(VERILATOR) --cc --build -j 2 $(VFLAGS) --top-module fpu_top \
	  -GROUND=$(word 1,$(FPU_CFG_$(1))) -GFTZ=$(word 2,$(FPU_CFG_$(1))) \
	  -GADD_LATENCY=$(word 3,$(FPU_CFG_$(1))) \
	  -GMUL_LATENCY=$(word 4,$(FPU_CFG_$(1))) \
	  -GDIV_LATENCY=$(word 5,$(FPU_CFG_$(1))) \
	  $(if $(word 6,$(FPU_CFG_$(1))),-GMUL_FEED=$(word 6,$(FPU_CFG_$(1)))) \
	  $(if $(word 7,$(FPU_CFG_$(1))),-GMUL_BLOCKS=$(word 7,$(FPU_CFG_$(1)))) \
	  -MAKEFLAGS OPT_FAST=-O2 \
	  --Mdir $(FPU_DIR)/obj_$(1) --prefix Vfpu_$(1) \
	  sim/fpu_top.v $(FPU_RTL) > $(FPU_DIR)/obj_$(1).log 2>&1 \
	  || { cat $(FPU_DIR)/obj_$(1).log; exit 1; }
	@touch $$@

$(call fpu_shim_obj,$(1)): sim/fpu_shim.cpp sim/fpu_model.h mk/fpu.mk $(call fpu_model_lib,$(1))
	$(CXX) $(VERILATOR_CXXFLAGS) -Isim -I$(FPU_DIR)/obj_$(1) \
	  -DFPU_NAME=$(1) -DFPU_PREFIX=Vfpu_$(1) \
	  -DFPU_ROUND=$(word 1,$(FPU_CFG_$(1))) -DFPU_FTZ=$(word 2,$(FPU_CFG_$(1))) \
	  -DFPU_ADD_LATENCY=$(word 3,$(FPU_CFG_$(1))) \
	  -DFPU_MUL_LATENCY=$(word 4,$(FPU_CFG_$(1))) \
	  -DFPU_DIV_LATENCY=$(word 5,$(FPU_CFG_$(1))) \
	  -c $$< -o $$@
endef
$(foreach m,$(FPU_MODELS_ALL),$(eval $(call FPU_MODEL_RULES,$(m))))

# Dispatchers (the C functions of fpu_model.h) over a list of models.
$(FPU_DIR)/shim_common_main.o: sim/fpu_shim.cpp sim/fpu_model.h mk/fpu.mk | $(SETUP_STAMP)
	@mkdir -p $(FPU_DIR)
	$(CXX) $(VERILATOR_CXXFLAGS) -Isim -DFPU_SHIM_COMMON \
	  '-DFPU_MODELS=$(foreach m,$(FPU_MODELS_MAIN),X($(m)))' -c $< -o $@
$(FPU_DIR)/shim_common_all.o: sim/fpu_shim.cpp sim/fpu_model.h mk/fpu.mk | $(SETUP_STAMP)
	@mkdir -p $(FPU_DIR)
	$(CXX) $(VERILATOR_CXXFLAGS) -Isim -DFPU_SHIM_COMMON \
	  '-DFPU_MODELS=$(foreach m,$(FPU_MODELS_ALL),X($(m)))' -c $< -o $@

# Verilator runtime ($(VERILATED_OBJS) of the top Makefile) as an archive:
# an executable that also links those objects directly takes them once.
$(FPU_RUNTIME): $(VERILATED_OBJS)
	@mkdir -p $(FPU_DIR)
	rm -f $@
	$(AR) rcs $@ $^

FPU_OBJS := $(FPU_DIR)/shim_common_main.o \
            $(foreach m,$(FPU_MODELS_MAIN),$(call fpu_shim_obj,$(m)))
FPU_LIBS := $(foreach m,$(FPU_MODELS_MAIN),$(call fpu_model_lib,$(m))) \
            $(FPU_RUNTIME)
FPU_DEPS := $(FPU_OBJS) $(FPU_LIBS)

FPU_TEST_OBJS := $(FPU_DIR)/shim_common_all.o \
                 $(foreach m,$(FPU_MODELS_ALL),$(call fpu_shim_obj,$(m)))
FPU_TEST_LIBS := $(foreach m,$(FPU_MODELS_ALL),$(call fpu_model_lib,$(m))) \
                 $(FPU_RUNTIME)

# C sources of this unit, compiled for the test program (with sanitizers)
# and for the benchmark (without).
FPU_TEST_SRC := tests/test_fpu.c sw/ref/fpref.c sw/engine/testfloat.c sw/cli/cmd_testfloat.c \
                sw/cli/cliopt.c
FPU_TEST_HDR := sw/ref/fpref.h sw/isa/fp3_isa.h sw/engine/testfloat.h sw/cli/cmd_testfloat.h \
                sw/cli/cliopt.h sim/fpu_model.h

$(FPU_DIR)/san/%.o: %.c $(FPU_TEST_HDR) | $(SETUP_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) $(FPU_INC) -c $< -o $@
$(FPU_DIR)/opt/%.o: %.c $(FPU_TEST_HDR) | $(SETUP_STAMP)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(FPU_INC) -c $< -o $@

$(BUILD)/tests/test_fpu: $(patsubst %.c,$(FPU_DIR)/san/%.o,$(FPU_TEST_SRC)) \
                         $(FPU_TEST_OBJS) $(FPU_TEST_LIBS)
	@mkdir -p $(dir $@)
	$(CXX) $(SAN_FLAGS) -o $@ $(filter %.o,$^) $(FPU_TEST_LIBS) \
	  $(CMOCKA_LIB) -lz -lm $(VERILATOR_LDLIBS)

$(FPU_DIR)/bench_fpu: $(patsubst %.c,$(FPU_DIR)/opt/%.o,$(FPU_TEST_SRC)) \
                      $(FPU_TEST_OBJS) $(FPU_TEST_LIBS)
	$(CXX) -o $@ $(filter %.o,$^) $(FPU_TEST_LIBS) $(CMOCKA_LIB) -lz -lm $(VERILATOR_LDLIBS)

TEST_BINS += $(BUILD)/tests/test_fpu

.PHONY: bench-fp
## bench-fp: 10^8 random operations per FP operation and configuration against the C reference, operations per second
bench-fp: $(FPU_DIR)/bench_fpu
	$(FPU_DIR)/bench_fpu --bench 100000000
