#!/usr/bin/env bash
# bench-cosim.sh TEST_ENGINES FIRST COUNT JOBS OUTDIR -- random co-simulation
# in ranges side by side (make bench-cosim): random programs FIRST ..
# FIRST+COUNT-1, RTL against the ISS bit for bit, on the default build and
# on every lanes build of tests/test_engines.c (l4, lf, drift), split into JOBS ranges
# that run at once, one process each (FP3_RANDOM_FIRST and
# FP3_RANDOM_PROGRAMS of TEST_ENGINES).  Program p is the same program in
# any split, so ranges run apart (in several sessions, say) cover the same
# programs as one run of all of them.
#
# Each range's output goes to OUTDIR/cosim-K.log (K from 1); a line a
# minute tells how far each range is.  At the end, a line per range (its
# programs and status) and the total: seconds, and the seed digest (the
# sum of every program's seed, mod 2^64: the same for any split).
# Exit status: 2 on a bad argument, 1 if any range fails (its log names the
# program and the seed that replays it: FP3_RANDOM_SEED=<seed>
# TEST_ENGINES), 0 when every program agrees.
set -euo pipefail
usage() { sed -n '2,17p' "$0" | sed 's/^# \{0,1\}//'; }
if [ "${1:-}" = -h ] || [ "${1:-}" = --help ]; then usage; exit 0; fi
[ $# -eq 5 ] || { usage >&2; exit 2; }
bin=$1 first=$2 count=$3 jobs=$4 out=$5
[ -x "$bin" ] || { echo "bench-cosim.sh: '$bin' is not an executable (make build/tests/test_engines)" >&2; exit 2; }
[[ "$first" =~ ^[0-9]+$ ]] || { echo "bench-cosim.sh: bad FIRST '$first' (a whole number)" >&2; exit 2; }
[[ "$count" =~ ^[1-9][0-9]*$ ]] || { echo "bench-cosim.sh: bad COUNT '$count' (a positive whole number)" >&2; exit 2; }
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || { echo "bench-cosim.sh: bad JOBS '$jobs' (a positive whole number)" >&2; exit 2; }
[ "$jobs" -le "$count" ] || jobs=$count
mkdir -p "$out"
rm -f "$out"/cosim-*.log

echo "bench-cosim: random programs $first .. $((first + count - 1)), $jobs ranges at once; logs $out/cosim-K.log"
# Range k (1 .. jobs): an equal share, the first (count mod jobs) ranges
# one program more.
declare -a pid rfirst rcount
base=$((count / jobs)) extra=$((count % jobs)) at=$first
for k in $(seq 1 "$jobs"); do
  n=$base; [ "$k" -le "$extra" ] && n=$((n + 1))
  rfirst[$k]=$at; rcount[$k]=$n
  FP3_RANDOM_FIRST=$at FP3_RANDOM_PROGRAMS=$n "$bin" > "$out/cosim-$k.log" 2>&1 &
  pid[$k]=$!
  at=$((at + n))
done

# Progress: each running range's last progress line, once a minute.
running() { local k; for k in $(seq 1 "$jobs"); do kill -0 "${pid[$k]}" 2>/dev/null && return 0; done; return 1; }
while running; do
  for _ in $(seq 60); do running || break; sleep 1; done
  running || break
  for k in $(seq 1 "$jobs"); do
    kill -0 "${pid[$k]}" 2>/dev/null || continue
    last=$(grep -a "random programs" "$out/cosim-$k.log" | tail -1 || true)
    echo "  range $k ($SECONDS s): ${last:-started}"
  done
done

failed=0
for k in $(seq 1 "$jobs"); do
  if wait "${pid[$k]}"; then status=passed; else status=FAILED; failed=1; fi
  echo "  range $k: programs ${rfirst[$k]} .. $((rfirst[$k] + rcount[$k] - 1)): $status ($out/cosim-$k.log)"
done
if [ $failed -ne 0 ]; then
  echo "bench-cosim: a range failed after $SECONDS s; its log names the program and the seed that replays it" >&2
  exit 1
fi
# The ranges' seed digests (each the sum of its programs' seeds, mod 2^64)
# add up to the digest of one run of all of them, whatever the split.
digest=0
for k in $(seq 1 "$jobs"); do
  d=$(sed -n 's/.*seed digest \(0x[0-9a-f]*\).*/\1/p' "$out/cosim-$k.log" | tail -1)
  [ -n "$d" ] || { echo "bench-cosim: range $k printed no seed digest ($out/cosim-$k.log)" >&2; exit 1; }
  digest=$((digest + d))
done
printf 'bench-cosim: %s random programs on the default build and every lanes build, RTL = ISS, in %s s; seed digest 0x%016x\n' \
  "$count" "$SECONDS" "$digest"
