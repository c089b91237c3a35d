#!/usr/bin/env bash
# test_pnr_seeds.sh -- scripts/pnr-seeds.sh (make pnr PNR_SEEDS=...), the
# ECP5 seed sweep, with a stand-in for nextpnr (NEXTPNR_ECP5): it places
# nothing but answers each seed with an Fmax of its own in the report, as
# nextpnr does, so the sweep's bookkeeping is checked without minutes of
# place and route: every seed run once, the best one chosen (ties: the
# lower seed), least / median / mean / greatest right, the best placement's
# configuration kept, a sweep in parts taken whole (the seeds of one
# netlist only), bad arguments refused, a seed that does not place failing
# the sweep without leaving a "best" configuration, and progress lines
# with each running seed's phase (PNR_PROGRESS, scripts/pnr-phase.py).
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# The stand-in: Fmax by seed from FAKE_FMAX ("seed:MHz ..."); a seed
# missing there does not place (exit 1, as nextpnr when a design does not
# fit).  Writes the report, the configuration and the log where told.
cat > "$tmp/fake-nextpnr" <<'FAKE'
#!/usr/bin/env bash
seed= report= cfg= log=
while [ $# -gt 0 ]; do
  case "$1" in
    --seed) seed=$2; shift ;; --report) report=$2; shift ;;
    --textcfg) cfg=$2; shift ;; -l) log=$2; shift ;;
  esac; shift
done
echo "fake nextpnr, seed $seed" > "$log"
# FAKE_SLOW: seconds spent in each of nextpnr's phases, written to the log
# as nextpnr writes them (for the progress lines).
if [ -n "${FAKE_SLOW:-}" ]; then
  echo "Info: Running main analytical placer, max placement attempts per cell = 1000." >> "$log"
  echo "Info:     at iteration #7, type ALL: wirelen solved = 1, spread = 2, legal = 3; time = 0.1s" >> "$log"
  sleep "$FAKE_SLOW"
  echo "Info: Running simulated annealing placer for refinement." >> "$log"
  echo "Info:   at iteration #12: temp = 0.000000, timing cost = 10, wirelen = 20" >> "$log"
  sleep "$FAKE_SLOW"
  printf 'Info: Routing globals...\nInfo: Routing..\nInfo: Routing 1000 arcs.\n' >> "$log"
  echo "Info:       3000 |      700       2000 |  300   700 |       250|       1.00       9.00|" >> "$log"
  sleep "$FAKE_SLOW"
  echo "Info: Router1 time 27.00s" >> "$log"
fi
fmax=$(tr ' ' '\n' <<< "$FAKE_FMAX" | awk -F: -v s="$seed" '$1 == s {print $2}')
[ -n "$fmax" ] || { echo "ERROR: Unable to place cell" >> "$log"; exit 1; }
echo "configuration of seed $seed" > "$cfg"
cat > "$report" <<JSON
{"utilization": {"TRELLIS_COMB": {"used": 100, "available": 83640},
                 "TRELLIS_FF": {"used": 50, "available": 83640}},
 "fmax": {"\$glbnet\$clk_i": {"achieved": $fmax, "constraint": 150.0}},
 "critical_paths": []}
JSON
FAKE
chmod +x "$tmp/fake-nextpnr"
echo '{}' > "$tmp/net.json"
export NEXTPNR_ECP5="$tmp/fake-nextpnr"

# A sweep: seed 7 is the best, out of order and among unequal seeds.
FAKE_FMAX="2:140.5 3:131.0 5:140.5 7:151.3 9:120.0" PNR_JOBS=2 \
  bash scripts/pnr-seeds.sh core "$tmp/net.json" "$tmp/out" 2 3 5 7 9 > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "pnr-seeds.sh failed on a sweep that places"; }
grep -q "least 120.0, median 140.5, mean 136.7, greatest 151.3 MHz (seed 7)" "$tmp/log" ||
  { cat "$tmp/log"; fail "pnr-seeds.sh: wrong least/median/mean/greatest or best seed"; }
[ "$(cat "$tmp/out/core_ecp5.config")" = "configuration of seed 7" ] ||
  fail "pnr-seeds.sh: the kept configuration is not the best seed's"
[ "$(tail -n +2 "$tmp/out/pnr_seeds.csv" | cut -d, -f1,2 | tr '\n' ' ')" = \
  "2,140.5 3,131.0 5,140.5 7,151.3 9,120.0 " ] ||
  { cat "$tmp/out/pnr_seeds.csv"; fail "pnr-seeds.sh: pnr_seeds.csv is not one row per seed"; }
[ "$(tail -1 "$tmp/out/pnr_summary.csv" | cut -d, -f7)" = 151.3 ] ||
  fail "pnr-seeds.sh: pnr_summary.csv does not end with the best seed's row"
