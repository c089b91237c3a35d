#!/usr/bin/env bash
# test_bench_cli.sh -- the integrator options of the CLI: fp3 run
# --integrator (every program bit-exact on the ISS, the stability-bound
# warning, --strict, divergence reports) and fp3 bench's bad input.
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

# every integrator, bit-exact on the ISS
for i in euler symeuler verlet rk2 rk4 rk4vs rk4comp rk4vscomp; do
  expect 0 "PASS: 200 integrations" -- run --engine iss --integrator "$i" --steps 200
done
expect 0 '"integrator": "rk4vs"' -- run --engine iss --integrator rk4vs --steps 10 --json

# bad input
expect 2 "unknown integrator 'leapfrog'" -- run --integrator leapfrog
expect 2 "needs a value"                 -- run --integrator
expect 2 "must be > 0"                   -- bench --from 0
expect 2 "must be > 0"                   -- bench --to -3
expect 2 "empty sweep"                   -- bench --from 2 --to 1
expect 2 "not a whole number of steps"   -- bench --h-over-tau 0.7 --t-end 1
expect 2 "unknown argument"              -- bench --bogus
expect 2 "sweep, stability or long"      -- bench --only everything
expect 0 "usage: fp3 bench"              -- bench --help

# the stability bound: a warning, an error with --strict, divergence found
expect 0 "warning: h/tau = h C/m = 2.1 exceeds the stability bound 2" \
  -- run --engine iss --integrator euler --set h=4.2 --steps 100
expect 0 "DIVERGED: |v - T/C| grows from integration 1" \
  -- run --engine iss --integrator euler --set h=4.2 --steps 100
expect 2 "error: h/tau" -- run --engine iss --integrator rk4 --set h=5.6 --strict
expect 0 "PASS" -- run --engine iss --integrator rk4 --set h=5.5 --strict --steps 100
# no drag: no bound, no warning
out=$("$FP3" run --engine iss --integrator euler --set C=0 --set h=100 --steps 10 2>&1)
if grep -q "warning" <<<"$out"; then bad "warning without drag"; else ok; fi
# tiny mass: overflow to non-finite is reported, and fails under --strict
expect 0 "DIVERGED: v or s not finite" \
  -- run --engine iss --integrator rk4 --set m=1e-30 --set C=1 --set T=1 --steps 50
expect 2 "exceeds the stability bound" \
  -- run --engine iss --integrator rk4 --set m=1e-30 --set C=1 --set T=1 --steps 50 --strict

# a one-point bench (sweep only) writes its CSV
expect 0 "Pareto" -- bench --out "$T" --only sweep --h-over-tau 0.5 --t-end 12 --repeats 1
if [ -s "$T/sweep.csv" ] && grep -q "^rk4vs,fp3,5" "$T/sweep.csv"; then ok; else bad "sweep.csv"; fi

echo "test_bench_cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
