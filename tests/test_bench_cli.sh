#!/usr/bin/env bash
# test_bench_cli.sh -- the integrator options of the CLI: fp3 run
# --program (every hand-written ship program bit-exact on the ISS against
# the ship model's golden model) and --integrator (every integrator the
# ship takes), non-finite states, and fp3 bench: the ship's sweep and
# its Pareto table (checked against the sweep's rows), the stability
# bound checked on the engine, binary32 stagnation far out, bad input.
#
# The CLI is $FP3_BIN (set by mk/sw.mk), else build/fp3 of this checkout.
set -u
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
if [ ! -x "$FP3" ]; then echo "test_bench_cli: $FP3 not built"; exit 1; fi
T=$(mktemp -d /tmp/fp3_test_bench_cli.XXXXXX)
trap 'rm -rf "$T"' EXIT

pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

# expect STATUS PATTERN -- ARGS...: exit status and a pattern in the output.
expect() {
  local want=$1 pat=$2; shift 3
  local out rc
  out=$("$FP3" "$@" 2>&1); rc=$?
  if [ "$rc" -ne "$want" ]; then bad "fp3 $*: exit $rc, want $want; $(echo "$out" | tail -3)"; return; fi
  if [ -n "$pat" ] && ! grep -q -- "$pat" <<<"$out"; then
    bad "fp3 $*: output lacks '$pat': $(echo "$out" | tail -3)"; return
  fi
  ok
}

# every hand-written ship program, bit-exact on the ISS against the ship
# model's golden model of its .integrator (rk4 is the paper's: rk4se)
for i in euler symeuler verlet rk2 rk4 rk4vs rk4comp rk4vscomp rk4_sleep; do
  expect 0 "PASS: 200 integrations" -- run --engine iss --program programs/ship_$i.s --steps 200
done
expect 0 '"integrator": "rk4vs"' -- run --engine iss --program programs/ship_rk4vs.s --steps 10 --json
# every model integrator the ship's shape takes, compiled for the ship
for i in euler rk2 rk4 rk4comp symeuler rk4se rk4secomp rk4vs rk4vscomp verletp; do
  expect 0 "PASS: 200 integrations" -- run --engine iss --integrator "$i" --steps 200
  expect 0 "PASS: 50 integrations" -- run --engine iss --integrator "$i" --literal --steps 50
done
# a hand-written program is checked against its own integrator's golden model
expect 2 "--integrator rk4, but programs/ship_euler.s computes euler" \
  -- run --engine iss --program programs/ship_euler.s --integrator rk4
sed 's/^\.integrator .*/.integrator rk4/' programs/ship_rk4.s > "$T/wrong.s"
sed -i 's|"ship_rk4_common.inc"|"'"$PWD"'/programs/ship_rk4_common.inc"|; s|"ship_rk4_velocity.inc"|"'"$PWD"'/programs/ship_rk4_velocity.inc"|' "$T/wrong.s"
expect 1 "golden model: [1-9][0-9]* mismatches" -- run --engine iss --program "$T/wrong.s" --steps 20
sed '/^\.integrator/d' "$T/wrong.s" > "$T/none.s"
expect 2 "no \`.integrator NAME\` line" -- run --engine iss --program "$T/none.s"

# bad input
expect 2 "unknown integrator 'leapfrog'" -- run --integrator leapfrog
expect 2 "needs a value"                 -- run --integrator
expect 2 "verlet needs accelerations that do not read velocities: v' reads velocity v" \
  -- run --engine iss --integrator verlet
expect 2 "--strict is gone" -- run --engine iss --strict
# the ship bench's options in h/tau name their form in h [s]
expect 2 "--from is gone: the sweep is in h, in seconds: --h-max H" -- bench --from 0
expect 2 "--to 3 is --h-max 6"           -- bench --to 3
expect 2 "--set h=H --points 1"          -- bench --h-over-tau 0.7 --t-end 1
expect 2 "--long-steps N"                -- bench --rtl-long-steps 10
expect 2 "--points K"                    -- bench --per-decade 4
expect 2 "unknown argument"              -- bench --bogus
expect 2 "sweep, stability or long"      -- bench --only everything
expect 2 "--only goes with --out DIR"    -- bench --only sweep
expect 2 "--h-max '0': a positive step"  -- bench --h-max 0
expect 2 "unknown integrator 'leapfrog'" -- bench --integrator leapfrog
expect 0 "usage: fp3 bench"              -- bench --help

# a state that overflows to a non-finite value fails the run, naming it
expect 1 "NON-FINITE: state variable v is not finite after integration" \
  -- run --engine iss --program programs/ship_rk4.s --set m=1e-30 --set C=1 --set T=1 --steps 50