for s in 2 3 5 7 9; do grep -q "seed $s: Fmax" "$tmp/log" || fail "pnr-seeds.sh: no line for seed $s"; done

# Progress (PNR_PROGRESS): a line a second, each running seed's phase
# from its log (scripts/pnr-phase.py); the watcher ends with the sweep.
TMPDIR=$tmp FAKE_SLOW=2.5 FAKE_FMAX="4:140.0 6:130.0" PNR_PROGRESS=1 PNR_JOBS=2 \
  bash scripts/pnr-seeds.sh core "$tmp/net.json" "$tmp/slow" 4 6 > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "pnr-seeds.sh failed on a slow sweep"; }
for want in "seed 4 HeAP placement (iteration 7); seed 6 HeAP placement" \
            "seed 6 annealing (iteration 12)" \
            "seed 4 routing (250 of 1,000 arcs left after 3,000 iterations)"; do
  grep -qF "$want" "$tmp/log" || { cat "$tmp/log"; fail "pnr-seeds.sh: no progress line with '$want'"; }
done
grep -q "^pnr-seeds: core: 0:00:0[1-9] elapsed; seed 4 " "$tmp/log" ||
  { cat "$tmp/log"; fail "pnr-seeds.sh: progress lines without the time elapsed"; }
sleep 0.3
! pgrep -f "pnr-phase.py --watch 1 pnr-seeds: core $tmp/" > /dev/null ||
  fail "pnr-seeds.sh: the progress watcher outlived the sweep"
[ -z "$(ls -d "$tmp"/fp3_pnr_seeds.* 2>/dev/null)" ] || fail "pnr-seeds.sh: its progress folder left behind"
FAKE_SLOW=2.5 FAKE_FMAX="1:140.0" PNR_PROGRESS=1 PNR_SEED=1 \
  bash scripts/pnr.sh ecp5 core "$tmp/net.json" "$tmp/one" > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "pnr.sh failed on a slow placement"; }
grep -q "^pnr: core, seed 1: 0:00:0[1-9] elapsed; annealing (iteration 12)" "$tmp/log" ||
  { cat "$tmp/log"; fail "pnr.sh: no progress line"; }
# A caller killed (SIGKILL: no EXIT trap) as its watcher starts leaves no
# watcher behind (pnr-progress.sh passes the caller's pid).
(PNR_PROGRESS=1 bash -c '. scripts/pnr-progress.sh; pnr_progress_start "orphan: $1" "$1/none.log"; kill -9 $$' _ "$tmp"; true) \
  > "$tmp/orphan.log" 2>&1 || true
sleep 1.5
! pgrep -f "pnr-phase.py --watch 1 orphan: $tmp" > /dev/null ||
  { pkill -f "pnr-phase.py --watch 1 orphan: $tmp"; fail "pnr-progress.sh: a watcher outlived its killed caller"; }
# The phases of logs as nextpnr writes them, router2's too.
printf 'Info: Running main analytical placer\nInfo: Running simulated annealing placer\nInfo: Routing globals...\nInfo: Running router2...\nInfo:     iter=3 wires=12 overused=4242 overuse=5000 archfail=NA\n' > "$tmp/r2.log"
[ "$(python3 scripts/pnr-phase.py "$tmp/r2.log")" = "routing (router2 iteration 3, 4,242 wires overused)" ] ||
  fail "pnr-phase.py: router2's phase: $(python3 scripts/pnr-phase.py "$tmp/r2.log")"
printf 'Info: Router1 time 9.0s\nInfo: Program finished normally.\n' >> "$tmp/r2.log"
[ "$(python3 scripts/pnr-phase.py "$tmp/r2.log")" = finished ] || fail "pnr-phase.py: a finished log"
[ "$(python3 scripts/pnr-phase.py "$tmp/none.log")" = starting ] || fail "pnr-phase.py: no log yet"
echo "Info: Packing" > "$tmp/p.log"
[ "$(python3 scripts/pnr-phase.py "$tmp/p.log")" = packing ] || fail "pnr-phase.py: packing"
for call in "pnr-seeds.sh core $tmp/net.json $tmp/b 1" "pnr.sh ecp5 core $tmp/net.json $tmp/b"; do
  set +e; PNR_PROGRESS=soon bash scripts/$call > "$tmp/log" 2>&1; rc=$?; set -e
  [ "$rc" -eq 2 ] && grep -q "bad PNR_PROGRESS" "$tmp/log" || { cat "$tmp/log"; fail "${call%% *}: PNR_PROGRESS=soon not refused"; }
done

