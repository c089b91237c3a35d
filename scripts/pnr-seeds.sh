#!/usr/bin/env bash
# pnr-seeds.sh NAME JSON OUTDIR SEED... -- place and route one ECP5 netlist
# once per nextpnr seed (scripts/pnr.sh; make pnr PNR_SEEDS="1 2 3 4"), a
# seed sweep: placement alone moves Fmax by 15-20 MHz on the build for
# clock rate (docs/fpga.md "How to sweep seeds"), so one seed says little.
#
# PNR_JOBS placements run at a time (default: the CPUs, nproc); each is
# single-threaded (--threads 1), so its result does not depend on the
# machine.  A line per seed as it ends, then the table of all seeds, their
# least, median, mean and greatest Fmax, and the best seed (ties: the lower
# seed); the median (of an even count, the mean of the middle two) also
# alone in OUTDIR/fmax_median.txt.  A sweep may be run in parts (SEED...
# of each call): the table covers every seed-K/ in OUTDIR placed from the
# same netlist (its SHA-256 in seed-K/netlist.sha256), this call's seeds
# and earlier calls'; seeds of another netlist are left out.
# Outputs in OUTDIR: seed-K/ per seed (pnr.sh's log, report,
# configuration); pnr_seeds.csv (seed,fmax_mhz,levels,logic_ns,routing_ns,
# from,to); pnr_summary.csv gets the best seed's row; NAME_ecp5.config is
# a copy of the best placement's configuration (for ecppack).
# Progress: a line every PNR_PROGRESS seconds (default 60, 0 for none)
# with the phase of each seed that is placing (scripts/pnr-phase.py).
# Exit status: 2 on a bad argument, 1 if a seed does not place (the
# netlist does not fit), 0 otherwise, also when timing misses.
set -euo pipefail
if [ $# -lt 4 ] || [ "${1:-}" = -h ] || [ "${1:-}" = --help ]; then
  sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'
  [ $# -ge 1 ] && { [ "$1" = -h ] || [ "$1" = --help ]; } && exit 0
  exit 2
fi
name=$1; json=$2; out=$3; shift 3
seeds=("$@")
for s in "${seeds[@]}"; do
  [[ "$s" =~ ^[0-9]+$ ]] || { echo "pnr-seeds.sh: bad seed '$s' (a non-negative integer)" >&2; exit 2; }
done
[ -f "$json" ] || { echo "pnr-seeds.sh: no netlist '$json'" >&2; exit 2; }
jobs=${PNR_JOBS:-$(nproc)}
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "pnr-seeds.sh: bad PNR_JOBS '$jobs' (a positive integer)" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out"
# An earlier sweep's best placement must not pose as this one's.
rm -f "$out/${name}_ecp5.config"
echo "pnr-seeds: $name, ${#seeds[@]} seeds (${seeds[*]}), $jobs at a time"

sum=$(sha256sum < "$json" | cut -d' ' -f1)

# One seed: pnr.sh into seed-K/, its output kept in seed-K/pnr.out; the
# netlist's checksum written once it has placed.
one() {
  local s=$1 dir="$out/seed-$1"
  rm -rf "$dir"; mkdir -p "$dir"
  echo "$dir/${name}_ecp5.log" > "$live/$s"
  if PNR_SEED=$s PNR_PROGRESS=0 bash "$here/pnr.sh" ecp5 "$name" "$json" "$dir" > "$dir/pnr.out" 2>&1; then
    rm -f "$live/$s"
    echo "$sum" > "$dir/netlist.sha256"
    echo "  seed $s: $(grep -o 'Fmax [0-9.]* MHz' "$dir/pnr.out")"
  else
    rm -f "$live/$s"
    echo "  seed $s: does not place (see $dir/pnr.out)"; return 1
  fi
}

# Progress: every PNR_PROGRESS seconds a line with each running seed's
# phase (scripts/pnr-progress.sh; a seed registers its log in $live while
# it runs).
live=$(mktemp -d "${TMPDIR:-/tmp}/fp3_pnr_seeds.XXXXXX")
. "$here/pnr-progress.sh"
trap 'pnr_progress_stop; rm -rf "$live"' EXIT
pnr_progress_start "pnr-seeds: $name" "$live"

failed=0; running=0
for s in "${seeds[@]}"; do
  if [ "$running" -ge "$jobs" ]; then
    wait -n || failed=1; running=$((running - 1))
  fi
  one "$s" & running=$((running + 1))
done
while [ "$running" -gt 0 ]; do wait -n || failed=1; running=$((running - 1)); done
pnr_progress_stop
[ "$failed" -eq 0 ] || { echo "pnr-seeds: $name does not place on every seed" >&2; exit 1; }

# Every seed placed from this netlist, in this call or an earlier one.
all=()
for d in "$out"/seed-*/; do
  s=${d%/}; s=${s##*/seed-}
  if [[ "$s" =~ ^[0-9]+$ ]] && [ "$(cat "$d/netlist.sha256" 2>/dev/null)" = "$sum" ] &&
     [ -f "$d/pnr_summary.csv" ]; then all+=("$s"); fi
done
mapfile -t all < <(printf '%s\n' "${all[@]}" | sort -n)
[ ${#all[@]} -eq ${#seeds[@]} ] ||
  echo "pnr-seeds: with the earlier placements of this netlist in $out: ${#all[@]} seeds (${all[*]})"

# pnr.sh's summary row: name,device,luts,ffs,dsps,brams,fmax_mhz,target_mhz,
# levels,logic_ns,routing_ns,from,to.
echo "seed,fmax_mhz,levels,logic_ns,routing_ns,from,to" > "$out/pnr_seeds.csv.tmp"
for s in "${all[@]}"; do
  tail -1 "$out/seed-$s/pnr_summary.csv" |
    awk -F, -v s="$s" 'BEGIN{OFS=","} {print s,$7,$9,$10,$11,$12,$13}'
done >> "$out/pnr_seeds.csv.tmp"
mv "$out/pnr_seeds.csv.tmp" "$out/pnr_seeds.csv"
best=$(tail -n +2 "$out/pnr_seeds.csv" | sort -t, -k2,2gr -k1,1n | head -1 | cut -d, -f1)
# The median (of an even count, the mean of the two middle values) is the
# figure a placement of this netlist can be expected to reach; the
# greatest is the best seed's.  It goes alone into fmax_median.txt too.
tail -n +2 "$out/pnr_seeds.csv" | cut -d, -f2 | sort -g |
  awk -v n="$name" -v b="$best" -v mf="$out/fmax_median.txt" '
  { v[NR] = $1; s += $1 }
  END { med = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
        printf "pnr-seeds: %s: Fmax over %d seeds: least %.1f, median %.1f, mean %.1f, greatest %.1f MHz (seed %s)\n",
               n, NR, v[1], med, s / NR, v[NR], b
        printf "%.1f\n", med > mf }'
awk -F, '{ printf "  %-5s %-9s %-7s %-9s %-11s %s\n", $1, $2, $3, $4, $5, $6 " -> " $7 }' \
  "$out/pnr_seeds.csv" | cut -c1-150
tail -1 "$out/seed-$best/pnr_summary.csv" >> "$out/pnr_summary.csv"
cp "$out/seed-$best/${name}_ecp5.config" "$out/${name}_ecp5.config.tmp"
mv "$out/${name}_ecp5.config.tmp" "$out/${name}_ecp5.config"
echo "pnr-seeds: the best placement's configuration: $out/${name}_ecp5.config"
