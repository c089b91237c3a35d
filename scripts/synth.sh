#!/usr/bin/env bash
# synth.sh OUTDIR TOP FAMILY [VERILOG...] -- synthesize TOP with Yosys for a
# Xilinx FAMILY (xc2v: the paper's Virtex-II; xc7: 7-series), fail on any
# latch or combinational loop, write the netlist, the `stat` report and a
# one-line summary (scripts/synth-report.sh).
set -euo pipefail
out=$1; top=$2; family=$3; shift 3
mkdir -p "$out"
yosys -q -l "$out/${top}_${family}.log" -p "
  read_verilog -Irtl $*
  synth_xilinx -flatten -family $family -top $top
  select -assert-none t:*latch* t:LD*
  check -assert
  tee -q -o $out/${top}_${family}_stat.txt stat
  write_verilog -noattr $out/${top}_${family}.v
"
printf '%-10s %-5s ' "$top" "$family"
bash "$(dirname "$0")/synth-report.sh" "$out/${top}_${family}_stat.txt"
