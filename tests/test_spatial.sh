#!/usr/bin/env bash
# test_spatial.sh -- `fp3 spatial` (sw/compiler/spatial.h, docs/spatial.md):
# the generated pipeline of every shipped model with every integrator that
# applies to it, and of variants of the cores (below), Verilated with the harness
# sim/spatial_tb.cpp, streams objects through it step after step, each
# object's new state fed back as its next input, and every object's
# carried values after every step must equal the golden model's
# (fp3_compiled_model_step, the vectors `fp3 spatial --vectors` writes) bit
# for bit: on 1 object (every step a lone object and LATENCY - 1 bubbles)
# and on more objects than the latency (one object every cycle).  The
# generated module must be `verilator --lint-only -Wall` clean, generate
# the same text twice, and bad input (also a pipeline that does not fit
# the LFE5U-85F, and with --scene a model scene beside a model, vectors,
# rk4 on a ship scene, a bad row) must exit 2 leaving no file.  --scene
# removes the terms of params zero in every object (coast.scene: T), none
# with --literal.  The ship's module with one delay stage removed must
# fail.
#
#   tests/test_spatial.sh [--quick]   (--quick: four models and the variants)
#
# The cases run FP3_TEST_JOBS at a time (default 2); each Verilator build is
# compiled by clang at -O0, so the 69 pipelines take about 7 CPU-minutes
# (about 4 minutes on two idle cores).
#
# Runs from anywhere; the CLI is $FP3_BIN, else build/fp3 of this checkout.
# The Verilated runtime comes from build/verilated (make builds it).
set -euo pipefail
cd "$(dirname "$0")/.."
. tests/verilated_env.sh
tmp=$(mktemp -d /tmp/fp3_test_spatial.XXXXXX); trap 'rm -rf "$tmp"' EXIT
fail=0
STEPS=3

# build_tb MODULE FILE.v OBJDIR EXE: the harness on a generated module.  The
# model is one translation unit (VM_PARALLEL_BUILDS=0), unoptimised and
# compiled by clang: the build, not the run, is what takes time here, and
# clang -O0 compiles a Verilated pipeline about 6 times faster than g++
# -O0 (rigidbody's rk4: 5 s against 30 s of CPU).  Its log: OBJDIR.log.
build_tb() {
  { nice $VERILATOR --cc --x-assign fast --x-initial fast --noassert -Irtl -y rtl \
      --top-module "$1" --prefix Vspatial --Mdir "$3" "$2" &&
    nice make -s -C "$3" -f Vspatial.mk VM_PARALLEL_BUILDS=0 OPT_FAST=-O0 OPT_SLOW=-O0 \
      CXX=clang++ Vspatial__ALL.a &&
    nice clang++ -O1 -std=c++17 -faligned-new -I"$VINC" -I"$VINC/vltstd" -I"$3" \
      sim/spatial_tb.cpp "$3/Vspatial__ALL.a" $RUNTIME -pthread -latomic -o "$4"; } \
    >"$3.log" 2>&1 || { tail -20 "$3.log"; return 1; }
}

# The cases: every shipped model with every integrator that applies to it
# (folded, --no-fit-check: most do not fit the chip at the default
# latencies), then variants of the cores: the literal ship on the chip
# builds' cores (--clock-cores: fp_mul with its feed register), also with
# three MULT18X18D per multiply (--mult-blocks 3), the
# oscillator with every multiply on fp_mul (--no-scaleb), the spring with
# RTZ and FTZ cores.  --quick: the ship, the spring, the oscillator and the
# projectile and the variants only (a quick check while developing).
# name, model, fp3 spatial options
cases=()
# the integrators, as fp3 lists them (fp3_model_integrators)
integrators=$("$FP3" spatial --help | sed -n 's/^The integrators: \(.*\)\.$/\1/p')
[ -n "$integrators" ] || { echo "test_spatial.sh: fp3 spatial --help names no integrators" >&2; exit 1; }
if [ "${1:-}" = --quick ]; then
  cases=("ship-rk4se     models/ship.fp3m       --integrator rk4se"
         "spring-rk4     models/spring.fp3m     --integrator rk4"
         "projectile-rk4 models/projectile.fp3m --integrator rk4 --no-fit-check")
