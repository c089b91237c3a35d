// sched-split-eq.v -- the lockstep check of the scheduler split (notes/
// sched-split.md): the unsplit fp3_scheduler of c2338ff, renamed
// fp3_scheduler_ref, beside the split one, the same random inputs, every
// output compared every cycle (!==, so X must match X).  Not part of make
// test (it needs the old module).  Usage, from the repository root:
//   git show c2338ff:rtl/fp3_scheduler.v | \
//     sed 's/^module fp3_scheduler #(/module fp3_scheduler_ref #(/' > /tmp/ref.v
//   iverilog -g2005 -Irtl -y rtl -s tb_eq [-Ptb_eq.NC=8 -Ptb_eq.CW=3 \
//     -Ptb_eq.PS=2 -Ptb_eq.FS=1 -Ptb_eq.SEED=3] -o /tmp/eq.vvp \
//     notes/sched-split-eq.v /tmp/ref.v rtl/fp3_scheduler.v
//   vvp -n /tmp/eq.vvp      (prints PASS or FAIL and the mismatches)
`default_nettype none
module tb_eq;
  parameter integer NC = 3, CW = 2, IW = 3, NUM_REGS = 6, AW = 4, IMEM_DEPTH = 16;
  parameter integer PS = 0, FS = 0, DRAIN = 3, CYCLES = 200000, SEED = 1;
  localparam integer XW = CW + IW;
  reg clk = 0, rst = 1;
  reg imem_we; reg [AW-1:0] imem_waddr; reg [63:0] imem_wdata;
  reg start, clear, steps_zero, steps_one; reg [31:0] steps_last2;
  reg contexts_bad; reg [NC-1:0] contexts_run; reg [CW-1:0] sel_ctx;
  reg [(1<<XW)-1:0] busy; reg [2:0] av, ev, pv; reg [3*XW-1:0] ai, ei, pi;
  reg [1:0] p2v, p3v; reg [2*XW-1:0] p2i, p3i; reg idle;
  reg [NC-1:0] br; reg br_taken; reg [AW-1:0] br_target;
  localparam integer OW = 1+1+1+4+32+32+64+64+64 + 1+CW+3*XW+2+1+1+32+1+1 + 1+XW+2;
  wire [OW-1:0] o_ref, o_new;
`define SCHED_PORTS(o) \
    .clk_i(clk), .rst_i(rst), .imem_we_i(imem_we), .imem_waddr_i(imem_waddr), .imem_wdata_i(imem_wdata), \
    .start_i(start), .clear_i(clear), .steps_zero_i(steps_zero), .steps_one_i(steps_one), \
    .steps_last2_i(steps_last2), .contexts_bad_i(contexts_bad), .contexts_run_i(contexts_run), \
    .sel_ctx_i(sel_ctx), .running_o(o[0]), .done_o(o[1]), .any_error_o(o[2]), .error_sel_o(o[6:3]), \
    .fault_pc_sel_o(o[38:7]), .steps_done_sel_o(o[70:39]), .cycles_o(o[134:71]), .issued_o(o[198:135]), \
    .stalls_o(o[262:199]), .busy_i(busy), .ahead_valid_i(av), .ahead_idx_i(ai), .early_valid_i(ev), \
    .early_idx_i(ei), .pre_valid_i(pv), .pre_idx_i(pi), .pre2_valid_i(p2v), .pre2_idx_i(p2i), \
    .pre3_valid_i(p3v), .pre3_idx_i(p3i), .idle_i(idle), .br_i(br), .br_taken_i(br_taken), \
    .br_target_i(br_target), .issue_o(o[263]), .issue_ctx_o(o[263+CW:264]), \
    .ra_o(o[263+CW+XW:264+CW]), .rb_o(o[263+CW+2*XW:264+CW+XW]), .rd_o(o[263+CW+3*XW:264+CW+2*XW]), \
    .issue_unit_o(o[265+CW+3*XW:264+CW+3*XW]), .issue_sub_o(o[266+CW+3*XW]), .issue_imm_o(o[267+CW+3*XW]), \
    .imm_o(o[299+CW+3*XW:268+CW+3*XW]), .endi_o(o[300+CW+3*XW]), .beq_o(o[301+CW+3*XW]), \
    .pick_wr_o(o[302+CW+3*XW]), .pick_rd_o(o[302+CW+4*XW:303+CW+3*XW]), .pick_unit_o(o[304+CW+4*XW:303+CW+4*XW])
  fp3_scheduler_ref #(.NUM_CONTEXTS(NC), .CW(CW), .NUM_REGS(NUM_REGS), .IW(IW), .IMEM_DEPTH(IMEM_DEPTH),
    .AW(AW), .PICK_STAGES(PS), .FETCH_STAGE(FS), .DRAIN(DRAIN), .HAS_SUB(NC != 3)) u_ref (`SCHED_PORTS(o_ref));
  fp3_scheduler #(.NUM_CONTEXTS(NC), .CW(CW), .NUM_REGS(NUM_REGS), .IW(IW), .IMEM_DEPTH(IMEM_DEPTH),
    .AW(AW), .PICK_STAGES(PS), .FETCH_STAGE(FS), .DRAIN(DRAIN), .HAS_SUB(NC != 3)) u_new (`SCHED_PORTS(o_new));
  always #5 clk = !clk;
  integer seed, cyc, errs, issues, runs, dones, grants, r;
  // a mostly legal word
  function [63:0] rword;
    input integer rr;
    reg [7:0] opc, rd, ra, rb; reg [31:0] imm;
    begin
      opc = $unsigned($random(seed)) % 10;
      rd = $unsigned($random(seed)) % (NUM_REGS + 1);
      ra = $unsigned($random(seed)) % (NUM_REGS + 1);
      rb = $unsigned($random(seed)) % (NUM_REGS + 1);
      imm = $unsigned($random(seed)) % (IMEM_DEPTH + 2);
      case (opc)
        0: begin rd = 0; ra = 0; rb = 0; imm = 0; end
        1, 2, 3: imm = 0;
        4: begin ra = 0; rb = 0; imm = $random(seed); end
        5: begin rb = 0; imm = 0; end
        6: begin rd = 0; ra = 0; rb = 0; end
        7: begin rd = 0; ra = 0; rb = 0; imm = 0; end
        default: rd = 0;
      endcase
      if (rr % 97 == 0) opc = 8'hff;
      rword = {opc, rd, ra, rb, imm};
    end
  endfunction
  task randin;
    integer m;
    begin
      m = $unsigned($random(seed)) % 1000;
      rst = (m == 0);
      imem_we = !o_ref[0] ? ($unsigned($random(seed)) % 4 == 0) : ($unsigned($random(seed)) % 500 == 0);
      imem_waddr = $random(seed); imem_wdata = rword($random(seed));
      start = !o_ref[0] && ($unsigned($random(seed)) % 20 == 0) || ($unsigned($random(seed)) % 300 == 0);
      clear = $unsigned($random(seed)) % 50 == 0;
      r = $unsigned($random(seed)) % 40;
      steps_zero = (r == 0); steps_one = (r == 1);
      steps_last2 = (r >= 2) ? r - 2 : 32'hffffffff;
      contexts_bad = $unsigned($random(seed)) % 30 == 0;
      contexts_run = $random(seed);
      sel_ctx = $random(seed);
      busy = $random(seed) & $random(seed);
      av = $random(seed); ev = $random(seed); pv = $random(seed);
      ai = {$random(seed), $random(seed)}; ei = {$random(seed), $random(seed)}; pi = {$random(seed), $random(seed)};
      p2v = $random(seed); p3v = $random(seed); p2i = $random(seed); p3i = $random(seed);
      idle = $unsigned($random(seed)) % 3 != 0;
      br = ($unsigned($random(seed)) % 8 == 0) ? (1 << ($unsigned($random(seed)) % NC)) : 0;
      br_taken = $random(seed); br_target = $random(seed);
    end
  endtask
  reg prev_run;
  initial begin
    seed = SEED; errs = 0; issues = 0; runs = 0; dones = 0; prev_run = 0;
    randin; rst = 1;
    repeat (3) @(negedge clk);
    for (cyc = 0; cyc < CYCLES; cyc = cyc + 1) begin
      @(negedge clk);
      if (o_ref !== o_new) begin
        errs = errs + 1;
        if (errs < 5) $display("MISMATCH cycle %0d: ref %h new %h diff %h", cyc, o_ref, o_new, o_ref ^ o_new);
      end
      if (o_ref[263] === 1'b1) issues = issues + 1;
      if (o_ref[0] === 1'b1 && !prev_run) runs = runs + 1;
      if (o_ref[1] === 1'b1) dones = dones + 1;
      prev_run = o_ref[0];
      randin;
    end
    $display("%s: NC=%0d PS=%0d FS=%0d seed %0d: %0d cycles, %0d runs, %0d issues, %0d done-cycles, %0d mismatches",
             errs ? "FAIL" : "PASS", NC, PS, FS, SEED, CYCLES, runs, issues, dones, errs);
    $finish;
  end
endmodule
