#!/usr/bin/env bash
# synth-report.sh [--fields] STAT.txt -- summarise a Yosys `stat` report of
# a mapped netlist (Xilinx, ECP5 or iCE40 cells) in one line:
#   LUTs     Xilinx LUT1..LUT6 and SRL16E/SRLC32E (a LUT used as a shift
#            register: delay flip-flops it absorbs are not in FFs); ECP5
#            LUT4 + 2 per CCU2C carry cell (each
#            holds two LUT4s); iCE40 SB_LUT4
#   FFs      Xilinx FD*; ECP5 TRELLIS_FF; iCE40 SB_DFF*
#   DSPs     Xilinx MULT18X18* (Virtex-II) and DSP48* (7-series); ECP5
#            MULT18X18D; iCE40 SB_MAC16
#   BRAMs    Xilinx RAMB*; ECP5 DP16KD/PDPW16KD; iCE40 SB_RAM40_4K
#   LUTRAMs  Xilinx RAM*X*/RAM*M; ECP5 TRELLIS_DPR16X4
# --fields prints the numbers only: "luts ffs mult18 dsp48 bram lutram".
# --module NAME counts the cells of module NAME only (a level kept by
# synth.sh -keep NAME); the default is the whole design.
#
# synth-report.sh --table DIR -- the per-core area table: reads
# DIR/fp_{add,mul,div,sqrt}_ROUND-r_FTZ-f_{xc2v,xc7,ecp5}_stat.txt
# (scripts/synth.sh), prints a markdown table and writes it to
# DIR/fp_cores_area.md and DIR/fp_cores_area.csv.
set -euo pipefail
self=$0
if [ "${1:-}" = --table ]; then
  dir=$2
  csv="$dir/fp_cores_area.csv"; md="$dir/fp_cores_area.md"
  echo "core,round,ftz,xc2v_luts,xc2v_ffs,xc2v_mult18x18,xc7_luts,xc7_ffs,xc7_dsp48,ecp5_luts,ecp5_ffs,ecp5_mult18x18" > "$csv"
  {
    echo "| core | rounding | subnormals | xc2v LUTs | xc2v FFs | xc2v MULT18X18 | xc7 LUTs | xc7 FFs | xc7 DSP48 | ECP5 LUT4s | ECP5 FFs | ECP5 MULT18X18 |"
    echo "| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
  } > "$md"
  for core in fp_add fp_mul fp_div fp_sqrt; do
    for cfg in "0 0" "1 0" "0 1" "1 1"; do
      set -- $cfg
      b="$dir/${core}_ROUND-$1_FTZ-$2"
      read -r l2 f2 m2 _ _ _ < <(bash "$self" --fields "${b}_xc2v_stat.txt")
      read -r l7 f7 _ d7 _ _ < <(bash "$self" --fields "${b}_xc7_stat.txt")
      read -r l5 f5 m5 _ _ _ < <(bash "$self" --fields "${b}_ecp5_stat.txt")
      echo "$core,$1,$2,$l2,$f2,$m2,$l7,$f7,$d7,$l5,$f5,$m5" >> "$csv"
      echo "| $core | $([ "$1" = 0 ] && echo RNE || echo RTZ) | $([ "$2" = 0 ] && echo IEEE || echo FTZ) | $l2 | $f2 | $m2 | $l7 | $f7 | $d7 | $l5 | $f5 | $m5 |" >> "$md"
    done
  done
  cat "$md"
  exit 0
fi
fields=0; module=""
[ "${1:-}" = --fields ] && { fields=1; shift; }
[ "${1:-}" = --module ] && { module=$2; shift 2; }
f=$1
# Which part of the report counts: the section of --module (a module kept
# as a hierarchy level, see synth.sh -keep), else the design-hierarchy
# total when there is one, else the only module.
hier=$(grep -c "^=== design hierarchy ===" "$f" || true)
awk -v fields=$fields -v want="$module" -v hier="$hier" '
  /^=== .* ===$/ {
    name = substr($0, 5, length($0) - 8)
    on = want != "" ? (index(name, want) > 0 && name != "design hierarchy") \
                    : (hier == 0 || name == "design hierarchy")
    next
  }
  !on { next }
  $1 ~ /^LUT[1-6]$/ || $1 == "SB_LUT4" || $1 ~ /^SRL/ { lut += $2 }
  $1 == "CCU2C"                         { lut += 2 * $2 }
  $1 ~ /^FD/ || $1 == "TRELLIS_FF" || $1 ~ /^SB_DFF/ { ff += $2 }
  $1 ~ /^MULT18X18/ || $1 == "SB_MAC16" { mult += $2 }
  $1 ~ /^DSP48/                         { dsp += $2 }
  $1 ~ /^RAMB/ || $1 ~ /^(DP16KD|PDPW16KD|SB_RAM40_4K)$/ { bram += $2 }
  $1 ~ /^RAM[0-9]+[XM]/ || $1 == "TRELLIS_DPR16X4" { lutram += $2 }
  END {
    if (fields) { printf "%d %d %d %d %d %d\n", lut, ff, mult, dsp, bram, lutram; exit }
    printf "LUTs %d  FFs %d  MULT18X18 %d  DSP48 %d  BRAMs %d  LUTRAMs %d\n",
           lut, ff, mult, dsp, bram, lutram
  }' "$f"
