#!/usr/bin/env bash
# test_json.sh -- every form of every `fp3 ... --json` against the one
# schema, docs/fp3.schema.json (docs/json.md): fp3 run (one object, many
# objects, model scenes, ship scenes, hand-written programs, run errors,
# golden mismatches, non-finite states), fp3 frames (ship and model
# form), fp3 compile and fp3 configure (ship and model scenes).
#
# Each command runs briefly (ISS, a few steps; two short RTL runs for the
# clock-cycle form); its exit status is checked here, its standard output
# by python3's jsonschema (Draft 2020-12) against the $defs entry of its
# subcommand.  Negative checks prove the validator bites: outputs with a
# required key removed, a value of the wrong type, an undocumented key or
# a NaN token must be rejected.
#
# Runs from anywhere; the CLI is $FP3_BIN, else build/fp3 of this checkout.
# Needs python3 with the jsonschema package (pip install jsonschema).
# Exit status non-zero if any check fails.
set -u
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
SCHEMA=docs/fp3.schema.json
if [ ! -x "$FP3" ]; then
  echo "test_json: $FP3 not built (make $FP3)"; exit 1
fi
if ! python3 -c 'import jsonschema' 2>/dev/null; then
  echo "test_json: python3 has no jsonschema module (pip install jsonschema)"; exit 1
fi
T=$(mktemp -d /tmp/fp3_test_json.XXXXXX)
trap 'rm -rf "$T"' EXIT

pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

# The manifest: one line per output to validate, "KIND FILE LABEL".
: >"$T/manifest"
n=0

# form KIND STATUS -- fp3 ARGS...: run fp3 with ARGS and --json, check the
# exit status, and queue its standard output for validation against
# $defs/KIND.
form() {
  local kind=$1 want=$2; shift 3
  n=$((n + 1))
  local out="$T/out$n.json" rc
  "$FP3" "$@" --json >"$out" 2>"$T/err$n"; rc=$?
  if [ "$rc" -ne "$want" ]; then
    bad "fp3 $* --json: exit $rc, want $want; stderr: $(head -3 "$T/err$n")"
    return
  fi
  ok
  printf '%s %s fp3 %s --json\n' "$kind" "$out" "$*" >>"$T/manifest"
}

