# configure.mk -- hardware sized to the scene.
#
#   make synth-scene SCENE=scenes/harbour.scene [INTEGRATOR=rk4]
#                    [SYNTH_SCENE_OPTS="--wb-ports 4"]
#        build/fp3 configure (with SYNTH_SCENE_OPTS) derives the RTL
#        parameters the scene needs; scripts/synth-scene.sh synthesizes
#        fp3_axil (fp3_top kept) with them and with the full default
#        configuration of as many lanes, in each flow of SYNTH_SCENE_FLOWS
#        (default xc2v; add ecp5), and writes the area table (LUTs, FFs,
#        DSPs, BRAMs: full, sized, saving in %) to
#        build/synth/scene/NAME.{md,csv}.  Several minutes per flow and
#        lane count (a benchmark, not a test).
#
# tests/test_configure.c links the scene-sized Verilated build `drift`
# (RTL_CFG_drift in mk/rtl.mk).

RTL_SCENE_OBJS := $(foreach c,$(RTL_SCENE_CONFIGS),$(call rtl_shim,$(c)) $(call rtl_archive,$(c)))

$(BUILD)/tests/test_configure: tests/test_configure.c $(BUILD)/sw-san/libfp3.a $(RTL_DEPS) \
                               $(RTL_SCENE_OBJS)
	@mkdir -p $(dir $@)
	$(CC) $(CFLAGS) $(SAN_FLAGS) -c $< -o $@.o
	$(CXX) $(SAN_FLAGS) -o $@ $@.o $(BUILD)/sw-san/libfp3.a $(RTL_OBJS) $(RTL_SCENE_OBJS) \
	  $(LDLIBS_SW) $(CMOCKA_LIB) $(VERILATOR_LDLIBS)
TEST_BINS += $(BUILD)/tests/test_configure

SCENE             ?=
INTEGRATOR        ?= rk4
SYNTH_SCENE_FLOWS ?= xc2v
SYNTH_SCENE_OPTS  ?=
SYNTH_SCENE_DIR   := $(SYNTH_DIR)/scene

.PHONY: synth-scene
## synth-scene: area of the build fp3 configure sizes for SCENE=FILE against the full default build of as many lanes
synth-scene: $(BUILD)/fp3 $(SETUP_STAMP)
	@test -n "$(SCENE)" || { echo "make synth-scene: give SCENE=FILE (e.g. scenes/harbour.scene)" >&2; exit 2; }
	bash scripts/synth-scene.sh $(BUILD)/fp3 $(SYNTH_SCENE_DIR) "$(SCENE)" "$(INTEGRATOR)" \
	  "$(SYNTH_SCENE_FLOWS)" "$(SYNTH_SCENE_OPTS)" $(RTL_SRC)
