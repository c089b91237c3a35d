#!/usr/bin/env bash
# synth.sh OUTDIR TOP FLOW [NAME=VALUE...] [-keep MODULE...] VERILOG... --
# synthesize TOP with Yosys for one FPGA flow, with optional parameter
# overrides, fail on any latch or combinational loop, write the netlists,
# the `stat` report and a one-line summary (scripts/synth-report.sh).
# -keep MODULE keeps that module as a level of hierarchy in the flattened
# netlist (e.g. fp3_top inside fp3_axil), so one run reports both: a line
# for MODULE alone and one for the whole TOP.
#
# FLOW   xc2v   synth_xilinx -family xc2v (the paper's Virtex-II, XC2V6000)
#        xc7    synth_xilinx -family xc7  (7-series)
#        ecp5   synth_ecp5                (Lattice ECP5, for nextpnr-ecp5)
#        ice40  synth_ice40               (Lattice iCE40, for nextpnr-ice40)
#        check  generic `synth` only: log and stat, no netlist (a smoke check)
# Outputs in OUTDIR, BASE = TOP[_NAME-VALUE...]_FLOW:
#   BASE.v           netlist (structural Verilog, every flow)
#   BASE.edf         netlist for the Xilinx tools (xc2v, xc7)
#   BASE.json        netlist for nextpnr (ecp5, ice40)
#   BASE_stat.txt    Yosys `stat` of the mapped netlist
#   BASE.log         the Yosys log
# Environment: YOSYS (default yosys); SYNTH_ECP5_SDFF (ecp5: default 1;
# 0 maps no flip-flop with a synchronous set or reset, see below).
set -euo pipefail
out=$1; top=$2; flow=$3; shift 3
chparam=(); tag=""; keep=()
while [ $# -gt 0 ] && { [[ "$1" == *=* ]] || [ "$1" = -keep ]; }; do
  if [ "$1" = -keep ]; then keep+=("$2"); shift 2; continue; fi
  chparam+=(-chparam "${1%%=*}" "${1#*=}"); tag+="_${1%%=*}-${1#*=}"; shift
done
[ $# -gt 0 ] || { echo "usage: synth.sh OUTDIR TOP FLOW [NAME=VALUE...] VERILOG..." >&2; exit 2; }
base="$out/${top}${tag}_${flow}"
mkdir -p "$out"

case "$flow" in
  xc2v|xc7) map="synth_xilinx -flatten -family $flow -top $top"
            write="write_edif -pvector bra $base.edf" ;;
  ecp5)     # FP3_ECP5_EBR: fp3_ram's two-cycle read as block RAM with
            # its output register (rtl/fp3_ram.v).  FP3_ECP5_DSP:
            # fp_dsp_mul as a MULT18X18D with its input and output
            # registers (rtl/fp_dsp_mul.v).
            # The ECP5 cells they instantiate, for `hierarchy -check`.
            defines="-DFP3_ECP5_EBR -DFP3_ECP5_DSP"; cells="read_verilog -lib +/ecp5/cells_bb.v"
            # synth_ecp5 up to its check step, then that step without
            # `autoname`, which takes many minutes on the multi-context
            # register file (Yosys 0.23) and only renames cells (the same
            # for ice40).
            # SYNTH_ECP5_SDFF=0: no flip-flop with a synchronous set or
            # reset.  Yosys folds `q <= c ? 0 : d` into a flip-flop's LSR
            # (set/reset) input, so that a flip-flop of such a register
            # has an LSR net of its own; nextpnr places a flip-flop only
            # beside flip-flops of the same clock and LSR net, and above
            # about 78 % of the TRELLIS_COMB its strict legalisation of
            # those flip-flops does not end.  Here dfflegalize, before
            # synth_ecp5's own flip-flop mapping, leaves every set and
            # reset in front of D, as LUT logic (docs/spatial.md).
            if [ "${SYNTH_ECP5_SDFF:-1}" = 0 ]; then
              map="synth_ecp5 -top $top -run begin:map_ffs
                   dfflegalize -cell \$_DFF_?_ 01 -cell \$_DFF_?P?_ r -cell \$_DFFE_??_ 01 -cell \$_DFFE_?P??_ r -cell \$_DLATCH_?_ x
                   synth_ecp5 -top $top -run map_ffs:check"
            else
              map="synth_ecp5 -top $top -run begin:check"
            fi
            map="$map; hierarchy -check; check -noinit; blackbox =A:whitebox"
            write="write_json $base.json" ;;
  ice40)    map="synth_ice40 -top $top -run begin:check; hierarchy -check; check -noinit; blackbox =A:whitebox"
            write="write_json $base.json" ;;
  check)    map="synth -flatten -top $top"; write="" ;;
  *) echo "synth.sh: unknown flow '$flow' (xc2v xc7 ecp5 ice40 check)" >&2; exit 2 ;;
esac

# Latches are looked for twice: as inferred by `proc` (before mapping can
# hide them in vendor cells) and as mapped cells (Xilinx LD*, generic).
# `check -assert` fails on combinational loops, multiple or missing drivers.
if ! ${YOSYS:-yosys} -q -l "$base.log" -p "
  ${cells:-}
  read_verilog ${defines:-} -Irtl $*
  hierarchy -check -top $top ${chparam[*]}
  $(for k in "${keep[@]}"; do echo "setattr -mod -set keep_hierarchy 1 *$k*;"; done)
  proc
  select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr
  $map
  select -assert-none t:*latch* t:*LATCH* t:LD*
  check -assert
  tee -q -o ${base}_stat.txt stat
  ${write}
  $( [ "$flow" = check ] || echo "write_verilog -noattr $base.v" )
" >/dev/null 2>&1; then
  echo "synth.sh: $top ($flow) FAILED: see $base.log" >&2
  grep -E "ERROR|Warning: found logic loop|Assert|latch" "$base.log" | head -20 >&2 || true
  exit 1
fi
if [ "$flow" = check ]; then echo "synth check: $top synthesizes, no latches, no loops"; exit 0; fi
for k in "${keep[@]}"; do
  printf '%-34s %-6s ' "$k" "$flow"
  bash "$(dirname "$0")/synth-report.sh" --module "$k" "${base}_stat.txt"
done
printf '%-34s %-6s ' "$top${tag}" "$flow"
bash "$(dirname "$0")/synth-report.sh" "${base}_stat.txt"
