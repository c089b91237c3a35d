#!/usr/bin/env bash
# test_spatial_engine.sh -- fp3 run --engine spatial (sw/compiler/
# engine_spatial.h, docs/spatial.md "The spatial engine"): a model's
# pipeline Verilated on first use into a cache, loaded, and every object's
# state compared bit for bit with the golden model after every step.
#   - the ship (rk4se) on a chip of 3 pipelines (--pipelines 3): 1
#     object, 240 objects (80 a pipeline: more than the latency), the ship
#     scene scenes/harbour.scene, and scenes/drift.scene (C zero in every
#     object: the pipeline without its terms, the module `fp3 spatial
#     --scene` writes for it); each
#     bit-exact, each with the same final states as --engine rtl, and the
#     JSON valid against docs/fp3.schema.json; fp3 frames of the harbour
#     bit-exact frame by frame;
#   - the oscillator's Euler step (latency 7): 1 and 20 objects, and 1
#     object whose products are subnormal (flags inexact and underflow);
#   - every comparison with rtl includes the run's exception flags;
#   - the cache: a run on a built entry builds nothing; an entry whose
#     shared object is cut short, and one holding another module's chip
#     (its HASH register is not the module's hash), are found unusable,
#     said, and built again (the first saying what it builds, with its
#     stages) (the second by a Verilator that fails: exit 1, the log
#     named);
#   - bad options: --program, --trace, `fp3 bench --engine spatial`, and
#     --pipelines without the spatial engine or out of 1..255, and
#     --clock-cores without it, are refused with exit 2.
# The runs use the tree's cache (build/spatial-cache: the ship's and the
# oscillator's chips, built there once per revision of their sources);
# the cache checks a copy in a temporary folder, where one oscillator
# chip is built again.  About 25 s with the tree's entries built, 50 s
# without.  CLI: $FP3_BIN (default
# build/fp3).
set -u
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
[ -x "$FP3" ] || { echo "test_spatial_engine: $FP3 not built (make build/fp3)"; exit 1; }
T=$(mktemp -d /tmp/fp3_test_spatial_engine.XXXXXX)
trap 'rm -rf "$T"' EXIT

pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok: $*"; }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

# same_results A.json B.json: A valid against docs/fp3.schema.json, pass true
# in both, the same "results" (every object's final state and reference).
same_results() { python3 tests/same_results.py "$1" "$2"; }

# against_rtl NAME ARGS...: fp3 run ARGS on spatial (with $PIPES) and on
# rtl, --json
against_rtl() {
  local name=$1; shift
  if "$FP3" run "$@" --engine spatial $PIPES --json >"$T/$name.sp.json" 2>"$T/$name.sp.err" &&
     "$FP3" run "$@" --engine rtl --json >"$T/$name.rtl.json" 2>"$T/$name.rtl.err" &&
     same_results "$T/$name.sp.json" "$T/$name.rtl.json"; then
    ok "$name: bit-exact on spatial after every step, the final states of --engine rtl"
  else
    cat "$T/$name.sp.err"; bad "$name: spatial against the golden model and rtl"
  fi
}

SHIP="--model models/ship.fp3m --integrator rk4se"
OSC="--model models/oscillator.fp3m --integrator euler"

# The chips of the runs below come from the tree's own cache
# (build/spatial-cache, what `fp3 run --engine spatial` uses): built there
# on first use, once per revision of the chip's sources, and shared with
# every later run.
export FP3_SPATIAL_CACHE="$PWD/build/spatial-cache"

# ---- the oscillator (latency 7), and the cache reused --------------------------
PIPES=
against_rtl osc-1 $OSC --steps 50
# values near the least normal: products round to subnormals, so the
# cores raise underflow as well as inexact, on both engines
against_rtl osc-underflow $OSC --set x=1e-38 --set v=1e-38 --steps 5
start=$(date +%s.%N)
against_rtl osc-20 $OSC --objects 20 --steps 9
if ! grep -q "building" "$T/osc-20.sp.err" &&
   python3 -c "import sys; sys.exit(0 if float(sys.argv[2]) - float(sys.argv[1]) < 10 else 1)" \
     "$start" "$(date +%s.%N)"; then
  ok "a second run reuses the entry: nothing built"
