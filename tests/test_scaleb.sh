#!/usr/bin/env bash
# test_scaleb.sh -- rtl/fp_scaleb.v (a multiply by +-2^k as an exponent
# adjustment, IEEE 754-2019 §5.3.3 scaleB) against the C reference: the
# harness sim/scaleb_tb.cpp drives sim/scaleb_top.v (RNE, RTZ, each with
# and without FTZ, at LATENCY 1, 2, 3 and 4: every register place) with
# directed edge cases times every power of two (39,624 pairs) and
# 2,000,000 random pairs, and every result
# and flag must equal fpref_mul's (sw/ref/fpref.h, which fp_mul equals),
# with valid_o LATENCY cycles after valid_i.  fp_scaleb must be
# `verilator --lint-only -Wall` clean at LATENCY 1 to 5 in every
# configuration.
#
# Runs from anywhere; the Verilated runtime comes from build/verilated
# (make builds it).
set -euo pipefail
cd "$(dirname "$0")/.."
. tests/verilated_env.sh
tmp=$(mktemp -d /tmp/fp3_test_scaleb.XXXXXX); trap 'rm -rf "$tmp"' EXIT
fail=0

for lat in 1 2 3 4 5; do
  for cfg in "0 0" "1 0" "0 1" "1 1"; do
    read -r round ftz <<<"$cfg"
    if ! $VERILATOR --lint-only -Wall -Irtl -y rtl --top-module fp_scaleb -GLATENCY=$lat \
        -GROUND=$round -GFTZ=$ftz rtl/fp_scaleb.v >"$tmp/lint.log" 2>&1; then
      head -20 "$tmp/lint.log"
      echo "FAIL: fp_scaleb LATENCY=$lat ROUND=$round FTZ=$ftz: verilator --lint-only -Wall"; fail=1
    fi
  done
done
[ "$fail" = 0 ] && echo "PASS: fp_scaleb is verilator -Wall clean at LATENCY 1 to 5, every ROUND and FTZ"

# the harness (the model unoptimised: the build is what takes time)
if { nice $VERILATOR --cc -Wall -Irtl -y rtl --top-module scaleb_top --Mdir "$tmp/obj" \
       sim/scaleb_top.v &&
     nice make -s -C "$tmp/obj" -f Vscaleb_top.mk VM_PARALLEL_BUILDS=0 OPT_FAST=-O1 OPT_SLOW=-O0 \
       Vscaleb_top__ALL.a &&
     nice g++ -O2 -std=c++17 -frounding-math -faligned-new -I"$VINC" -I"$VINC/vltstd" \
       -I"$tmp/obj" -Isw/ref -Isw/isa -x c++ sw/ref/fpref.c -x none sim/scaleb_tb.cpp \
       "$tmp/obj/Vscaleb_top__ALL.a" $RUNTIME -pthread -latomic -o "$tmp/tb"; } \
     >"$tmp/build.log" 2>&1; then
  if out=$("$tmp/tb" 2000000 2>&1); then
    echo "$out" | tail -1
  else
    echo "$out"; echo "FAIL: fp_scaleb differs from fpref_mul"; fail=1
  fi
else
  tail -20 "$tmp/build.log"; echo "FAIL: Verilator build of sim/scaleb_top.v"; fail=1
fi

[ "$fail" = 0 ] || exit 1
echo "PASS: test_scaleb"
