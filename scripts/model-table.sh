#!/usr/bin/env bash
# model-table.sh -- the shipped models' cost and error table of
# docs/models.md ("Shipped models"): for every model of models/ and every
# integrator that applies, folded (the default) and literal, the
# instructions per integration, the registers the program needs, the
# engine (the default RTL build where it runs the program; a program that
# needs more than its 32 registers on the RTL build with NUM_REGS=40,
# FP3_REGS_BIN, default build-r40/fp3: `make build-r40/fp3 NUM_REGS=40
# BUILD=build-r40`; without that build, or for a unit the build lacks, the
# ISS shaped as a build that has them: HAS_DIV, HAS_SQRT, NUM_REGS), its cycles
# per object-step of one object (600 integrations) and of 64 objects
# (--objects 64 --seed 1, 200 integrations; the ISS counts one cycle an
# instruction), the scheduler's estimate for one object (fp3 compile, for
# the default build; on the NUM_REGS=40 build, its own compilation's), and the
# largest |state - GSL rk8pd (1e-12)| of one object at t = 600 h.  Every
# run is checked bit for bit against the golden model after every
# integration; a failed check stops the script.
#
#   scripts/model-table.sh [MODEL ...]   prints Markdown rows (default: all seven)
# Uses build/fp3 (FP3_BIN to override).
set -euo pipefail
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-build/fp3}
BIG=${FP3_REGS_BIN:-build-r40/fp3}
declare -A set=(
  [ship]="--set h=0.0166666675 --set T=50000 --set C=5000 --set m=10000 --set v=0 --set s=0"
  [spring]="--set h=0.015625 --set k=40 --set c=0.8 --set m=2 --set x=0.5 --set v=-0.25"
  [oscillator]="--set h=0.015625 --set w=3 --set x=0.75 --set v=-0.5"
  [projectile]="--set h=0.015625 --set kd=0.002 --set g=9.81 --set x=0 --set y=2 --set z=0 --set vx=30 --set vy=40 --set vz=-5"
  [orbit]="--set h=0.015625 --set mu=1 --set x=1 --set y=0 --set vx=0 --set vy=1.1"
  [spring3d]="--set h=0.015625 --set k=30 --set L=1 --set m=1.5 --set x=1.5 --set y=0.2 --set z=-0.3 --set vx=0 --set vy=0.8 --set vz=0.1"
  [rigidbody]="--set h=0.015625 --set g=9.81 --set Ix=1 --set Iy=2 --set Iz=3 --set x=0 --set y=10 --set z=0 --set qw=1 --set qx=0 --set qy=0 --set qz=0 --set vx=1 --set vy=5 --set vz=0 --set wx=0.3 --set wy=0.2 --set wz=2"
)
echo "| model | integrator | instructions / step | registers needed | engine | cycles / object-step, one object | 64 objects | scheduler estimate, one object | error vs GSL |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"
for m in ${@:-ship spring oscillator projectile orbit spring3d rigidbody}; do
  for ig in euler rk2 rk4 rk4comp symeuler verlet; do
    for lit in "" --literal; do
      "$FP3" compile --model models/$m.fp3m --integrator $ig $lit -o /dev/null 2>/tmp/fp3-table.$$ || continue
      est=$(sed -n 's/.*estimated \([0-9]*\) cycles per later integration.*/\1/p' /tmp/fp3-table.$$)
      eng=rtl bin=$FP3
      one=$("$bin" run --model models/$m.fp3m ${set[$m]} --integrator $ig $lit --engine rtl \
            --steps 600 --json 2>/tmp/fp3-table-err.$$) || {
        # only a unit or registers the default build lacks send a run
        # elsewhere: registers to the build with more, else the ISS
        grep -q 'this hardware has no\|NUM_REGS is' /tmp/fp3-table-err.$$ ||
          { echo "$m $ig $lit: rtl run failed: $(cat /tmp/fp3-table-err.$$)" >&2; exit 1; }
        if grep -q 'NUM_REGS is' /tmp/fp3-table-err.$$ && [ -x "$BIG" ]; then bin=$BIG; else eng=iss; fi
        one=$("$bin" run --model models/$m.fp3m ${set[$m]} --integrator $ig $lit --engine $eng \
              --steps 600 --json 2>/tmp/fp3-table-err.$$) ||
          { echo "$m $ig $lit: $eng run failed: $(cat /tmp/fp3-table-err.$$)" >&2; exit 1; }; }
      many=$("$bin" run --model models/$m.fp3m ${set[$m]} --integrator $ig $lit --engine $eng \
             --objects 64 --seed 1 --steps 200 --json 2>/dev/null)
      python3 - "$m" "$ig" "${lit:+literal}" "$est" "$eng" "$one" "$many" <<'PY'
import json, sys
m, ig, lit, est, eng, one, many = sys.argv[1:]
a, b = json.loads(one), json.loads(many)
if not (a["pass"] and b["pass"]):
    sys.exit("%s %s %s: not bit-exact" % (m, ig, lit))
r = a["results"][0]
err = max(abs(r[k] - r[k + "_ref"]) for k in r if k + "_ref" in r)
big = eng == "rtl" and a["num_regs"] != 32  # the build with more registers
print("| %s | %s%s | %d | %d | %s | %.2f | %.2f | %s | %.2g |" % (
    m, ig, " literal" if lit else "", a["insns_per_step"], a["registers_needed"],
    eng.upper() + ("" if eng == "rtl" and not big else " (NUM_REGS %d)" % a["num_regs"]),
    a["cycles_later_step"], b["cycles_per_object_step"],
    b["est_cycles_per_step"] if big else est, err))
PY
    done
  done
done
rm -f /tmp/fp3-table.$$ /tmp/fp3-table-err.$$
