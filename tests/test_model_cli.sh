#!/usr/bin/env bash
# test_model_cli.sh -- `fp3 run --model` and `fp3 compile --model` on the
# shipped models (docs/models.md): a run passes bit-exact on both engines
# with its reference in the JSON; bad input (a syntax error, a missing
# value, an unknown name, a missing unit) exits non-zero with FILE:LINE
# and leaves no output file.  Defaults: every shipped model runs with no
# --set, as the docs' values; --set overrides a default, --set NAME0 is
# state NAME; the values still missing are named in one message.
set -uo pipefail
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-build/fp3}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
check() { if eval "$2"; then echo "PASS: $1"; else echo "FAIL: $1"; fail=1; fi; }
spring="--set h=0.015625 --set k=40 --set c=0.8 --set m=2 --set x=0.5 --set v=-0.25"
for eng in iss rtl; do
  for lit in "" --literal; do
    out=$("$FP3" run --model models/spring.fp3m $spring --steps 300 --engine $eng $lit --json)
    check "spring $eng $lit: pass, x and x_ref" \
      "echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); r=d[\"results\"][0]; \
sys.exit(0 if d[\"pass\"] and d[\"golden_mismatches\"]==0 and abs(r[\"x\"]-r[\"x_ref\"])<1e-5 and \"cycles_per_object_step\" in d else 1)'"
  done
done
out=$("$FP3" run --model models/ship.fp3m --set h=0.0166666675 --set T=50000 --set C=5000 \
      --set m=10000 --set v=0 --set s=0 --steps 600 --engine iss --literal --integrator euler)
check "ship euler literal passes" "grep -q '^PASS' <<<\"\$out\""
printf 'state x\nx'"'"' = x +\n' >"$tmp/bad.fp3m"
err=$("$FP3" run --model "$tmp/bad.fp3m" --set h=1 --set x=1 2>&1); rc=$?
check "syntax error: exit 2, FILE:LINE:COL" "[ $rc -eq 2 ] && grep -q 'bad.fp3m:2:9: expected an expression' <<<\"\$err\""
# defaults (docs/models.md): the model file's values unless --set gives
# others; what has neither is named, all of it in one message, exit 2
printf 'param k, c = 0.5, m\nposition x\nvelocity v = 0\nx'"'"' = v\nv'"'"' = -(k*x + c*v)/m\n' \
  >"$tmp/nd.fp3m"
err=$("$FP3" run --model "$tmp/nd.fp3m" --set m=1 --engine iss 2>&1); rc=$?
want="fp3 run: $tmp/nd.fp3m: no value for the step h, param k (line 1), state variable x (line 2): \
give --set h=VALUE --set k=VALUE --set x=VALUE, or a default in the model file (param h = VALUE)"
check "every missing value in one message, exit 2" "[ $rc -eq 2 ] && [ \"\$err\" = \"\$want\" ]"
err=$("$FP3" run --model "$tmp/nd.fp3m" --set h=0.01 --set k=1 --set m=1 --engine iss 2>&1); rc=$?
check "one missing state: its keyword in the hint" \
  "[ $rc -eq 2 ] && grep -qF 'no value for state variable x (line 2): give --set x=VALUE, or a default in the model file (position x = VALUE)' <<<\"\$err\""
"$FP3" run --model "$tmp/nd.fp3m" --set h=0.01 --set k=1 --set m=1 --set x0=1 --engine iss --steps 5 >/dev/null 2>&1
check "--set x0= gives state x's initial value" "[ $? -eq 0 ]"
json() { "$FP3" run "$@" --engine iss --steps 20 --json 2>/dev/null | python3 -c \
  'import json,sys; d=json.load(sys.stdin); assert d["pass"]; print(json.dumps(d["results"]))'; }
def=$(json --model models/spring.fp3m)
check "spring with no --set: the defaults are the docs' values" \
  "[ -n \"\$def\" ] && [ \"\$def\" = \"\$(json --model models/spring.fp3m $spring)\" ]"
