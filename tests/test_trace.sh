#!/usr/bin/env bash
# test_trace.sh -- fp3 run --trace: the waveform file appears whole or not
# at all (a temporary renamed after a finished run, removed after a
# refused or failed run and on SIGINT or SIGTERM, the exit status the
# signal's), the size estimate against --trace-limit, and --trace with
# fp3 run --model.
#
# Runs from anywhere; the CLI is $FP3_BIN (set by mk/sw.mk), else
# build/fp3 of this checkout.  Exit status non-zero if any check fails.
set -u
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
if [ ! -x "$FP3" ]; then
  echo "test_trace: $FP3 not built (make $FP3)"; exit 1
fi
T=$(mktemp -d /tmp/fp3_test_trace.XXXXXX)
trap 'rm -rf "$T"' EXIT

pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
has() { grep -q -- "$2" "$1" && return 0; bad "$3: '$2' not in $(head -c 600 "$1")"; return 1; }

# no_trace NAME WHAT: neither T/NAME nor a temporary T/NAME.tmp.* is left
no_trace() {
  [ ! -e "$T/$1" ] && ok || bad "$2: $1 left behind"
  if compgen -G "$T/$1.tmp.*" >/dev/null; then bad "$2: a temporary left: $(ls "$T")"; else ok; fi
}
# vcd NAME WHAT: T/NAME is a whole VCD (header, timestamps, no temporary)
vcd() {
  [ -s "$T/$1" ] || { bad "$2: no $1"; return; }
  ok
  has "$T/$1" '^\$enddefinitions \$end' "$2: VCD header" && ok
  local n; n=$(grep -c '^#[0-9]' "$T/$1")
  [ "$n" -ge 4 ] && ok || bad "$2: $n timestamps in $1"
  if compgen -G "$T/$1.tmp.*" >/dev/null; then bad "$2: a temporary left beside $1"; else ok; fi
}

LONG=(run --steps 4000000000 --trace-window 0:all --trace-limit none)

# ---- a short run: the file appears, whole, and no temporary -------------
"$FP3" run --steps 3 --trace "$T/a.vcd" >/dev/null 2>"$T/a.err"; rc=$?
[ $rc -eq 0 ] && ok || bad "run --steps 3 --trace: exit $rc: $(cat "$T/a.err")"
vcd a.vcd "run --trace"
has "$T/a.err" "trace $T/a.vcd: cycles 0\.\.[0-9]* of the run's" "the note after the run" && ok
# a file of that name is replaced only at the end
echo old >"$T/b.vcd"
"$FP3" run --steps 2 --trace "$T/b.vcd" --trace-window 0:all >/dev/null 2>&1
vcd b.vcd "run --trace over an old file"

# ---- while tracing: only the temporary exists ---------------------------
"$FP3" "${LONG[@]}" --trace "$T/w.vcd" >/dev/null 2>&1 &
pid=$!
for _ in $(seq 100); do compgen -G "$T/w.vcd.tmp.$pid" >/dev/null && break; sleep 0.1; done
compgen -G "$T/w.vcd.tmp.$pid" >/dev/null && ok || bad "no temporary w.vcd.tmp.$pid while tracing"
[ ! -e "$T/w.vcd" ] && ok || bad "w.vcd exists before the run finished"
kill -TERM "$pid"; wait "$pid"; rc=$?
[ $rc -eq 143 ] && ok || bad "SIGTERM while tracing: exit $rc, want 143"
no_trace w.vcd "SIGTERM (background)"

# ---- SIGTERM and SIGINT: no file, no temporary, the signal's status -----
timeout --preserve-status -s TERM 2 "$FP3" "${LONG[@]}" --trace "$T/t.vcd" >/dev/null 2>&1
rc=$?
[ $rc -eq 143 ] && ok || bad "timeout -s TERM: exit $rc, want 143 (SIGTERM)"
no_trace t.vcd "SIGTERM"
timeout --preserve-status -s INT 2 "$FP3" "${LONG[@]}" --trace "$T/i.vcd" >/dev/null 2>&1
rc=$?
[ $rc -eq 130 ] && ok || bad "timeout -s INT: exit $rc, want 130 (SIGINT)"
no_trace i.vcd "SIGINT"
# an older file of the name is left as it was
echo old >"$T/o.vcd"
timeout --preserve-status -s TERM 2 "$FP3" "${LONG[@]}" --trace "$T/o.vcd" >/dev/null 2>&1
[ "$(cat "$T/o.vcd")" = old ] && ok || bad "SIGTERM: the old o.vcd was changed"

# ---- a run the engine fails: no file ----------------------------------
# a program of 40 registers on the default build's 32: writing its .in
# register fails before the run
printf '.regs 40\n.integrator euler\n.in T, r35\n.out v, r5\n.out s, r6\nbody:\n  add r5, r5, r35\n  endi body\n' \
  >"$T/regs.s"
"$FP3" run --program "$T/regs.s" --steps 2 --trace "$T/f.vcd" >/dev/null 2>"$T/f.err"; rc=$?
[ $rc -eq 1 ] && ok || bad "a program of 40 registers: exit $rc: $(head -3 "$T/f.err")"
has "$T/f.err" "register r35 out of range" "a program of 40 registers" && ok
no_trace f.vcd "a failed run"

# ---- the size estimate and --trace-limit --------------------------------
# 10,000 integrations of the ship (about 1.1 million cycles, about 24 KB
# each): about 30 GiB, above the default 1 GiB
# (timeout: a CLI without the limit would write those 30 GiB)
timeout 20 "$FP3" run --steps 10000 --trace "$T/l.vcd" --trace-window 0:all >/dev/null \
  2>"$T/l.err"; rc=$?
