#!/usr/bin/env bash
# bench-simspeed.sh -- how fast the Verilated models simulate (issue 41's
# "simulation stays usable" target; make bench-simspeed, docs/lanes.md
# "Simulation speed").
#
#   scripts/bench-simspeed.sh [--rounds N] [--baseline FP3] BENCH_CHIP [BEFORE_BENCH_CHIP]
#
# BENCH_CHIP is a bench_chip linked with the chip build (make
# build/bench_chip BENCH_CHIP_MODELS=chip).  Each round runs it once
# (--steps 200; its CSV to a scratch file) and reads its line
# "Verilated model speed on this host":
# object-steps per CPU second of the default 8-context build on 64 ships
# and of the chip build on 256 ships (fp3_run_objects, what
# `fp3 run --objects N --steps 200` runs, every object checked against its
# golden model).  Reported: the median of N rounds (default 3) of both,
# and the ratio chip / default (issue 41 asks >= 4).  When bench_chip
# also prints its line "Verilated spatial chip" (the spatial engine's
# folded ship chip, docs/spatial.md), its median and the ratio spatial /
# chip build, from the same rounds (the spatial issue asks >= 10).
#
# With BEFORE_BENCH_CHIP (the same program built from another revision),
# the rounds alternate between the two, so that both see the same load,
# and the speed-ups after / before are printed too.
#
# With --baseline FP3 (build/fp3 of another revision, e.g. the one the
# lanes issue was filed at, whose default build is the issue's "today's
# 8-context model"), each round also runs `FP3 run --objects 64` for 200
# and for 20 integrations and times their CPU (bash `time`, user + sys);
# the baseline's object-steps per CPU second are 64 x 180 over the
# difference (process start, model construction and the first 20
# integrations cancel), and the chip build's median over that is printed
# as the ratio against the baseline.
#
# A benchmark: it prints figures and fails only when a run fails (a
# golden-model mismatch fails bench_chip), never on a speed.
set -euo pipefail
rounds=3 baseline=
while [ $# -gt 0 ]; do
  case $1 in
    --rounds) [ $# -ge 2 ] || { echo "$0: --rounds needs a value" >&2; exit 2; }; rounds=$2; shift 2;;
    --baseline) [ $# -ge 2 ] || { echo "$0: --baseline needs an fp3 executable" >&2; exit 2; }; baseline=$2; shift 2;;
    *) break;;
  esac
done
[ $# -ge 1 ] && [ $# -le 2 ] || { echo "usage: $0 [--rounds N] [--baseline FP3] BENCH_CHIP [BEFORE_BENCH_CHIP]" >&2; exit 2; }
case $rounds in ''|*[!0-9]*|0) echo "$0: --rounds must be a positive integer" >&2; exit 2;; esac
for b in "$@" $baseline; do [ -x "$b" ] || { echo "$0: $b: not an executable" >&2; exit 2; }; done

after=$1; before=${2:-}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# One run of $1: "DEFAULT CHIP SPATIAL" object-steps per CPU second (SPATIAL
# "-" when it printed none), appended to $2.
one() {
  local out dc sp
  out=$("$1" --steps 200 --csv "$tmp/chip.csv") || { echo "$0: $1 failed" >&2; echo "$out" >&2; exit 1; }
  dc=$(echo "$out" | sed -n 's/^Verilated model speed.*64 ships: \([0-9]*\); chip (.*256 ships: \([0-9]*\);.*/\1 \2/p')
  [ -n "$dc" ] || { echo "$0: $1 printed no chip build speed (is the chip build linked?)" >&2; exit 1; }
  sp=$(echo "$out" | sed -n 's/^Verilated spatial chip (\([0-9]*\) pipelines, folded), \([0-9]*\) ships: \([0-9]*\) object-steps.*/\3 \1 \2/p')
  echo "$dc ${sp:--}" >>"$2"
}
# CPU seconds (user + sys) of `$baseline run --objects 64 --steps $1`.
cpu_run() {
  local TIMEFORMAT='%3U %3S' t
  t=$( { time "$baseline" run --objects 64 --steps "$1" >/dev/null 2>"$tmp/base.err"; } 2>&1 ) \
    || { echo "$0: $baseline run --objects 64 --steps $1 failed:" >&2; cat "$tmp/base.err" >&2; exit 1; }
  echo "$t" | awk '{ print $1 + $2 }'
}
# One baseline round: object-steps per CPU second, appended to $tmp/base.
base_one() {
  local long short
  long=$(cpu_run 200); short=$(cpu_run 20)
  awk -v l="$long" -v s="$short" 'BEGIN { if (l <= s) { print "bad" } else printf "%.0f\n", 64 * 180 / (l - s) }' >>"$tmp/base"
  ! grep -q bad "$tmp/base" || { echo "$0: the baseline's 200 integrations took no longer than 20" >&2; exit 1; }
}
for r in $(seq "$rounds"); do
  [ -n "$before" ] && one "$before" "$tmp/before"
  one "$after" "$tmp/after"
  [ -n "$baseline" ] && base_one
done

median() { sort -n | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
report() {
  local d c
  d=$(cut -d' ' -f1 "$tmp/$1" | median); c=$(cut -d' ' -f2 "$tmp/$1" | median)
  printf '%-6s default build, 64 ships: %6.0f   chip build, 256 ships: %6.0f   ratio %.2f\n' \
    "$1" "$d" "$c" "$(echo "$c / $d" | bc -l)"
  echo "$d $c" >"$tmp/$1.med"
  # the spatial chip, when every round printed it
  if ! cut -d' ' -f3 "$tmp/$1" | grep -q -- '^-$'; then
    local sp pipes ships
    sp=$(cut -d' ' -f3 "$tmp/$1" | median)
    read -r _ _ _ pipes ships <"$tmp/$1"
    printf '%-6s spatial chip (%s pipelines, folded), %s ships: %6.0f   spatial / chip build: %.2f\n' \
      "" "$pipes" "$ships" "$sp" "$(echo "$sp / $c" | bc -l)"
  fi
}
echo "object-steps per CPU second, median of $rounds rounds (bench_chip --steps 200):"
[ -n "$before" ] && report before
report after
if [ -n "$baseline" ]; then
  b=$(median <"$tmp/base"); read -r ad ac <"$tmp/after.med"
  printf 'baseline %s run --objects 64: %6.0f   chip build / baseline: %.2f\n' "$baseline" "$b" \
    "$(echo "$ac / $b" | bc -l)"
fi
if [ -n "$before" ]; then
  read -r bd bc <"$tmp/before.med"; read -r ad ac <"$tmp/after.med"
  printf 'speed-up after / before: default build %.2f, chip build %.2f\n' \
    "$(echo "$ad / $bd" | bc -l)" "$(echo "$ac / $bc" | bc -l)"
fi