else
  for m in models/*.fp3m; do
    for i in $integrators; do
      cases+=("$(basename "$m" .fp3m)-$i $m --integrator $i --no-fit-check")
    done
  done
fi
cases+=("ship-literal   models/ship.fp3m       --integrator rk4se --literal --clock-cores"
        "ship-literal-b3 models/ship.fp3m      --integrator rk4se --literal --clock-cores --mult-blocks 3"
        "oscillator-rk4-no-scaleb models/oscillator.fp3m --integrator rk4 --no-scaleb"
        "spring-rk4-rtz-ftz models/spring.fp3m --integrator rk4 --round rtz --ftz")

# one_case NAME MODEL OPTS: generate, lint, build and run one case (and for
# ship-rk4se the shortened modules); its lines on stdout; 1 if it failed,
# 3 if fp3 spatial refused it because the integrator does not apply to the
# model.
one_case() {
  local name=$1 model=$2 opts=$3 fail=0
  local d="$tmp/$name"; mkdir -p "$d"
  # shellcheck disable=SC2086
  if ! "$FP3" spatial "$model" $opts -o "$d/gen" 2>"$d.log"; then
    if grep -q "integrator .* needs" "$d.log"; then
      echo "PASS: $name refused: $(head -1 "$d.log" | sed 's/^fp3 spatial: [^:]*: //')"; return 3
    fi
    cat "$d.log"; echo "FAIL: $name: fp3 spatial"; return 1
  fi
  local lat v mod many
  lat=$(sed -n 's/^latency: \([0-9]*\) cycles.*/\1/p' "$d/gen/report.txt")
  v=$(ls "$d/gen"/*.v); mod=$(basename "$v" .v)
  # vectors: 1 object, and more objects than the latency
  many=$((lat + 17))
  # shellcheck disable=SC2086
  "$FP3" spatial "$model" $opts -o "$d/one" --vectors 1 --steps $STEPS 2>/dev/null
  # shellcheck disable=SC2086
  "$FP3" spatial "$model" $opts -o "$d/many" --vectors $many --steps $STEPS --seed 7 2>/dev/null
  cmp -s "$v" "$d/one/$mod.v" && cmp -s "$v" "$d/many/$mod.v" || {
    echo "FAIL: $name: two runs generate different Verilog"; fail=1; }
  if ! $VERILATOR --lint-only -Wall -Irtl -y rtl --top-module "$mod" "$v" >"$d.lint" 2>&1; then
    head -20 "$d.lint"; echo "FAIL: $name: verilator --lint-only -Wall"; return 1
  fi
  if ! build_tb "$mod" "$v" "$d/obj" "$d/tb"; then
    echo "FAIL: $name: Verilator build"; return 1
  fi
  local set out
  for set in one many; do
    if out=$("$d/tb" "$d/$set/vectors.txt" 2>&1); then
      echo "PASS: $name $set ($(sed -n 's/^cores: \([0-9]*\),.*/\1 cores/p' "$d/gen/report.txt" | head -1), latency $lat): ${out#PASS: }"
    else
      echo "$out"; echo "FAIL: $name: $set"; fail=1
    fi
  done
  rm -rf "$d/obj"
  # the harness bites: the ship's module with one delay stage removed must
  # fail, whichever form the shortened segment has: the first flip-flop
  # segment deeper than 1 (fp_pipe), the first LUT-RAM segment and the
  # first block-RAM segment (fp_delay STYLE 1 and 2) made one stage shorter
  if [ "$name" = ship-rk4se ]; then
    for form in ff lutram ebr; do
      python3 - "$v" "$d/short-$form.v" "$form" <<'PY'
import re, sys
s = open(sys.argv[1]).read()
pat = {"ff": r"fp_pipe #\(\.WIDTH\(32\), \.DEPTH\(([0-9]+)\)\)",
       "lutram": r"fp_delay #\(\.WIDTH\(32\), \.DEPTH\(([0-9]+)\), \.STYLE\(1\)\)",
       "ebr": r"fp_delay #\(\.WIDTH\(32\), \.DEPTH\(([0-9]+)\), \.STYLE\(2\)\)"}[sys.argv[3]]
for m in re.finditer(pat, s):
    if int(m.group(1)) > 1:
        s = s[:m.start(1)] + str(int(m.group(1)) - 1) + s[m.end(1):]
        break
else:
    sys.exit("no %s delay segment to shorten" % sys.argv[3])
open(sys.argv[2], "w").write(s)
PY
      if build_tb "$mod" "$d/short-$form.v" "$d/objs-$form" "$d/tbs-$form"; then
        for set in one many; do
          if out=$("$d/tbs-$form" "$d/$set/vectors.txt" 2>&1); then
            echo "FAIL: $name with a $form delay stage removed passes ($set)"; fail=1
          else
            echo "PASS: $name with a $form delay stage removed fails ($set): $(echo "$out" | tail -1)"
          fi
        done
      else
        echo "FAIL: $name: Verilator build of the module shortened in $form"; fail=1
      fi
    done
  fi
  return $fail
}

