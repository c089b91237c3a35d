#!/usr/bin/env bash
# test_formal.sh -- the quick subset of the formal property sets (mk/formal.mk
# FORMAL_QUICK, less the tasks that must fail: the AXI4-Lite slave properties on fp3_axil in both
# builds, the round-robin arbiter's grant and fairness properties, the
# UARTBone bridge's master, frame, timeout and status properties, their
# covers).  Fails if any task fails; scripts/formal.sh prints the trace and
# the failing assertion.
set -u
cd "$(dirname "$0")/.."
out=${FORMAL_OUT:-build/formal}
tasks=""
for s in formal/axil.sby formal/rr_arbiter.sby formal/uartbone.sby; do
  for t in $(yowasp-sby --dumptasks "$s"); do
    case "$t" in mutant*|*_tight) ;; *) tasks="$tasks $s:$t";; esac
  done
done
# shellcheck disable=SC2086
bash scripts/formal.sh "$out" $tasks