[ $rc -eq 2 ] && ok || bad "a 30 GiB trace: exit $rc, want 2"
has "$T/l.err" "about [0-9.]* GiB" "the estimate" && ok
has "$T/l.err" "window 0:all" "the window" && ok
has "$T/l.err" "--trace-limit SIZE" "the option that raises the limit" && ok
no_trace l.vcd "a refused trace"
# 3 integrations, the whole run: about 9 MiB; a limit of 1M refuses it, 40M
# and none let it run
"$FP3" run --steps 3 --trace "$T/m1.vcd" --trace-window 0:all --trace-limit 1M \
  >/dev/null 2>"$T/m1.err"; rc=$?
[ $rc -eq 2 ] && ok || bad "--trace-limit 1M: exit $rc, want 2"
has "$T/m1.err" "about [0-9.]* MiB .*above the limit of 1 MiB" "--trace-limit 1M" && ok
no_trace m1.vcd "--trace-limit 1M"
"$FP3" run --steps 3 --trace "$T/m40.vcd" --trace-window 0:all --trace-limit 40M \
  >/dev/null 2>&1; rc=$?
[ $rc -eq 0 ] && ok || bad "--trace-limit 40M: exit $rc"
vcd m40.vcd "--trace-limit 40M"
"$FP3" run --steps 3 --trace "$T/n.vcd" --trace-window 0:all --trace-limit none \
  >/dev/null 2>&1; rc=$?
[ $rc -eq 0 ] && ok || bad "--trace-limit none: exit $rc"
vcd n.vcd "--trace-limit none"
"$FP3" run --steps 3 --trace "$T/n2.vcd" --trace-window 0:all --trace-limit=41943040 \
  >/dev/null 2>&1; rc=$?
[ $rc -eq 0 ] && ok || bad "--trace-limit=41943040 (bytes): exit $rc"
for arg in 5X 0 -1 "" 1.5G 99999999999999999999T; do
  out=$("$FP3" run --steps 2 --trace "$T/x.vcd" --trace-limit "$arg" 2>&1); rc=$?
  [ $rc -eq 2 ] && grep -q -- "--trace-limit '$arg': want a size" <<<"$out" && ok ||
    bad "--trace-limit '$arg': exit $rc: $out"
done
no_trace x.vcd "bad --trace-limit"

# ---- fp3 run --model --trace --------------------------------------------
SPRING=(run --model models/spring.fp3m --set h=0.015625 --set k=40 --set c=0.8 --set m=2
        --set x=0.5 --set v=-0.25)
"$FP3" "${SPRING[@]}" --steps 5 --trace "$T/s.vcd" >"$T/s.out" 2>"$T/s.err"; rc=$?
[ $rc -eq 0 ] && ok || bad "run --model --trace: exit $rc: $(cat "$T/s.err")"
vcd s.vcd "run --model --trace"
has "$T/s.err" "trace $T/s.vcd: cycles 0\.\.[0-9]* of the run's" "run --model: the note" && ok
has "$T/s.out" "PASS" "run --model --trace: the run" && ok
"$FP3" "${SPRING[@]}" --steps 5 --trace "$T/s2.vcd" --trace-window 20:all >/dev/null 2>&1
vcd s2.vcd "run --model --trace-window 20:all"
# the model's limit comes from the compiler's cycles per integration
timeout 20 "$FP3" "${SPRING[@]}" --steps 1000000 --trace "$T/s3.vcd" --trace-window 0:all \
  >/dev/null 2>"$T/s3.err"; rc=$?
[ $rc -eq 2 ] && ok || bad "run --model, a huge trace: exit $rc, want 2"
has "$T/s3.err" "GiB.*--trace-limit SIZE" "run --model: the limit" && ok
no_trace s3.vcd "run --model, a refused trace"
out=$("$FP3" "${SPRING[@]}" --engine iss --trace "$T/s4.vcd" 2>&1); rc=$?
[ $rc -eq 2 ] && grep -q -- "--trace needs --engine rtl" <<<"$out" && ok ||
  bad "run --model --engine iss --trace: exit $rc: $out"
out=$("$FP3" "${SPRING[@]}" --objects 4 --trace "$T/s4.vcd" 2>&1); rc=$?
[ $rc -eq 2 ] && grep -q -- "--trace is for one object" <<<"$out" && ok ||
  bad "run --model --objects 4 --trace: exit $rc: $out"
out=$("$FP3" run --scene scenes/springs.scene --trace "$T/s4.vcd" 2>&1); rc=$?
[ $rc -eq 2 ] && grep -q -- "--trace is for one object" <<<"$out" && ok ||
  bad "run --scene MODEL_SCENE --trace: exit $rc: $out"
out=$("$FP3" "${SPRING[@]}" --trace "$T/nodir/s.vcd" 2>&1); rc=$?
[ $rc -eq 2 ] && grep -q -- "cannot write the trace file $T/nodir/s.vcd ($T/nodir: " <<<"$out" &&
  ok || bad "run --model --trace into a missing folder: exit $rc: $out"
no_trace s4.vcd "run --model, refused options"
# a model run killed while tracing
timeout --preserve-status -s TERM 2 "$FP3" "${SPRING[@]}" --steps 4000000000 \
  --trace "$T/sk.vcd" --trace-window 0:all --trace-limit none >/dev/null 2>&1; rc=$?
[ $rc -eq 143 ] && ok || bad "run --model, SIGTERM: exit $rc, want 143"
no_trace sk.vcd "run --model, SIGTERM"

echo "test_trace: $pass passed, $fail failed"
[ $fail -eq 0 ]