# beyond the stability bound: reported (h/tau = 2.1 > 2 for Euler), still bit-exact
expect 0 "DIVERGED: state variable v is beyond 1000, 1000 (1 + max |initial state|), from integration 49" \
  -- run --engine iss --program programs/ship_euler.s --set h=4.2 --steps 100
out=$("$FP3" run --engine iss --program programs/ship_euler.s --set h=3.8 --steps 100 2>&1)
if grep -q DIVERGED <<<"$out"; then bad "h/tau = 1.9 reported as diverged"; else ok; fi
# no drag: an unbounded ship, finite and bit-exact
expect 0 "PASS" -- run --engine iss --program programs/ship_euler.s --set C=0 --set h=100 --steps 10

# fp3 bench without --model: the ship through the model path, every
# integrator that applies, the sweep and its Pareto table
expect 0 "Pareto front of ship" -- bench --out "$T/sw" --only sweep --h-max 1 --points 4 --t-end 12
rows=$(tail -n +2 "$T/sw/sweep.csv" | wc -l)
if [ "$rows" -eq 40 ] && grep -q "^ship,rk4se,0.125,96,12," "$T/sw/sweep.csv"; then ok
else bad "sweep.csv: $rows rows, want 10 integrators x 4 steps with ship,rk4se,0.125,96"; fi
# the Pareto table: for each target the row of fewest work_cycles (column
# 8) among those whose error_max (column 10) is at most the target
want=$(awk -F, 'NR > 1 { n[NR] = $2; h[NR] = $3; w[NR] = $8; e[NR] = $10 }
  END { split("1e-2 1e-3 1e-4 1e-5 1e-6 1e-7", t, " ")
        for (i = 1; i <= 6; i++) { b = 0
          for (r in n) if (e[r] + 0 <= t[i] + 0 && e[r] != "nan" && (!b || w[r] + 0 < w[b] + 0)) b = r
          print (b ? n[b] " " h[b] : "none") } }' "$T/sw/sweep.csv")
got=$(awk -F' *\\| *' 'NR > 2 { print ($3 == "none in the sweep" ? "none" : $3 " " $4) }' "$T/sw/pareto.md")
if [ -n "$want" ] && [ "$want" = "$got" ]; then ok
else bad "pareto.md: cheapest per target '$(echo $got)', the sweep's rows give '$(echo $want)'"; fi
grep -q "| 1e-03 | rk4" "$T/sw/pareto.md" && ok || bad "pareto.md: 1e-3 not an RK4: $(sed -n 4p "$T/sw/pareto.md")"
# stability: Euler's bound h = 2 tau = 4 s, the RTL stable just below, diverging just above
expect 0 "" -- bench --out "$T/st" --only stability --integrator euler
# (|1 - h/tau| = 1.04 at 1.02 x 4 s: |v| passes 1000 from 10 at integration 117)
if grep -q "^ship,euler,4.000[0-4][0-9]*,20000,1000,rtl,20000,0,1,117,1$" "$T/st/stability.csv" &&
   grep -q "| euler | 4.000[0-4][0-9]* | stable | diverges from integration 117 | yes |" "$T/st/stability.md"
then ok; else bad "stability: $(cat "$T/st/stability.csv" "$T/st/stability.md")"; fi
# long runs far out (s = 2^24 m): the plain RK4's s never moves (v h < 1 m,
# half an ulp), the compensated one's does; every integration bit-exact
expect 0 "" -- bench --out "$T/far" --only long --set s=16777216 --long-steps 3000 \
  --integrator rk4se,rk4secomp
# (columns 6 mismatches, 10 s, 14 s last changed at, 15 s unchanged)
if awk -F, '$2 == "rk4se" && $6 == 0 && $10 == 16777216 && $14 == 0 && $15 == 2999 { a = 1 }
            $2 == "rk4secomp" && $6 == 0 && $10 > 16777600 && $14 > 2900 { b = 1 }
            END { exit !(a && b) }' "$T/far/longrun.csv" &&
   grep -q "| rk4se | rtl, 3000 integrations, bit-exact |" "$T/far/longrun.md"
then ok; else bad "longrun far out: $(cat "$T/far/longrun.csv")"; fi
# any model: the same files (the oscillator's stagnation columns are x and v)
expect 0 "Pareto front of oscillator" -- bench --model models/oscillator.fp3m --out "$T/osc" \
  --points 2 --long-steps 100 --integrator rk4,verlet --engine iss
if [ "$(grep -c '^| 1e-0[2-7] |' "$T/osc/pareto.md")" -eq 6 ] &&
   grep -q "^model,integrator,engine,steps,.*,x_last_change,x_unchanged,v_last_change,v_unchanged$" "$T/osc/longrun.csv" &&
   grep -q "^oscillator,verlet,.*,1$" "$T/osc/stability.csv"
then ok; else bad "oscillator: $(cat "$T/osc/pareto.md" "$T/osc/stability.csv" | head -12)"; fi

echo "test_bench_cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
