# axil.mk -- the AXI4-Lite wrapper rtl/fp3_axil.v: its Verilated models
# (top fp3_axil), their C shim, their lint and their test.
#
# One model per build variant (enum fp3_axil_variant of
# sim/fp3_axil_model.h): default, every parameter at its default; fmax, the
# build for clock rate, with the parameters of the processor model
# RTL_CFG_fmax; lanes, 8 contexts x 4 lanes (RTL_CFG_l4).  tests/test_axil drives real AXI4-Lite transactions from C
# and links the host-port RTL models (RTL_OBJS and RTL_AXIL_CONFIGS) too,
# through the sw library's engines, to compare the two (the Makefile reads
# mk/rtl.mk, which defines them and rtl_gparams, before this file).

AXIL_TOP      := fp3_axil
AXIL_VARIANTS := default fmax lanes
AXIL_PARAMS_default :=
AXIL_PARAMS_fmax    := $(call rtl_gparams,fmax)
AXIL_PARAMS_lanes   := $(call rtl_gparams,l4)
AXIL_VFLAGS   := $(VFLAGS) --trace -MAKEFLAGS OPT_FAST=-O2 --top-module $(AXIL_TOP)

axil_objdir  = $(BUILD)/obj_fp3_axil_$(1)
axil_archive = $(call axil_objdir,$(1))/Vfp3_axil_$(1)__ALL.a

# `make lint` also lints the wrapper as a top of its own, in each variant.
.PHONY: lint-axil
## lint-axil: verilator --lint-only -Wall on the AXI4-Lite wrapper fp3_axil, each variant (part of make lint)
lint: lint-axil

define AXIL_MODEL_RULES
$(call axil_archive,$(1)): $(RTL_SRC) $(RTL_INC) mk/axil.mk mk/rtl.mk | $(SETUP_STAMP)
	@mkdir -p $(call axil_objdir,$(1))
	$(VERILATOR) --cc --build -j 2 $(AXIL_VFLAGS) $(AXIL_PARAMS_$(1)) \
	  --prefix Vfp3_axil_$(1) --Mdir $(call axil_objdir,$(1)) $(RTL_SRC) \
	  >$(call axil_objdir,$(1))/build.log 2>&1 || { tail -40 $(call axil_objdir,$(1))/build.log; exit 1; }
	@touch $$@

.PHONY: lint-axil-$(1)
lint-axil: lint-axil-$(1)
lint-axil-$(1): $(SETUP_STAMP)
	$(VERILATOR) --lint-only -Wall -Irtl --top-module $(AXIL_TOP) $(AXIL_PARAMS_$(1)) $(RTL_SRC)
	@echo "lint: $(AXIL_TOP) ($(1)) verilator -Wall clean"
endef
$(foreach v,$(AXIL_VARIANTS),$(eval $(call AXIL_MODEL_RULES,$(v))))

# One shim serves every variant (a template over the Verilated class).
AXIL_ARCHIVES := $(foreach v,$(AXIL_VARIANTS),$(call axil_archive,$(v)))
AXIL_SHIM_OBJ := $(BUILD)/sim/fp3_axil_shim.o
AXIL_OBJS     := $(AXIL_SHIM_OBJ) $(AXIL_ARCHIVES) \
                 $(foreach c,$(RTL_AXIL_CONFIGS) l4,$(call rtl_shim,$(c)) $(call rtl_archive,$(c)))

$(AXIL_SHIM_OBJ): sim/fp3_axil_shim.cpp sim/fp3_axil_model.h sim/vmodel.h $(AXIL_ARCHIVES)
	@mkdir -p $(dir $@)
	$(CXX) $(VERILATOR_CXXFLAGS) $(foreach v,$(AXIL_VARIANTS),-I$(call axil_objdir,$(v))) -c $< -o $@

$(BUILD)/tests/test_axil: tests/test_axil.c sim/fp3_axil_model.h $(BUILD)/sw-san/libfp3.a \
                          $(AXIL_OBJS) $(RTL_DEPS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -Isim -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(BUILD)/sw-san/libfp3.a $(AXIL_OBJS) $(RTL_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_axil
