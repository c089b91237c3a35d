#!/usr/bin/env bash
# test_simspeed.sh -- scripts/bench-simspeed.sh, the simulation-speed
# benchmark's arithmetic and bad input, on stand-ins (no Verilated model):
#
#  - a stand-in bench_chip prints the line the script reads (64 ships:
#    1000, 256 ships: 5000): the medians and the ratio 5.00 come back,
#    and no spatial line;
#  - one that also prints the spatial chip's line, 40000, 90000 and
#    50000 in three rounds: the median 50000 (the mean would be 60000) and spatial / chip 10.00;
#  - a stand-in baseline fp3 burns CPU in proportion to --steps: the
#    baseline's speed is 64 x 180 object-steps over its CPU for 200 less
#    20 integrations, so it is positive and the chip / baseline ratio is
#    5000 over it (checked to the printed precision);
#  - a baseline that fails, a missing executable, --rounds 0 and a
#    bench_chip without the chip build's line are refused (exit 1 or 2).
set -u
cd "$(dirname "$0")/.."
T=$(mktemp -d /tmp/fp3_test_simspeed.XXXXXX)
trap 'rm -rf "$T"' EXIT
S=scripts/bench-simspeed.sh
pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

cat >"$T/bench_chip" <<'EOS'
#!/usr/bin/env bash
echo "Verilated model speed on this host (object-steps per CPU second): the 8-context build, 64 ships: 1000; chip (16 lanes), 256 ships: 5000; ratio 5.00"
EOS
cat >"$T/spatial" <<'EOS'
#!/usr/bin/env bash
# the spatial line's speed from a counter: 40000, 90000, 50000 in three rounds
f=$(dirname "$0")/count; n=$(cat "$f" 2>/dev/null || echo 0); echo $((n + 1)) >"$f"
echo "Verilated model speed on this host (object-steps per CPU second): the 8-context build, 64 ships: 1000; chip (16 lanes), 256 ships: 5000; ratio 5.00"
echo "Verilated spatial chip (3 pipelines, folded), 1026 ships: $(( (4 + (n % 3 == 1) * 5 + (n % 3 == 2)) * 10000 )) object-steps per CPU second; ratio to the 8-context build 50.00, to chip 10.00"
EOS
cat >"$T/nochip" <<'EOS'
#!/usr/bin/env bash
echo "no speed line"
EOS
cat >"$T/fp3" <<'EOS'
#!/usr/bin/env bash
# fp3 run --objects 64 --steps N: CPU in proportion to N
n=0; while [ $# -gt 0 ]; do [ "$1" = --steps ] && n=$2; shift; done
awk -v n="$n" 'BEGIN { for (i = 0; i < n * 20000; i++) s += i * 0.5; if (s < 0) print s }'
EOS
cat >"$T/fp3bad" <<'EOS'
#!/usr/bin/env bash
echo "golden-model mismatch" >&2; exit 1
EOS
chmod +x "$T"/bench_chip "$T"/spatial "$T"/nochip "$T"/fp3 "$T"/fp3bad

out=$(bash "$S" --rounds 3 "$T/bench_chip" 2>&1); rc=$?
[ $rc -eq 0 ] && grep -q "default build, 64 ships:   1000   chip build, 256 ships:   5000   ratio 5.00" <<<"$out" \
  && ok || bad "medians and ratio: rc $rc: $out"

! grep -q "spatial chip" <<<"$out" && ok || bad "a spatial line without the spatial chip: $out"

out=$(bash "$S" --rounds 3 "$T/spatial" 2>&1); rc=$?
[ $rc -eq 0 ] && grep -q "spatial chip (3 pipelines, folded), 1026 ships:  50000   spatial / chip build: 10.00" <<<"$out" \
  && ok || bad "the spatial chip's median and ratio: rc $rc: $out"

out=$(bash "$S" --rounds 1 --baseline "$T/fp3" "$T/bench_chip" 2>&1); rc=$?
line=$(grep "chip build / baseline" <<<"$out")
base=$(sed -n 's/.*run --objects 64: *\([0-9]*\) .*/\1/p' <<<"$line")
ratio=$(sed -n 's/.*chip build \/ baseline: \([0-9.]*\).*/\1/p' <<<"$line")
[ $rc -eq 0 ] && [ -n "$base" ] && [ "$base" -gt 0 ] \
  && awk -v b="$base" -v r="$ratio" 'BEGIN { exit !(r - 5000 / b < 0.006 && 5000 / b - r < 0.006) }' \
  && ok || bad "baseline: rc $rc, baseline '$base', ratio '$ratio': $out"

out=$(bash "$S" --rounds 1 --baseline "$T/fp3bad" "$T/bench_chip" 2>&1); rc=$?
[ $rc -eq 1 ] && grep -q "golden-model mismatch" <<<"$out" && ok || bad "failing baseline: rc $rc: $out"
out=$(bash "$S" --baseline "$T/missing" "$T/bench_chip" 2>&1); rc=$?
[ $rc -eq 2 ] && grep -q "missing: not an executable" <<<"$out" && ok || bad "missing baseline: rc $rc: $out"
out=$(bash "$S" --rounds 0 "$T/bench_chip" 2>&1); rc=$?
[ $rc -eq 2 ] && grep -q "positive integer" <<<"$out" && ok || bad "--rounds 0: rc $rc: $out"
out=$(bash "$S" --rounds 1 "$T/nochip" 2>&1); rc=$?
[ $rc -eq 1 ] && grep -q "printed no chip build speed" <<<"$out" && ok || bad "no speed line: rc $rc: $out"
out=$(bash "$S" 2>&1); rc=$?
[ $rc -eq 2 ] && grep -q "usage" <<<"$out" && ok || bad "no arguments: rc $rc: $out"

echo "test_simspeed: $pass passed, $fail failed"
[ $fail -eq 0 ]
