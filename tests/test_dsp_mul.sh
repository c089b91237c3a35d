#!/usr/bin/env bash
# test_dsp_mul.sh -- fp_dsp_mul's ECP5 form (a MULT18X18D with its input
# and output registers, FP3_ECP5_DSP: rtl/fp_dsp_mul.v), which only
# synthesis sees:
#   - the ECP5 flow (scripts/synth.sh) maps fp_dsp_mul, W = 12 and 18, to
#     one MULT18X18D with REG_INPUTA_CLK, REG_INPUTB_CLK and REG_OUTPUT_CLK
#     on CLK0 and no flip-flop or LUT beside it;
#   - that netlist, simulated by Icarus with a model of the block
#     (sim/ecp5_mult18x18d.v), multiplies as the behavioural form does,
#     every cycle for 20,000 cycles (sim/tb_dsp_mul.v);
#   - fp_mul takes the registered blocks at MUL_LATENCY 6 to 9 (four
#     MULT18X18D, all three registers on) and not at 5 (four, none on)
#     nor at 10 (the LUT product: none); at 10 with FEED = 1 it takes
#     them with the feed register in front, at least the 48 significand
#     flip-flops more than at 9; with MULT_BLOCKS = 3 it takes three
#     MULT18X18D, registered at 10 with FEED = 1, not at 3.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
synth() { # OUTNAME TOP PARAM... -- FILES
  bash scripts/synth.sh "$tmp" "$@" >"$tmp/synth.log" 2>&1 || {
    tail -20 "$tmp/synth.log"; echo "FAIL: scripts/synth.sh ecp5 $2"; exit 1; }
}
count() { awk -v c="$1" '$1 == c { n = $2 } END { print n + 0 }' "$2"; }
regs_on() { grep -c "$1(\"CLK0\")" "$2" || true; }

for w in 12 18; do
  synth fp_dsp_mul ecp5 W=$w rtl/fp_dsp_mul.v
  base="$tmp/fp_dsp_mul_W-${w}_ecp5"
  st="${base}_stat.txt"
  [ "$(count MULT18X18D "$st")" = 1 ] && [ "$(count TRELLIS_FF "$st")" = 0 ] &&
    [ "$(count LUT4 "$st")" = 0 ] || {
    cat "$st"; echo "FAIL: W = $w is not one MULT18X18D alone"; exit 1; }
  for r in REG_INPUTA_CLK REG_INPUTB_CLK REG_OUTPUT_CLK; do
    [ "$(regs_on $r "$base.v")" = 1 ] || {
      grep -n "REG_" "$base.v"; echo "FAIL: W = $w: $r is not CLK0"; exit 1; }
  done
  echo "PASS: scripts/synth.sh ecp5 maps fp_dsp_mul W = $w to one MULT18X18D, input and output registers on"

  # The netlist, its module renamed beside the RTL's, simulated.
  sed 's/^module fp_dsp_mul(/module fp_dsp_mul_ecp5(/' "$base.v" > "$tmp/net.v"
  grep -q "^module fp_dsp_mul_ecp5(" "$tmp/net.v" || { echo "FAIL: no module fp_dsp_mul in the netlist"; exit 1; }
  iverilog -g2005 -Irtl -P tb_dsp_mul.W=$w -s tb_dsp_mul -o "$tmp/tb.vvp" rtl/fp_dsp_mul.v \
    "$tmp/net.v" sim/ecp5_mult18x18d.v sim/tb_dsp_mul.v 2>"$tmp/iv.log" || {
    cat "$tmp/iv.log"; echo "FAIL: iverilog on the MULT18X18D netlist"; exit 1; }
  vvp -n "$tmp/tb.vvp" +cycles=20000 +seed=$((w + 5)) | tee "$tmp/sim.log" | tail -6
  grep -q "^PASS" "$tmp/sim.log" || { echo "FAIL: the MULT18X18D form multiplies differently"; exit 1; }
done

# fp_mul's product by latency: registered blocks from 6 to 9 only.
# (every RTL file read, as make synth reads them: no second list of
# fp_mul's submodules to keep beside mk/fpu.mk's)
for spec in 5:4:0 6:4:4 9:4:4 10:0:0 10,FEED=1:4:4 10,FEED=1,MULT_BLOCKS=3:3:3 \
            3,MULT_BLOCKS=3:3:0; do
  IFS=: read -r lat blocks on <<<"$spec"
  params="LATENCY=${lat//,/ }"                                 # LATENCY=10 FEED=1
  synth fp_mul ecp5 $params rtl/*.v
  base="$tmp/fp_mul_$(echo "$params" | sed 's/=/-/g; s/ /_/g')_ecp5"
  got_blocks=$(count MULT18X18D "${base}_stat.txt")
  got_on=$(regs_on REG_OUTPUT_CLK "$base.v")
  got_in=$(regs_on REG_INPUTA_CLK "$base.v")
  [ "$got_blocks" = "$blocks" ] && [ "$got_on" = "$on" ] && [ "$got_in" = "$on" ] || {
    echo "FAIL: fp_mul $params: $got_blocks MULT18X18D, $got_in/$got_on with input/output" \
         "registers; want $blocks, $on/$on"; exit 1; }
  echo "PASS: fp_mul $params: $blocks MULT18X18D, $on with their input and output registers"
done
ff9=$(count TRELLIS_FF "$tmp/fp_mul_LATENCY-9_ecp5_stat.txt")
ff10f=$(count TRELLIS_FF "$tmp/fp_mul_LATENCY-10_FEED-1_ecp5_stat.txt")
[ $((ff10f - ff9)) -ge 48 ] || {
  echo "FAIL: fp_mul LATENCY=10 FEED=1 has $ff10f flip-flops, LATENCY=9 $ff9: no feed register"; exit 1; }
echo "PASS: fp_mul FEED=1: $((ff10f - ff9)) flip-flops in front of the blocks ($ff9 at latency 9, $ff10f)"
