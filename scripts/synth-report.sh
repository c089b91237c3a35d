#!/usr/bin/env bash
# synth-report.sh STAT.txt -- summarise a Yosys `stat` report of a Xilinx
# netlist: LUTs (all LUT1..LUT6), flip-flops (FD*), multipliers (MULT18X18*,
# DSP48*), block RAMs (RAMB*) and distributed RAM (RAM*M/RAM*S).
set -euo pipefail
f=$1
awk '
  $1 ~ /^LUT[1-6]$/            { lut += $2 }
  $1 ~ /^FD/                   { ff += $2 }
  $1 ~ /^MULT18X18/            { mult += $2 }
  $1 ~ /^DSP48/                { dsp += $2 }
  $1 ~ /^RAMB/                 { bram += $2 }
  $1 ~ /^RAM[0-9]+[XM]/        { lutram += $2 }
  END {
    printf "LUTs %d  flip-flops %d  MULT18X18 %d  DSP48 %d  block RAMs %d  LUT RAMs %d\n",
           lut, ff, mult, dsp, bram, lutram
  }' "$f"
