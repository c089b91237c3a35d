# spatial.mk -- the spatial back end's test (fp3 spatial, docs/spatial.md).
#
# tests/test_spatial.sh generates the pipelines of the ship (folded and
# literal RK4), the spring, the oscillator and the projectile, Verilates
# each with sim/spatial_tb.cpp and checks every object after every step
# bit for bit against the golden model (about 40 s, most of it the five
# Verilator builds); it needs build/fp3 and the Verilated runtime.
#
# tests/test_spatial_chip.sh generates the ship's chip top (--pipelines 1
# and 3), Verilates it with sim/spatial_chip_tb.cpp and drives it over
# AXI4-Lite: register map, SLVERR cases, runs over awake lists checked bit
# for bit and against the cycle formula, and two broken frames that must
# fail (about a minute, four Verilator builds).
TEST_SCRIPTS += tests/test_spatial.sh tests/test_spatial_chip.sh
test-build: $(BUILD)/fp3 $(VERILATED_OBJS)

# tests/test_spatial_engine.sh: fp3 run and fp3 frames --engine spatial
# (the model's chip, Verilated on first use into a temporary cache, loaded
# with dlopen, driven over AXI4-Lite): the ship and the oscillator
# bit-exact after every step and equal to --engine rtl, the cache reused,
# damaged entries found and rebuilt, bad options refused (about a minute,
# three Verilator builds).
TEST_SCRIPTS += tests/test_spatial_engine.sh