# Run the cases JOBS at a time (default 2, this machine's cores), each into
# its own output file, then print them in order.
JOBS=${FP3_TEST_JOBS:-2}
k=0
for c in "${cases[@]}"; do
  read -r name model opts <<<"$c"
  while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n || true; done
  { rc=0; one_case "$name" "$model" "$opts" || rc=$?; echo $rc >"$tmp/rc.$k"; } \
    >"$tmp/out.$k" 2>&1 &
  k=$((k + 1))
done
wait
passed=0 skipped=0
for ((j = 0; j < k; j++)); do
  cat "$tmp/out.$j"
  case $(cat "$tmp/rc.$j" 2>/dev/null || echo 1) in
    0) passed=$((passed + 1));;
    3) skipped=$((skipped + 1));;
    *) fail=1;;
  esac
done
echo "cases: $passed passed, $skipped refused (the integrator does not apply), $((k - passed - skipped)) failed"

# the usage
if "$FP3" spatial --help | grep -q "^usage: fp3 spatial MODEL.fp3m | --scene FILE -o DIR"; then
  echo "PASS: fp3 spatial --help"
else
  echo "FAIL: fp3 spatial --help"; fail=1
fi

# a scene: the params zero in every object drop their terms (coast.scene:
# T; the folded ship has 21 cores), none with --literal (30 cores)
scene_cores() { # ARGS... -> "CORES|REMOVED"
  "$FP3" spatial "$@" --integrator rk4se -o "$tmp/scene" 2>/dev/null || { echo fail; return; }
  echo "$(sed -n 's/^cores: \([0-9]*\),.*/\1/p' "$tmp/scene/report.txt")|$(sed -n \
    's/^scene: .*zero in every object: //p' "$tmp/scene/report.txt")"
  rm -rf "$tmp/scene"
}
got="$(scene_cores models/ship.fp3m) $(scene_cores --scene scenes/coast.scene)"
got="$got $(scene_cores --scene scenes/coast.scene --literal)"
if [ "$got" = "21| 17|T 30|none (--literal)" ]; then
  echo "PASS: fp3 spatial --scene: coast.scene's T terms removed (21 -> 17 cores), none with --literal"
else
  echo "FAIL: fp3 spatial --scene: cores|removed '$got'"; fail=1
fi

# bad input: exit 2, nothing written
bad() {
  local what=$1; shift
  local rc=0
  "$FP3" spatial "$@" -o "$tmp/bad" >/dev/null 2>"$tmp/bad.log" || rc=$?
  if [ "$rc" != 2 ] || [ -e "$tmp/bad" ] || ! [ -s "$tmp/bad.log" ]; then
    echo "FAIL: $what: exit $rc (want 2 with a message and no files)"; fail=1
  else
    echo "PASS: $what: exit 2, '$(head -1 "$tmp/bad.log")', no files"
  fi
}
bad "unknown integrator" models/ship.fp3m --integrator rk5
bad "bad rounding" models/ship.fp3m --round up
bad "fp_mul's feed register at latency 3" models/ship.fp3m --mul-feed --mul-latency 3
bad "three MULT18X18D per multiply without the DSP product" models/ship.fp3m --mult-blocks 3 --mul-latency 10
bad "two MULT18X18D per multiply" models/ship.fp3m --mult-blocks 2
bad "--steps without --vectors" models/ship.fp3m --steps 3
bad "missing model" models/no-such-model.fp3m
bad "rk4se on an unsplit model" models/projectile.fp3m --integrator rk4se
bad "a model scene and a model" models/ship.fp3m --scene scenes/springs.scene
bad "--vectors for a scene" --scene scenes/drift.scene --vectors 4
bad "rk4 on a ship scene (its RK4 is rk4se)" --scene scenes/drift.scene --integrator rk4
{ cat scenes/drift.scene; echo "1000 0 10000 x 2"; } >"$tmp/bad-row.scene"
bad "a scene with a bad row" --scene "$tmp/bad-row.scene"
grep -q "bad-row.scene:13:" "$tmp/bad.log" ||
  { echo "FAIL: the bad row's error names the file and line 13: $(cat "$tmp/bad.log")"; fail=1; }
# projectile's RK4 (119 cores) needs about 155,000 LUT4s at the default
# latencies: more than the LFE5U-85F has
bad "a pipeline that does not fit the LFE5U-85F" models/projectile.fp3m --integrator rk4

[ "$fail" = 0 ] || exit 1
echo "PASS: test_spatial"
