# spatial.mk -- the spatial back end's test (fp3 spatial, docs/spatial.md).
#
# tests/test_spatial.sh generates the pipelines of the ship (folded and
# literal RK4), the spring, the oscillator and the projectile, Verilates
# each with sim/spatial_tb.cpp and checks every object after every step
# bit for bit against the golden model (about 40 s, most of it the five
# Verilator builds); it needs build/fp3 and the Verilated runtime.
TEST_SCRIPTS += tests/test_spatial.sh tests/test_scaleb.sh
test-build: $(BUILD)/fp3 $(VERILATED_OBJS)
