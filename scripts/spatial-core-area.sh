#!/usr/bin/env bash
# spatial-core-area.sh [OUTDIR] -- the per-core area table of the spatial
# back end's estimate (sw/compiler/spatial.c, core_area[]): every core
# configuration a pipeline uses, synthesized alone with Yosys synth_ecp5
# (scripts/synth.sh ecp5: the flow of the chip builds, with FP3_ECP5_DSP),
# and one C table row each:
#   { kind, LATENCY, ROUND, FTZ, LUT4s, FFs, MULT18X18D },
# LUT4s counted as scripts/synth-report.sh does (a CCU2C as two).
# fp_scaleb is measured as the generator uses it, with a constant b (the
# larger of b = 0.5 and b = 2; a constant folds most of it away).
# Synthesized in the flow of make pnr-spatial: no flip-flop with a
# synchronous set or reset (SYNTH_ECP5_SDFF=0, docs/spatial.md); a core
# maps to up to about 15 % more or fewer LUT4s than in Yosys's own
# flip-flops' flow (fp_add at latency 9: 907 against 1,051; at 4: 1,175
# against 1,099).
# Takes about 15 minutes on this machine (fp_div and fp_sqrt the longest).
set -euo pipefail
cd "$(dirname "$0")/.."
export SYNTH_ECP5_SDFF=0
out=${1:-build/spatial-core-area}
mkdir -p "$out"
# core  kind-name  parameters beside LATENCY, ROUND, FTZ (comma-separated;
# - none)  latencies (MUL_FEED: fp_mul with its feed register in front of
# the MULT18X18D; MUL_B3, MUL_FEED_B3: its product in three blocks)
rows=(
  "fp_add FP3_IR_ADD - 4 9 10"
  "fp_mul FP3_IR_MUL - 3 9 10"
  "fp_mul MUL_FEED FEED=1 10"
  "fp_mul MUL_B3 MULT_BLOCKS=3 3 9"
  "fp_mul MUL_FEED_B3 FEED=1,MULT_BLOCKS=3 10"
  "fp_div FP3_IR_DIV - 8"
  "fp_sqrt FP3_IR_SQRT - 8"
)
for r in "${rows[@]}"; do
  read -r core kind extra lats <<<"$r"
  [ "$extra" = - ] && extra=
  for lat in $lats; do
    for cfg in "0 0" "0 1" "1 0"; do
      read -r round ftz <<<"$cfg"
      params=(LATENCY=$lat ${extra//,/ } ROUND=$round FTZ=$ftz)
      tag=""; for p in "${params[@]}"; do tag+="_${p%%=*}-${p#*=}"; done
      bash scripts/synth.sh "$out" "$core" ecp5 "${params[@]}" rtl/*.v >/dev/null
      read -r luts ffs mult _ < <(bash scripts/synth-report.sh --fields \
        "$out/${core}${tag}_ecp5_stat.txt")
      printf '    {%s, %u, %u, %u, %u, %u, %u}, /* %s */\n' "$kind" "$lat" "$round" "$ftz" \
        "$luts" "$ffs" "$mult" "$core${extra:+, ${extra//[=,]/ }}"
    done
  done
done
# fp_scaleb with a constant b: a wrapper per constant
for lat in 1 2 4; do
  for cfg in "0 0" "0 1" "1 0"; do
    read -r round ftz <<<"$cfg"
    best="0 0 0"
    for b in 3F000000 40000000; do
      cat > "$out/scaleb_$b.v" <<EOV
// fp_scaleb with b = 32'h$b, for its area (scripts/spatial-core-area.sh)
module scaleb_$b #(parameter integer LATENCY = 1, parameter integer ROUND = 0,
                   parameter integer FTZ = 0) (
  input wire clk_i, input wire rst_i, input wire valid_i, input wire [31:0] a_i,
  output wire valid_o, output wire [31:0] y_o, output wire [4:0] flags_o);
  fp_scaleb #(.LATENCY(LATENCY), .ROUND(ROUND), .FTZ(FTZ)) u_scaleb (
    .clk_i(clk_i), .rst_i(rst_i), .valid_i(valid_i), .a_i(a_i), .b_i(32'h$b),
    .valid_o(valid_o), .y_o(y_o), .flags_o(flags_o));
endmodule
EOV
      bash scripts/synth.sh "$out" "scaleb_$b" ecp5 LATENCY=$lat ROUND=$round FTZ=$ftz \
        "$out/scaleb_$b.v" rtl/*.v >/dev/null
      read -r luts ffs mult _ < <(bash scripts/synth-report.sh --fields \
        "$out/scaleb_${b}_LATENCY-${lat}_ROUND-${round}_FTZ-${ftz}_ecp5_stat.txt")
      read -r bl _ <<<"$best"
      [ "$luts" -gt "$bl" ] && best="$luts $ffs $mult"
    done
    read -r luts ffs mult <<<"$best"
    printf '    {%s, %u, %u, %u, %u, %u, %u}, /* %s */\n' SCALEB "$lat" "$round" "$ftz" \
      "$luts" "$ffs" "$mult" "fp_scaleb, b = 0.5 or 2"
  done
done
# fp_sign has neither rounding nor FTZ
bash scripts/synth.sh "$out" fp_sign ecp5 LATENCY=1 rtl/*.v >/dev/null
read -r luts ffs mult _ < <(bash scripts/synth-report.sh --fields "$out/fp_sign_LATENCY-1_ecp5_stat.txt")
printf '    {%s, %u, %u, %u, %u, %u, %u}, /* %s */\n' SIGN 1 0 0 "$luts" "$ffs" "$mult" fp_sign
