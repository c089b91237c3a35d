# spatial.mk -- the spatial back end's test (fp3 spatial, docs/spatial.md).
#
# tests/test_spatial.sh generates the pipeline of every shipped model
# with every integrator that applies to it, and three variants of the
# cores, Verilates each with sim/spatial_tb.cpp and checks every object
# after every step bit for bit against the golden model, and the ship's
# module with a delay stage removed in each form of delay segment must
# fail (72 Verilator builds, two at a time: about 7 CPU minutes, 4 on two
# idle cores); it needs build/fp3 and the Verilated runtime.
#
# tests/test_scaleb.sh checks rtl/fp_scaleb.v (a multiply by a power of
# two) against fpref_mul on directed and 3,000,000 random operand pairs
# (about 20 s, one Verilator build).
#
# tests/test_spatial_chip.sh generates the ship's chip top (--pipelines 3),
# Verilates it with sim/spatial_chip_tb.cpp and drives it over
# AXI4-Lite: register map, SLVERR cases, runs over awake lists checked bit
# for bit and against the cycle formula, and two broken frames that must
# fail (three Verilator builds, about 50 s; kept in build/spatial-chip-tb
# by a hash of their inputs, so about 18 s on the same sources).
TEST_SCRIPTS += tests/test_spatial.sh tests/test_scaleb.sh tests/test_spatial_chip.sh
test-build: $(BUILD)/fp3 $(VERILATED_OBJS)

# tests/test_spatial_engine.sh: fp3 run and fp3 frames --engine spatial
# (the model's chip, Verilated on first use into build/spatial-cache,
# loaded with dlopen, driven over AXI4-Lite, observed on its trace port):
# the ship and the oscillator bit-exact after every step and equal to
# --engine rtl, the cache reused, damaged entries found and rebuilt (in a
# temporary copy), bad options refused (about 18 s once the tree's two
# chips are built, 55 s before).
TEST_SCRIPTS += tests/test_spatial_engine.sh