else
  cat "$T/osc-20.sp.err"; bad "the second run built again"
fi
# an empty $VERILATOR or $FP3_SPATIAL_CXX is as unset: the same entry
VERILATOR= FP3_SPATIAL_CXX= "$FP3" run $OSC --steps 5 --engine spatial >"$T/empty.out" 2>"$T/empty.err"
rc=$?
if [ "$rc" -eq 0 ] && ! grep -q "building" "$T/empty.err"; then
  ok "VERILATOR and FP3_SPATIAL_CXX empty: the defaults, the entry reused"
else
  cat "$T/empty.err"; bad "empty VERILATOR / FP3_SPATIAL_CXX: exit $rc"
fi

# ---- the ship, 3 pipelines -----------------------------------------------------
PIPES="--pipelines 3"
against_rtl ship-1 $SHIP --steps 40
against_rtl ship-240 $SHIP --objects 240 --steps 12
entry=$(ls -d "$FP3_SPATIAL_CACHE"/fp3_spatial_ship_rk4se-* 2>/dev/null |
        grep -v -e '\.tmp\.' -e '\.failed\.log$' | head -1)
# The pipeline's latency as `fp3 spatial` reports it for the same model
# and core options (the engine's JSON must agree).
"$FP3" spatial models/ship.fp3m --integrator rk4se -o "$T/ship-report" 2>/dev/null
Lref=$(sed -n 's/^latency: \([0-9]*\) cycles.*/\1/p' "$T/ship-report/report.txt")
python3 - "$T/ship-240.sp.json" "$Lref" <<'PY' && ok "240 objects on 3 pipelines (80 rounds > latency + 3): CYCLES of one run of 12 steps = 11 x 80 + 80 + L + 4" || bad "240 objects' cycles"
import json, sys
j = json.load(open(sys.argv[1]))
L = j["pipeline_latency"]
Lref = int(sys.argv[2] or -1)
# one run of all 12 steps (each observed on the trace port): the frame
# feeds 3 objects a cycle, 80 rounds a step (80 > L + 3, so no bubbles),
# and is done L + 4 cycles after the last step's last round
# (docs/spatial.md)
want = 11 * max(80, L + 3) + 80 + L + 4
print(f"  latency {L}, cycles {j['cycles']}, expected {want}")
print(f"  fp3 spatial reports latency {Lref}")
sys.exit(0 if L == Lref and L + 3 <= 80 and j["cycles"] == want and j["contexts"] == 1026
         else 1)
PY
against_rtl harbour --scene scenes/harbour.scene --steps 30
# a scene whose objects all have C = 0: the pipeline without the drag
# terms (7 cores), the one `fp3 spatial --scene` writes for it
against_rtl drift --scene scenes/drift.scene --steps 30
"$FP3" spatial --scene scenes/drift.scene --integrator rk4se -o "$T/drift" 2>/dev/null
same=
for e in "$FP3_SPATIAL_CACHE"/fp3_spatial_ship_rk4se-*/; do
  cmp -s "$e/fp3_spatial_ship_rk4se.v" "$T/drift/fp3_spatial_ship_rk4se.v" && same=$e
done
if [ -n "$same" ] && grep -q '^cores: 7,' "$T/drift/report.txt" &&
   grep -q 'terms removed, zero in every object: C$' "$T/drift/report.txt"; then
  ok "drift.scene: the engine ran the pipeline fp3 spatial --scene writes (7 cores, C's terms removed)"
else
  cat "$T/drift/report.txt"; bad "drift.scene: fp3 spatial --scene and the engine's pipeline"