check "--set k=41 overrides the default k = 40" \
  "over=\$(json --model models/spring.fp3m --set k=41) && [ -n \"\$over\" ] && [ \"\$over\" != \"\$def\" ] && \
   [ \"\$over\" = \"\$(json --model models/spring.fp3m $spring --set k=41)\" ]"
check "--set x0=0.25 is --set x=0.25" \
  "a0=\$(json --model models/spring.fp3m --set x0=0.25) && [ -n \"\$a0\" ] && [ \"\$a0\" != \"\$def\" ] && \
   [ \"\$a0\" = \"\$(json --model models/spring.fp3m --set x=0.25)\" ]"
check "ship: --set v0=1 --set s0=0 as the ship program takes them" \
  "v1=\$(json --model models/ship.fp3m --set v0=1 --set s0=0) && [ -n \"\$v1\" ] && \
   [ \"\$v1\" = \"\$(json --model models/ship.fp3m --set v=1)\" ] && [ \"\$v1\" != \"\$(json --model models/ship.fp3m)\" ]"
check "ship with no --set is the paper's default scene" \
  "[ \"\$(json --model models/ship.fp3m)\" = \"\$(json --model models/ship.fp3m --set h=0.0166666675 \
     --set T=50000 --set C=5000 --set m=10000 --set v=0 --set s=0)\" ]"
out=$("$FP3" run --model models/spring.fp3m --objects 64 --steps 20 2>&1); rc=$?
check "fp3 run --model models/spring.fp3m --objects 64 --steps 20: no --set, passes" \
  "[ $rc -eq 0 ] && grep -q '^PASS' <<<\"\$out\""
