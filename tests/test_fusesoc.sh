#!/usr/bin/env bash
# test_fusesoc.sh -- the FuseSoC core description fp3.core works: it lists
# every RTL file, its lint target (Verilator -Wall) and sim target (the
# Icarus testbench) run through `fusesoc` and pass, their failures reach
# fusesoc's exit status, and the synth target sets up a Yosys project.
#
# Installs FuseSoC (pip, scripts/setup.sh) when missing.  Writes only to a
# temporary directory.  Uses $FP3_BIN (set by mk/sw.mk) or build/fp3.
set -u
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
command -v fusesoc >/dev/null || bash scripts/setup.sh >/dev/null
if ! command -v fusesoc >/dev/null; then echo "test_fusesoc: fusesoc not installed"; exit 1; fi
if [ ! -x "$FP3" ]; then echo "test_fusesoc: $FP3 not built"; exit 1; fi
T=$(mktemp -d /tmp/fp3_test_fusesoc.XXXXXX)
trap 'rm -rf "$T"' EXIT
pass=0; fail=0
ok()  { pass=$((pass + 1)); }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }
FS=(fusesoc --cores-root . run --build-root "$T/build")

# ---- the rtl fileset is rtl/*.v, no more, no less -------------------------
listed=$(sed -n 's/^ *- \(rtl\/[A-Za-z0-9_]*\.v\)$/\1/p' fp3.core | sort)
actual=$(ls rtl/*.v | sort)
if [ "$listed" = "$actual" ]; then ok; else
  bad "fp3.core rtl fileset differs from rtl/*.v"; diff <(echo "$listed") <(echo "$actual"); fi

# ---- lint: verilator --lint-only -Wall through fusesoc --------------------
start=$(date +%s)
"${FS[@]}" --target lint fp3 >"$T/lint.log" 2>&1; rc=$?
[ $rc -eq 0 ] && ok || { bad "fusesoc lint exited $rc"; tail -20 "$T/lint.log"; }
echo "fusesoc lint: $(( $(date +%s) - start ))s"

# a lint warning fails the target: a core whose top has an unused input
mkdir -p "$T/neg"
cat >"$T/neg/neg.v" <<'EOF'
module neg (input wire a, input wire b, output wire y);
  assign y = a;
endmodule
EOF
cat >"$T/neg/neg.core" <<'EOF'
CAPI=2:
name: ::neg:0
filesets:
  rtl: {files: [neg.v], file_type: verilogSource}
targets:
  lint:
    filesets: [rtl]
    toplevel: neg
    default_tool: verilator
    tools: {verilator: {mode: lint-only, verilator_options: [-Wall]}}
EOF
fusesoc --cores-root "$T/neg" run --build-root "$T/build" --target lint neg >"$T/neg.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "fusesoc lint passed a design with an unused input"
grep -q "UNUSED" "$T/neg.log" && ok || bad "fusesoc lint: no UNUSED warning shown"

# ---- sim: the Icarus testbench through fusesoc ---------------------------
"$FP3" tbgen programs/ship_rk4.s -o "$T/wave" --steps 2 >"$T/tbgen.log" 2>&1 || {
  bad "fp3 tbgen failed"; cat "$T/tbgen.log"; }
start=$(date +%s)
"${FS[@]}" --target sim fp3 --dir "$T/wave" >"$T/sim.log" 2>&1; rc=$?
[ $rc -eq 0 ] && ok || { bad "fusesoc sim exited $rc"; tail -20 "$T/sim.log"; }
grep -q "^PASS: tb_fp3: 1 context(s) x 2 integrations" "$T/sim.log" && ok || bad "fusesoc sim: no PASS"
echo "fusesoc sim: $(( $(date +%s) - start ))s"
# ... with lanes (NUM_LANES, a parameter of the core): every lane checked
"${FS[@]}" --target sim fp3 --dir "$T/wave" --NUM_LANES 2 >"$T/sim_lanes.log" 2>&1; rc=$?
[ $rc -eq 0 ] && ok || { bad "fusesoc sim --NUM_LANES 2 exited $rc"; tail -20 "$T/sim_lanes.log"; }
grep -q "^PASS: tb_fp3: 1 context(s) x 2 integrations.*2 lane(s) per context" "$T/sim_lanes.log" \
  && ok || bad "fusesoc sim --NUM_LANES 2: no PASS with 2 lanes"
# a FAIL of the testbench fails the target
cp -r "$T/wave" "$T/wave_bad"
line=$(grep -n -- '// 1: v' "$T/wave/expected.hex" | head -1)    # v after integration 1
n=${line%%:*}; line=${line#*:}; word=${line%% *}
sed "${n}s/^$word/$(printf '%08x' $(( 16#$word ^ 1 )))/" "$T/wave/expected.hex" >"$T/wave_bad/expected.hex"
cmp -s "$T/wave/expected.hex" "$T/wave_bad/expected.hex" && bad "could not corrupt expected.hex"
"${FS[@]}" --target sim fp3 --dir "$T/wave_bad" >"$T/sim_bad.log" 2>&1; rc=$?
[ $rc -ne 0 ] && ok || bad "fusesoc sim passed a corrupted expected value"
grep -q "^FAIL: tb_fp3" "$T/sim_bad.log" && ok || bad "fusesoc sim: no FAIL line"

# ---- synth: the Yosys project is set up (make synth runs synthesis) ------
"${FS[@]}" --setup --target synth fp3 >"$T/synth.log" 2>&1; rc=$?
[ $rc -eq 0 ] && ok || { bad "fusesoc synth --setup exited $rc"; tail -20 "$T/synth.log"; }
if grep -rqs "synth_xilinx" "$T/build"/*/synth-yosys/; then ok; else
  bad "fusesoc synth: no synth_xilinx in the generated project"; fi

echo "test_fusesoc: $pass passed, $fail failed"
[ $fail -eq 0 ]
