#!/usr/bin/env bash
# test_wave.sh -- make wave: the RTL under Icarus Verilog, self-checked
# against the ISS (values) and the Verilated RTL (cycles), and the ways it
# must fail: a corrupted expected value, a hung run (watchdog), a missing
# or malformed program.  Also: every signal of sim/fp3.gtkw is in the
# waveform, several contexts, FST output, Verilator accepts the testbench,
# and the Verilator waveform window of fp3 run --trace/--trace-window.
#
# Runs from anywhere; uses $FP3_BIN (set by mk/sw.mk) or build/fp3.
set -u
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
if [ ! -x "$FP3" ]; then echo "test_wave: $FP3 not built"; exit 1; fi
T=$(mktemp -d /tmp/fp3_test_wave.XXXXXX)
trap 'rm -rf "$T"' EXIT
W=$T/wave
pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
has() { grep -q -- "$2" "$1" || { bad "$3: output lacks '$2'"; sed 's/^/    /' "$1" | tail -15; return 1; }; }

# ---- make wave on the ship program: PASS, Verilator's cycle count --------
start=$(date +%s)
make -s --no-print-directory wave STEPS=3 WAVE_DIR="$W" >"$T/make.log" 2>&1; rc=$?
secs=$(( $(date +%s) - start ))
if [ $rc -eq 0 ]; then ok; else bad "make wave exited $rc"; tail -30 "$T/make.log"; fi
has "$T/make.log" "^PASS: tb_fp3: 1 context(s) x 3 integrations" "make wave" && ok
# the cycle comparison with Verilator took place (run.hex had its counts)
has "$T/make.log" "^tb_fp3: Verilator: [1-9][0-9]* cycles" "make wave" && ok
echo "make wave STEPS=3: ${secs}s, $(grep -c . "$W/expected.hex") expected lines," \
     "$(du -k "$W/fp3.vcd" 2>/dev/null | cut -f1) KiB VCD"

# ---- the sleeping program (beq) under Icarus: asleep from integration 2 --
# (a ship at rest: the beq falls through once, then is taken)
make -s --no-print-directory wave PROGRAM=programs/ship_rk4_sleep.s STEPS=6 SET="T=0 v0=0" \
  WAVE_DIR="$T/wsleep" >"$T/sleep.log" 2>&1 || bad "make wave (sleeping program) failed"
has "$T/sleep.log" "^tb_fp3: first integration 129 cycles, later 14.00 per integration" \
  "make wave (sleeping)" && ok
has "$T/sleep.log" "^PASS: tb_fp3: 1 context(s) x 6 integrations" "make wave (sleeping)" && ok

# ---- the waveform holds every signal of the GTKWave view ----------------
if [ -s "$W/fp3.vcd" ] && grep -q '^\$enddefinitions' "$W/fp3.vcd"; then ok; else bad "no VCD"; fi
awk '
  /^\$scope/ { scope[++d] = $3 }
  /^\$upscope/ { d-- }
  /^\$var/ { n = ""; for (i = 1; i <= d; i++) n = n scope[i] "."; print n $5 }
  /^\$enddefinitions/ { exit }' "$W/fp3.vcd" | sort -u >"$T/vcd.names"
