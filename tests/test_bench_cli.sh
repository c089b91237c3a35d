#!/usr/bin/env bash
# test_bench_cli.sh -- the integrator options of the CLI: fp3 run
# --program (every hand-written ship program bit-exact on the ISS against
# the ship model's golden model) and --integrator (every integrator the
# ship takes), non-finite states, and fp3 bench's bad input.
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
expect 2 "must be > 0"                   -- bench --from 0
expect 2 "must be > 0"                   -- bench --to -3
expect 2 "empty sweep"                   -- bench --from 2 --to 1
expect 2 "not a whole number of steps"   -- bench --h-over-tau 0.7 --t-end 1
expect 2 "unknown argument"              -- bench --bogus
expect 2 "sweep, stability or long"      -- bench --only everything
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

# a one-point bench (sweep only) writes its CSV
expect 0 "Pareto" -- bench --out "$T" --only sweep --h-over-tau 0.5 --t-end 12 --repeats 1
if [ -s "$T/sweep.csv" ] && grep -q "^rk4vs,fp3,5" "$T/sweep.csv"; then ok; else bad "sweep.csv"; fi

echo "test_bench_cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
