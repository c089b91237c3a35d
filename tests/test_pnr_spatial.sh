#!/usr/bin/env bash
# test_pnr_spatial.sh -- make pnr-spatial's reuse of a netlist
# (scripts/pnr-spatial.sh, docs/spatial.md "Chip builds"): a sweep run in
# parts synthesizes its chip once.  Yosys and nextpnr are stand-ins here
# (YOSYS, NEXTPNR_ECP5): the stand-in Yosys writes the files synth.sh
# reads and counts its syntheses; the stand-in nextpnr fails, so each run
# ends at placement ("does not place and route").  On the ship's folded
# rk4se chip of 1 pipeline:
#   - a first run synthesizes; the same run again does not, and says so;
#   - each input of the digest synthesizes again when it changes: the
#     generated modules (--round rtz), SYNTH_ECP5_SDFF, Yosys's version;
#   - a synthesis that fails leaves no digest, so the next run of the same
#     inputs synthesizes (a digest written before synthesis would reuse a
#     half-written folder);
#   - a netlist file removed from the folder synthesizes again.
set -euo pipefail
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
[ -x "$FP3" ] || { echo "test_pnr_spatial.sh: $FP3 not built (make build/fp3)" >&2; exit 1; }
tmp=$(mktemp -d /tmp/fp3_test_pnr_spatial.XXXXXX); trap 'rm -rf "$tmp"' EXIT
fail=0 pass=0

# The stand-in Yosys: `-V` prints $FAKE_YOSYS_VERSION; otherwise it reads
# the top (hierarchy -top), the kept module (*NAME*) and the output files
# from the script, writes them (a stat with the two sections synth.sh and
# pnr-spatial.sh read) and adds a line to $FAKE_COUNT; FAKE_FAIL=1 fails
# after writing half the files, as a Yosys run stopped midway would.
cat > "$tmp/yosys" <<'EOF'
#!/usr/bin/env bash
[ "$1" = -V ] && { echo "Yosys ${FAKE_YOSYS_VERSION:-0.0}"; exit 0; }
script=${*: -1}
top=$(sed -n 's/.*hierarchy -check -top \([^ ]*\).*/\1/p' <<<"$script" | head -1)
keep=$(sed -n 's/.*set keep_hierarchy 1 \*\([^*]*\)\*.*/\1/p' <<<"$script" | head -1)
json=$(sed -n 's/.*write_json \([^ ]*\).*/\1/p' <<<"$script")
stat=$(sed -n 's/.*tee -q -o \([^ ]*\) stat.*/\1/p' <<<"$script")
net=$(sed -n 's/.*write_verilog -noattr \([^ ]*\).*/\1/p' <<<"$script")
echo '{"modules": {}}' > "$json"
[ "${FAKE_FAIL:-0}" = 1 ] && exit 1
printf '=== %s ===\n\n     LUT4  100\n     TRELLIS_FF  50\n\n=== %s ===\n\n     LUT4  10\n     TRELLIS_FF  5\n' \
  "$keep" "$top" > "$stat"
echo "// stand-in netlist" > "$net"
echo synth >> "$FAKE_COUNT"
EOF
printf '#!/usr/bin/env bash\nexit 1\n' > "$tmp/nextpnr"
chmod +x "$tmp/yosys" "$tmp/nextpnr"
export YOSYS="$tmp/yosys" NEXTPNR_ECP5="$tmp/nextpnr" FAKE_COUNT="$tmp/count" FP3_BIN="$FP3"
: > "$FAKE_COUNT"
out="$tmp/chip"

# run LABEL WANT [OPTION...]: one pnr-spatial run; WANT "synth" (a
# synthesis) or "reuse" (none, and the message that says so).
run() {
  local label=$1 want=$2; shift 2
  local before after rc=0
  before=$(wc -l < "$FAKE_COUNT")
  bash scripts/pnr-spatial.sh "$out" models/ship.fp3m rk4se 1 "" --clock-cores "$@" \
    > "$tmp/run.log" 2>&1 || rc=$?
  after=$(wc -l < "$FAKE_COUNT")
  local got=reuse; [ "$after" -gt "$before" ] && got=synth
  if [ "$rc" -ne 1 ] || ! grep -q "does not place and route" "$tmp/run.log"; then
    echo "FAIL: $label: the run did not end at the stand-in nextpnr (exit $rc)"; sed 's/^/  /' "$tmp/run.log"
    fail=$((fail + 1)); return
  fi
  if [ "$got" != "$want" ] ||
     { [ "$want" = reuse ] && ! grep -q "synthesis inputs are unchanged" "$tmp/run.log"; }; then
    echo "FAIL: $label: wanted $want, got $got"; sed 's/^/  /' "$tmp/run.log"
    fail=$((fail + 1)); return
  fi
  echo "PASS: $label: $want"; pass=$((pass + 1))
}

run "first run" synth
[ -s "$out/synth/inputs.sha256" ] || { echo "FAIL: no inputs.sha256 after a synthesis"; fail=$((fail + 1)); }
run "the same run again" reuse
run "--round rtz (other generated modules)" synth --round rtz
run "back to the default rounding" synth
run "and again" reuse
SYNTH_ECP5_SDFF=1 run "SYNTH_ECP5_SDFF=1" synth
run "SYNTH_ECP5_SDFF back to 0" synth
FAKE_YOSYS_VERSION=9.9 run "another Yosys version" synth
run "the first Yosys again" synth
# A failed synthesis (of new inputs: Yosys 8.8): synth.sh fails, so
# pnr-spatial stops before placement; then a run of the same inputs must
# synthesize.
export FAKE_YOSYS_VERSION=8.8
rc=0; FAKE_FAIL=1 bash scripts/pnr-spatial.sh "$out" models/ship.fp3m rk4se 1 "" --clock-cores \
  > "$tmp/run.log" 2>&1 || rc=$?
if [ "$rc" -ne 0 ] && [ ! -e "$out/synth/inputs.sha256" ]; then
  echo "PASS: a failed synthesis exits $rc and leaves no inputs.sha256"; pass=$((pass + 1))
else
  echo "FAIL: a failed synthesis: exit $rc, inputs.sha256 $([ -e "$out/synth/inputs.sha256" ] && echo kept || echo removed)"
  fail=$((fail + 1))
fi
run "after the failed synthesis" synth
run "and again" reuse
rm "$out/synth/"*_ecp5_stat.txt
run "the stat report removed" synth

echo "test_pnr_spatial: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
