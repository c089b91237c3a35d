#!/usr/bin/env bash
# test_delay_ebr.sh -- fp_delay's ECP5 block-RAM form (STYLE 2 with
# FP3_ECP5_EBR: rtl/fp_delay.v), which only synthesis sees: the ECP5 flow
# (scripts/synth.sh) maps a delay line of up to 512 words to one PDPW16KD
# with REGMODE OUTREG, no LUT RAM and no fabric read register, and the
# netlist, simulated by Icarus with the model of the block
# (sim/ecp5_pdpw16kd.v), delays every word exactly as the RTL form that the
# simulators see (random words, every cycle compared once the line is
# full): at the shortest delay (3: a word read one cycle after its
# write), at 100, and at 510 (512 words, the block full).  A line of more
# than 512 words keeps the inferred form (block RAM, no output register).
# Shown to fail: the read address one word off (BACK + 1) fails every
# depth's comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

# synth DEPTH: the ECP5 flow's netlist of a 32-bit STYLE 2 line; prints its
# base name
synth() {
  bash scripts/synth.sh "$tmp" fp_delay ecp5 WIDTH=32 DEPTH="$1" STYLE=2 rtl/fp_delay.v rtl/fp3_ram.v \
    >"$tmp/synth-$1.log" 2>&1 || { tail -20 "$tmp/synth-$1.log" >&2; echo "FAIL: synth.sh ecp5 fp_delay DEPTH=$1" >&2; exit 1; }
  echo "$tmp/fp_delay_WIDTH-32_DEPTH-$1_STYLE-2_ecp5"
}
# Yosys's simulation models of the ECP5 cells (LUT4, TRELLIS_FF, ...), as a
# library: only the cells the netlist uses, the block RAM from our model
cells="$(dirname "$(command -v "${YOSYS:-yosys}")")/../share/yosys/ecp5/cells_sim.v"
[ -f "$cells" ] || { echo "FAIL: no Yosys ECP5 cell models at $cells"; exit 1; }
count() { awk -v c="$2" '$1 == c { n = $2 } END { print n + 0 }' "$1_stat.txt"; }

for depth in 3 100 510; do
  base=$(synth "$depth")
  if [ "$(count "$base" PDPW16KD)" != 1 ] || [ "$(count "$base" DP16KD)" != 0 ] ||
     [ "$(count "$base" TRELLIS_DPR16X4)" != 0 ] || [ "$(grep -c 'REGMODE("OUTREG")' "$base.v")" != 1 ]; then
    cat "$base"_stat.txt; echo "FAIL: DEPTH $depth is not one PDPW16KD with its output register"; exit 1
  fi
  # the netlist beside the RTL: every cycle's word equal once DEPTH words went in
  sed 's/^module fp_delay(/module fp_delay_ebr(/' "$base.v" >"$tmp/net.v"
  grep -q '^module fp_delay_ebr(' "$tmp/net.v" || { echo "FAIL: no module fp_delay in the netlist"; exit 1; }
  cat >"$tmp/tb.v" <<EOF
module tb;
  reg clk = 1'b0;
  reg [31:0] d = 32'd0;
  wire [31:0] q_rtl, q_net;
  fp_delay #(.WIDTH(32), .DEPTH($depth), .STYLE(2)) u_rtl (.clk_i(clk), .data_i(d), .data_o(q_rtl));
  fp_delay_ebr u_net (.clk_i(clk), .data_i(d), .data_o(q_net));
  integer t, seed = $depth;
  always #5 clk = !clk;
  initial begin
    for (t = 0; t < 3000; t = t + 1) begin
      @(negedge clk);
      if (t >= $depth + 2 && q_rtl !== q_net) begin
        \$display("DEPTH $depth, cycle %0d: RTL %h, netlist %h", t, q_rtl, q_net);
        \$display("FAIL");
        \$finish;
      end
      d = \$random(seed);
    end
    \$display("PASS");
    \$finish;
  end
endmodule
EOF
  iverilog -g2005 -Irtl -I"$(dirname "$cells")" -s tb -o "$tmp/tb.vvp" rtl/fp_delay.v rtl/fp3_ram.v "$tmp/net.v" \
    sim/ecp5_pdpw16kd.v "$tmp/tb.v" -l "$cells" 2>"$tmp/iv.log" || { cat "$tmp/iv.log"; echo "FAIL: iverilog, DEPTH $depth"; exit 1; }
  vvp -n "$tmp/tb.vvp" >"$tmp/sim.log"
  grep -q '^PASS' "$tmp/sim.log" || { tail -3 "$tmp/sim.log"; echo "FAIL: the block form delays differently (DEPTH $depth)"; exit 1; }
  echo "PASS: DEPTH $depth: one PDPW16KD, REGMODE OUTREG; the netlist delays as the RTL, 3,000 cycles"
done

# More than 512 words: the inferred form (no output register)
base=$(synth 514)
if [ "$(count "$base" PDPW16KD)$(count "$base" DP16KD)" = 00 ] || grep -q 'REGMODE("OUTREG")' "$base.v"; then
  cat "$base"_stat.txt; echo "FAIL: DEPTH 514 (1024 words) is not the inferred block RAM"; exit 1
fi
echo "PASS: DEPTH 514 (1024 words): block RAM inferred, without the output register"
echo "PASS: test_delay_ebr"
