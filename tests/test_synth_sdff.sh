#!/usr/bin/env bash
# test_synth_sdff.sh -- scripts/synth.sh's SYNTH_ECP5_SDFF=0 (the flow of
# make pnr-spatial, docs/spatial.md "Flip-flops without a set or reset"):
# Yosys folds a register's `q <= c ? 0 : d` into the flip-flop's LSR input,
# so that each such register has an LSR net of its own, and nextpnr cannot
# legalise such flip-flops on a chip above about 78 % full.  fp_mul with
# its feed register (LATENCY 10, FEED 1) has such registers:
#   - with the default flow (SYNTH_ECP5_SDFF=1) some TRELLIS_FF has an LSR
#     net that is neither a constant nor rst_i (the check below can fail);
#   - with SYNTH_ECP5_SDFF=0 every TRELLIS_FF's LSR is a constant, the
#     netlist passes synth.sh's checks, and it has as many flip-flops and
#     MULT18X18D as the default flow's.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d /tmp/fp3_test_synth_sdff.XXXXXX); trap 'rm -rf "$tmp"' EXIT

for v in 1 0; do
  SYNTH_ECP5_SDFF=$v bash scripts/synth.sh "$tmp/s$v" fp_mul ecp5 LATENCY=10 FEED=1 rtl/*.v \
    >"$tmp/synth$v.log" 2>&1 || { tail -20 "$tmp/synth$v.log"; echo "FAIL: synth.sh, SYNTH_ECP5_SDFF=$v"; exit 1; }
done

# "FLIP-FLOPS LOGIC_LSR MULT18X18D" of a netlist: LOGIC_LSR counts the
# flip-flops whose LSR is driven by a net other than a constant or rst_i.
count() {
  python3 - "$1" <<'EOF'
import json, sys
m = json.load(open(sys.argv[1]))["modules"]["fp_mul"]
rst = set(m["netnames"]["rst_i"]["bits"])
ff = logic = mult = 0
for cell in m["cells"].values():
    if cell["type"] == "MULT18X18D":
        mult += 1
    if cell["type"] != "TRELLIS_FF":
        continue
    ff += 1
    lsr = cell["connections"].get("LSR", ["0"])
    if cell["parameters"].get("LSRMUX", "LSR").strip() == "LSR" and \
            any(not isinstance(b, str) and b not in rst for b in lsr):
        logic += 1
print(ff, logic, mult)
EOF
}
read -r ff1 lsr1 m1 < <(count "$tmp/s1/fp_mul_LATENCY-10_FEED-1_ecp5.json")
read -r ff0 lsr0 m0 < <(count "$tmp/s0/fp_mul_LATENCY-10_FEED-1_ecp5.json")
[ "$lsr1" -gt 0 ] || { echo "FAIL: the default flow has no flip-flop with a logic-driven LSR ($ff1 flip-flops): the check below proves nothing"; exit 1; }
echo "PASS: the default flow: $lsr1 of $ff1 flip-flops have a logic-driven LSR"
[ "$lsr0" -eq 0 ] || { echo "FAIL: SYNTH_ECP5_SDFF=0 left $lsr0 flip-flops with a logic-driven LSR"; exit 1; }
[ "$ff0" -eq "$ff1" ] && [ "$m0" -eq "$m1" ] || {
  echo "FAIL: SYNTH_ECP5_SDFF=0: $ff0 flip-flops, $m0 MULT18X18D against $ff1, $m1"; exit 1; }
echo "PASS: SYNTH_ECP5_SDFF=0: no flip-flop with a logic-driven LSR ($ff0 flip-flops, $m0 MULT18X18D, as the default flow)"
