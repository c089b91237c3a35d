# verilated_env.sh -- sourced by the tests that Verilate a harness of their
# own (test_spatial.sh, test_spatial_chip.sh, test_scaleb.sh) from the
# repository's root: the tools and the prebuilt Verilator runtime they link.
#   FP3        build/fp3 (or $FP3_BIN)
#   VERILATOR  the verilator to run (or $VERILATOR)
#   VINC       Verilator's include folder
#   RUNTIME    the runtime objects `make test-build` prebuilds
# Ends the test (FAIL, exit 1) when one of them is not built.
FP3=${FP3_BIN:-$PWD/build/fp3}
VERILATOR=${VERILATOR:-verilator}
VINC=$($VERILATOR --getenv VERILATOR_ROOT)/include
RUNTIME="build/verilated/verilated.o build/verilated/verilated_threads.o"
for f in "$FP3" $RUNTIME; do
  [ -e "$f" ] || { echo "FAIL: $f not built (make $f)"; exit 1; }
done
