#!/usr/bin/env bash
# test_cli.sh -- the command line build/fp3: error handling, exit codes,
# --help, and a short run on the instruction-set simulator.
#
# Runs from anywhere; the CLI is $FP3_BIN (set by mk/sw.mk), else
# build/fp3 of this checkout.  Exit status non-zero if any check fails.
set -u
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
if [ ! -x "$FP3" ]; then
  echo "test_cli: $FP3 not built (make $FP3)"; exit 1
fi
T=$(mktemp -d /tmp/fp3_test_cli.XXXXXX)
trap 'rm -rf "$T"' EXIT

pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

# expect STATUS GREP-PATTERN -- fp3 ARGS...: exit status and a pattern in
# stdout+stderr (an empty pattern matches anything).
expect() {
  local want=$1 pat=$2; shift 3
  local out rc
  out=$("$FP3" "$@" 2>&1); rc=$?
  if [ "$want" = "nz" ]; then [ "$rc" -ne 0 ] || { bad "fp3 $* exited 0, want non-zero"; return; }
  elif [ "$rc" -ne "$want" ]; then bad "fp3 $*: exit $rc, want $want; output: $(echo "$out" | head -5)"; return; fi
  if [ -n "$pat" ] && ! grep -q -- "$pat" <<<"$out"; then
    bad "fp3 $*: output lacks '$pat': $(echo "$out" | head -5)"; return
  fi
  ok
}

ISS=(run --engine iss)

# ---- a program with div: the default build runs it on its div/sqrt unit ----
# (not the ship any more: its golden model disagrees, exit 1), every step as
# the ISS computes it.  A build without HAS_DIV refuses it before running,
# naming HAS_DIV: tests/test_engines.c (test_new_ops_or_refusal).
sed 's/mul  a, F, minv/div  a, F, minv/; s|"ship_scene.inc"|"'"$PWD"'/programs/ship_scene.inc"|' \
  programs/ship_euler.s > "$T/div.s"
expect 1 "golden model: 19 mismatches in 10 integrations" -- run --program "$T/div.s" --integrator euler --steps 10
div_rtl=$("$FP3" run --program "$T/div.s" --integrator euler --steps 10 2>&1 | grep -E '^ +[0-9]+ ')
div_iss=$("$FP3" run --engine iss --program "$T/div.s" --integrator euler --steps 10 2>&1 | grep -E '^ +[0-9]+ ')
[ -n "$div_rtl" ] && [ "$div_rtl" = "$div_iss" ] && ok || bad "div program: RTL and ISS steps differ"

# ---- --help of every command ------------------------------------------------
expect 0 "usage: fp3 COMMAND" -- --help
expect 0 "usage: fp3 COMMAND" -- help
expect 0 "usage: fp3 asm"     -- asm --help
expect 0 "usage: fp3 disasm"  -- disasm --help
expect 0 "usage: fp3 run"     -- run --help
expect 0 ""                   -- testfloat --help
expect 2 "usage"              --
expect 2 "unknown command 'frobnicate'" -- frobnicate
expect 2 "unknown option '--bogus'"     -- asm --bogus x.s
expect 2 "unknown option '-x'"          -- disasm -x
expect 2 "more than one input file ('b.s')" -- asm a.s b.s
expect 2 "more than one scene ('b.scene')"  -- configure a.scene b.scene
expect 2 "more than one program ('b.s')"    -- tbgen a.s b.s -o x
expect 2 "unknown argument '--bogus'"   -- run --bogus
expect 2 "unknown engine 'gpu'"         -- run --engine gpu
expect 2 "needs a value"                -- run --steps
expect 2 "no input file"                -- asm
expect 2 "no input file"                -- disasm

# ---- missing files -----------------------------------------------------------
expect 2 "$T/missing.s"   -- asm "$T/missing.s" -o "$T/missing.hex"
[ ! -e "$T/missing.hex" ] && ok || bad "asm of a missing file left an output"
expect 2 "$T/missing.hex" -- disasm "$T/missing.hex"
expect 2 "$T/missing.s"   -- "${ISS[@]}" --program "$T/missing.s" --steps 10

# ---- malformed assembly: FILE:LINE, every error, no output -----------------------
cat >"$T/bad.s" <<'EOF'
; two errors
        li   r1, 1.0
        frob r1, r2
        add  r1, r2, r77
        endi nowhere
