#!/usr/bin/env bash
# pnr-unit.sh OUTDIR MODULE [NAME=VALUE...] -- VERILOG...
# Place and route one RTL module alone on the ECP5 (make pnr-unit): its
# ports are fed from and into flip-flops by a generated wrapper, fp3_unit
# (scripts/unit-wrap.py), which is synthesized (scripts/synth.sh, with
# MODULE kept as a level of hierarchy) and placed and routed
# (scripts/pnr.sh: LFE5U-85F-6, the clock of constraints/fp3_ecp5.lpf).
# Prints utilisation, Fmax and the critical path; appends a row to
# OUTDIR/pnr_summary.csv.  Used to find a block's own limit: in the whole
# design a path may start or end in another block.
# Exits non-zero on a bad argument, a synthesis error or a design that
# does not place.
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: pnr-unit.sh OUTDIR MODULE [NAME=VALUE...] -- VERILOG..." >&2; exit 2; }
out=$1; mod=$2; shift 2
params=(); chparam=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do
  [[ "$1" == *=* ]] || { echo "pnr-unit.sh: bad parameter '$1' (NAME=VALUE)" >&2; exit 2; }
  params+=("$1"); chparam+=(-chparam "${1%%=*}" "${1#*=}"); shift
done
[ "${1:-}" = -- ] && shift
[ $# -gt 0 ] || { echo "pnr-unit.sh: no Verilog sources" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
name="$mod$(printf '_%s' "${params[@]/=/-}")"
[ ${#params[@]} -gt 0 ] || name=$mod
dir="$out/$name"
mkdir -p "$dir"
if ! ${YOSYS:-yosys} -q -l "$dir/ports.log" -p "
  read_verilog -Irtl $*
  hierarchy -check -top $mod ${chparam[*]}
  proc
  write_json $dir/ports.json" >/dev/null 2>&1; then
  echo "pnr-unit.sh: $mod with ${params[*]:-its defaults} does not elaborate: see $dir/ports.log" >&2
  grep -E "ERROR" "$dir/ports.log" | head -5 >&2 || true
  exit 1
fi
python3 "$here/unit-wrap.py" "$mod" "$dir/ports.json" "${params[@]}" > "$dir/fp3_unit.v.tmp"
mv "$dir/fp3_unit.v.tmp" "$dir/fp3_unit.v"
bash "$here/synth.sh" "$dir" fp3_unit ecp5 -keep "$mod" "$@" "$dir/fp3_unit.v"
[ -f "$out/pnr_summary.csv" ] ||
  echo "name,device,luts,ffs,dsps,brams,fmax_mhz,target_mhz,levels,logic_ns,routing_ns,from,to" \
    > "$out/pnr_summary.csv"
bash "$here/pnr.sh" ecp5 "$name" "$dir/fp3_unit_ecp5.json" "$dir"
tail -1 "$dir/pnr_summary.csv" >> "$out/pnr_summary.csv"
