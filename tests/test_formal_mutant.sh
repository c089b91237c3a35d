#!/usr/bin/env bash
# test_formal_mutant.sh -- the proofs can fail: formal/rr_arbiter.sby's task
# `mutant` reads rtl/fp3_rr_arbiter.v with FP3_MUTANT_RR_STUCK (the
# round-robin position never moves, so a context behind others that keep
# requesting starves).  The proof must FAIL, and scripts/formal.sh must
# name the counterexample trace (an existing VCD) and the failing
# assertion's file:line in the repository.
set -u
cd "$(dirname "$0")/.."
out=${FORMAL_OUT:-build/formal}/mutant
log=$(mktemp)
trap 'rm -f "$log"' EXIT
bash scripts/formal.sh "$out" --expect-fail formal/rr_arbiter.sby:mutant | tee "$log"
rc=${PIPESTATUS[0]}
fail() { echo "test_formal_mutant: $*"; exit 1; }
[ "$rc" -eq 0 ] || fail "the mutant's proof did not fail"
grep -q '^formal: FAIL' "$log" || fail "no FAIL verdict"
vcd=$(sed -n 's/^ *trace: \(.*\.vcd\)$/\1/p' "$log" | head -1)
[ -n "$vcd" ] || fail "no counterexample trace named"
[ -s "$vcd" ] || fail "the trace $vcd does not exist"
grep -Eq 'failed assertion: [^ ]+ at (rtl|formal)/[a-z0-9_]+\.v:[0-9]+$' "$log" ||
  fail "no failing assertion with file:line"
grep -Eq 'f2_served_within_n|rr_taken_onehot' "$log" || fail "not the expected assertion"
echo "test_formal_mutant: the mutant fails its proof, trace $vcd"