EOF
expect 2 "$T/bad.s:3: unknown mnemonic 'frob'" -- asm "$T/bad.s" -o "$T/bad.hex"
expect 2 "$T/bad.s:4: register out of range"   -- asm "$T/bad.s" -o "$T/bad.hex"
expect 2 "$T/bad.s:5: undefined label"         -- asm "$T/bad.s" -o "$T/bad.hex"
[ ! -e "$T/bad.hex" ] && [ ! -e "$T/bad.hex.tmp" ] && ok || bad "failed asm left $T/bad.hex"
expect 2 "$T/bad.s:3:" -- "${ISS[@]}" --program "$T/bad.s" --steps 1
# output into a missing directory
expect 1 "$T/nodir/x.hex" -- asm programs/ship_rk4.s -o "$T/nodir/x.hex"
[ ! -e "$T/nodir" ] && ok || bad "asm into a missing directory created something"

# a program that cannot end: empty, or no endi / halt (the PC would run off)
: > "$T/empty.s"
expect 2 "$T/empty.s: no instructions" -- asm "$T/empty.s" -o "$T/empty.hex"
[ ! -e "$T/empty.hex" ] && ok || bad "asm of an empty program left $T/empty.hex"
printf 'start:\n  add r1, r1, r2\n  mov r3, r1\n' > "$T/noend.s"
expect 2 "$T/noend.s: no 'endi' or 'halt'" -- asm "$T/noend.s" -o "$T/noend.hex"
[ ! -e "$T/noend.hex" ] && ok || bad "asm of an endless program left $T/noend.hex"
expect 2 "$T/noend.s: no 'endi' or 'halt'" -- "${ISS[@]}" --program "$T/noend.s" --steps 1

# ---- bad parameters: clear message, exit 2 ---------------------------------------
# (a model states no ranges: a value its equations cannot take, m = 0 here,
# shows as a state that is not finite, named with its integration, exit 1)
expect 1 "NON-FINITE: state variable v is not finite after integration 1" -- "${ISS[@]}" --set m=0
expect 2 "the step must be above 0"      -- "${ISS[@]}" --set h=0
expect 2 "the step must be above 0"      -- "${ISS[@]}" --set h=-0.1
expect 2 "set T: 'nan' is not a finite number"  -- "${ISS[@]}" --set T=nan
expect 2 "set v0: 'inf' is not a finite number" -- "${ISS[@]}" --set v0=inf
expect 2 "set s0: '1e39' is not a finite number" -- "${ISS[@]}" --set s0=1e39
expect 2 "has no param or state 'mass'"  -- "${ISS[@]}" --set mass=3
expect 2 "has no param or state 'minv'"  -- "${ISS[@]}" --set minv=3
expect 2 "wants NAME=VALUE"              -- "${ISS[@]}" --set m
expect 2 "'ten' is not a finite number"  -- "${ISS[@]}" --set m=ten
expect 2 "'' is not a finite number"     -- "${ISS[@]}" --set m=
expect 2 "want 1..4294967295 integrations" -- "${ISS[@]}" --steps 0
expect 2 "--steps 'abc': want 1..4294967295" -- "${ISS[@]}" --steps abc
expect 2 "--steps '-5': want 1.."        -- "${ISS[@]}" --steps -5
expect 2 "--steps '10x': want 1.."       -- "${ISS[@]}" --steps 10x
expect 2 "want 1..4294967295 integrations" -- "${ISS[@]}" --steps 4294967296
expect 2 "needs --engine rtl"            -- "${ISS[@]}" --trace "$T/x.vcd"
# a trace file that cannot be created: its name and the system's reason
expect 2 "trace file $T/nodir/x.vcd ($T/nodir: No such file or directory)" -- \
  run --trace "$T/nodir/x.vcd" --steps 1

# ---- a program without results to check --------------------------------------------
printf 'b: nop\n   endi b\n' >"$T/nointeg.s"
expect 2 "nointeg.s: no \`.integrator NAME\` line" -- "${ISS[@]}" --program "$T/nointeg.s" --steps 2
printf '.integrator euler\nb: nop\n   endi b\n' >"$T/noout.s"
expect 2 "no \`.out v, rN\`: state variable v of model ship" -- "${ISS[@]}" --program "$T/noout.s" --steps 2
printf '.integrator euler\n.in mass, r1\n.out v, r2\n.out s, r3\nb: nop\n   endi b\n' >"$T/badin.s"
expect 2 "badin.s:2: .in mass: model ship" -- "${ISS[@]}" --program "$T/badin.s" --steps 2
printf '.integrator euler\n.model "%s/models/spring.fp3m"\nb: nop\n   endi b\n' "$PWD" >"$T/other.s"
expect 2 "is a program of .*spring.fp3m (its .model line), not of" -- "${ISS[@]}" --program "$T/other.s" --model models/ship.fp3m