missing=0
while read -r sig; do
  base=${sig%%\[*}
  grep -qx -- "$base" "$T/vcd.names" || { echo "  gtkw signal not in the VCD: $sig"; missing=1; }
done < <(grep -E '^tb_fp3\.' sim/fp3.gtkw)
[ $missing -eq 0 ] && ok || bad "sim/fp3.gtkw names signals the waveform lacks"
[ "$(grep -cE '^-' sim/fp3.gtkw)" -ge 14 ] && ok || bad "sim/fp3.gtkw: groups missing"

# The checks below run the same inputs on the testbench built without the
# div/sqrt unit, which the ship programs do not use (the same cycles and
# values): Icarus evaluates its cores every cycle, and a run takes about 15
# times as long with them.  make wave above ran the default build.
# tb_nodiv OUT NAME=VALUE...: compile the testbench with make wave's
# command file, without the div/sqrt unit, and the parameters given.
tb_nodiv() {
  local out=$1 p args=(); shift
  for p in HAS_DIV=0 HAS_SQRT=0 "$@"; do args+=("-Ptb_fp3.$p"); done
  iverilog -g2005 -Wall -Irtl -y rtl -s tb_fp3 "${args[@]}" \
    -c "$W/iverilog.cmd" -o "$out" sim/tb_fp3.v >"$out.log" 2>&1 \
    && ok || { bad "iverilog HAS_DIV=0 HAS_SQRT=0 $*"; tail -5 "$out.log"; }
}
ND_VVP=$T/tb_nodiv.vvp
tb_nodiv "$ND_VVP"
VVP=(vvp -n "$ND_VVP")

# ---- negative: a corrupted expected value makes it FAIL ------------------
# corrupt FILE PATTERN: flip the lowest bit of the first word on the first
# line matching PATTERN.
corrupt() {
  local line n word
  line=$(grep -n -- "$2" "$1" | head -1)
  n=${line%%:*}; line=${line#*:}; word=${line%% *}
  sed "${n}s/^$word/$(printf '%08x' $(( 16#$word ^ 1 )))/" "$1"
}
cp -r "$W" "$T/bad_v"
corrupt "$W/expected.hex" '// 2: v' >"$T/bad_v/expected.hex"   # v after integration 2
cmp -s "$W/expected.hex" "$T/bad_v/expected.hex" && bad "could not corrupt expected.hex"
"${VVP[@]}" +dir="$T/bad_v" >"$T/bad_v.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "corrupted v: vvp exited 0"
has "$T/bad_v.log" "MISMATCH: context 0, integration 2: v = " "corrupted v" && ok
has "$T/bad_v.log" "^FAIL: tb_fp3" "corrupted v" && ok

cp -r "$W" "$T/bad_r"                                           # final s (r6)
corrupt "$W/expected.hex" '// r6 = ' >"$T/bad_r/expected.hex"
"${VVP[@]}" +dir="$T/bad_r" >"$T/bad_r.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "corrupted r6: vvp exited 0"
has "$T/bad_r.log" "ERROR: context 0: r6 = " "corrupted r6" && ok

cp -r "$W" "$T/bad_c"                               # Verilator's cycle count
corrupt "$W/run.hex" 'Verilated RTL CYCLES' >"$T/bad_c/run.hex"
"${VVP[@]}" +dir="$T/bad_c" >"$T/bad_c.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "corrupted cycle count: vvp exited 0"
has "$T/bad_c.log" "ERROR: CYCLES vs Verilator" "corrupted cycle count" && ok

# ---- negative: a run that never ends trips the watchdog ------------------
# A budget of 500 cycles (+watchdog), so the endless run stops early
# whatever the default budget (ISSUED x (longest latency + 1) + 100) is;
# the timeout only keeps a watchdog that never fires from hanging the suite.
timeout 600 "${VVP[@]}" +dir="$W" +steps=4000000000 +watchdog=500 >"$T/hang.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "endless run: vvp exited 0"
has "$T/hang.log" "^WATCHDOG: run not done within the cycle budget at cycle 500 .*: pc [0-9]" "endless run" && ok
has "$T/hang.log" "^FAIL: tb_fp3: the run hung" "endless run" && ok
[ $rc -ne 124 ] && ok || bad "the watchdog did not stop the run (timeout)"

# ---- missing input files -------------------------------------------------
"${VVP[@]}" +dir="$T/nowhere" >"$T/nodir.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "missing files: vvp exited 0"
has "$T/nodir.log" "FAIL: tb_fp3: cannot open $T/nowhere/run.hex" "missing files" && ok

# ---- several contexts share the arithmetic unit, every result checked ---
"${VVP[@]}" +dir="$W" +contexts=4 >"$T/ctx.log" 2>&1; rc=$?
[ $rc -eq 0 ] && ok || bad "+contexts=4: vvp exited $rc"
has "$T/ctx.log" "^PASS: tb_fp3: 4 context(s) x 3 integrations, v and s bit-exact after each (24 values)" "+contexts=4" && ok

# ---- lanes: 2 contexts x 3 lanes, every lane checked; the sleeping
# program's beq taken in every lane (the same scene in each).  The
# testbench is compiled here with the lane parameters (make wave
# NUM_LANES=3 would rebuild build/fp3's Verilated models with them) and
# runs the inputs generated above.  Without the div/sqrt unit, which the
# ship programs do not use: Icarus evaluates its cores in every lane every
# cycle (a run takes about 60 times as long with them). ----------------------
LANES_VVP=$T/tb_lanes.vvp
tb_nodiv "$LANES_VVP" NUM_CONTEXTS=2 NUM_LANES=3
vvp -n "$LANES_VVP" +dir="$W" +contexts=2 >"$T/lanes.log" 2>&1 || bad "NUM_LANES=3: vvp failed"
has "$T/lanes.log" "^PASS: tb_fp3: 2 context(s) x 3 integrations, v and s bit-exact after each (36 values).*3 lane(s) per context" \
  "NUM_LANES=3" && ok
vvp -n "$LANES_VVP" +dir="$T/wsleep" >"$T/lsleep.log" 2>&1 || bad "NUM_LANES=3 (sleeping) failed"
# (3 cycles more per integration than one lane, for its beq:
# FP3_LANES_BEQ_CYCLES; the testbench checks the run's cycles against
# Verilator's one-lane model with that)
has "$T/lsleep.log" "^tb_fp3: first integration 132 cycles, later 17.00 per integration" \
  "NUM_LANES=3 (sleeping)" && ok
has "$T/lsleep.log" "^PASS: tb_fp3" "NUM_LANES=3 (sleeping)" && ok
# a corrupted expected value fails in every lane (lane 2 reported)
cp -r "$W" "$T/wlbad"
line=$(grep -n -- '// 3: v' "$W/expected.hex" | head -1)    # v after integration 3
n=${line%%:*}; line=${line#*:}; word=${line%% *}
sed "${n}s/^$word/$(printf '%08x' $(( 16#$word ^ 1 )))/" "$W/expected.hex" >"$T/wlbad/expected.hex"
cmp -s "$W/expected.hex" "$T/wlbad/expected.hex" && bad "could not corrupt expected.hex"
vvp -n "$LANES_VVP" +dir="$T/wlbad" +contexts=2 >"$T/lbad.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "NUM_LANES=3, a corrupted value: vvp exited 0"
has "$T/lbad.log" "MISMATCH: context 1, lane 2, integration 3" "NUM_LANES=3, corrupted" && ok

# ---- another model: euler on the damped spring (models/spring.fp3m) ------
# A hand-written program bound to the model by its names (fp3 run
# --program's path): no .model line here, so make wave's MODEL= names it;
# --set by the model's names (x0: the NAME0 alias of state variable x).
# The checked pair is the model's first two state variables, x and v.
cat >"$T/spring_euler.s" <<'EOS'
; euler on the damped spring: x += h v; v += h (-(k x + c v) minv)
.integrator euler
.reg h r1
.reg k r2
.reg c r3
.reg x r4
.reg v r5
.reg minv r6
.in h, h
.in k, k
.in c, c
.in x0, x
.in v0, v
.in minv, minv
.out x, x
.out v, v
body:
        mul  r7, k, x        ; k x
        mul  r8, c, v        ; c v
        mul  r9, h, v        ; h x'
        add  r10, r7, r8     ; k x + c v
        add  x, x, r9        ; x + h x'
        mul  r11, r10, minv  ; -v'
        mul  r12, h, r11     ; -h v'
        sub  v, v, r12       ; v + h v'
        endi body
EOS
SW=$T/wspring
make -s --no-print-directory wave PROGRAM="$T/spring_euler.s" MODEL=models/spring.fp3m STEPS=5 \
  SET="k=30 x0=1" WAVE_DIR="$SW" >"$T/spring.log" 2>&1 || { bad "make wave (spring) failed"; tail -20 "$T/spring.log"; }
has "$T/spring.log" "model spring, 5 integrations, 5 checked (x, v)" "make wave (spring)" && ok
has "$T/spring.log" "^PASS: tb_fp3: 1 context(s) x 5 integrations, x and v bit-exact after each (10 values)" \
  "make wave (spring)" && ok
has "$SW/init.hex" "^3f800000  // r4$" "spring: --set x0=1 in x's register" && ok
has "$SW/run.hex" "^00000004  // 10 register of state variable 0 (x)" "spring run.hex" && ok
# the same program with its .model line: the same files
{ printf '.model "%s/models/spring.fp3m"\n' "$PWD"; cat "$T/spring_euler.s"; } >"$T/spring_model.s"
"$FP3" tbgen "$T/spring_model.s" -o "$T/wspring2" --steps 5 --set k=30 --set x0=1 --no-rtl \
  >"$T/spring2.log" 2>&1 || bad "tbgen of a program with .model failed"
for f in program init expected; do
  cmp -s <(grep -v '^//' "$SW/$f.hex" | sed 's, *//.*,,') \
         <(grep -v '^//' "$T/wspring2/$f.hex" | sed 's, *//.*,,') && ok \
    || bad "spring: $f.hex differs between --model and .model"
done
cp -r "$SW" "$T/spring_bad"                 # a corrupted x names x in the message
corrupt "$SW/expected.hex" '// 3: x' >"$T/spring_bad/expected.hex"
"${VVP[@]}" +dir="$T/spring_bad" >"$T/spring_bad.log" 2>&1 && bad "corrupted x: vvp exited 0"
has "$T/spring_bad.log" "MISMATCH: context 0, integration 3: x = " "corrupted x" && ok
# a file of the previous format is refused
cp -r "$SW" "$T/spring_v1"
sed 's,^00000002\(  //  1 format version\),00000001\1,' "$SW/run.hex" >"$T/spring_v1/run.hex"
cmp -s "$SW/run.hex" "$T/spring_v1/run.hex" && bad "could not change run.hex's version"
"${VVP[@]}" +dir="$T/spring_v1" >"$T/spring_v1.log" 2>&1 && bad "run.hex version 1: vvp exited 0"
has "$T/spring_v1.log" "is not an fp3 tbgen file of version 2" "run.hex version 1" && ok

# ---- a one-state model: one value checked, the second register none ------
printf 'model decay\nparam h = 0.125, a = 2\nstate y = 1\ny'"'"' = -a*y\n' >"$T/decay.fp3m"
cat >"$T/decay_euler.s" <<'EOS'
.model "decay.fp3m"
.integrator euler
.in h, r1
.in a, r2
.in y0, r3
.out y, r3
body:
        mul  r4, r2, r3      ; a y
        mul  r5, r1, r4      ; -h y'
        sub  r3, r3, r5      ; y + h y'
        endi body
EOS
"$FP3" tbgen "$T/decay_euler.s" -o "$T/wdecay" --steps 4 --no-rtl >"$T/decay.log" 2>&1 \
  && ok || { bad "tbgen (one-state model) failed"; cat "$T/decay.log"; }
has "$T/wdecay/run.hex" "^ffffffff  // 11 register of state variable 1" "one-state run.hex" && ok
"${VVP[@]}" +dir="$T/wdecay" >"$T/decay_tb.log" 2>&1 || bad "one-state model: vvp failed"
has "$T/decay_tb.log" "^PASS: tb_fp3: 1 context(s) x 4 integrations, y bit-exact after each (4 values)" \
  "one-state model" && ok

# ---- tbgen refuses what is not a model's program, and writes nothing -----
# tbgen_refused RC PATTERN WHAT ARGS...: fp3 tbgen ARGS -o DIR exits RC
# with PATTERN on stderr and leaves DIR missing.
tbgen_refused() {
  local want=$1 pat=$2 what=$3 dir=$T/refused rc; shift 3
  rm -rf "$dir"
  "$FP3" tbgen "$@" -o "$dir" --no-rtl >"$T/refused.log" 2>&1; rc=$?
  [ $rc -eq "$want" ] && ok || bad "$what: tbgen exited $rc, not $want"
  has "$T/refused.log" "$pat" "$what" && ok
  [ ! -e "$dir" ] && ok || bad "$what: tbgen wrote into $dir"
}
grep -v '^\.integrator' "$T/spring_euler.s" >"$T/no_integ.s"
tbgen_refused 2 "no_integ.s: no \`.integrator NAME\` line" "no .integrator" \
  "$T/no_integ.s" --model models/spring.fp3m
tbgen_refused 2 "spring_euler.s has no \`.model \"FILE.fp3m\"\` line: give --model FILE.fp3m" \
  "no model" "$T/spring_euler.s"
tbgen_refused 2 "is a program of .*spring.fp3m (its .model line), not of models/ship.fp3m" \
  "--model against .model" "$T/spring_model.s" --model models/ship.fp3m
tbgen_refused 2 "has no param or state 'T'" "--set of another model's name" \
  "$T/spring_model.s" --set T=1
{ grep -v '^\.out *s' programs/ship_scene.inc | sed 's,^\.model .*,,'
  grep -v '^\.include' programs/ship_euler.s; } >"$T/ship_no_s.s"
tbgen_refused 2 "no \`.out s, rN\`: state variable s of model ship" "a ship program without .out s" \
  "$T/ship_no_s.s" --model models/ship.fp3m
# a program that computes something else than its .integrator: the ISS
# disagrees with the golden model, exit 1
sed 's/^\( *\)sub  v, v, r12/\1add  v, v, r12/' "$T/spring_model.s" >"$T/spring_wrong.s"
tbgen_refused 1 "the ISS disagrees with the golden model (.integrator euler, model .*spring.fp3m): after integration 1 v = " \
  "a wrong program" "$T/spring_wrong.s"

# ---- FST -----------------------------------------------------------------
vvp -n "$ND_VVP" -fst +dir="$W" +wave="$T/fp3.fst" >"$T/fst.log" 2>&1; rc=$?
[ $rc -eq 0 ] && [ -s "$T/fst.log" ] && [ -s "$T/fp3.fst" ] && ok || bad "vvp -fst: exit $rc, no FST"

# ---- bad input: the assembler's error, make fails ------------------------
make -s --no-print-directory wave PROGRAM="$T/missing.s" WAVE_DIR="$T/w2" >"$T/miss.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "make wave with a missing program exited 0"
has "$T/miss.log" "$T/missing.s" "missing program" && ok
printf 'body:\n  mul r1, r2\n  endi body\n' >"$T/bad.s"
make -s --no-print-directory wave PROGRAM="$T/bad.s" WAVE_DIR="$T/w3" >"$T/bad.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "make wave with a malformed program exited 0"
has "$T/bad.log" "bad.s:2:" "malformed program" && ok
[ ! -e "$T/w3/tb_fp3.vvp" ] && ok || bad "make wave went on after the assembler error"

# ---- Verilator accepts the testbench (lint, -Wall, its waivers) ---------
out=$(verilator --lint-only -Wall --timing -Irtl -y rtl --top-module tb_fp3 sim/tb_fp3.vlt \
      sim/tb_fp3.v 2>&1); rc=$?
[ $rc -eq 0 ] && [ -z "$out" ] && ok || { bad "verilator lint of the testbench"; echo "$out" | head -20; }

# ---- Verilator: fp3 run --trace writes a window of cycles ----------------
# timestamps of a VCD: two per cycle, plus the reset and the INFO reads
# before the first run (29: INFO1 and INFO2 are read over 5 cycles, the
# longest read, before they tell how long a read takes)
stamps() { grep -c '^#' "$1"; }
"$FP3" run --steps 300 --trace "$T/def.vcd" >/dev/null 2>"$T/def.err"; rc=$?
[ $rc -eq 0 ] && ok || bad "fp3 run --trace exited $rc"
has "$T/def.err" "trace $T/def.vcd: cycles 0..9999 of the run's [0-9]* " "default window" && ok
# 10,000 cycles at about 24 KB: above 100 MiB, a warning with the estimate
has "$T/def.err" "warning: --trace $T/def.vcd: the waveform will be about 2[0-9][0-9] MiB" \
  "the size warning" && ok
n=$(stamps "$T/def.vcd"); [ "$n" -ge 20000 ] && [ "$n" -le 20035 ] && ok || bad "default window: $n timestamps"
"$FP3" run --steps 300 --trace "$T/win.vcd" --trace-window 1000:50 >/dev/null 2>"$T/win.err"; rc=$?
[ $rc -eq 0 ] && ok || bad "fp3 run --trace-window exited $rc"
has "$T/win.err" "cycles 1000..1049 of the run" "--trace-window 1000:50" && ok
n=$(stamps "$T/win.vcd"); [ "$n" -ge 100 ] && [ "$n" -le 135 ] && ok || bad "window 1000:50: $n timestamps"
"$FP3" run --steps 2 --trace "$T/all.vcd" --trace-window 0:all >/dev/null 2>"$T/all.err"
has "$T/all.err" "cycles 0\.\.237 of the run's 238" "--trace-window 0:all" && ok
for arg in 5 5:0 x:3 3:y -1:5; do
  "$FP3" run --steps 2 --trace "$T/x.vcd" --trace-window "$arg" >/dev/null 2>&1
  [ $? -eq 2 ] && ok || bad "--trace-window $arg accepted"
done

echo "test_wave: $pass passed, $fail failed"
[ $fail -eq 0 ]
