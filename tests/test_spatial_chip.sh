#!/usr/bin/env bash
# test_spatial_chip.sh -- the spatial chip (`fp3 spatial --pipelines N
# --objects M`, docs/spatial.md "The frame"): the generated top is the
# same text twice, `verilator --lint-only -Wall` clean, and Verilated
# with the harness sim/spatial_chip_tb.cpp, which drives it only through
# AXI4-Lite and the register map of sw/isa/fp3_spatial_regs.h: ID, HASH,
# INFO, LATENCY, MAXOBJ, STRIDES; every object's inputs and state written
# and read back;
# the SLVERR cases; runs over awake lists that skip objects, with fewer
# awake objects than the latency and with more than N x L, after which
# every object must equal the golden model bit for bit (the sleeping ones
# unchanged) and CYCLES must equal the formula; the checks while running.
# On the ship's folded RK4 step (latency 68) with 3 pipelines and 252
# objects; `--all` also with 1 pipeline and 96 (outside make test: the
# 1-pipeline chip, with its trace port, is the spatial engine's, which
# tests/test_spatial_engine.sh runs bit-exact through the same slave).
#
# The slave's divider by N (fp3_spatial_divn) is checked alone, on every
# 10-bit dividend, for N = 1, 2, 3, 5, 12 and 255 (iverilog).
# A broken frame must fail (on 3 pipelines): the feeder reading an object
# one cycle before its write-back has landed (PERIOD L + 1), and a frame
# that never feeds bank 1.  `--mutants` (which implies --all) also runs
# the other broken frames (write-back one
# cycle early, DONE a cycle late, the awake entry's bank unchecked, INFO's
# fields swapped, windows writable while running, an input write landing
# in every word, a write response before the write, the read's word
# captured a cycle before the frame's read has arrived or a cycle after, a
# window read performed as START reaches the frame), outside make test.
# Bad --pipelines / --objects exit 2 and leave no file.
#
# Runs from anywhere; the CLI is $FP3_BIN, else build/fp3 of this checkout.
# The Verilated runtime comes from build/verilated (make builds it).
set -euo pipefail
all= mutants=
for a in "$@"; do
  case $a in
    --all) all=1;;
    --mutants) all=1 mutants=1;;
    *) echo "usage: $0 [--all] [--mutants]" >&2; exit 2;;
  esac
done
cd "$(dirname "$0")/.."
. tests/verilated_env.sh
tmp=$(mktemp -d /tmp/fp3_test_spatial_chip.XXXXXX); trap 'rm -rf "$tmp"' EXIT
fail=0
MODEL="models/ship.fp3m --integrator rk4se"
TOP=fp3_spatial_ship_rk4se_top
STEP=fp3_spatial_ship_rk4se

