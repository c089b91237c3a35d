#!/usr/bin/env bash
# test_make_help.sh -- `make help` lists every target: each name declared
# .PHONY in Makefile or mk/*.mk (but the per-variant rules written by a
# $(call ...) template, whose names hold a "$(") has a "## target: text"
# line, and `make help` prints it.
set -euo pipefail
cd "$(dirname "$0")/.."
help=$(make --no-print-directory help)
targets=$(sed -n 's/^\.PHONY: *//p' Makefile mk/*.mk | tr ' ' '\n' | grep -v '^$' | grep -v '\$(' | sort -u)
missing=0
for t in $targets; do
  if ! grep -q "^  make $t  *[^ ]" <<<"$help"; then
    echo "FAIL: .PHONY target '$t' has no '## $t: ...' line above its rule (make help)"
    missing=$((missing + 1))
  fi
done
n=$(wc -w <<<"$targets")
[ "$missing" -eq 0 ] || exit 1
echo "PASS: make help lists all $n .PHONY targets"