# `make pnr-spatial MODEL=models/ship.fp3m | SCENE=FILE [INTEGRATOR=rk4se]
# [LITERAL=1] [PIPELINES=N] [FTZ=1] [MULT_BLOCKS=3] [PNR_SEED=n |
# PNR_SEEDS="1 2 ..."] [SPATIAL_OPTS="..."]`: a spatial chip (the step module in the frame
# behind its AXI4-Lite slave; with SCENE, for that scene: the terms of
# params zero in every object removed, `fp3 spatial --scene`; LITERAL=1
# the integrator's literal operations, `--literal`; MULT_BLOCKS=3 three
# MULT18X18D per multiply, `--mult-blocks 3`; SDFF=1 Yosys's flip-flops
# with a synchronous set or reset, which do not place above about 78 % of
# the TRELLIS_COMB: by default every set and reset is LUT logic) on the LFE5U-85F, N
# pipelines (default: as many as the area estimate fits), through
# scripts/pnr-spatial.sh (synth_ecp5, nextpnr).  The cores at
# SPATIAL_OPTS (default --clock-cores: the cores for clock rate, `fp3
# spatial --help`).  Each chip has its own folder,
# $(BUILD)/pnr-spatial/NAME (PNR_SPATIAL_NAME: the model's or scene's
# name, the integrator, -literal, -ftz, -b3, -sdff, -nN when PIPELINES is given; name
# SPATIAL_OPTS' other choices yourself, PNR_SPATIAL_NAME=...), so that the
# folded and the literal ship's seeds (make bench-chip reads both) do not
# mix.  About 25 minutes a seed for three ship pipelines on this machine,
# two at a time.
MODEL        ?=
SCENE        ?=
PIPELINES    ?=
FTZ          ?=
LITERAL      ?=
MULT_BLOCKS  ?=
SDFF         ?=
SPATIAL_OPTS ?= --clock-cores
# The integrator: INTEGRATOR; with SCENE and no INTEGRATOR of the user's,
# fp3 spatial's choice for the scene (rk4se for a ship scene).
PNR_SPATIAL_INTEGRATOR = $(if $(and $(SCENE),$(filter file default undefined,$(origin INTEGRATOR))),,$(INTEGRATOR))
PNR_SPATIAL_NAME ?= $(basename $(notdir $(or $(SCENE),$(MODEL))))$(if $(PNR_SPATIAL_INTEGRATOR),-$(PNR_SPATIAL_INTEGRATOR))$(if $(filter 1,$(LITERAL)),-literal)$(if $(filter 1,$(FTZ)),-ftz)$(if $(filter 3,$(MULT_BLOCKS)),-b3)$(if $(filter 1,$(SDFF)),-sdff)$(if $(PIPELINES),-n$(PIPELINES))
# tests/test_synth_sdff.sh: synth.sh's flow without synchronous set/reset
# flip-flops, the one pnr-spatial synthesizes with (SDFF above).
TEST_SCRIPTS += tests/test_synth_sdff.sh
# tests/test_pnr_spatial.sh: pnr-spatial.sh synthesizes a chip once for a
# sweep in parts (stand-ins for Yosys and nextpnr).
TEST_SCRIPTS += tests/test_pnr_spatial.sh
.PHONY: pnr-spatial
## pnr-spatial: a spatial chip on the LFE5U-85F (MODEL=models/ship.fp3m | SCENE=FILE, INTEGRATOR=rk4se [LITERAL=1] [PIPELINES=N] [FTZ=1] [MULT_BLOCKS=3] [SDFF=1] [PNR_SEED=n]), in build/pnr-spatial/NAME
pnr-spatial: $(BUILD)/fp3 pnr-tools
	@test -n "$(MODEL)$(SCENE)" || { echo "make pnr-spatial: name the model or a scene: MODEL=models/ship.fp3m or SCENE=scenes/drift.scene" >&2; exit 2; }
	@test -z "$(LITERAL)" -o "$(LITERAL)" = 1 || { echo "make pnr-spatial: LITERAL=1 or nothing, not '$(LITERAL)'" >&2; exit 2; }
	@test -z "$(MULT_BLOCKS)" -o "$(MULT_BLOCKS)" = 3 -o "$(MULT_BLOCKS)" = 4 || { echo "make pnr-spatial: MULT_BLOCKS=3, 4 or nothing, not '$(MULT_BLOCKS)'" >&2; exit 2; }
	@test -z "$(SDFF)" -o "$(SDFF)" = 0 -o "$(SDFF)" = 1 || { echo "make pnr-spatial: SDFF=1, 0 or nothing, not '$(SDFF)'" >&2; exit 2; }
	@SYNTH_ECP5_SDFF=$(if $(filter 1,$(SDFF)),1,0) bash scripts/pnr-spatial.sh $(BUILD)/pnr-spatial/$(PNR_SPATIAL_NAME) "$(MODEL)" "$(PNR_SPATIAL_INTEGRATOR)" "$(PIPELINES)" "$(FTZ)" $(SPATIAL_OPTS) $(if $(SCENE),--scene $(SCENE)) $(if $(LITERAL),--literal) $(if $(MULT_BLOCKS),--mult-blocks $(MULT_BLOCKS))

# test-spatial-all: what make test leaves out of the spatial chip's test:
# the 1-pipeline chip and seven more broken frames (about 3 minutes).
.PHONY: test-spatial-all
## test-spatial-all: the spatial chip's slower checks (tests/test_spatial_chip.sh --mutants)
test-spatial-all: $(BUILD)/fp3 $(VERILATED_OBJS)
	bash tests/test_spatial_chip.sh --mutants

# spatial-table: docs/models.md's table of spatial chips, every shipped
# model x integrator (scripts/spatial-table.sh; SPATIAL_FMAX, the placed
# ship chip's median, adds ns per object-step).
.PHONY: spatial-table
## spatial-table: every shipped model x integrator as a spatial pipeline: cores, latency, area, pipelines per chip (SPATIAL_FMAX= adds ns per object-step)
spatial-table: $(BUILD)/fp3
	@bash scripts/spatial-table.sh $(if $(SPATIAL_FMAX),--fmax $(SPATIAL_FMAX)) $(BUILD)/fp3
