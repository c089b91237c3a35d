#!/usr/bin/env bash
# test_ram_ebr.sh -- fp3_ram's ECP5 form (block RAM with its output
# register, FP3_ECP5_EBR: rtl/fp3_ram.v), which only synthesis sees:
# the ECP5 flow (scripts/synth.sh) maps the instruction memory's shape (256
# x 75, two read cycles) to three PDPW16KD blocks with REGMODE OUTREG and
# no LUT RAM; the netlist,
# simulated by Icarus with a model of the block (sim/ecp5_pdpw16kd.v),
# reads what the LUT-RAM form reads (sim/tb_ram_ebr.v); and the form is
# not taken without the define, or deeper than one block (512 words); and
# the form Verilator simulates reads what the LUT-RAM form reads.
set -euo pipefail
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
# The ECP5 flow's own synthesis (scripts/synth.sh, as make synth and make
# pnr run it) of the instruction memory's shape.
bash scripts/synth.sh "$tmp" fp3_ram ecp5 DEPTH=256 AW=8 WIDTH=75 READ_STAGES=2 rtl/fp3_ram.v \
  >"$tmp/synth.log" 2>&1 || { tail -20 "$tmp/synth.log"; echo "FAIL: scripts/synth.sh ecp5 fp3_ram"; exit 1; }
base="$tmp/fp3_ram_DEPTH-256_AW-8_WIDTH-75_READ_STAGES-2_ecp5"
count() { awk -v c="$1" '$1 == c { n = $2 } END { print n + 0 }' "${base}_stat.txt"; }
[ "$(count PDPW16KD)" = 3 ] && [ "$(count TRELLIS_DPR16X4)" = 0 ] || {
  cat "${base}_stat.txt"; echo "FAIL: 256 x 75 is not three PDPW16KD without LUT RAM"; exit 1; }
[ "$(grep -c 'REGMODE("OUTREG")' "$base.v")" = 3 ] || {
  grep -n REGMODE "$base.v"; echo "FAIL: the blocks' output registers are not used"; exit 1; }
echo "PASS: scripts/synth.sh ecp5 maps 256 x 75 to 3 PDPW16KD, REGMODE OUTREG, no LUT RAM"

# The netlist, its module renamed beside the RTL's, simulated.
sed 's/^module fp3_ram(/module fp3_ram_ebr(/' "$base.v" > "$tmp/ram.v"
grep -q "^module fp3_ram_ebr(" "$tmp/ram.v" || { echo "FAIL: no module fp3_ram in the netlist"; exit 1; }
iverilog -g2005 -Irtl -s tb_ram_ebr -o "$tmp/tb.vvp" rtl/fp3_ram.v "$tmp/ram.v" \
  sim/ecp5_pdpw16kd.v sim/tb_ram_ebr.v 2>"$tmp/iv.log" || {
  cat "$tmp/iv.log"; echo "FAIL: iverilog on the block-RAM netlist"; exit 1; }
vvp -n "$tmp/tb.vvp" +cycles=20000 +seed=7 | tee "$tmp/sim.log" | tail -3
grep -q "^PASS" "$tmp/sim.log" || { echo "FAIL: the block-RAM form reads differently"; exit 1; }

# The form Verilator simulates (READ_STAGES = 2 with the lanes merged,
# under VERILATOR): Icarus with the define, renamed fp3_ram_vl, against
# the LUT-RAM form on random writes and reads, every cycle's word compared
# (reads of the word written in the same cycle included).
iverilog -E -DVERILATOR -o "$tmp/ram_vl_pp.v" rtl/fp3_ram.v
sed 's/^module fp3_ram /module fp3_ram_vl /' "$tmp/ram_vl_pp.v" > "$tmp/ram_vl.v"
grep -q "^module fp3_ram_vl " "$tmp/ram_vl.v" || { echo "FAIL: no module fp3_ram in rtl/fp3_ram.v"; exit 1; }
cat > "$tmp/tb_vl.v" <<'EOF'
module tb_vl;
  reg clk = 1'b0, we = 1'b0;
  reg [7:0] wa = 8'd0, ra = 8'd0;
  reg [74:0] wd = 75'd0;
  wire [74:0] q_lut, q_vl;
  fp3_ram #(.DEPTH(256), .AW(8), .WIDTH(75), .READ_STAGES(2)) u_lut (
    .clk_i(clk), .we_i(we), .waddr_i(wa), .wdata_i(wd), .raddr_i(ra), .rdata_o(q_lut));
  fp3_ram_vl #(.DEPTH(256), .AW(8), .WIDTH(75), .READ_STAGES(2)) u_vl (
    .clk_i(clk), .we_i(we), .waddr_i(wa), .wdata_i(wd), .raddr_i(ra), .rdata_o(q_vl));
  integer t, seed = 11;
  always #5 clk = !clk;
  initial begin
    for (t = 0; t < 20000; t = t + 1) begin
      @(negedge clk);
      if (q_lut !== q_vl) begin
        $display("cycle %0d: LUT-RAM form %h, Verilator form %h", t, q_lut, q_vl);
        $display("FAIL");
        $finish;
      end
      // (addresses from 0 .. 7 half the time: reads meet recent writes)
      we = $random(seed);
      wa = ($random(seed) & 1) ? ($random(seed) & 7) : $random(seed);
      ra = ($random(seed) & 1) ? ($random(seed) & 7) : $random(seed);
      wd = {$random(seed), $random(seed), $random(seed)};
    end
    $display("PASS");
    $finish;
  end
endmodule
EOF
iverilog -g2005 -Irtl -s tb_vl -o "$tmp/tb_vl.vvp" rtl/fp3_ram.v "$tmp/ram_vl.v" "$tmp/tb_vl.v" \
  2>"$tmp/iv_vl.log" || { cat "$tmp/iv_vl.log"; echo "FAIL: iverilog on the Verilator form"; exit 1; }
vvp -n "$tmp/tb_vl.vvp" > "$tmp/sim_vl.log"
grep -q "^PASS" "$tmp/sim_vl.log" || { tail -3 "$tmp/sim_vl.log"; echo "FAIL: the Verilator form reads differently"; exit 1; }
echo "PASS: the Verilator form of the LUT RAM (lanes merged) reads what the lanes read, 20,000 cycles"

# Without the define, or deeper than one block, the LUT-RAM form
# (elaborated only: the instance is chosen there).
for args in "|256|8" "-DFP3_ECP5_EBR|1024|10"; do
  IFS='|' read -r def depth aw <<<"$args"
  ${YOSYS:-yosys} -q -p "read_verilog $def -Irtl rtl/fp3_ram.v;
    chparam -set DEPTH $depth -set AW $aw -set WIDTH 75 -set READ_STAGES 2 fp3_ram;
    hierarchy -top fp3_ram; select -assert-none t:PDPW16KD" >"$tmp/yosys.log" 2>&1 || {
    tail -5 "$tmp/yosys.log"; echo "FAIL: PDPW16KD with '$def', $depth words"; exit 1; }
done
echo "PASS: LUT RAM without FP3_ECP5_EBR, and for 1024 words (a block holds 512)"
