# rtl.mk -- the Verilated processor model, lint and synthesis.
#
# Exports RTL_OBJS (what an executable links to use sim/fp3_model.h) and
# RTL_DEPS.  Model configuration: NUM_REGS, IMEM_DEPTH, ADD_LATENCY,
# MUL_LATENCY on the make command line override the defaults of
# sw/fp3_isa.h (e.g. `make sim ADD_LATENCY=6`); the C side reads the
# values back from the model's INFO registers.

RTL_TOP      := fp3_top
RTL_OBJDIR   := $(BUILD)/obj_fp3
RTL_PARAMS   := $(foreach p,NUM_REGS IMEM_DEPTH ADD_LATENCY MUL_LATENCY ROUND FTZ,\
                  $(if $($(p)),-G$(p)=$($(p))))
RTL_ARCHIVE  := $(RTL_OBJDIR)/Vfp3_top__ALL.a
RTL_SHIM_OBJ := $(BUILD)/sim/fp3_shim.o
RTL_OBJS     := $(RTL_SHIM_OBJ) $(RTL_ARCHIVE) $(VERILATED_OBJS) $(BUILD)/verilated/verilated_vcd_c.o
RTL_DEPS     := $(RTL_OBJS)

RTL_VFLAGS   := $(VFLAGS) --trace -MAKEFLAGS OPT_FAST=-O2 --top-module $(RTL_TOP) $(RTL_PARAMS)

# Rebuild the model when the sources, the parameters or the flags change.
RTL_PARAM_STAMP := $(RTL_OBJDIR)/params.$(shell echo '$(RTL_VFLAGS)' | md5sum | cut -c1-8)

$(RTL_PARAM_STAMP):
	@mkdir -p $(RTL_OBJDIR)
	@rm -f $(RTL_OBJDIR)/params.*
	@touch $@

$(RTL_ARCHIVE): $(RTL_SRC) $(RTL_INC) $(RTL_PARAM_STAMP) | $(SETUP_STAMP)
	$(VERILATOR) --cc --build -j 2 $(RTL_VFLAGS) --Mdir $(RTL_OBJDIR) $(RTL_SRC) >$(RTL_OBJDIR)/build.log 2>&1 || \
	  { tail -40 $(RTL_OBJDIR)/build.log; exit 1; }

$(RTL_SHIM_OBJ): sim/fp3_shim.cpp sim/fp3_model.h $(RTL_ARCHIVE)
	@mkdir -p $(dir $@)
	$(CXX) $(VERILATOR_CXXFLAGS) -I$(RTL_OBJDIR) -c $< -o $@

# rtl/fp3_isa.vh is generated from sw/fp3_isa.h (and committed).
$(BUILD)/gen_isa: sw/gen_isa.c sw/fp3_isa.h
	@mkdir -p $(dir $@)
	$(CC) $(CSTD) $(CWARN) -Isw $< -o $@

.PHONY: isa
isa: $(BUILD)/gen_isa
	$(BUILD)/gen_isa > rtl/fp3_isa.vh

# ---- lint ------------------------------------------------------------------
lint: $(SETUP_STAMP)
	$(VERILATOR) --lint-only -Wall -Irtl --top-module $(RTL_TOP) $(RTL_SRC)
	@echo "lint: verilator -Wall clean"

# ---- synthesis -------------------------------------------------------------
SYNTH_DIR := $(BUILD)/synth
synth: $(SETUP_STAMP)
	@echo "synth: Yosys synth_xilinx, $(RTL_TOP), netlists and reports in $(SYNTH_DIR)/"
	@bash scripts/synth.sh $(SYNTH_DIR) $(RTL_TOP) xc2v $(RTL_SRC)

# ---- RTL against ISS and golden model (cmocka) ------------------------------
$(BUILD)/tests/test_engines: tests/test_engines.c $(BUILD)/sw-san/libfp3.a $(RTL_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(BUILD)/sw-san/libfp3.a $(RTL_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_engines

# ---- one source of truth, tool acceptance -----------------------------------
TEST_SCRIPTS += tests/test_isa_sync.sh tests/test_rtl_tools.sh
test: $(BUILD)/gen_isa

# ---- make sim: the default ship scene on the RTL ----------------------------
SIM_STEPS ?= 10000
sim: $(BUILD)/fp3
	$(BUILD)/fp3 run --engine rtl --program programs/ship_rk4.s --steps $(SIM_STEPS)