# An even count of seeds: the median is the mean of the two middle ones.
FAKE_FMAX="1:130.0 2:150.0 3:142.0 4:120.0" bash scripts/pnr-seeds.sh core "$tmp/net.json" "$tmp/even" 1 2 3 4 > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "pnr-seeds.sh failed on four seeds"; }
grep -q "least 120.0, median 136.0, mean 135.5, greatest 150.0 MHz (seed 2)" "$tmp/log" ||
  { cat "$tmp/log"; fail "pnr-seeds.sh: wrong median of an even count"; }

# A sweep in parts: the second call's table and median cover the first
# call's seeds of the same netlist too, not those of another netlist.
FAKE_FMAX="1:130.0 2:150.0" bash scripts/pnr-seeds.sh core "$tmp/net.json" "$tmp/parts" 1 2 > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "pnr-seeds.sh failed on the first part of a sweep"; }
FAKE_FMAX="3:142.0 4:120.0" bash scripts/pnr-seeds.sh core "$tmp/net.json" "$tmp/parts" 3 4 > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "pnr-seeds.sh failed on the second part of a sweep"; }
grep -q "least 120.0, median 136.0, mean 135.5, greatest 150.0 MHz (seed 2)" "$tmp/log" &&
  [ "$(cat "$tmp/parts/fmax_median.txt")" = 136.0 ] &&
  [ "$(cat "$tmp/parts/core_ecp5.config")" = "configuration of seed 2" ] ||
  { cat "$tmp/log"; fail "pnr-seeds.sh: a sweep in two parts is not the sweep of all four seeds"; }
echo '{"another": 1}' > "$tmp/net2.json"
FAKE_FMAX="5:99.0" bash scripts/pnr-seeds.sh core "$tmp/net2.json" "$tmp/parts" 5 > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "pnr-seeds.sh failed on another netlist"; }
grep -q "Fmax over 1 seeds: least 99.0, median 99.0" "$tmp/log" ||
  { cat "$tmp/log"; fail "pnr-seeds.sh: another netlist's sweep counted the earlier netlist's seeds"; }
# ... and back on the first netlist (seed 3 placed again), whose seeds
# are the four, with seed 5's directory of the other netlist the last.
FAKE_FMAX="3:142.0" bash scripts/pnr-seeds.sh core "$tmp/net.json" "$tmp/parts" 3 > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "pnr-seeds.sh failed on a third part"; }
grep -q "Fmax over 4 seeds: least 120.0, median 136.0" "$tmp/log" ||
  { cat "$tmp/log"; fail "pnr-seeds.sh: the third part is not the sweep of the first netlist's four seeds"; }

# Ties: the lower seed.
FAKE_FMAX="4:140.0 2:140.0" bash scripts/pnr-seeds.sh core "$tmp/net.json" "$tmp/tie" 4 2 > "$tmp/log" 2>&1 ||
  { cat "$tmp/log"; fail "pnr-seeds.sh failed on a tie"; }
grep -q "(seed 2)" "$tmp/log" || { cat "$tmp/log"; fail "pnr-seeds.sh: a tie did not go to the lower seed"; }

# A seed that does not place: the sweep fails, names it, keeps no best
# configuration (also not an earlier sweep's).
cp "$tmp/out/core_ecp5.config" "$tmp/stale.config"
if FAKE_FMAX="2:140.5" bash scripts/pnr-seeds.sh core "$tmp/net.json" "$tmp/out" 2 3 > "$tmp/log" 2>&1; then
  cat "$tmp/log"; fail "pnr-seeds.sh succeeded although seed 3 does not place"; fi
grep -q "seed 3: does not place" "$tmp/log" || { cat "$tmp/log"; fail "pnr-seeds.sh: the failing seed not named"; }
[ ! -e "$tmp/out/core_ecp5.config" ] || fail "pnr-seeds.sh: a failed sweep left a best configuration"

# Bad arguments: exit 2 with a message, nothing run.
for args in "core $tmp/net.json $tmp/b 1 x" "core $tmp/none.json $tmp/b 1" "core $tmp/net.json $tmp/b"; do
  set +e; bash scripts/pnr-seeds.sh $args > "$tmp/log" 2>&1; rc=$?; set -e
  [ "$rc" -eq 2 ] || { cat "$tmp/log"; fail "pnr-seeds.sh $args: exit $rc, not 2"; }
done
set +e; PNR_JOBS=0 bash scripts/pnr-seeds.sh core "$tmp/net.json" "$tmp/b" 1 > "$tmp/log" 2>&1; rc=$?; set -e
[ "$rc" -eq 2 ] && grep -q "bad PNR_JOBS" "$tmp/log" || fail "pnr-seeds.sh: PNR_JOBS=0 not refused"
bash scripts/pnr-seeds.sh --help | grep -q "seed sweep" || fail "pnr-seeds.sh --help"
echo "PASS: test_pnr_seeds (pnr-seeds.sh: sweep, best seed, ties, a sweep in parts, a seed that does not place, bad arguments, progress lines)"