# ---- a program that faults: FAIL, exit 1 ---------------------------------------------
cp tests/data/fault.s "$T/fault.s"   # ILLEGAL_INSN at pc 1
expect 1 "FAIL: run error ILLEGAL_INSN" -- "${ISS[@]}" --program "$T/fault.s" --steps 3
expect 1 "at pc 1"                     -- "${ISS[@]}" --program "$T/fault.s" --steps 3

# ---- a program that computes something else: golden mismatches, exit 1 ----------------
cp programs/*.inc "$T/"   # the files the ship programs include
sed 's/^\( *\)add  s, s, hv/\1sub  s, s, hv/' programs/ship_rk4.s >"$T/wrong.s"
expect 2 "wrong.s: its .model line names .*models/ship.fp3m: .*--model FILE names the model" \
  -- "${ISS[@]}" --program "$T/wrong.s" --steps 20
expect 1 "FAIL: .* golden mismatches, first at integration 1" -- "${ISS[@]}" --program "$T/wrong.s" \
  --model models/ship.fp3m --steps 20

# ---- things that work ---------------------------------------------------------------
expect 0 "PASS: 200 integrations on iss bit-exact" -- "${ISS[@]}" --steps 200
expect 0 "PASS" -- "${ISS[@]}" --steps 50 --set C=0 --set m=2 --set=h=0.001 --set v0=-3
expect 0 "cycles: first integration 34 (paper 445), later 31.00" -- "${ISS[@]}" --steps 3
expect 0 "" -- asm programs/ship_rk4.s -o "$T/ship.hex"
[ -f "$T/ship.hex" ] && [ ! -e "$T/ship.hex.tmp" ] && ok || bad "asm wrote no $T/ship.hex"
grep -q '^// .in minv r' "$T/ship.hex" && ok || bad "ship.hex lacks the .in comments"
expect 0 "" -- disasm "$T/ship.hex"
"$FP3" disasm "$T/ship.hex" >"$T/round.s" 2>&1 && ok || bad "disasm failed"
expect 0 "" -- asm "$T/round.s" -o "$T/round.hex"
if diff <(grep -v '^//' "$T/ship.hex" | cut -c1-16) <(grep -v '^//' "$T/round.hex" | cut -c1-16) >/dev/null; then ok
else bad "disasm | asm does not give the same words"; fi
# an image with unknown opcode bits and a nonzero unused field: listed, reported, exit 1
printf '0F00000000000000\n0100000000000001\n0700000000000000\n' > "$T/bad.hex"
expect 1 "bad.hex: word 0 (0x0f00000000000000): illegal instruction: unknown opcode" -- disasm "$T/bad.hex"
expect 1 "word 1 (0x0100000000000001): illegal instruction: imm field" -- disasm "$T/bad.hex"
# default output name
cp programs/ship_rk4.s "$T/def.s"
expect 0 "" -- asm "$T/def.s"
[ -f "$T/def.hex" ] && ok || bad "asm without -o wrote no $T/def.hex"

# --json: one valid JSON object with the required keys
json=$("$FP3" "${ISS[@]}" --steps 100 --json 2>&1); rc=$?
[ "$rc" -eq 0 ] && ok || bad "run --json exit $rc"
if command -v python3 >/dev/null; then
  if python3 - "$json" <<'EOF'
import json, sys
d = json.loads(sys.argv[1])
for k in ("engine", "program", "steps", "cycles", "cycles_first_step",
          "cycles_per_object_step", "golden_mismatches", "flags", "results"):
    assert k in d, k
assert d["engine"] == "iss" and d["steps"] == 100 and d["golden_mismatches"] == 0
r = d["results"][0]
for k in ("v", "s", "v_exact", "s_exact"):
    assert k in r, k
assert abs(r["v"] - r["v_exact"]) < 1e-4
EOF
  then ok; else bad "run --json output is not the expected JSON: $json"; fi
fi

# ---- many objects: scenes ---------------------------------------------------
cat > "$T/harbour.scene" <<'EOF'
# a small harbour
h 0.0166666675
# T       C      m        v0    s0
50000     5000   10000    0     0
0         300    5000     12.5  100    # coasting
2000      0      1000     1     -5     # no drag
-30       12     0.75     4     0
0         0      2e6      0     0      # moored
EOF
expect 0 "PASS: 5 objects" -- run --scene "$T/harbour.scene" --steps 300
expect 0 "PASS: 5 objects" -- "${ISS[@]}" --scene "$T/harbour.scene" --steps 300
expect 0 "PASS: 40 objects" -- run --objects 40 --seed 7 --steps 100
printf '1 2 3 4\n' > "$T/short.scene"
expect 2 "short.scene:1: expected 5 numbers" -- run --scene "$T/short.scene"
printf '# ok\n1 2 3 4 5\n1 2 0 4 5\n' > "$T/mass.scene"
expect 2 "mass.scene:3: parameter m = 0" -- run --scene "$T/mass.scene"
printf '1 -2 3 4 5\n' > "$T/drag.scene"
expect 2 "drag.scene:1: parameter C = -2" -- run --scene "$T/drag.scene"
printf '1 2 3 nan 5\n' > "$T/nan.scene"
expect 2 "nan.scene:1: parameter v0" -- run --scene "$T/nan.scene"
printf '1 2 3 4 5 6\n' > "$T/long.scene"
expect 2 "long.scene:1: more than 5 numbers" -- run --scene "$T/long.scene"
printf '1 2 3 4 5\nh 0.1\n' > "$T/lateh.scene"
expect 2 "lateh.scene:2: 'h' must come before" -- run --scene "$T/lateh.scene"
printf '# no step\n1 2 3 4 5\n1 2 3 4 5\n' > "$T/noh.scene"
expect 2 "noh.scene:2: no 'h STEP' line" -- run --scene "$T/noh.scene"
printf 'h 0.1\nh 0.2\n1 2 3 4 5\n' > "$T/twoh.scene"
expect 2 "twoh.scene:2: a second 'h' line" -- run --scene "$T/twoh.scene"
printf '# nothing\n' > "$T/empty.scene"
expect 2 "no objects" -- run --scene "$T/empty.scene"
expect 2 "No such file" -- run --scene "$T/missing.scene"
expect 2 "want 1..1000000 objects" -- run --objects 0
expect 2 "want 1..1000000 objects" -- run --objects 1000001
expect 2 "seed goes with" -- run --seed 3
# counts and seeds: one parser (cliopt.c), one message
expect 2 "--seed 'x1': want an unsigned 64-bit integer" -- run --objects 2 --seed x1
expect 2 "--seed '-3': want an unsigned 64-bit integer" -- frames --seed -3
expect 2 "--points '25': want 1..24" -- bench --points 25
expect 2 "--trace-window '5': want FIRST:COUNT" -- run --engine iss --trace-window 5
expect 2 "has 5 objects" -- run --scene "$T/harbour.scene" --objects 4
json=$("$FP3" run --scene "$T/harbour.scene" --steps 50 --json 2>&1); rc=$?
[ "$rc" -eq 0 ] && ok || bad "run --scene --json exit $rc"
if python3 - "$json" <<'EOF'
import json, sys
d = json.loads(sys.argv[1])
assert d["objects"] == 5 and len(d["results"]) == 5, d
assert d["golden_mismatches"] == 0 and d["run_error"] is None and d["pass"]
assert d["cycles_per_object_step"] > 0 and "utilization" in d
moored = d["results"][4]
assert moored["v"] == 0 and moored["s"] == 0          # at rest stays at rest
assert abs(d["results"][0]["v"] - d["results"][0]["v_exact"]) < 1e-3
EOF
then ok; else bad "run --scene --json output: $json"; fi

# ---- the scene compiler: fp3 compile, fp3 run --scene compiles ------------------------
expect 0 "usage: fp3 compile" -- compile --help
expect 0 "rk4se folded: 22 instructions per integration (literal program 31)" -- compile "$T/harbour.scene" -o "$T/harbour.s"
[ -f "$T/harbour.s" ] && ! ls "$T"/harbour.s.tmp* >/dev/null 2>&1 && ok || bad "compile -o wrote no $T/harbour.s"
grep -q '^;   hv_0 .*(host: hv_0 = .* \* T)' "$T/harbour.s" && grep -q '^; instructions per integration: 22' "$T/harbour.s" \
  && ok || bad "the compiled program lacks its host input (h minv) T or its header"
expect 0 "" -- asm "$T/harbour.s" -o "$T/harbour.hex"
expect 0 "instructions per integration: 31" -- compile "$T/harbour.scene" --literal
printf 'h 0.01\n2000 0 1000 1 -5\n50 0 10 0 0\n' > "$T/nodrag.scene"
expect 0 "4 instructions per integration .*zero in every object: C$" -- compile "$T/nodrag.scene"
json=$("$FP3" compile "$T/nodrag.scene" --integrator euler -o "$T/nodrag.s" --json 2>&1)
python3 -c 'import json,sys; d=json.loads(sys.argv[1]); assert d["params_zero"] == ["C"] and d["insns_per_step"] <= d["literal_insns_per_step"], d' "$json" \
  && ok || bad "compile --json: $json"
expect 2 "unknown integrator 'leapfrog'" -- compile "$T/harbour.scene" --integrator leapfrog -o "$T/x.s"
expect 2 "short.scene:1: expected 5 numbers" -- compile "$T/short.scene" -o "$T/x.s"
expect 2 "mass.scene:3: parameter m = 0" -- compile "$T/mass.scene"
expect 2 "No such file" -- compile "$T/missing.scene"
expect 2 "no scene file" -- compile
expect 2 "unknown option '--bogus'" -- compile "$T/harbour.scene" --bogus
expect 2 "want 1..64 cycles" -- compile "$T/harbour.scene" --add-latency 0
# the build for clock rate (FMAX_PIPE=1, add 9, mul 10): the literal rk4's
# cycles of one ship as the RTL counts them (docs/fpga.md "Devices and Fmax")
expect 0 "estimated 275 cycles per later integration of one object (first 296)" -- compile "$T/harbour.scene" \
  --literal --fmax-pipe --add-latency 9 --mul-latency 10
expect 2 "FMAX_PIPE needs add and mul latencies of at least 3" -- compile "$T/harbour.scene" \
  --fmax-pipe --mul-latency 2
expect 2 "needs -o" -- compile "$T/harbour.scene" --json
[ ! -e "$T/x.s" ] && ok || bad "a failed compile left $T/x.s"
expect 1 "$T/nodir/p.s" -- compile "$T/harbour.scene" -o "$T/nodir/p.s"
[ ! -e "$T/nodir" ] && ok || bad "compile into a missing directory created something"
mkdir "$T/ro" && chmod 555 "$T/ro"
if [ ! -w "$T/ro" ]; then   # (root writes anyway)
  expect 1 "$T/ro/p.s" -- compile "$T/harbour.scene" -o "$T/ro/p.s"
  [ -z "$(ls -A "$T/ro")" ] && ok || bad "compile into a read-only directory left a file"
fi
chmod 755 "$T/ro"
# run --scene: compiled by default, checked against the IR golden model
expect 0 "PASS: 5 objects x 300 integrations on iss bit-exact" -- "${ISS[@]}" --scene "$T/harbour.scene" --steps 300
expect 0 "program: 22 instructions per integration (literal program 31)" -- "${ISS[@]}" --scene "$T/harbour.scene" --steps 10
expect 0 "program: 31 instructions per integration" -- "${ISS[@]}" --scene "$T/harbour.scene" --steps 10 --literal
expect 0 "PASS: 2 objects x 500 integrations on iss" -- "${ISS[@]}" --scene "$T/nodrag.scene" --steps 500 --integrator rk2
expect 0 "PASS: 24 objects" -- "${ISS[@]}" --objects 24 --seed 3 --steps 100 --integrator symeuler
expect 2 "whose verlet is the model integrator verletp" -- "${ISS[@]}" --scene "$T/harbour.scene" --integrator verlet
expect 0 "PASS" -- "${ISS[@]}" --scene "$T/harbour.scene" --integrator verletp --literal --steps 20
expect 2 "--compile is gone" -- "${ISS[@]}" --scene "$T/harbour.scene" --literal --compile
expect 2 "--compile is gone" -- "${ISS[@]}" --compile
json=$("$FP3" run --scene "$T/harbour.scene" --steps 100 --json 2>&1); rc=$?
[ "$rc" -eq 0 ] && ok || bad "run --scene (rtl, compiled) exit $rc"
python3 - "$json" <<'EOF2' && ok || bad "run --scene (rtl, compiled) --json: $json"
import json, sys
d = json.loads(sys.argv[1])
assert d["engine"] == "rtl" and not d["literal"] and d["golden_mismatches"] == 0, d
assert d["insns_per_step"] < d["literal_insns_per_step"] and d["cycles_per_object_step"] > 0, d
EOF2

# ---- fp3 configure: RTL parameters sized to the scene ------------------------------
expect 0 "usage: fp3 configure" -- configure --help
expect 0 "^NUM_CONTEXTS=4 NUM_LANES=2 NUM_REGS=11 HAS_ADD=1 HAS_SUB=0 HAS_MUL=1 HAS_DIV=0 HAS_SQRT=0 HAS_SIGN=0 ROUND=1 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=4 WB_PORTS=1$" -- configure scenes/drift.scene
expect 0 "HAS_SUB=0 *the program has no sub" -- configure scenes/drift.scene
expect 0 "^NUM_CONTEXTS=5 NUM_LANES=7 NUM_REGS=12 HAS_ADD=1 HAS_SUB=1 HAS_MUL=1 HAS_DIV=0 HAS_SQRT=0 HAS_SIGN=0 ROUND=1 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=4 WB_PORTS=1$" -- configure scenes/harbour.scene
expect 0 "WB_PORTS=1 *one write-back port a lane .no live value table.: the program has no div or sqrt" -- configure scenes/harbour.scene
expect 0 "^NUM_CONTEXTS=4 NUM_LANES=8 NUM_REGS=12 .* ADD_LATENCY=4 MUL_LATENCY=3 WB_PORTS=4$" -- configure scenes/harbour.scene --wb-ports 4
expect 0 "WB_PORTS=4 *four write-back ports .--wb-ports 4." -- configure scenes/harbour.scene --wb-ports 4
expect 2 "--wb-ports '2': want 1 or 4" -- configure scenes/harbour.scene --wb-ports 2
expect 0 "^NUM_CONTEXTS=5 NUM_LANES=3 " -- configure scenes/harbour.scene --max-lanes 3
expect 2 "--max-lanes .0.: want 1..64" -- configure scenes/harbour.scene --max-lanes 0
expect 2 "--max-lanes .65.: want 1..64" -- configure scenes/harbour.scene --max-lanes 65
expect 0 "^NUM_CONTEXTS=32 NUM_LANES=1 NUM_REGS=12 " -- configure scenes/harbour.scene --context-per-object
expect 0 "^NUM_CONTEXTS=5 NUM_LANES=6 NUM_REGS=12 " -- configure scenes/harbour.scene --device ecp5-45
expect 0 "the LFE5U-45F holds 6: LUT4s .routing." -- configure scenes/harbour.scene --device ecp5-45
expect 0 "lane model .1 write-back port.: 10281 fixed" -- configure scenes/harbour.scene --device ecp5-45
expect 0 "\"device_max_lanes\": 3, \"device_limit\": \"LUT4s .routing.\"" -- configure scenes/harbour.scene --device ecp5-45 --wb-ports 4 --json
expect 2 "--device 'ecp5-99': unknown device .known: ecp5-25, ecp5-45, ecp5-85." -- configure scenes/harbour.scene --device ecp5-99
expect 0 "^NUM_CONTEXTS=5 NUM_LANES=2 " -- configure scenes/harbour.scene --device ecp5-25
expect 2 "the LFE5U-25F .ecp5-25. does not hold one lane of this build" -- configure scenes/harbour.scene --device ecp5-25 --wb-ports 4
expect 0 "^NUM_CONTEXTS=3 NUM_LANES=11 NUM_REGS=7 " -- configure scenes/harbour.scene --integrator euler
expect 0 "ROUND=0 FTZ=1 ADD_LATENCY" -- configure scenes/harbour.scene --error-budget 1e-9
expect 0 "<- chosen" -- configure "$T/harbour.scene" --literal --steps 50
out=$("$FP3" configure scenes/drift.scene -o "$T/drift.params" 2>/dev/null); rc=$?
[ "$rc" -eq 0 ] && [ -z "$out" ] && [ "$(cat "$T/drift.params")" = \
  "NUM_CONTEXTS=4 NUM_LANES=2 NUM_REGS=11 HAS_ADD=1 HAS_SUB=0 HAS_MUL=1 HAS_DIV=0 HAS_SQRT=0 HAS_SIGN=0 ROUND=1 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=4 WB_PORTS=1" ] \
  && ! ls "$T"/drift.params.tmp* >/dev/null 2>&1 && ok || bad "configure -o: rc $rc, '$out', $(cat "$T/drift.params")"
json=$("$FP3" configure scenes/drift.scene --json 2>/dev/null)
python3 - "$json" <<'EOF2' && ok || bad "configure --json: $json"
import json, sys
d = json.loads(sys.argv[1])
assert d["params"] == {"NUM_CONTEXTS": 4, "NUM_LANES": 2, "NUM_REGS": 11, "HAS_ADD": 1, "HAS_SUB": 0,
                       "HAS_MUL": 1, "HAS_DIV": 0, "HAS_SQRT": 0, "HAS_SIGN": 0,
                       "ROUND": 1, "FTZ": 1, "ADD_LATENCY": 4, "MUL_LATENCY": 4, "WB_PORTS": 1}, d
assert d["unit_pc"]["sub"] is None and d["chosen_mode"] == "RTZ+FTZ" and len(d["modes"]) == 4, d
assert d["modes"][0]["allowed"] and d["modes"][0]["added_error"] == 0, d
EOF2
# bad input: nothing written, an existing output untouched
echo keep > "$T/keep.params"
expect 2 "unknown integrator 'leapfrog'" -- configure scenes/drift.scene --integrator leapfrog -o "$T/keep.params"
expect 2 "short.scene:1: expected 5 numbers" -- configure "$T/short.scene" -o "$T/keep.params"
expect 2 "mass.scene:3: parameter m = 0" -- configure "$T/mass.scene"
expect 2 "no objects" -- configure "$T/empty.scene"
expect 2 "No such file" -- configure "$T/missing.scene"
expect 2 "error-budget '0'" -- configure scenes/drift.scene --error-budget 0
expect 2 "error-budget '-1e-4'" -- configure scenes/drift.scene --error-budget -1e-4
expect 2 "error-budget 'nan'" -- configure scenes/drift.scene --error-budget nan
expect 2 "error-budget 'x'" -- configure scenes/drift.scene --error-budget x -o "$T/keep.params"
expect 2 "want 1..10000000 integrations" -- configure scenes/drift.scene --steps 0
expect 2 "no scene file" -- configure
expect 2 "unknown option '--bogus'" -- configure scenes/drift.scene --bogus
[ "$(cat "$T/keep.params")" = keep ] && ok || bad "a failed configure changed its -o file"
expect 1 "$T/nodir/p.params" -- configure scenes/drift.scene -o "$T/nodir/p.params"
[ ! -e "$T/nodir" ] && ok || bad "configure into a missing directory created something"
mkdir "$T/adir"
expect 1 "$T/adir" -- configure scenes/drift.scene -o "$T/adir"
[ -z "$(ls -A "$T/adir")" ] && ! ls "$T"/adir.tmp* >/dev/null 2>&1 && ok \
  || bad "configure -o onto a directory left a temporary file"

# ---- fp3 frames: sleeping objects -------------------------------------------------
expect 0 "usage: fp3 frames" -- frames --help
expect 0 "golden model: bit-identical" -- frames --engine iss --harbour 20 --frames 30 --wake 10:2:T=4*C
expect 0 '"pass": true' -- frames --engine iss --scene scenes/harbour.scene --frames 20 --json
expect 2 "frames '0'" -- frames --frames 0
expect 2 "harbour '-3'" -- frames --harbour -3
expect 2 "want FRAME:COUNT" -- frames --wake 5
expect 2 "want FRAME:COUNT:..., FRAME 1.." -- frames --wake 0:2:T=1
expect 2 "fmax 'x'" -- frames --fmax x
expect 2 "unknown integrator 'leapfrog'" -- frames --integrator leapfrog
expect 2 "engine 'gpu'" -- frames --engine gpu
expect 2 "mass.scene:3: parameter m = 0" -- frames --scene "$T/mass.scene"
expect 2 "No such file" -- frames --program "$T/missing.s"
expect 2 "unknown argument '--bogus'" -- frames --bogus

echo "test_cli: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
