#!/usr/bin/env bash
# test_rtl_tools.sh -- the RTL is Verilog-2005 that every tool of the flow
# accepts: Verilator -Wall lint with zero warnings, and Icarus Verilog
# (iverilog -g2005) elaborating the top.
set -euo pipefail
src=$(ls rtl/*.v)
out=$(verilator --lint-only -Wall -Irtl --top-module fp3_top $src 2>&1) || {
  echo "$out"; echo "FAIL: verilator lint"; exit 1; }
if [ -n "$out" ]; then echo "$out"; echo "FAIL: verilator lint printed warnings"; exit 1; fi
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
iverilog -g2005 -Wall -Irtl -s fp3_top -o "$tmp/top.vvp" $src 2>"$tmp/iv.log" || {
  cat "$tmp/iv.log"; echo "FAIL: iverilog -g2005"; exit 1; }
if grep -v "^\s*$" "$tmp/iv.log" | grep -qi "warning"; then
  cat "$tmp/iv.log"; echo "FAIL: iverilog warnings"; exit 1; fi
echo "PASS: verilator -Wall clean, iverilog -g2005 elaborates fp3_top"

# The build for clock rate (FMAX_PIPE, deep FP cores: docs/fpga.md) is
# lint-clean too.
out=$(verilator --lint-only -Wall -Irtl --top-module fp3_top -GFMAX_PIPE=1 -GADD_LATENCY=9 \
        -GMUL_LATENCY=10 $src 2>&1) || { echo "$out"; echo "FAIL: verilator lint, FMAX_PIPE=1"; exit 1; }
if [ -n "$out" ]; then echo "$out"; echo "FAIL: verilator lint (FMAX_PIPE=1) printed warnings"; exit 1; fi
echo "PASS: verilator -Wall clean with FMAX_PIPE=1 ADD_LATENCY=9 MUL_LATENCY=10"

# No latch in either build (make synth fails on one, scripts/synth.sh; this
# is the same check after Yosys's proc alone, seconds instead of minutes):
# a combinational block that leaves a variable unassigned on some path.
for params in "" "-chparam FMAX_PIPE 1 -chparam NUM_CONTEXTS 8 -chparam ADD_LATENCY 9 -chparam MUL_LATENCY 10"; do
  ${YOSYS:-yosys} -q -p "read_verilog -Irtl ${src//$'\n'/ }; hierarchy -top fp3_axil $params; proc;
    select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr" >"$tmp/latch.log" 2>&1 || {
    grep -E "ERROR|latch" "$tmp/latch.log" | head; echo "FAIL: a latch in fp3_axil ($params)"; exit 1; }
done
echo "PASS: no latch after yosys proc (default and FMAX_PIPE=1 builds)"

# make pnr-unit's wrapper (scripts/unit-wrap.py): for the register file of
# the build for clock rate it elaborates in Icarus without a warning, its
# input shift register is as wide as the module's inputs but the reset,
# which comes from a pin (16 8-bit indices, 5 32-bit words, 15 one-bit
# inputs and the two 4-bit LVT choices: 311), and a module it cannot find
# is an error.
${YOSYS:-yosys} -q -p "read_verilog -Irtl ${src//$'\n'/ }; hierarchy -top fp3_regfile -chparam ENTRIES 256 \
  -chparam XW 8 -chparam READ_STAGES 4; proc; write_json $tmp/ports.json" >/dev/null 2>&1 || {
  echo "FAIL: yosys could not elaborate fp3_regfile for unit-wrap.py"; exit 1; }
python3 scripts/unit-wrap.py fp3_regfile "$tmp/ports.json" ENTRIES=256 XW=8 READ_STAGES=4 \
  > "$tmp/unit.v" || { echo "FAIL: unit-wrap.py"; exit 1; }
grep -q "reg \[310:0\] chain;" "$tmp/unit.v" && grep -q "\.rst_i(rst_i)" "$tmp/unit.v" || {
  grep "chain;" "$tmp/unit.v"; echo "FAIL: unit-wrap.py: input chain is not 311 bits, or the reset not from its pin"; exit 1; }
iverilog -g2005 -Wall -Irtl -s fp3_unit -o "$tmp/unit.vvp" $src "$tmp/unit.v" 2>"$tmp/iu.log" || {
  cat "$tmp/iu.log"; echo "FAIL: iverilog on the unit-wrap.py wrapper"; exit 1; }
if grep -v "^\s*$" "$tmp/iu.log" | grep -qi "warning"; then
  cat "$tmp/iu.log"; echo "FAIL: iverilog warnings on the unit-wrap.py wrapper"; exit 1; fi
if python3 scripts/unit-wrap.py no_such_module "$tmp/ports.json" 2>"$tmp/err.txt"; then
  echo "FAIL: unit-wrap.py accepted a missing module"; exit 1; fi
grep -q "module 'no_such_module' not in" "$tmp/err.txt" || {
  cat "$tmp/err.txt"; echo "FAIL: unit-wrap.py: no clear error for a missing module"; exit 1; }
echo "PASS: unit-wrap.py wraps fp3_regfile (311 input bits, the reset from a pin), elaborates, refuses a missing module"
