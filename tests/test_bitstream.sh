#!/usr/bin/env bash
# test_bitstream.sh -- scripts/bitstream.sh (make bitstream BOARD=...), with
# stand-ins for nextpnr (NEXTPNR_ECP5) and ecppack (ECPPACK), so that its
# verdict is checked without a quarter of an hour of place and route: a
# clock that meets its constraint gives a bitstream and exit status 0; one
# that misses, exit status 1, "MISSES" and no bitstream; a design that does
# not place, exit status 1 with nextpnr's error shown.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

# nextpnr's stand-in: the derived clock's Fmax from FAKE_FMAX (empty: the
# design does not place), its constraint 100 MHz.
cat > "$tmp/fake-nextpnr" <<'FAKE'
#!/usr/bin/env bash
report= cfg= log=
while [ $# -gt 0 ]; do
  case "$1" in --report) report=$2; shift ;; --textcfg) cfg=$2; shift ;; -l) log=$2; shift ;; esac
  shift
done
echo "fake nextpnr" > "$log"
[ -n "$FAKE_FMAX" ] || { echo "ERROR: Unable to place cell 'u_fp3'" >> "$log"; exit 1; }
echo "configuration" > "$cfg"
cat > "$report" <<JSON
{"utilization": {"TRELLIS_COMB": {"used": 16000, "available": 83640},
                 "EHXPLLL": {"used": 1, "available": 4}},
 "fmax": {"\$glbnet\$clk": {"achieved": $FAKE_FMAX, "constraint": 100.0}}}
JSON
FAKE
cat > "$tmp/fake-ecppack" <<'FAKE'
#!/usr/bin/env bash
while [ $# -gt 0 ]; do [ "$1" = --bit ] && { echo bitstream > "$2"; }; shift; done
FAKE
chmod +x "$tmp/fake-nextpnr" "$tmp/fake-ecppack"
echo '{}' > "$tmp/top.json"; : > "$tmp/pins.lpf"
run() {
  NEXTPNR_ECP5="$tmp/fake-nextpnr" ECPPACK="$tmp/fake-ecppack" \
    bash scripts/bitstream.sh "$tmp/out$1" top "$tmp/top.json" "$tmp/pins.lpf" 100 --85k
}

out=$(FAKE_FMAX=107.4 run 1) || fail "107.4 MHz at 100: exit $?"
grep -q "Fmax 107.4 MHz meets its 100.0 MHz" <<< "$out" || fail "no verdict: $out"
[ -s "$tmp/out1/top.bit" ] || fail "no bitstream after timing was met"
rc=0; out=$(FAKE_FMAX=93.1 run 2) || rc=$?
[ "$rc" -eq 1 ] || fail "93.1 MHz at 100: exit $rc, not 1"
grep -q "Fmax 93.1 MHz MISSES its 100.0 MHz" <<< "$out" || fail "no MISSES: $out"
[ ! -e "$tmp/out2/top.bit" ] || fail "a bitstream although timing missed"
rc=0; out=$(FAKE_FMAX= run 3 2>&1) || rc=$?
[ "$rc" -eq 1 ] && grep -q "Unable to place" <<< "$out" || fail "a design that does not place: exit $rc, $out"
echo "PASS: test_bitstream (met: bitstream; missed: exit 1, no bitstream; not placed: exit 1)"
