#!/usr/bin/env bash
# test_mscene.sh -- model scenes (docs/models.md "Scenes of a model"):
# fp3 run --scene runs every object of a model scene on the contexts of
# both engines, bit-exact after every integration, in batches when the
# scene has more objects than contexts; --model --objects N; fp3 compile,
# configure, frames (rest skipping) and bench --model take models; bad
# scenes exit 2 naming FILE:LINE and write no output file; a state that
# becomes non-finite exits 1 naming the integrator and the variable.
set -uo pipefail
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-build/fp3}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail=0
check() { if eval "$2"; then echo "PASS: $1"; else echo "FAIL: $1"; fail=1; fi; }
# json FIELD-TEST: a python expression over d (the JSON of $out)
jtest() { python3 -c "import json,sys; d=json.load(sys.stdin); sys.exit(0 if ($1) else 1)" <<<"$out"; }

for eng in iss rtl; do
  out=$("$FP3" run --scene scenes/springs.scene --steps 200 --engine $eng --json)
  check "springs.scene on $eng: 24 objects bit-exact, GSL error < 1e-3" \
    "jtest 'd[\"pass\"] and d[\"objects\"]==24 and d[\"golden_mismatches\"]==0 and d[\"max_error_ref\"]<1e-3 and len(d[\"results\"])==24'"
done
# 32 ships on the 8 contexts of the default RTL build: 4 batches
out=$("$FP3" run --scene scenes/fleet.scene --steps 100 --integrator euler --literal --json)
check "fleet.scene on rtl: 32 ships in 4 batches, bit-exact" \
  "jtest 'd[\"pass\"] and d[\"batches\"]==4 and d[\"contexts\"]==8 and d[\"cycles_per_object_step\"]>0'"
out=$("$FP3" run --model models/spring.fp3m --objects 20 --seed 3 --set h=0.015625 --set k=40 \
      --set c=0.8 --set m=2 --set x=0.5 --set v=-0.25 --steps 100 --integrator symeuler --json)
check "--model --objects 20 symeuler: bit-exact, 3 batches" \
  "jtest 'd[\"pass\"] and d[\"objects\"]==20 and d[\"batches\"]==3'"

# bad scenes: exit 2, FILE:LINE, the reason; no output file
cp models/spring.fp3m "$tmp/"
bad() { # NAME TEXT PATTERN
  printf "$2" >"$tmp/$1.scene"
  err=$("$FP3" run --scene "$tmp/$1.scene" --engine iss 2>&1); rc=$?
  check "bad scene $1: exit 2, '$3'" "[ $rc -eq 2 ] && grep -q -- \"$3\" <<<\"\$err\""
}
bad nocol 'model spring.fp3m\nh 0.01\nk c x v\n1 2 3 4\n' \
  "nocol.scene:3: the header does not give param 'm' of model spring"
bad short 'model spring.fp3m\nh 0.01\nk c m x v\n1 2 3 4\n' \
  "short.scene:4: 4 numbers, the header (line 3) has 5 columns: no value for 'v'"
bad noh 'model spring.fp3m\nk c m x v\n1 0 1 1 0\n' "noh.scene:3: no 'h STEP' line"
bad unknown 'model spring.fp3m\nh 0.01\nk c m x v w\n' \
  "unknown.scene:3: column 'w' is neither a param nor a state variable"
bad nan 'model spring.fp3m\nh 0.01\nk c m x v\n1 0 1 1 nan\n' "nan.scene:4: v = 'nan' is not a finite number"
bad nomodel 'model missing.fp3m\nh 0.01\n' "nomodel.scene:1: model: .*missing.fp3m: cannot read"
err=$("$FP3" compile "$tmp/short.scene" -o "$tmp/short.s" 2>&1); rc=$?
check "compile of a bad scene: exit 2, no file" "[ $rc -eq 2 ] && [ ! -e $tmp/short.s ]"
err=$("$FP3" configure "$tmp/short.scene" -o "$tmp/short.cfg" 2>&1); rc=$?
check "configure of a bad scene: exit 2, no file" "[ $rc -eq 2 ] && [ ! -e $tmp/short.cfg ]"

# a state that overflows: exit 1, the object, the variable, the integrator
printf 'model spring.fp3m\nh 0.01\nk c m x v\n1 0 1 1 0\n1e30 0 1e-30 1e30 1e30\n' >"$tmp/inf.scene"
err=$("$FP3" run --scene "$tmp/inf.scene" --engine iss --steps 5 2>&1 >/dev/null); rc=$?
check "non-finite state: exit 1, object, variable, integrator" \
  "[ $rc -eq 1 ] && grep -q 'inf.scene:5: object 1: state variable x is not finite after integration 1 of rk4' <<<\"\$err\""