for f in models/*.fp3m; do
  integ=rk4; [ "$f" = models/rigidbody.fp3m ] && integ=rk2 # its rk4 exceeds IMEM_DEPTH
  "$FP3" run --model "$f" --integrator $integ --engine iss --steps 20 >/dev/null 2>&1 && \
    "$FP3" run --model "$f" --integrator $integ --engine iss --steps 20 --objects 64 >/dev/null 2>&1
  check "$f $integ: one object and --objects 64 with no --set" "[ $? -eq 0 ]"
done
err=$("$FP3" run --model models/spring.fp3m $spring --set q=1 2>&1); rc=$?
check "unknown --set name" "[ $rc -eq 2 ] && grep -q \"no param or state 'q'\" <<<\"\$err\""
if ! printf 'sqrt r1, r2\nhalt\n' | "$FP3" asm /dev/stdin -o "$tmp/x.hex" >/dev/null 2>&1; then
  err=$("$FP3" compile --model models/projectile.fp3m -o "$tmp/p.s" 2>&1); rc=$?
  check "projectile refused naming HAS_SQRT, no file" \
    "[ $rc -eq 2 ] && grep -q 'needs sqrt: this build has no HAS_SQRT unit' <<<\"\$err\" && [ ! -e $tmp/p.s ]"
else
  proj="--set h=0.015625 --set kd=0.002 --set g=9.81 --set x=0 --set y=2 --set z=0 --set vx=30 --set vy=40 --set vz=-5"
  out=$("$FP3" run --model models/projectile.fp3m $proj --integrator euler --steps 50 2>&1); rc=$?
  check "projectile on the RTL (its sqrt on the div/sqrt unit): bit-exact with its golden model" \
    "[ $rc -eq 0 ] && grep -q '^PASS' <<<\"\$out\""
  "$FP3" run --model models/projectile.fp3m $proj --integrator euler --steps 50 --engine iss >/dev/null 2>&1
  check "projectile on the ISS: bit-exact with its golden model" "[ $? -eq 0 ]"
fi
# registers: folded rk4 of the 3-D spring needs 33 (no spilling); the ISS
# runs it as a build with NUM_REGS=33, a 32-register RTL refuses it with
# the numbers; its literal rk4 fits 32 (bounded register pressure)
s3="--set h=0.015625 --set k=30 --set L=1 --set m=1.5 --set x=1.5 --set y=0.2 --set z=-0.3 --set vx=0 --set vy=0.8 --set vz=0.1"
out=$("$FP3" run --model models/spring3d.fp3m $s3 --steps 100 --engine iss --json 2>"$tmp/err"); rc=$?
check "spring3d rk4 folded on the ISS: NUM_REGS=33, bit-exact" \
  "[ $rc -eq 0 ] && grep -q 'ISS runs it as a build with NUM_REGS=33' $tmp/err && \
   echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if d[\"pass\"] and d[\"num_regs\"]==33 and d[\"registers_needed\"]==33 else 1)'"
out=$("$FP3" run --model models/spring3d.fp3m $s3 --steps 100 --engine iss --literal --json 2>&1)
check "spring3d rk4 literal on the ISS: 32 registers, bit-exact" \
  "echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if d[\"pass\"] and d[\"num_regs\"]==32 and d[\"registers_needed\"]<=32 else 1)'"
err=$("$FP3" run --model models/spring3d.fp3m $s3 --steps 100 --engine rtl 2>&1); rc=$?
check "spring3d rk4 folded on a 32-register RTL: refused with the numbers" \
  "[ $rc -eq 2 ] && grep -q 'the program needs 33 registers; NUM_REGS is 32' <<<\"\$err\""
"$FP3" compile --model models/spring3d.fp3m -o "$tmp/s3.s" 2>/dev/null
check "compile --model for 33 registers: .regs 33" "grep -q '^.regs 33$' $tmp/s3.s"
# rk4comp: RK4 with Kahan-compensated updates, a compensation carried per
# state variable; bit-exact on both engines; frame by frame, the golden
# model steps each object from its state and compensations (a golden model
# that restarted the compensations at 0 fails the springs within frames),
# and an object rests when both come back bit-identical: the moored ships
for eng in iss rtl; do
  out=$("$FP3" run --model models/spring.fp3m $spring --steps 300 --engine $eng --integrator rk4comp --json)
  check "spring rk4comp $eng: pass" \
    "echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if d[\"pass\"] and d[\"golden_mismatches\"]==0 else 1)'"
  out=$("$FP3" frames --scene scenes/springs.scene --integrator rk4comp --frames 20 --engine $eng --json)
  check "frames rk4comp $eng: the springs, every frame bit-exact, none at rest" \
    "echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if d[\"pass\"] and d[\"object_frames_skipped\"]==0 and d[\"object_frames_run\"]==24*20 else 1)'"
done
# ... so does the ship's harbour compiled for rk4comp; the hand-written
# ship_rk4comp.s keeps them where nothing binds them: refused, saying so
out=$("$FP3" frames --harbour 20 --integrator rk4comp --frames 30 --engine iss --json)
check "frames --harbour rk4comp (compiled): every frame bit-exact" \
  "echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if d[\"pass\"] and d[\"woken\"]==0 else 1)'"
err=$("$FP3" frames --harbour 20 --program programs/ship_rk4comp.s --frames 3 2>&1); rc=$?
check "frames refuses ship_rk4comp.s: its compensations have no register the host reads" \
  "[ $rc -eq 2 ] && grep -q 'binds no register for value 2' <<<\"\$err\" && grep -q 'integrator rk4secomp' <<<\"\$err\""
out=$("$FP3" frames --scene scenes/fleet.scene --integrator rk4comp --frames 30 --json)
check "frames rk4comp: the 12 moored ships rest, every frame bit-exact" \
  "echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if d[\"pass\"] and d[\"asleep_at_end\"]==12 and d[\"object_frames_skipped\"]>0 else 1)'"
"$FP3" compile --model models/spring.fp3m --literal -o "$tmp/s.s" 2>/dev/null
check "compile --model writes the program" "grep -q 'model spring' $tmp/s.s && grep -q endi $tmp/s.s"
[ $fail -eq 0 ]
