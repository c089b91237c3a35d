#!/usr/bin/env bash
# test_isa_sync.sh -- the Verilog view of the ISA (rtl/fp3_isa.vh) is exactly
# what sw/isa/gen_isa.c makes of sw/isa/fp3_isa.h: one source of truth.
set -euo pipefail
gen=${BUILD:-build}/gen_isa
[ -x "$gen" ] || { echo "FAIL: $gen not built"; exit 1; }
if ! diff -u rtl/fp3_isa.vh <("$gen"); then
  echo "FAIL: rtl/fp3_isa.vh is stale: run 'make isa' and commit it"
  exit 1
fi
# docs/isa.md's instruction and host-port tables are the generated ones.
python3 - "$gen" <<'PY'
import subprocess, sys
md = subprocess.run([sys.argv[1], "--markdown"], check=True, capture_output=True,
                    text=True).stdout
doc = open("docs/isa.md", encoding="utf-8").read()
missing = [t for t in md.split("\n\n") if t.strip() and t.strip() not in doc]
if missing:
    print("FAIL: docs/isa.md lacks the generated table starting", missing[0].splitlines()[0])
    print("      regenerate with: make isa")
    sys.exit(1)
PY
echo "PASS: rtl/fp3_isa.vh and docs/isa.md's tables match sw/isa/fp3_isa.h"
