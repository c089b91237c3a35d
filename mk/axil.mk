# axil.mk -- the AXI4-Lite wrapper rtl/fp3_axil.v: its own Verilated model
# (top fp3_axil, default parameters), its C shim, its lint and its test.
#
# tests/test_axil drives real AXI4-Lite transactions from C
# (sim/fp3_axil_model.h) and links the host-port RTL model (RTL_OBJS) too,
# through the sw library's engines, to compare the two (the Makefile reads
# mk/rtl.mk, which defines RTL_OBJS and RTL_DEPS, before this file).

AXIL_TOP      := fp3_axil
AXIL_OBJDIR   := $(BUILD)/obj_fp3_axil
AXIL_ARCHIVE  := $(AXIL_OBJDIR)/Vfp3_axil__ALL.a
AXIL_SHIM_OBJ := $(BUILD)/sim/fp3_axil_shim.o
AXIL_OBJS     := $(AXIL_SHIM_OBJ) $(AXIL_ARCHIVE)
AXIL_VFLAGS   := $(VFLAGS) --trace -MAKEFLAGS OPT_FAST=-O2 --top-module $(AXIL_TOP)

$(AXIL_ARCHIVE): $(RTL_SRC) $(RTL_INC) mk/axil.mk | $(SETUP_STAMP)
	@mkdir -p $(AXIL_OBJDIR)
	$(VERILATOR) --cc --build -j 2 $(AXIL_VFLAGS) --Mdir $(AXIL_OBJDIR) $(RTL_SRC) \
	  >$(AXIL_OBJDIR)/build.log 2>&1 || { tail -40 $(AXIL_OBJDIR)/build.log; exit 1; }
	@touch $@

$(AXIL_SHIM_OBJ): sim/fp3_axil_shim.cpp sim/fp3_axil_model.h sim/vmodel.h $(AXIL_ARCHIVE)
	@mkdir -p $(dir $@)
	$(CXX) $(VERILATOR_CXXFLAGS) -I$(AXIL_OBJDIR) -c $< -o $@

# `make lint` also lints the wrapper as a top of its own.
.PHONY: lint-axil
lint: lint-axil
lint-axil: $(SETUP_STAMP)
	$(VERILATOR) --lint-only -Wall -Irtl --top-module $(AXIL_TOP) $(RTL_SRC)
	@echo "lint: $(AXIL_TOP) verilator -Wall clean"

$(BUILD)/tests/test_axil: tests/test_axil.c sim/fp3_axil_model.h $(BUILD)/sw-san/libfp3.a \
                          $(AXIL_OBJS) $(RTL_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -Isim -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(BUILD)/sw-san/libfp3.a $(AXIL_OBJS) $(RTL_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_axil
