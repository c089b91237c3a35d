#!/usr/bin/env bash
# test_rtl_tools.sh -- the RTL is Verilog-2005 that every tool of the flow
# accepts: Verilator -Wall lint with zero warnings, and Icarus Verilog
# (iverilog -g2005) elaborating the top.
set -euo pipefail
src=$(ls rtl/*.v)
out=$(verilator --lint-only -Wall -Irtl --top-module fp3_top $src 2>&1) || {
  echo "$out"; echo "FAIL: verilator lint"; exit 1; }
if [ -n "$out" ]; then echo "$out"; echo "FAIL: verilator lint printed warnings"; exit 1; fi
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
iverilog -g2005 -Wall -Irtl -s fp3_top -o "$tmp/top.vvp" $src 2>"$tmp/iv.log" || {
  cat "$tmp/iv.log"; echo "FAIL: iverilog -g2005"; exit 1; }
if grep -v "^\s*$" "$tmp/iv.log" | grep -qi "warning"; then
  cat "$tmp/iv.log"; echo "FAIL: iverilog warnings"; exit 1; fi
echo "PASS: verilator -Wall clean, iverilog -g2005 elaborates fp3_top"