# compile, configure, frames, bench
"$FP3" compile scenes/springs.scene --integrator rk2 -o "$tmp/springs.s" 2>/dev/null
check "compile a model scene" "grep -q '^; model spring' $tmp/springs.s && grep -q endi $tmp/springs.s"
line=$("$FP3" configure scenes/springs.scene --steps 100 2>/dev/null)
check "configure a model scene: NUM_CONTEXTS=3 NUM_LANES=N NUM_REGS=15" \
  "grep -q '^NUM_CONTEXTS=3 NUM_LANES=[0-9]* NUM_REGS=15 HAS_ADD=1 HAS_SUB=1 HAS_MUL=1 ' <<<\"\$line\""
out=$("$FP3" frames --scene scenes/fleet.scene --frames 60 --integrator euler --json)
check "frames: the 12 moored ships rest, every frame bit-exact" \
  "jtest 'd[\"pass\"] and d[\"asleep_at_end\"]==12 and d[\"object_frames_skipped\"]>0'"
out=$("$FP3" frames --scene scenes/fleet.scene --frames 60 --integrator euler --no-rest-skip --json)
check "frames --no-rest-skip: nothing skipped" \
  "jtest 'd[\"pass\"] and d[\"object_frames_skipped\"]==0 and d[\"object_frames_run\"]==32*60'"
# --frames equal to fp3 run's default step count (1000) is not the frames default (600)
out=$("$FP3" frames --scene scenes/fleet.scene --frames 1000 --integrator euler --engine iss --json)
check "frames --frames 1000: 1000 frames run" "jtest 'd[\"pass\"] and d[\"frames\"]==1000'"
"$FP3" bench --model models/spring.fp3m --set h=0.015625 --set k=40 --set c=0.8 --set m=2 \
  --set x=0.5 --set v=-0.25 --points 3 --engine iss -o "$tmp/wp.csv" 2>/dev/null
check "bench --model: the 10 integrators the spring takes x 3 points, rk4's error falls with h" \
  "[ \$(grep -c '^spring,' $tmp/wp.csv) -eq 30 ] && awk -F, '\$2==\"rk4\"{e[n++]=\$10} END{exit !(e[0]>e[1] && e[0]<1e-5)}' $tmp/wp.csv"
# stability bounds against theory for x'' = -w^2 x, w = 3: symplectic Euler
# and Verlet stable for h w < 2, RK4 for h w < 2 sqrt(2)
"$FP3" bench --model models/oscillator.fp3m --set h=0.015625 --set w=3 --set x=0.75 \
  --set v=-0.5 --points 1 --engine iss --stability "$tmp/stab.csv" -o "$tmp/wp1.csv" 2>/dev/null
check "bench --stability: verlet, symeuler at 2/w, rk4 at 2 sqrt(2)/w (1e-3)" \
  "awk -F, '\$2==\"verlet\"||\$2==\"symeuler\"{if (\$3<0.6657||\$3>0.6677) bad=1; n++} \
    \$2==\"rk4\"{if (\$3<0.9418||\$3>0.9438) bad=1; n++} END{exit bad || n!=3}' $tmp/stab.csv"
# a 3-D model scene whose folded rk4 needs 33 registers: configure derives
# NUM_REGS=33 and the units; the ISS runs it as such a build, bit-exact
cat >"$tmp/anchors.scene" <<EOF
model $PWD/models/spring3d.fp3m
h 0.015625
k L m x y z vx vy vz
30 1 1.5 1.5 0.2 -0.3 0 0.8 0.1
20 0.8 1.0 -1.2 0.5 0.3 0.2 -0.4 0.6
EOF
line=$("$FP3" configure "$tmp/anchors.scene" --steps 100 2>/dev/null)
check "configure of a 3-D spring scene: NUM_REGS=33, HAS_DIV=1, HAS_SQRT=1, four write-back ports" \
  "grep -q 'NUM_REGS=33 .*HAS_DIV=1 HAS_SQRT=1 .* ADD_LATENCY=4 MUL_LATENCY=3 WB_PORTS=4\$' <<<\"\$line\""
err=$("$FP3" configure "$tmp/anchors.scene" --steps 100 --wb-ports 1 -o "$tmp/anchors.cfg" 2>&1 >/dev/null); rc=$?
check "configure --wb-ports 1 with div: exit 2, names div and its pc, no file" \
  "[ $rc -eq 2 ] && [ ! -e $tmp/anchors.cfg ] && grep -q 'one write-back port needs a program without div and sqrt.*has div at pc [0-9]' <<<\"\$err\""
out=$("$FP3" run --scene "$tmp/anchors.scene" --engine iss --steps 100 --json 2>/dev/null)
check "3-D spring scene on the ISS with 33 registers: bit-exact" \
  "jtest 'd[\"pass\"] and d[\"num_regs\"]==33 and d[\"registers_needed\"]==33'"
# ... and its folded rk4comp needs 39, within the 40 registers of the RTL
# test build nc3 (tests/test_model.c runs it there)
line=$("$FP3" configure "$tmp/anchors.scene" --integrator rk4comp --steps 100 2>/dev/null)
check "configure of a 3-D spring scene, rk4comp: NUM_REGS=39" "grep -q 'NUM_REGS=39 ' <<<\"\$line\""
[ $fail -eq 0 ]