fi
# fp3 frames: the harbour frame by frame (moored ships skipped at rest)
if "$FP3" frames --scene scenes/harbour.scene --engine spatial $PIPES --frames 20 --json \
     >"$T/frames.json" 2>"$T/frames.err" &&
   python3 - "$T/frames.json" <<'PY'
import json, sys
import jsonschema
j = json.load(open(sys.argv[1]))
schema = json.load(open("docs/fp3.schema.json"))
jsonschema.validate(j, {"$defs": schema["$defs"], "$ref": "#/$defs/frames"})
print(f"  frames: {j['object_frames_run']} object-frames run, {j['object_frames_skipped']} skipped, "
      f"{j['golden_mismatches']} mismatches")
sys.exit(0 if j["pass"] and j["golden_mismatches"] == 0 and j["object_frames_skipped"] > 0 else 1)
PY
then
  ok "fp3 frames on spatial: every carried value after every frame bit-exact, objects at rest skipped"
else
  cat "$T/frames.err"; bad "fp3 frames on spatial"
fi
# ---- a build, with its progress; an unusable entry found and built again ------
# The oscillator's entries copied into a new cache ($T/cache), each shared
# object cut short: the run finds its entry unusable, says so and what it
# builds, with each stage and its time, builds it and passes.
mkdir -p "$T/cache"
for dir in "$FP3_SPATIAL_CACHE"/fp3_spatial_oscillator_euler-*; do
  case $dir in *.tmp.*|*.failed.log) continue;; esac
  cp -r "$dir" "$T/cache/" && head -c 4096 "$dir/spatial.so" >"$T/cache/${dir##*/}/spatial.so"
done
export FP3_SPATIAL_CACHE="$T/cache"
"$FP3" run $OSC --steps 5 --engine spatial >"$T/re.out" 2>"$T/re.err"
rc=$?
osc=$(sed -n 's/.*cache entry \(.*\) is unusable (spatial\.so (4096 bytes.*/\1/p' "$T/re.err" | head -1)
if [ "$rc" -eq 0 ] && [ -n "$osc" ] && grep -q "^PASS" "$T/re.out" &&
   grep -q "spatial: building oscillator euler (Verilator) into $osc\$" "$T/re.err" &&
   grep -q "\[2/3\] compile the model (clang++) \.\.\. [0-9.]* s" "$T/re.err" &&
   grep -q "\[3/3\] link the shared object \.\.\. [0-9.]* s" "$T/re.err"; then
  ok "a shared object cut short: found unusable, said; the build says what it builds, and each stage with its time (the model compiled by clang++); bit-exact"
else
  cat "$T/re.err" "$T/re.out"; bad "a shared object cut short, rebuilt: exit $rc"
fi
[ -n "$osc" ] && [ -f "$osc/spatial.so" ] && [ -f "$osc/manifest" ] &&
  [ -z "$(ls -d "$T"/cache/*.tmp.* 2>/dev/null)" ] &&
  ok "the entry holds spatial.so and its manifest, no temporary left" ||
  bad "the cache entry: $(ls -la "$T/cache" "$osc" 2>&1)"
# the ship's pipeline in the oscillator's entry, the manifest's size and
# FNV-1a 64 made to match it: only the HASH the loaded object reports tells
cp "$entry/spatial.so" "$osc/spatial.so"
python3 - "$osc" <<'PY'
import os, re, sys
d = sys.argv[1]
h = 0xcbf29ce484222325
for byte in open(f"{d}/spatial.so", "rb").read():
    h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
