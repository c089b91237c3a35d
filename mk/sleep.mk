# sleep.mk -- sleeping objects: the benchmark.
#
#   make bench-sleep [SLEEP_SHIPS=1000] [SLEEP_FRAMES=600]
#       scripts/bench-sleep.sh: a harbour of SLEEP_SHIPS ships for
#       SLEEP_FRAMES frames of h = 1/60 s on the RTL, awake against
#       sleeping, every object checked against the golden model every
#       frame -> build/bench/sleep.{csv,md}.  About 25 minutes for the
#       default size on a loaded 2-core machine (the awake run is half).
# The library sources (sw/scene/frames.c, sw/cli/cmd_frames.c) reach libfp3.a and
# build/fp3 through mk/sw.mk's wildcard; tests/test_engines checks them.

SLEEP_SHIPS  ?= 1000
SLEEP_FRAMES ?= 600

.PHONY: bench-sleep
## bench-sleep: sleeping objects: a 1,000-ship harbour frame by frame, awake against sleeping (RTL, long)
bench-sleep: $(BUILD)/fp3
	bash scripts/bench-sleep.sh $(BUILD)/fp3 $(BENCH_DIR) $(SLEEP_SHIPS) $(SLEEP_FRAMES)
