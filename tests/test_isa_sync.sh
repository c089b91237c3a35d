#!/usr/bin/env bash
# test_isa_sync.sh -- the Verilog view of the ISA (rtl/fp3_isa.vh) is exactly
# what sw/gen_isa.c makes of sw/fp3_isa.h: one source of truth.
set -euo pipefail
gen=${BUILD:-build}/gen_isa
[ -x "$gen" ] || { echo "FAIL: $gen not built"; exit 1; }
if ! diff -u rtl/fp3_isa.vh <("$gen"); then
  echo "FAIL: rtl/fp3_isa.vh is stale: run 'make isa' and commit it"
  exit 1
fi
echo "PASS: rtl/fp3_isa.vh matches sw/fp3_isa.h"