m = open(f"{d}/manifest").read()
m = re.sub(r"so_size \d+", f"so_size {os.path.getsize(f'{d}/spatial.so')}", m)
m = re.sub(r"so_hash [0-9a-f]+", f"so_hash {h:016x}", m)
open(f"{d}/manifest", "w").write(m)
PY
# ... found, and built again by a Verilator that fails (it answers
# --version and --getenv as the real one, so the entry is the same): the
# run says so, names the kept log and its last line, and exits 1
printf '#!/bin/sh\ncase "$1" in --getenv|--version) exec verilator "$@";; esac\necho "%%Error: a build that fails" >&2\nexit 1\n' >"$T/vfail"
chmod +x "$T/vfail"
VERILATOR="$T/vfail" "$FP3" run $OSC --steps 5 --engine spatial >"$T/re.out" 2>"$T/re.err"
rc=$?
if [ "$rc" -eq 1 ] && grep -q "cache entry $osc is unusable (its HASH is" "$T/re.err" &&
   grep -q "verilate failed (exit 1); log $osc.failed.log:" "$T/re.err" &&
   grep -q "a build that fails" "$T/re.err" && [ -f "$osc.failed.log" ] && [ ! -e "$osc" ]; then
  ok "another module's chip (HASH mismatch): found unusable; the failed rebuild names its log, exit 1"
else
  cat "$T/re.err"; bad "HASH mismatch, then a failed build: exit $rc"
fi
# $FP3_SPATIAL_CXX names the model's C++ compiler, part of the key: one
# that fails makes a new entry's build fail at its stage 2, named, with
# its log kept and no entry left
printf '#!/bin/sh\necho "error: a compiler that fails" >&2\nexit 1\n' >"$T/cxxfail"
chmod +x "$T/cxxfail"
FP3_SPATIAL_CXX="$T/cxxfail" "$FP3" run $OSC --steps 5 --engine spatial >"$T/re.out" 2>"$T/re.err"
rc=$?
cxx_entry=$(sed -n 's/.*spatial: building oscillator euler (Verilator) into \(.*\)$/\1/p' "$T/re.err")
if [ "$rc" -eq 1 ] && [ -n "$cxx_entry" ] && [ "$cxx_entry" != "$osc" ] &&
   grep -q "\[2/3\] compile the model ($T/cxxfail) \.\.\. failed" "$T/re.err" &&
   grep -q "a compiler that fails" "$cxx_entry.failed.log" && [ ! -e "$cxx_entry" ]; then
  ok "FP3_SPATIAL_CXX: another compiler, another entry; one that fails: stage 2 named, its log kept, exit 1"
else
  cat "$T/re.err"; bad "FP3_SPATIAL_CXX that fails: exit $rc"
fi

# ---- options that make no sense with the spatial engine ------------------------
refused() {
  local what=$1 pattern=$2; shift 2
  "$FP3" "$@" >"$T/ref.out" 2>"$T/ref.err"
  local rc=$?
  if [ "$rc" -eq 2 ] && grep -q -- "$pattern" "$T/ref.err"; then
    ok "$what: exit 2, '$(head -1 "$T/ref.err" | cut -c1-90)...'"
  else
    cat "$T/ref.err"; bad "$what: exit $rc"
  fi
}
refused "--program with --engine spatial" "--program does not go with --engine spatial" \
  run --engine spatial --program programs/ship_rk4.s --steps 3
refused "--trace with --engine spatial" "--trace needs --engine rtl" \
  run --engine spatial $SHIP --trace "$T/x.vcd"
refused "fp3 bench --engine spatial" "unknown engine 'spatial'" \
  bench --model models/ship.fp3m --engine spatial
refused "--pipelines without --engine spatial" "--pipelines goes with --engine spatial" \
  run $SHIP --pipelines 2 --steps 3
refused "--clock-cores without --engine spatial" "--clock-cores goes with --engine spatial" \
  run $SHIP --clock-cores --steps 3
refused "--pipelines 0" "--pipelines" run --engine spatial $SHIP --pipelines 0 --steps 3
refused "--pipelines 256" "--pipelines" run --engine spatial $SHIP --pipelines 256 --steps 3

echo "test_spatial_engine: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
