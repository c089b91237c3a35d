# spatial.mk -- the spatial back end's test (fp3 spatial, docs/spatial.md).
#
# tests/test_spatial.sh generates the pipelines of the ship (folded and
# literal RK4), the spring, the oscillator and the projectile, Verilates
# each with sim/spatial_tb.cpp and checks every object after every step
# bit for bit against the golden model (about 40 s, most of it the five
# Verilator builds); it needs build/fp3 and the Verilated runtime.
#
# tests/test_scaleb.sh checks rtl/fp_scaleb.v (a multiply by a power of
# two) against fpref_mul on directed and 3,000,000 random operand pairs
# (about 20 s, one Verilator build).
#
# tests/test_spatial_chip.sh generates the ship's chip top (--pipelines 1
# and 3), Verilates it with sim/spatial_chip_tb.cpp and drives it over
# AXI4-Lite: register map, SLVERR cases, runs over awake lists checked bit
# for bit and against the cycle formula, and two broken frames that must
# fail (about a minute, four Verilator builds).
TEST_SCRIPTS += tests/test_spatial.sh tests/test_scaleb.sh tests/test_spatial_chip.sh
test-build: $(BUILD)/fp3 $(VERILATED_OBJS)