# ---- programs that fail on purpose ------------------------------------------
# a fault (ILLEGAL_INSN at pc 1) and a wrong result (s - h v for s + h v);
# the ship programs' includes and .model line (../models) resolve in $T
cp tests/data/fault.s "$T/fault.s"   # ILLEGAL_INSN at pc 1
mkdir -p "$T/programs" "$T/models"
cp programs/*.inc "$T/programs/"
cp models/ship.fp3m "$T/models/"
sed 's/^\( *\)add  s, s, hv/\1sub  s, s, hv/' programs/ship_rk4.s >"$T/programs/wrong.s"
grep -q 'sub  s, s, hv' "$T/programs/wrong.s" && ok || bad "programs/ship_rk4.s: no 'add  s, s, hv' to break"

ISS=(--engine iss)

# ---- fp3 run: one object ----------------------------------------------------
form run 0 -- run "${ISS[@]}" --steps 5                                   # the paper's ship
form run 0 -- run --steps 5                                               # RTL: clock cycles
form run 0 -- run "${ISS[@]}" --program programs/ship_rk4.s --steps 5
form run 0 -- run "${ISS[@]}" --program programs/ship_euler.s --steps 1   # one step: no per-step mean
form run 0 -- run "${ISS[@]}" --model models/spring.fp3m --steps 5
form run 0 -- run "${ISS[@]}" --model models/orbit.fp3m --steps 3 --literal   # no exact solution
form run 1 -- run "${ISS[@]}" --model models/spring.fp3m --set h=1e30 --steps 3 # non-finite
form run 1 -- run "${ISS[@]}" --program "$T/fault.s" --steps 3                   # run error
form run 1 -- run "${ISS[@]}" --program "$T/programs/wrong.s" --steps 3          # mismatch

# ---- fp3 run: many objects, model scenes --------------------------------------
form run 0 -- run "${ISS[@]}" --objects 4 --steps 5
form run 0 -- run "${ISS[@]}" --model models/spring.fp3m --objects 3 --seed 2 --round rtz --ftz --steps 5
form run 0 -- run "${ISS[@]}" --scene scenes/springs.scene --steps 5
form run 0 -- run "${ISS[@]}" --scene scenes/fleet.scene --literal --steps 3
form run 0 -- run "${ISS[@]}" --scene scenes/fleet.scene --program programs/ship_rk4.s --steps 3
form run 1 -- run "${ISS[@]}" --model models/spring.fp3m --set h=1e30 --objects 2 --steps 3
form run 1 -- run "${ISS[@]}" --program "$T/fault.s" --objects 3 --steps 3

# ---- fp3 run: ship scenes (five columns) ---------------------------------------
form run 0 -- run "${ISS[@]}" --scene scenes/harbour.scene --steps 5      # the scene compiler
form run 0 -- run --scene scenes/harbour.scene --steps 3                  # RTL
form run 0 -- run "${ISS[@]}" --scene scenes/coast.scene --literal --steps 5
form run 0 -- run "${ISS[@]}" --scene scenes/drift.scene --program programs/ship_euler.s --integrator euler --steps 5
form run 1 -- run "${ISS[@]}" --scene scenes/harbour.scene --program "$T/programs/wrong.s" --steps 3
form run 1 -- run "${ISS[@]}" --scene scenes/harbour.scene --program "$T/fault.s" --integrator euler --steps 3

# ---- fp3 frames ---------------------------------------------------------------
form frames 0 -- frames --harbour 50 --frames 20 "${ISS[@]}"
form frames 0 -- frames --harbour 20 --seed 3 --frames 5 --no-rest-skip --wake 2:3:T=4*C "${ISS[@]}"
form frames 0 -- frames --scene scenes/drift.scene --program programs/ship_euler.s --integrator euler --frames 5 "${ISS[@]}"
form frames 0 -- frames --scene scenes/fleet.scene --frames 20 "${ISS[@]}"
form frames 0 -- frames --scene scenes/springs.scene --frames 5 --literal --no-rest-skip "${ISS[@]}"

# ---- fp3 compile (ship scenes, a model, a model scene) -------------------------------
form compile 0 -- compile scenes/harbour.scene -o "$T/harbour.s"
form compile 0 -- compile scenes/coast.scene -o "$T/coast.s" --literal --integrator euler
form compile 0 -- compile --model models/spring.fp3m -o "$T/spring.s"
form compile 0 -- compile scenes/springs.scene -o "$T/springs.s" --integrator rk2 --literal

# ---- fp3 configure (ship and model scenes) ----------------------------------------
form configure 0 -- configure scenes/harbour.scene
form configure 0 -- configure scenes/springs.scene --integrator rk2
form configure 0 -- configure scenes/fleet.scene --device ecp5-85 --context-per-object

# ---- validate every output, and the negative checks ----------------------------------
# One python3 process; it prints "ok LABEL" or "FAILED: LABEL: reason" a line.
python3 - "$SCHEMA" "$T/manifest" >"$T/verdicts" 2>&1 <<'EOF'
import copy, json, sys
from jsonschema import Draft202012Validator

schema = json.load(open(sys.argv[1]))
try:
    Draft202012Validator.check_schema(schema)
    print("ok the schema is a valid Draft 2020-12 schema")
except Exception as e:
    print(("FAILED: %s is not a valid schema: %s" % (sys.argv[1], e)).replace("\n", " "))
    sys.exit(0)

validators = {}
def validator(kind):
    # the $defs entry as the root's $ref, so the entry's own $refs resolve
    if kind not in validators:
        root = {"$schema": schema["$schema"], "$defs": schema["$defs"], "$ref": "#/$defs/" + kind}
        validators[kind] = Draft202012Validator(root)
    return validators[kind]

def no_constants(name):  # NaN, Infinity, -Infinity are not JSON
    raise ValueError("non-JSON number %s" % name)

def problems(kind, text):
    """The reasons text is not one object of $defs/kind ([] when it is)."""
    try:
        doc = json.loads(text, parse_constant=no_constants)
    except ValueError as e:
        return ["not JSON: %s" % e]
    return ["%s (at /%s)" % (e.message, "/".join(map(str, e.absolute_path)))
            for e in sorted(validator(kind).iter_errors(doc), key=lambda e: list(e.absolute_path))]

samples = {}
for line in open(sys.argv[2]):
    kind, path, label = line.rstrip("\n").split(" ", 2)
    text = open(path).read()
    if text.count("\n") != 1 or not text.endswith("\n"):
        print("FAILED: %s: want one line on stdout, got %d" % (label, text.count("\n")))
        continue
    errs = problems(kind, text)
    if errs:
        print("FAILED: %s: %s" % (label, "; ".join(errs[:5])))
    else:
        print("ok " + label)
        samples.setdefault(kind, json.loads(text))

# Negative checks: each variant of a valid output must be rejected.
def reject(label, kind, doc):
    if kind not in samples:
        print("FAILED: negative check %s: no valid %s output to start from" % (label, kind))
        return
    text = doc if isinstance(doc, str) else json.dumps(doc)
    if problems(kind, text):
        print("ok negative check: " + label)
    else:
        print("FAILED: negative check %s: the schema accepted it" % label)

def without(kind, key):
    d = copy.deepcopy(samples.get(kind, {})); d.pop(key, None); return d

def with_(kind, path, value):
    d = copy.deepcopy(samples.get(kind, {}))
    o = d
    for k in path[:-1]:
        o = o[k]
    o[path[-1]] = value
    return d

if "run" in samples:
    reject("run without cycles_counted", "run", without("run", "cycles_counted"))
    reject("run without results", "run", without("run", "results"))
    reject("run with steps a string", "run", with_("run", ["steps"], "5"))
    reject("run with pass 1", "run", with_("run", ["pass"], 1))
    reject("run with a result value a string", "run", with_("run", ["results", 0, "v"], "0.5"))
    reject("run with run_error a string", "run", with_("run", ["run_error"], "ILLEGAL_INSN"))
    reject("run with an undocumented key", "run", with_("run", ["cycles_total"], 1))
    reject("run with an unknown engine", "run", with_("run", ["engine"], "fpga"))
    reject("run with a NaN token", "run", json.dumps(with_("run", ["max_error_ref"], float("nan"))))
reject("frames without run_error", "frames", without("frames", "run_error"))
reject("frames with cycles_per_frame a string", "frames", with_("frames", ["cycles_per_frame"], "1.5"))
reject("compile without registers", "compile", without("compile", "registers"))
reject("compile with fold a string", "compile", with_("compile", ["fold"], "true"))
reject("configure without modes", "configure", without("configure", "modes"))
reject("configure with NUM_LANES a float", "configure", with_("configure", ["params", "NUM_LANES"], 1.5))
EOF
[ -s "$T/verdicts" ] || bad "the python validator printed nothing"
while IFS= read -r line; do
  case $line in
    ok\ *) ok ;;
    FAILED:*) bad "${line#FAILED: }" ;;
    *) bad "validator: $line" ;;
  esac
done <"$T/verdicts"

echo "test_json: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
