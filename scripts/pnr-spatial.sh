#!/usr/bin/env bash
# pnr-spatial.sh OUTDIR MODEL INTEGRATOR PIPELINES FTZ [FP3 SPATIAL OPTIONS...]
# -- a spatial chip on the LFE5U-85F (make pnr-spatial, docs/spatial.md):
#   1. `fp3 spatial` of MODEL with INTEGRATOR and the options, to read the
#      area estimate's pipelines that fit (report.txt); PIPELINES empty
#      takes that many (none: the model does not fit, exit 2);
#   2. the chip top with PIPELINES pipelines (--pipelines N) in OUTDIR/gen;
#   3. Yosys synth_ecp5 (scripts/synth.sh ecp5), the step module kept as a
#      level of hierarchy (mapped once for the N copies, as the lane chip
#      build keeps fp3_lane), with no flip-flop's synchronous set or reset
#      (SYNTH_ECP5_SDFF, default 0 here: every set and reset as LUT logic
#      in front of D, so that the flip-flops share one LSR net and place
#      above 78 % of the TRELLIS_COMB), into OUTDIR/synth, unless the
#      netlist there was synthesized from the same inputs (below); its area
#      beside the estimate's N x per-pipeline figures;
#   4. nextpnr: scripts/pnr.sh with PNR_SEED (default 1), or with
#      PNR_SEEDS="1 2 ..." scripts/pnr-seeds.sh (a sweep, in parts if need
#      be), into OUTDIR.
# INTEGRATOR empty: fp3 spatial's default.  MODEL may be empty when the
# options name a scene (--scene FILE: the scene's model, its zero params'
# terms removed).  FTZ = 1 adds --ftz.  Environment: FP3_BIN (default
# build/fp3), SYNTH_ECP5_SDFF (default 0; 1: Yosys's synchronous
# set/reset flip-flops), as scripts/synth.sh (YOSYS), pnr.sh and
# pnr-seeds.sh (PNR_SEED, PNR_SEEDS, PNR_JOBS, ...).
set -euo pipefail
[ $# -ge 5 ] || { sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
out=$1; model=$2; integ=$3; pipes=$4; ftz=$5; shift 5
here=$(cd "$(dirname "$0")" && pwd)
fp3=${FP3_BIN:-$here/../build/fp3}
opts=(${integ:+--integrator "$integ"} "$@")
[ "$ftz" = 1 ] && opts+=(--ftz)
src=()
if [ -n "$model" ]; then
  [ -f "$model" ] || { echo "pnr-spatial: no model file '$model' (MODEL=models/ship.fp3m)" >&2; exit 2; }
  src=("$model")
fi
mkdir -p "$out"
# 1. the estimate
rm -rf "$out/est"
"$fp3" spatial "${src[@]}" "${opts[@]}" -o "$out/est" 2>/dev/null || {
  "$fp3" spatial "${src[@]}" "${opts[@]}" -o "$out/est" >/dev/null || true; exit 2; }
fit=$(sed -n 's/^pipelines that fit: \([0-9]*\) .*/\1/p' "$out/est/report.txt")
est=$(sed -n 's/^estimate per pipeline: //p' "$out/est/report.txt")
if [ -z "$pipes" ]; then pipes=$fit; fi
[[ "$pipes" =~ ^[1-9][0-9]*$ ]] || { echo "pnr-spatial: bad PIPELINES '$pipes' (1 or more)" >&2; exit 2; }
echo "pnr-spatial: ${model:+$(basename "$model") }$integ ${*:-}$([ "$ftz" = 1 ] && echo ' --ftz'):" \
     "estimate per pipeline $est; $fit fit; placing $pipes"
# 2. the chip top
rm -rf "$out/gen"
"$fp3" spatial "${src[@]}" "${opts[@]}" --pipelines "$pipes" -o "$out/gen" 2>"$out/gen.log" || {
  cat "$out/gen.log" >&2; exit 2; }
step=$(sed -n 's/^module: //p' "$out/gen/report.txt")
top=${step}_top
# 3. synthesis, or the netlist already in OUTDIR/synth when its inputs are
# the same: a sweep run in parts (PNR_SEEDS="4", later "5" ...) places one
# netlist and synthesizes it once (about 8 minutes for a full chip).  The
# inputs are digested into OUTDIR/synth/inputs.sha256, written only after
# a synthesis that succeeded: the generated modules (fp3 spatial writes
# the same text for the same model and options), rtl/'s .v and .vh files,
# this script, synth.sh, SYNTH_ECP5_SDFF and Yosys's version.
sdff=${SYNTH_ECP5_SDFF:-0}
stamp="$out/synth/inputs.sha256"
digest=$({ ${YOSYS:-yosys} -V; echo "SYNTH_ECP5_SDFF=$sdff top=$top step=$step"
           (cd "$out/gen" && sha256sum "$step.v" "$top.v")
           (cd "$here/.." && sha256sum rtl/*.v rtl/*.vh scripts/synth.sh scripts/pnr-spatial.sh)
         } | sha256sum | cut -d' ' -f1)
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$digest" ] &&
   [ -f "$out/synth/${top}_ecp5.json" ] && [ -f "$out/synth/${top}_ecp5_stat.txt" ]; then
  echo "pnr-spatial: the synthesis inputs are unchanged: placing the netlist in $out/synth" \
       "(remove that folder to synthesize again)"
else
  rm -f "$stamp"
  SYNTH_ECP5_SDFF=$sdff \
    bash "$here/synth.sh" "$out/synth" "$top" ecp5 -keep "$step" "$out/gen/$step.v" "$out/gen/$top.v" \
    "$here"/../rtl/*.v
  echo "$digest" > "$stamp"
fi
# The area by part, exact section names (synth.sh's -keep line matches the
# step module's name as a prefix, so it also counts the top's own cells):
# LUT4 sites as the estimate counts them (LUT4, 2 per CCU2C, 6 per
# TRELLIS_DPR16X4).
part() { # SECTION -> "LUT4 FF MULT18X18D EBR"
  awk -v want="=== $1 ===" '
    /^=== / { on = ($0 == want); next }
    on && $1 == "LUT4" { l += $2 } on && $1 == "CCU2C" { l += 2 * $2 }
    on && $1 == "TRELLIS_DPR16X4" { l += 6 * $2 } on && $1 == "TRELLIS_FF" { f += $2 }
    on && $1 == "MULT18X18D" { m += $2 } on && $1 ~ /^(DP16KD|PDPW16KD)$/ { e += $2 }
    END { printf "%d %d %d %d\n", l, f, m, e }' "$out/synth/${top}_ecp5_stat.txt"
}
read -r sl sf sm se < <(part "$step")
read -r fl ff fm fe < <(part "$top")
echo "pnr-spatial: synthesized: each pipeline $sl LUT4, $sf FF, $sm MULT18X18D, $se EBR" \
     "(estimate $est); the frame $fl LUT4, $ff FF, $fm MULT18X18D, $fe EBR;" \
     "in all $((pipes * sl + fl)) LUT4 of 83640, $((pipes * sm + fm)) MULT18X18D of 156," \
     "$((pipes * se + fe)) EBR of 208"
# 4. placement and routing
json="$out/synth/${top}_ecp5.json"
name="${top}_n$pipes"
if [ -n "${PNR_SEEDS:-}" ]; then
  # shellcheck disable=SC2086
  bash "$here/pnr-seeds.sh" "$name" "$json" "$out" $PNR_SEEDS
else
  bash "$here/pnr.sh" ecp5 "$name" "$json" "$out"
fi
