#!/usr/bin/env bash
# test_model_cli.sh -- `fp3 run --model` and `fp3 compile --model` on the
# shipped models (docs/models.md): a run passes bit-exact on both engines
# with its reference in the JSON; bad input (a syntax error, a missing
# value, an unknown name, a missing unit) exits non-zero with FILE:LINE
# and leaves no output file.
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
sys.exit(0 if d[\"pass\"] and d[\"golden_mismatches\"]==0 and abs(r[\"x\"]-r[\"x_ref\"])<1e-5 and \"cycles_per_step\" in d else 1)'"
  done
done
out=$("$FP3" run --model models/ship.fp3m --set h=0.0166666675 --set T=50000 --set C=5000 \
      --set m=10000 --set v=0 --set s=0 --steps 600 --engine iss --literal --integrator euler)
check "ship euler literal passes" "grep -q '^PASS' <<<\"\$out\""
printf 'state x\nx'"'"' = x +\n' >"$tmp/bad.fp3m"
err=$("$FP3" run --model "$tmp/bad.fp3m" --set h=1 --set x=1 2>&1); rc=$?
check "syntax error: exit 2, FILE:LINE:COL" "[ $rc -eq 2 ] && grep -q 'bad.fp3m:2:9: expected an expression' <<<\"\$err\""
err=$("$FP3" run --model models/spring.fp3m --set h=0.01 --set k=1 --set m=1 --set x=1 --set v=0 2>&1); rc=$?
check "missing param named with its line" "[ $rc -eq 2 ] && grep -q \"models/spring.fp3m:3: param 'c' has no value\" <<<\"\$err\""
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
# registers: folded rk4 of the 3-D spring needs 34 (no spilling); the ISS
# runs it as a build with NUM_REGS=34, a 32-register RTL refuses it with
# the numbers; its literal rk4 fits 32 (bounded register pressure)
s3="--set h=0.015625 --set k=30 --set L=1 --set m=1.5 --set x=1.5 --set y=0.2 --set z=-0.3 --set vx=0 --set vy=0.8 --set vz=0.1"
out=$("$FP3" run --model models/spring3d.fp3m $s3 --steps 100 --engine iss --json 2>"$tmp/err"); rc=$?
check "spring3d rk4 folded on the ISS: NUM_REGS=34, bit-exact" \
  "[ $rc -eq 0 ] && grep -q 'ISS runs it as a build with NUM_REGS=34' $tmp/err && \
   echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if d[\"pass\"] and d[\"num_regs\"]==34 and d[\"registers_needed\"]==34 else 1)'"
out=$("$FP3" run --model models/spring3d.fp3m $s3 --steps 100 --engine iss --literal --json 2>&1)
check "spring3d rk4 literal on the ISS: 32 registers, bit-exact" \
  "echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if d[\"pass\"] and d[\"num_regs\"]==32 and d[\"registers_needed\"]<=32 else 1)'"
err=$("$FP3" run --model models/spring3d.fp3m $s3 --steps 100 --engine rtl 2>&1); rc=$?
check "spring3d rk4 folded on a 32-register RTL: refused with the numbers" \
  "[ $rc -eq 2 ] && grep -q 'the program needs 34 registers; NUM_REGS is 32' <<<\"\$err\""
"$FP3" compile --model models/spring3d.fp3m -o "$tmp/s3.s" 2>/dev/null
check "compile --model for 34 registers: .regs 34" "grep -q '^.regs 34$' $tmp/s3.s"
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
# ... but a ship program's prologue restarts them each frame: refused, saying so
err=$("$FP3" frames --harbour 20 --integrator rk4comp --frames 3 2>&1); rc=$?
check "frames refuses rk4comp on a ship program, naming the prologue and the model scene" \
  "[ $rc -eq 2 ] && grep -q 'restarts its Kahan compensations at 0' <<<\"\$err\" && grep -q 'scenes/fleet.scene' <<<\"\$err\""
out=$("$FP3" frames --scene scenes/fleet.scene --integrator rk4comp --frames 30 --json)
check "frames rk4comp: the 12 moored ships rest, every frame bit-exact" \
  "echo '$out' | python3 -c 'import json,sys; d=json.load(sys.stdin); sys.exit(0 if d[\"pass\"] and d[\"asleep_at_end\"]==12 and d[\"object_frames_skipped\"]>0 else 1)'"
"$FP3" compile --model models/spring.fp3m --literal -o "$tmp/s.s" 2>/dev/null
check "compile --model writes the program" "grep -q 'model spring' $tmp/s.s && grep -q endi $tmp/s.s"
[ $fail -eq 0 ]
