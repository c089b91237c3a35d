#!/usr/bin/env bash
# test_rr_arbiter.sh -- fp3_rr_arbiter (the scheduler's issue and fetch
# arbiters) against a reference round robin: sim/tb_rr_arbiter.v under
# Icarus Verilog, random requests, the last grant masked or not, for 1, 2, 3, 8 and 16
# requesters (the processor is built with 1, 3 and 8 contexts; 16 for the
# throughput benchmark), each with its own seed.  The program's other
# tests see the arbiters only through cycle counts and a loose fairness
# bound (test_engines: test_many_ships), which an arbiter starting its
# round at the last grant instead of after it passes; this test fails it.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for n in 1 2 3 8 16; do
  iverilog -g2005 -Wall -Ptb_rr_arbiter.N=$n -s tb_rr_arbiter -o "$tmp/tb$n.vvp" \
    rtl/fp3_rr_arbiter.v sim/tb_rr_arbiter.v 2>"$tmp/iv.log" || {
    cat "$tmp/iv.log"; echo "FAIL: iverilog tb_rr_arbiter N=$n"; exit 1; }
  if grep -qi "warning" "$tmp/iv.log"; then cat "$tmp/iv.log"; echo "FAIL: iverilog warnings"; exit 1; fi
  vvp -n "$tmp/tb$n.vvp" +cycles=20000 +seed=$((n * 7919)) >"$tmp/sim$n.log"
  tail -1 "$tmp/sim$n.log"
  grep -q "^PASS" "$tmp/sim$n.log" || { head -12 "$tmp/sim$n.log"; exit 1; }
done
