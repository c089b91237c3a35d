#!/usr/bin/env bash
# pnr-spatial.sh OUTDIR MODEL INTEGRATOR PIPELINES FTZ [FP3 SPATIAL OPTIONS...]
# -- a spatial chip on the LFE5U-85F (make pnr-spatial, docs/spatial.md):
#   1. `fp3 spatial` of MODEL with INTEGRATOR and the options, to read the
#      area estimate's pipelines that fit (report.txt); PIPELINES empty
#      takes that many (none: the model does not fit, exit 2);
#   2. the chip top with PIPELINES pipelines (--pipelines N) in OUTDIR/gen;
#   3. Yosys synth_ecp5 (scripts/synth.sh ecp5), the step module kept as a
#      level of hierarchy (mapped once for the N copies, as the lane chip
#      build keeps fp3_lane), into OUTDIR/synth; its area beside the
#      estimate's N x per-pipeline figures;
#   4. nextpnr: scripts/pnr.sh with PNR_SEED (default 1), or with
#      PNR_SEEDS="1 2 ..." scripts/pnr-seeds.sh (a sweep, in parts if need
#      be), into OUTDIR.
# FTZ = 1 adds --ftz.  Environment: FP3_BIN (default build/fp3), as
# scripts/pnr.sh and pnr-seeds.sh (PNR_SEED, PNR_SEEDS, PNR_JOBS, ...).
set -euo pipefail
[ $# -ge 5 ] || { sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 2; }
out=$1; model=$2; integ=$3; pipes=$4; ftz=$5; shift 5
here=$(cd "$(dirname "$0")" && pwd)
fp3=${FP3_BIN:-$here/../build/fp3}
opts=(--integrator "$integ" "$@")
[ "$ftz" = 1 ] && opts+=(--ftz)
[ -f "$model" ] || { echo "pnr-spatial: no model file '$model' (MODEL=models/ship.fp3m)" >&2; exit 2; }
mkdir -p "$out"
# 1. the estimate
rm -rf "$out/est"
"$fp3" spatial "$model" "${opts[@]}" -o "$out/est" 2>/dev/null || {
  "$fp3" spatial "$model" "${opts[@]}" -o "$out/est" >/dev/null || true; exit 2; }
fit=$(sed -n 's/^pipelines that fit: \([0-9]*\) .*/\1/p' "$out/est/report.txt")
est=$(sed -n 's/^estimate per pipeline: //p' "$out/est/report.txt")
if [ -z "$pipes" ]; then pipes=$fit; fi
[[ "$pipes" =~ ^[1-9][0-9]*$ ]] || { echo "pnr-spatial: bad PIPELINES '$pipes' (1 or more)" >&2; exit 2; }
echo "pnr-spatial: $(basename "$model") $integ ${*:-}$([ "$ftz" = 1 ] && echo ' --ftz'):" \
     "estimate per pipeline $est; $fit fit; placing $pipes"
# 2. the chip top
rm -rf "$out/gen"
"$fp3" spatial "$model" "${opts[@]}" --pipelines "$pipes" -o "$out/gen" 2>"$out/gen.log" || {
  cat "$out/gen.log" >&2; exit 2; }
step=$(sed -n 's/^module: //p' "$out/gen/report.txt")
top=${step}_top
# 3. synthesis
bash "$here/synth.sh" "$out/synth" "$top" ecp5 -keep "$step" "$out/gen/$step.v" "$out/gen/$top.v" \
  "$here"/../rtl/*.v
# 4. placement and routing
json="$out/synth/${top}_ecp5.json"
name="${top}_n$pipes"
if [ -n "${PNR_SEEDS:-}" ]; then
  # shellcheck disable=SC2086
  bash "$here/pnr-seeds.sh" "$name" "$json" "$out" $PNR_SEEDS
else
  bash "$here/pnr.sh" ecp5 "$name" "$json" "$out"
fi
