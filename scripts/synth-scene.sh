#!/usr/bin/env bash
# synth-scene.sh FP3 OUTDIR SCENE INTEGRATOR "FLOWS" "OPTS" VERILOG... --
# the area of the processor sized to a scene against the full default
# build of as many lanes.
#
# `FP3 configure SCENE --integrator INTEGRATOR OPTS` (OPTS: more of its
# options, e.g. "--wb-ports 4", or empty) writes the parameters
# (OUTDIR/NAME.params, NAME = the scene's file name without .scene, then
# each word of OPTS as _word, e.g. harbour_wb-ports_4); then, per flow,
# scripts/synth.sh synthesizes fp3_axil with fp3_top kept, once with those
# parameters (OUTDIR/NAME/) and once with the defaults but the same
# NUM_LANES (OUTDIR/full-lanesL/, reused while newer than every VERILOG
# file): sizing leaves the lanes, the scene in flight, and saves within
# them.  The table of LUTs, FFs, DSPs (MULT18X18 on xc2v and ECP5, DSP48
# on xc7) and BRAMs of fp3_axil -- full, sized, saving in % -- goes to
# OUTDIR/NAME.md and OUTDIR/NAME.csv.
set -euo pipefail
fp3=$1; out=$2; scene=$3; integ=$4; flows=$5; opts=$6; shift 6
here=$(dirname "$0")
name=$(basename "$scene" .scene)
read -r -a optv <<< "$opts"
for o in "${optv[@]}"; do o=${o#--}; name+="_${o//[^A-Za-z0-9.-]/-}"; done
mkdir -p "$out"
"$fp3" configure "$scene" --integrator "$integ" "${optv[@]}" -o "$out/$name.params"
read -r -a params < "$out/$name.params"
echo "synth-scene: $scene ($integ${opts:+, $opts}): ${params[*]}"
lanes=1
for p in "${params[@]}"; do [ "${p%%=*}" = NUM_LANES ] && lanes=${p#*=}; done
fulldir="$out/full-lanes$lanes"

newer_than_rtl() { # FILE: exists and newer than every VERILOG source
  [ -f "$1" ] || return 1
  for v in "$@"; do [ "$v" = "$1" ] || [ "$1" -nt "$v" ] || return 1; done
}

csv="$out/$name.csv"; md="$out/$name.md"
echo "flow,build,params,luts,ffs,dsps,brams" > "$csv"
{
  echo "Scene \`$scene\`, integrator $integ: \`${params[*]}\` (\`fp3 configure${opts:+ $opts}\`); full: the defaults with NUM_LANES=$lanes."
  echo
  echo "| flow | build | LUTs | FFs | DSPs | BRAMs |"
  echo "| --- | --- | ---: | ---: | ---: | ---: |"
} > "$md"
tag=""; for p in "${params[@]}"; do tag+="_${p%%=*}-${p#*=}"; done
for flow in $flows; do
  full="$fulldir/fp3_axil_NUM_LANES-${lanes}_${flow}_stat.txt"
  if newer_than_rtl "$full" "$@"; then
    echo "synth-scene: full build ($flow): reusing $full"
  else
    bash "$here/synth.sh" "$fulldir" fp3_axil "$flow" "NUM_LANES=$lanes" -keep fp3_top "$@"
  fi
  bash "$here/synth.sh" "$out/$name" fp3_axil "$flow" "${params[@]}" -keep fp3_top "$@"
  sized="$out/$name/fp3_axil${tag}_${flow}_stat.txt"
  read -r fl ff fm fd fb _ < <(bash "$here/synth-report.sh" --fields "$full")
  read -r sl sf sm sd sb _ < <(bash "$here/synth-report.sh" --fields "$sized")
  fdsp=$((fm + fd)); sdsp=$((sm + sd))
  pct() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == 0) print "—"; else printf "%.1f %%", 100 * (a - b) / a }'; }
  echo "$flow,full,NUM_LANES=$lanes,$fl,$ff,$fdsp,$fb" >> "$csv"
  echo "$flow,sized,${params[*]},$sl,$sf,$sdsp,$sb" >> "$csv"
  {
    echo "| $flow | full (defaults, $lanes lane$([ "$lanes" = 1 ] || echo s)) | $fl | $ff | $fdsp | $fb |"
    echo "| | sized to the scene | $sl | $sf | $sdsp | $sb |"
    echo "| | saving | $(pct "$fl" "$sl") | $(pct "$ff" "$sf") | $(pct "$fdsp" "$sdsp") | $(pct "$fb" "$sb") |"
  } >> "$md"
done
cat "$md"
echo "synth-scene: $md, $csv"