# build RTLDIR GENDIR OBJDIR EXE: the harness on the chip top of GENDIR
# with the frame's RTL from RTLDIR (rtl/, or a broken copy).  One
# translation unit, unoptimised: the build, not the run, takes the time.
# The executable is kept in $TBCACHE as tb-KEY, KEY a hash of every input
# of the build (the RTL, the generated top and step, the harness and the
# map it includes, the runtime, the tools' versions), so a later run on
# the same sources builds nothing and any change builds anew.
TBCACHE=${FP3_SPATIAL_TB_CACHE:-$PWD/build/spatial-chip-tb}
build() {
  local key
  key=$(cat "$1"/*.v rtl/*.v rtl/*.vh "$2/$TOP.v" "$2/$STEP.v" sim/spatial_chip_tb.cpp \
          sw/isa/*.h $RUNTIME | cat - <($VERILATOR --version; g++ --version) |
        sha256sum | cut -c1-16)
  if [ -x "$TBCACHE/tb-$key" ]; then cp "$TBCACHE/tb-$key" "$4"; return; fi
  build_tb "$@" || return 1
  mkdir -p "$TBCACHE" && cp "$4" "$TBCACHE/tb-$key.tmp.$$" &&
    mv "$TBCACHE/tb-$key.tmp.$$" "$TBCACHE/tb-$key"
}
build_tb() {
  { nice $VERILATOR --cc --x-assign fast --x-initial fast --noassert -I"$1" -y "$1" -Irtl -y rtl \
      --top-module $TOP --prefix Vchip --Mdir "$3" "$2/$TOP.v" "$2/$STEP.v" &&
    nice make -s -C "$3" -f Vchip.mk VM_PARALLEL_BUILDS=0 OPT_FAST=-O0 OPT_SLOW=-O0 \
      Vchip__ALL.a &&
    nice g++ -O1 -std=c++17 -faligned-new -I"$VINC" -I"$VINC/vltstd" -I"$3" -Isw/isa \
      sim/spatial_chip_tb.cpp "$3/Vchip__ALL.a" $RUNTIME -pthread -latomic -o "$4"; } \
    >"$3.log" 2>&1 || { tail -20 "$3.log"; return 1; }
}

# gen N M: the top, the step and vectors of M objects, 5 steps, in $tmp/nN
gen() {
  local d="$tmp/n$1"
  # shellcheck disable=SC2086
  "$FP3" spatial $MODEL --pipelines "$1" --objects "$2" --vectors "$2" --steps 5 \
    -o "$d" 2>"$d.log" || { cat "$d.log"; echo "FAIL: fp3 spatial --pipelines $1"; return 1; }
}

# run_tb EXE N M: the harness on the vectors of $tmp/nN
run_tb() {
  local d="$tmp/n$2"
  "$1" "$d/vectors.txt" "$2" "$3" "$(sed -n 's/^hash: \([0-9a-f]*\).*/\1/p' "$d/report.txt")"
}

# mutant NAME N M FILE PYTHON-REPLACEMENT CHECK: a copy of rtl/FILE with
# one replacement (old => new, which must occur) must fail check CHECK.
mutant() {
  local name=$1 n=$2 m=$3 file=$4 old=$5 new=$6 check=$7
  local r="$tmp/rtl-$name"; mkdir -p "$r"
  if ! python3 - "rtl/$file" "$r/$file" "$old" "$new" <<'PY'; then
import sys
s = open(sys.argv[1]).read()
if sys.argv[3] not in s:
    sys.exit("mutant: text not found: " + sys.argv[3])
open(sys.argv[2], "w").write(s.replace(sys.argv[3], sys.argv[4], 1))
PY
    echo "FAIL: mutant $name: cannot apply"; fail=1; return
  fi
  if ! build "$r" "$tmp/n$n" "$tmp/obj-$name" "$tmp/tb-$name"; then
    echo "FAIL: mutant $name: Verilator build"; fail=1; return
  fi
  local out
  if out=$(run_tb "$tmp/tb-$name" "$n" "$m" 2>&1); then
    echo "FAIL: $name passes"; fail=1
  elif grep -q "^FAIL: $check:" <<<"$out"; then
    echo "PASS: $name fails the '$check' check: $(grep -m1 "^FAIL: $check:" <<<"$out")"
  else
    echo "$out" | tail -5; echo "FAIL: $name fails, but not the '$check' check"; fail=1
  fi
}

# the slave's division by N (rtl/fp3_spatial_divn.v), every 10-bit number
for n in 1 2 3 5 12 255; do
  if iverilog -g2005 -Wall -Irtl -P tb_spatial_divn.N=$n -P tb_spatial_divn.W=10 \
       -o "$tmp/divn.vvp" sim/tb_spatial_divn.v rtl/fp3_spatial_divn.v >"$tmp/divn.log" 2>&1 &&
     out=$(vvp -n "$tmp/divn.vvp" | tail -1) && [[ $out == PASS* ]]; then
    echo "$out"
  else
    cat "$tmp/divn.log"; echo "${out:-}"; echo "FAIL: fp3_spatial_divn N=$n"; fail=1
  fi
done

for nm in "3 252" ${all:+"1 96"}; do
  read -r n m <<<"$nm"
  gen "$n" "$m" || { fail=1; continue; }
  d="$tmp/n$n"
  # shellcheck disable=SC2086
  "$FP3" spatial $MODEL --pipelines "$n" --objects "$m" -o "$d-again" 2>/dev/null &&
    cmp -s "$d/$TOP.v" "$d-again/$TOP.v" || { echo "FAIL: N=$n: two runs write different tops"; fail=1; }
  if ! $VERILATOR --lint-only -Wall -Irtl -y rtl --top-module $TOP "$d/$TOP.v" "$d/$STEP.v" \
      >"$d.lint" 2>&1; then
    head -20 "$d.lint"; echo "FAIL: N=$n: verilator --lint-only -Wall"; fail=1
  fi
  # No latch for synthesis (make pnr-spatial's synth.sh fails on one; this
  # is its check after Yosys's proc alone, seconds instead of minutes).
  if ! ${YOSYS:-yosys} -q -p "read_verilog -Irtl $(ls rtl/*.v | tr '\n' ' ') $d/$STEP.v $d/$TOP.v;
      hierarchy -top $TOP; proc; select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr" \
      >"$d.latch" 2>&1; then
    grep -E "ERROR|Latch inferred" "$d.latch" | head -5; echo "FAIL: N=$n: a latch after yosys proc"; fail=1
  else
    echo "PASS: N=$n: no latch after yosys proc"
  fi
  if ! build rtl "$d" "$tmp/obj$n" "$tmp/tb$n"; then
    echo "FAIL: N=$n: Verilator build"; fail=1; continue
  fi
  if out=$(run_tb "$tmp/tb$n" "$n" "$m" 2>&1); then
    echo "$out" | sed 's/^/  /'
    echo "PASS: chip N=$n M=$m"
  else
    echo "$out" | tail -25; echo "FAIL: chip N=$n M=$m"; fail=1
  fi
done

# broken frames
mutant period-short 3 252 fp3_spatial_frame.v ".PERIOD(LATENCY + 3)" ".PERIOD(LATENCY + 2)" run
mutant bank1-unfed 3 252 fp3_spatial_frame.v "fv1_q <= !rst_i && feed &&" \
  "fv1_q <= !rst_i && feed && b != 1 &&" run
if [ -n "$mutants" ]; then
  mutant writeback-early 1 96 fp3_spatial_frame.v "fp_pipe #(.WIDTH(RW), .DEPTH(LATENCY + 2))" \
    "fp_pipe #(.WIDTH(RW), .DEPTH(LATENCY + 1))" run
  mutant flags-kept 1 96 fp3_spatial_frame.v "flags_q <= rst_i || (start_i && !running)" \
    "flags_q <= rst_i" flags
  mutant done-late 1 96 fp3_spatial_frame.v ".DRAIN(LATENCY + 4)" ".DRAIN(LATENCY + 5)" cycles
  mutant awake-bank-unchecked 3 252 fp3_spatial_axil.v "wd_bank == wa_bank_q" "1'b1" slverr
  mutant info-swapped 3 252 fp3_spatial_axil.v "CARRIED[7:0], INPUTS[7:0]" \
    "INPUTS[7:0], CARRIED[7:0]" id
  mutant busy-window-writable 1 96 fp3_spatial_axil.v \
    "(!busy && wk_ok_idle_q)" "(1'b1 && wk_ok_idle_q)" busy
  mutant busy-without-start 3 252 fp3_spatial_axil.v "wire busy = running_i || start_q;" \
    "wire busy = running_i;" busy
  mutant read-early 3 252 fp3_spatial_axil.v "RD_CYCLES  = 6;" "RD_CYCLES  = 5;" load
  mutant read-late 3 252 fp3_spatial_axil.v "RD_CYCLES  = 6;" "RD_CYCLES  = 7;" load
  mutant input-word-ignored 1 96 fp3_spatial_frame.v \
    "{NI{we && host_sel_i == SEL_INPUT}} & host_input_word" "{NI{we && host_sel_i == SEL_INPUT}}" load
  mutant b-before-w 1 96 fp3_spatial_axil.v "assign s_axil_bvalid_o  = b_valid_q;" \
    "assign s_axil_bvalid_o  = b_valid_q || aw_valid_q;" axi
fi

# bad --pipelines / --objects: exit 2, a message, nothing written
bad() {
  local what=$1; shift
  local rc=0
  # shellcheck disable=SC2086
  "$FP3" spatial $MODEL "$@" -o "$tmp/bad" >/dev/null 2>"$tmp/bad.log" || rc=$?
  if [ "$rc" != 2 ] || [ -e "$tmp/bad" ] || ! [ -s "$tmp/bad.log" ]; then
    echo "FAIL: $what: exit $rc (want 2 with a message and no files)"; fail=1
  else
    echo "PASS: $what: exit 2, '$(head -1 "$tmp/bad.log")', no files"
  fi
}
bad "--pipelines 0" --pipelines 0
bad "--pipelines 256" --pipelines 256
bad "--pipelines x" --pipelines x
bad "--objects without --pipelines" --objects 64
bad "--objects not a multiple of N" --pipelines 3 --objects 100
bad "--objects below 2N" --pipelines 3 --objects 3
bad "--objects beyond a window" --pipelines 1 --objects 1048576

[ "$fail" = 0 ] || exit 1
echo "PASS: test_spatial_chip"
