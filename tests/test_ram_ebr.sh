#!/usr/bin/env bash
# test_ram_ebr.sh -- fp3_ram's ECP5 form (block RAM with its output
# register, FP3_ECP5_EBR: rtl/fp3_ram.v), which only synthesis sees:
# the ECP5 flow (scripts/synth.sh) maps the instruction memory's shape (256
# x 75, two read cycles) to three PDPW16KD blocks with REGMODE OUTREG and
# no LUT RAM; the netlist,
# simulated by Icarus with a model of the block (sim/ecp5_pdpw16kd.v),
# reads what the LUT-RAM form reads (sim/tb_ram_ebr.v); and the form is
# not taken without the define, or deeper than one block (512 words).
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# The ECP5 flow's own synthesis (scripts/synth.sh, as make synth and make
# pnr run it) of the instruction memory's shape.
bash scripts/synth.sh "$tmp" fp3_ram ecp5 DEPTH=256 AW=8 WIDTH=75 READ_STAGES=2 rtl/fp3_ram.v \
  >"$tmp/synth.log" 2>&1 || { tail -20 "$tmp/synth.log"; echo "FAIL: scripts/synth.sh ecp5 fp3_ram"; exit 1; }
base="$tmp/fp3_ram_DEPTH-256_AW-8_WIDTH-75_READ_STAGES-2_ecp5"
count() { awk -v c="$1" '$1 == c { n = $2 } END { print n + 0 }' "${base}_stat.txt"; }
[ "$(count PDPW16KD)" = 3 ] && [ "$(count TRELLIS_DPR16X4)" = 0 ] || {
  cat "${base}_stat.txt"; echo "FAIL: 256 x 75 is not three PDPW16KD without LUT RAM"; exit 1; }
[ "$(grep -c 'REGMODE("OUTREG")' "$base.v")" = 3 ] || {
  grep -n REGMODE "$base.v"; echo "FAIL: the blocks' output registers are not used"; exit 1; }
echo "PASS: scripts/synth.sh ecp5 maps 256 x 75 to 3 PDPW16KD, REGMODE OUTREG, no LUT RAM"

# The netlist, its module renamed beside the RTL's, simulated.
sed 's/^module fp3_ram(/module fp3_ram_ebr(/' "$base.v" > "$tmp/ram.v"
grep -q "^module fp3_ram_ebr(" "$tmp/ram.v" || { echo "FAIL: no module fp3_ram in the netlist"; exit 1; }
iverilog -g2005 -Irtl -s tb_ram_ebr -o "$tmp/tb.vvp" rtl/fp3_ram.v "$tmp/ram.v" \
  sim/ecp5_pdpw16kd.v sim/tb_ram_ebr.v 2>"$tmp/iv.log" || {
  cat "$tmp/iv.log"; echo "FAIL: iverilog on the block-RAM netlist"; exit 1; }
vvp -n "$tmp/tb.vvp" +cycles=20000 +seed=7 | tee "$tmp/sim.log" | tail -3
grep -q "^PASS" "$tmp/sim.log" || { echo "FAIL: the block-RAM form reads differently"; exit 1; }

# Without the define, or deeper than one block, the LUT-RAM form
# (elaborated only: the instance is chosen there).
for args in "|256|8" "-DFP3_ECP5_EBR|1024|10"; do
  IFS='|' read -r def depth aw <<<"$args"
  ${YOSYS:-yosys} -q -p "read_verilog $def -Irtl rtl/fp3_ram.v;
    chparam -set DEPTH $depth -set AW $aw -set WIDTH 75 -set READ_STAGES 2 fp3_ram;
    hierarchy -top fp3_ram; select -assert-none t:PDPW16KD" >"$tmp/yosys.log" 2>&1 || {
    tail -5 "$tmp/yosys.log"; echo "FAIL: PDPW16KD with '$def', $depth words"; exit 1; }
done
echo "PASS: LUT RAM without FP3_ECP5_EBR, and for 1024 words (a block holds 512)"
