// tb_ram_ebr.v -- fp3_ram's ECP5 block-RAM form, as Yosys synthesizes it
// (module fp3_ram_ebr: tests/test_ram_ebr.sh), against the LUT-RAM form
// that every simulation runs (fp3_ram, READ_STAGES = 2), on random writes
// and reads: the same word two cycles after each read address, for every
// read that is not of the word written in the same cycle (which the block
// does not promise; neither user of the form takes such a read).
// Prints PASS with the reads compared, or the first difference and FAIL.
// Plusargs: +cycles=N (default 20000), +seed=S.
`timescale 1ns / 1ps
`default_nettype none
module tb_ram_ebr;
  localparam integer DEPTH = 256, AW = 8, WIDTH = 75;
  reg              clk = 1'b0;
  reg              we = 1'b0;
  reg  [AW-1:0]    wa = {AW{1'b0}}, ra = {AW{1'b0}};
  reg  [WIDTH-1:0] wd = {WIDTH{1'b0}};
  wire [WIDTH-1:0] q_lut, q_ebr;
  fp3_ram #(.DEPTH(DEPTH), .AW(AW), .WIDTH(WIDTH), .READ_STAGES(2)) u_lut (
    .clk_i(clk), .we_i(we), .waddr_i(wa), .wdata_i(wd), .raddr_i(ra), .rdata_o(q_lut));
  fp3_ram_ebr u_ebr (
    .clk_i(clk), .we_i(we), .waddr_i(wa), .wdata_i(wd), .raddr_i(ra), .rdata_o(q_ebr));

  integer cycles, seed, t, compared;
  reg [1:0] chk;          // a read to compare issued 1 and 2 cycles ago
  always #5 clk = !clk;
  initial begin
    if (!$value$plusargs("cycles=%d", cycles)) cycles = 20000;
    if (!$value$plusargs("seed=%d", seed)) seed = 1;
    chk = 2'b00;
    compared = 0;
    for (t = 0; t < cycles; t = t + 1) begin
      @(negedge clk);
      if (chk[1]) begin
        compared = compared + 1;
        if (q_lut !== q_ebr) begin
          $display("cycle %0d: LUT-RAM form %h, block-RAM form %h", t, q_lut, q_ebr);
          $display("FAIL");
          $finish;
        end
      end
      // Addresses from a small range half the time, so that reads meet
      // recent writes (one and two cycles before) often.
      we = $random(seed);
      wa = ($random(seed) & 1) ? ($random(seed) & 7) : $random(seed);
      ra = ($random(seed) & 1) ? ($random(seed) & 7) : $random(seed);
      wd = {$random(seed), $random(seed), $random(seed)};
      chk = {chk[0], !(we && wa == ra)};
    end
    $display("PASS: %0d reads of the block-RAM form equal the LUT-RAM form's", compared);
    $finish;
  end
endmodule
`default_nettype wire
