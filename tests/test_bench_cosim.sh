#!/usr/bin/env bash
# test_bench_cosim.sh -- scripts/bench-cosim.sh (make bench-cosim), random
# co-simulation in ranges side by side, with a stand-in for test_engines
# that records the range it was given: the ranges cover FIRST ..
# FIRST+COUNT-1 exactly once, a range that fails fails the run naming its
# log, bad arguments are refused; and the real test_engines runs the same
# program at index p whether alone or inside a longer range.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# The stand-in: appends "FIRST COUNT" to $RANGES, fails when its range
# holds program $BAD_PROGRAM, and prints the sum of its program indices as
# its seed digest.
cat > "$tmp/fake-engines" <<'FAKE'
#!/usr/bin/env bash
echo "$FP3_RANDOM_FIRST $FP3_RANDOM_PROGRAMS" >> "$RANGES"
if [ -n "${BAD_PROGRAM:-}" ] && [ "$BAD_PROGRAM" -ge "$FP3_RANDOM_FIRST" ] &&
   [ "$BAD_PROGRAM" -lt $((FP3_RANDOM_FIRST + FP3_RANDOM_PROGRAMS)) ]; then
  echo "random program $BAD_PROGRAM differs (replay: FP3_RANDOM_SEED=0x1234)"; exit 1
fi
sum=0; for ((p = FP3_RANDOM_FIRST; p < FP3_RANDOM_FIRST + FP3_RANDOM_PROGRAMS; p++)); do sum=$((sum + p)); done
printf 'random programs: seed digest 0x%016x\n' "$sum"
FAKE
chmod +x "$tmp/fake-engines"
export RANGES="$tmp/ranges"

# 10 programs from 5 in 3 ranges: 4 + 3 + 3, covering 5 .. 14 once.
: > "$RANGES"
bash scripts/bench-cosim.sh "$tmp/fake-engines" 5 10 3 "$tmp/out" > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "bench-cosim.sh failed on ranges that pass"; }
[ "$(sort -n "$RANGES" | tr '\n' ' ')" = "5 4 9 3 12 3 " ] ||
  { cat "$RANGES"; fail "bench-cosim.sh: ranges do not split 5 .. 14 into 4 + 3 + 3"; }
grep -q "10 random programs on the default build and every lanes build, RTL = ISS, in [0-9]* s; seed digest 0x000000000000005f" "$tmp/log" ||
  { cat "$tmp/log"; fail "no total line, or the ranges' digests do not add up (5 + ... + 14 = 0x5f)"; }
[ "$(ls "$tmp/out"/cosim-*.log | wc -l)" = 3 ] || fail "bench-cosim.sh: not one log a range"

# More jobs than programs: one range a program.
: > "$RANGES"
bash scripts/bench-cosim.sh "$tmp/fake-engines" 0 2 4 "$tmp/out" > "$tmp/log" 2>&1 || fail "2 programs, 4 jobs"
[ "$(sort -n "$RANGES" | tr '\n' ' ')" = "0 1 1 1 " ] || { cat "$RANGES"; fail "2 programs in 4 jobs"; }
[ "$(ls "$tmp/out"/cosim-*.log | wc -l)" = 2 ] || fail "bench-cosim.sh: an earlier run's logs are left"

# A failing program fails the run, and the line names its range's log.
: > "$RANGES"
if BAD_PROGRAM=11 bash scripts/bench-cosim.sh "$tmp/fake-engines" 0 20 2 "$tmp/out" > "$tmp/log" 2>&1; then
  cat "$tmp/log"; fail "bench-cosim.sh passed with a failing program"
fi
grep -q "programs 10 .. 19: FAILED ($tmp/out/cosim-2.log)" "$tmp/log" || { cat "$tmp/log"; fail "the failing range is not named"; }
grep -q "programs 0 .. 9: passed" "$tmp/log" || { cat "$tmp/log"; fail "the passing range is not reported"; }
grep -q "FP3_RANDOM_SEED=0x1234" "$tmp/out/cosim-2.log" || fail "the failing range's log lost its output"

# Bad arguments: exit 2 with a reason.
for args in "$tmp/fake-engines x 10 2" "$tmp/fake-engines 0 0 2" "$tmp/fake-engines 0 10 0" \
            "$tmp/none 0 10 2" "$tmp/fake-engines 0 10"; do
  # shellcheck disable=SC2086
  set +e; bash scripts/bench-cosim.sh $args "$tmp/out" > "$tmp/log" 2>&1; rc=$?; set -e
  [ $rc = 2 ] || { cat "$tmp/log"; fail "bench-cosim.sh $args: exit $rc, not 2"; }
done
bash scripts/bench-cosim.sh --help | grep -q "FP3_RANDOM_FIRST" || fail "--help"

# The real test_engines (built before the test scripts run): program p is
# the same program in any split, so one range of 0 .. 5 and three ranges
# of two give the same seed digest; and a bad FP3_RANDOM_FIRST is refused.
eng=build/tests/test_engines
[ -x "$eng" ] || fail "no $eng (make build/tests/test_engines)"
digest() { sed -n 's/.*seed digest \(0x[0-9a-f]*\)$/\1/p' "$1"; }
bash scripts/bench-cosim.sh "$eng" 0 6 1 "$tmp/one" > "$tmp/log1" 2>&1 || { cat "$tmp/log1"; fail "6 programs in one range"; }
bash scripts/bench-cosim.sh "$eng" 0 6 3 "$tmp/three" > "$tmp/log3" 2>&1 || { cat "$tmp/log3"; fail "6 programs in three ranges"; }
[ -n "$(digest "$tmp/log1")" ] && [ "$(digest "$tmp/log1")" = "$(digest "$tmp/log3")" ] ||
  { cat "$tmp/log1" "$tmp/log3"; fail "the programs depend on the split: seed digests differ"; }
set +e; FP3_RANDOM_FIRST=-3 "$eng" > "$tmp/bad" 2>&1; rc=$?; set -e
{ [ $rc = 2 ] && grep -q "FP3_RANDOM_FIRST='-3'" "$tmp/bad"; } || { cat "$tmp/bad"; fail "FP3_RANDOM_FIRST=-3 not refused"; }
echo "PASS: bench-cosim.sh ranges, digests, failures, bad arguments"
