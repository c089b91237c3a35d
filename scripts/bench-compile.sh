#!/usr/bin/env bash
# bench-compile.sh FP3 OUTDIR OBJECTS STEPS -- the scene compiler against the
# literal (paper's) program on the RTL (make bench-compile).
#
# Four generated scenes of OBJECTS ships (h = 1/60 s): all terms (every
# ship with drag and thrust), no drag (every C = 0), no thrust (every
# T = 0), mixed (fp3_scene_generate's mix: one ship in eight without
# drag).  Each runs STEPS integrations with `fp3 run --scene` on the RTL,
# every object checked bit for bit against its golden model, once with
# --literal (programs/ship_rk4.s) and once compiled (the default).
# Writes OUTDIR/compile.csv and OUTDIR/compile.md: instructions per
# integration, measured cycles per object-step, and the error of v and s
# after STEPS integrations against the exact solution (models/ship.fp3m):
# the largest over the objects, and the mean, of |x - exact| / max(|exact|, 1)
# (exact: the exact solution, or the GSL reference where the model has none,
# C = 0).
set -eu
FP3=$1; OUT=$2; N=$3; STEPS=$4
mkdir -p "$OUT/compile-scenes"
python3 - "$OUT/compile-scenes" "$N" <<'PY'
import math, random, struct, sys
d, n = sys.argv[1], int(sys.argv[2])
f32 = lambda x: struct.unpack('f', struct.pack('f', x))[0]
def ship(r, drag, thrust):
    m = 10 ** r.uniform(0, 6); tau = r.uniform(0.5, 50); vinf = r.uniform(-5, 30)
    C = m / tau if drag else 0.0
    T = (vinf * C if drag else m * r.uniform(-0.5, 0.5)) if thrust else 0.0
    if thrust and T == 0.0: T = 1.0
    return T, C, m, r.uniform(-10, 30), r.uniform(-100, 100)
kinds = {'all': lambda r, i: (True, True), 'nodrag': lambda r, i: (False, True),
         'nothrust': lambda r, i: (True, False), 'mixed': lambda r, i: (i % 8 != 0, True)}
for k, f in kinds.items():
    r = random.Random(k)
    with open(f'{d}/{k}.scene', 'w') as o:
        o.write(f'# {k}: {n} ships (scripts/bench-compile.sh)\nh 0.0166666675\n')
        for i in range(n):
            o.write(' '.join('%.9g' % f32(x) for x in ship(r, *f(r, i))) + '\n')
PY
csv="$OUT/compile.csv"; md="$OUT/compile.md"
echo "scene,program,objects,steps,insns_per_step,est_cycles_per_step,cycles,cycles_per_object_step,golden_mismatches,v_err_max,v_err_mean,s_err_max,s_err_mean" >"$csv.tmp"
rc=0
for k in all nodrag nothrust mixed; do
  for prog in literal compiled; do
    flag=; [ "$prog" = literal ] && flag=--literal
    json=$("$FP3" run --engine rtl --scene "$OUT/compile-scenes/$k.scene" --steps "$STEPS" --json $flag) || rc=1
    python3 - "$k" "$prog" "$json" >>"$csv.tmp" <<'PY'
import json, sys
k, prog, d = sys.argv[1], sys.argv[2], json.loads(sys.argv[3])
err = lambda x, e: abs(x - e) / max(abs(e), 1.0)
res = d['results']
# the exact solution, or where the model has none (C = 0) the GSL reference
want = lambda r, k: r[k + '_exact'] if r[k + '_exact'] is not None else r[k + '_ref']
ve = [err(r['v'], want(r, 'v')) for r in res]
se = [err(r['s'], want(r, 's')) for r in res]
print(f"{k},{prog},{d['objects']},{d['steps']},{d['insns_per_step']},{d.get('est_cycles_per_step', '')},"
      f"{d['cycles']},{d['cycles_per_object_step']:.4f},{d['golden_mismatches']},"
      f"{max(ve):.4e},{sum(ve) / len(ve):.4e},{max(se):.4e},{sum(se) / len(se):.4e}")
PY
    echo "bench-compile: $k $prog done"
  done
done
mv "$csv.tmp" "$csv"
python3 - "$csv" >"$md.tmp" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print('| scene | program | instructions per integration | cycles per object-step (RTL) | v error max | v error mean | s error max | s error mean | golden mismatches |')
print('| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |')
for r in rows:
    print(f"| {r['scene']} | {r['program']} | {r['insns_per_step']} | {r['cycles_per_object_step']} | "
          f"{r['v_err_max']} | {r['v_err_mean']} | {r['s_err_max']} | {r['s_err_mean']} | {r['golden_mismatches']} |")
r0 = rows[0]
print(f"\n{r0['objects']} objects x {r0['steps']} integrations each, h = 1/60 s; error: largest over "
      "the objects (and mean) of |x - exact| / max(|exact|, 1) after the last integration (exact: the exact solution, or the GSL reference rk8pd where C = 0).")
PY
mv "$md.tmp" "$md"
cat "$md"
exit $rc
