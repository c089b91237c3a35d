# spatial.mk -- the spatial back end's test (fp3 spatial, docs/spatial.md).
#
# tests/test_spatial.sh generates the pipelines of the ship (folded and
# literal RK4), the spring, the oscillator and the projectile, Verilates
# each with sim/spatial_tb.cpp and checks every object after every step
# bit for bit against the golden model (about 40 s, most of it the five
# Verilator builds); it needs build/fp3 and the Verilated runtime.
#
# tests/test_spatial_chip.sh generates the ship's chip top (--pipelines 3),
# Verilates it with sim/spatial_chip_tb.cpp and drives it over
# AXI4-Lite: register map, SLVERR cases, runs over awake lists checked bit
# for bit and against the cycle formula, and two broken frames that must
# fail (three Verilator builds, about 50 s; kept in build/spatial-chip-tb
# by a hash of their inputs, so about 18 s on the same sources).
TEST_SCRIPTS += tests/test_spatial.sh tests/test_spatial_chip.sh
test-build: $(BUILD)/fp3 $(VERILATED_OBJS)

# tests/test_spatial_engine.sh: fp3 run and fp3 frames --engine spatial
# (the model's chip, Verilated on first use into build/spatial-cache,
# loaded with dlopen, driven over AXI4-Lite, observed on its trace port):
# the ship and the oscillator bit-exact after every step and equal to
# --engine rtl, the cache reused, damaged entries found and rebuilt (in a
# temporary copy), bad options refused (about 20 s once the tree's two
# chips are built, 50 s before).
TEST_SCRIPTS += tests/test_spatial_engine.sh

# test-spatial-all: what make test leaves out of the spatial chip's test:
# the 1-pipeline chip and seven more broken frames (about 3 minutes).
.PHONY: test-spatial-all
## test-spatial-all: the spatial chip's slower checks (tests/test_spatial_chip.sh --mutants)
test-spatial-all: $(BUILD)/fp3 $(VERILATED_OBJS)
	bash tests/test_spatial_chip.sh --mutants
