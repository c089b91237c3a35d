// fp3_regfile -- register banks, one per context, in RAM, with one
// busy flag per register (the scoreboard of paper §4), write-back bypass
// and a host port.
//
// Every index is {context, register} (XW bits).  Busy flags: an issued
// instruction marks its destination busy (set_i); the flag clears when the
// unit that computes the result announces its write-back, READ_STAGES +
// (fp3_top's pick stage) cycles ahead of it (clr*_i, from the tag lines,
// fp3_wb_tag).  The scheduler reads the flags (busy_o) and stalls an
// instruction while a source is busy (RAW) or its destination is busy
// (WAW), unless it is announced in this very cycle; so at most one result
// per register is in flight and write-backs to one register happen in
// program order.
//
// Storage: RAM with a registered read (one write port per RAM): FPGA block
// RAM for the banks of many contexts, or RAM read over two cycles for
// clock rate (READ_STAGES = 4; fp3_ram READ_STAGES 2: LUT RAM, or in ECP5
// synthesis block RAM with its output register).  The four write-back
// ports (add core, mul core, move path, div/sqrt unit) each write a RAM of
// their own, replicated once per read port, and a live value table (LVT,
// 2 bits per register, in flip-flops) records which port wrote each
// register last.  A port that is never written (a build without its unit:
// its valid input tied to 0) leaves RAMs that synthesis removes; the
// compares of its index remain and cost a little logic
// (LaForest & Steffan,
// "Efficient Multi-Ported Memories for FPGAs", FPGA 2010).  A read
// presented in cycle t (the issue cycle) returns its data in cycle
// t + READ_STAGES (the last operand-read stage).
//
// Bypass: the scheduler issues a consumer up to READ_STAGES - 1 cycles
// before its operand is written back (DESIGN.md: no whole-pipeline stall
// on write-back).  The RAMs' word misses the writes from cycle t on (with
// READ_STAGES = 1 a write lands at the edge the read samples; with
// READ_STAGES = 4 the RAMs register their writes and are read in cycle
// t + 1), up to t + READ_STAGES - 1, so those write values are captured
// beside the read and replace the RAM data (the newest wins).  Writes in
// later cycles are never needed by a read of cycle t (the scoreboard did
// not count the operand as free).
//
//   READ_STAGES = 1  cycle t + 1: bypass of cycle t's writes, LVT select
//                    of the four RAMs' data (one stage; the default)
//   READ_STAGES = 4  for clock rate.  Cycle t: the RAMs register the read
//                    address, and the index is compared with the writes
//                    of cycle t and the write-backs of cycles t + 1 and
//                    t + 2 (announced ahead), registered; cycle t + 1:
//                    the RAMs are read, the LVT's first half is read,
//                    and the index is compared with the write-backs of
//                    cycle t + 3 (announced two cycles ahead, wb*_in2_i),
//                    the newest hit registered one-hot; cycle t + 2: the
//                    RAMs' words (from their registers) and the
//                    bypass word registered, with a one-hot choice among
//                    them and the write-backs of cycle t + 3; cycle t + 3:
//                    one AND-OR of nine words, registered; cycle t + 4:
//                    the operands leave those flip-flops (nothing sits in
//                    front of their users).
//
// Parameters
//   ENTRIES      registers in all, 2**XW
//   XW           index width, clog2(NUM_CONTEXTS) + clog2(NUM_REGS)
//   READ_STAGES  1 or 4, see above
//   FLAGS_AHEAD  0: set_*/clr*_* change the busy flags at the edge ending
//                the cycle they are given in.  1 (for clock rate): they
//                are given a cycle earlier (the instruction picked, which
//                issues in the next cycle: fp3_scheduler pick_*; the tag
//                lines' early_*) and registered (the clears decoded in two
//                halves first, the set after), and change the flags at
//                the same edge as with 0.
//   CTRL         1: busy flags and LVT (the whole bank); 0: data only, the
//                LVT's choice from lvt_*_i (lanes 1 .., see "Lanes" below)
//   WB_PORTS     4: the four write-back ports above, with the LVT; 1: the
//                units never write back (nor announce, nor clear) in one
//                cycle (fp3_top WB_PORTS), so their ports are merged into
//                port 0 at the inputs, whose two RAMs alone are built,
//                and there is no LVT (lvt_*_o name port 0); the host's
//                write goes into port 0's RAMs (as with HOST_ALL).  Saves
//                the LVT (some 9,000 LUT4s at 512 registers, CTRL = 1),
//                six RAMs and most of the bypass's words (some 1,300
//                LUT4s a bank with READ_STAGES = 4)
//   HOST_ALL     1: the host's write goes into all four ports' RAMs and
//                not into the LVT (banks that share an LVT); 0: port 2's
//                RAMs, and its LVT entry names port 2 (one lane)
// Ports (indices XW bits wide, data 32 bits)
//   ra_i/rb_i (cycle t) -> ra_data_o/rb_data_o (cycle t + READ_STAGES),
//     bypassed.  Port A reads host_idx_i instead while host_sel_i is set
//     (no run in progress): the host's register read data is ra_data_o
//     READ_STAGES cycles later.
//   busy_o: every busy flag; idle_o: none was set in the last cycle
//     (registered: see idle_o below).
//   set_i/set_idx_i: mark a destination busy (issue of add/mul/move).
//   clr{0,1,2,3}_*: write-back announcements (add, mul, move, div/sqrt tag
//     lines); each
//     clears the register's busy flag.  A register announced in the cycle
//     a new instruction claims it stays busy: the set wins.  (FLAGS_AHEAD
//     = 1: both a cycle ahead, see above.)
//   wb{0,1,2,3}_*: write-back ports (add core, mul core, move path,
//     div/sqrt unit).
//   wb{0,1,2,3}_in2_*: the write-back ports' valid and index two cycles
//     ahead (fp3_wb_tag next2_*; read with READ_STAGES = 4).
//   host_we_i/host_idx_i/host_wdata_i: host write through port 2's RAM
//     (only while stopped: the move path is idle then), registered first.
//   lvt_a_o/lvt_b_o: the RAM each read takes unless bypassed, one-hot
//     {port 3, 2, 1, 0}: the LVT entry of the read's index, in the cycle the
//     read stages use it (READ_STAGES = 1: cycle t + 1, = 4: cycle t + 2).
//   lvt_a_i/lvt_b_i: the same, from a CTRL = 1 bank (CTRL = 0 only).
//
// Lanes (fp3_lane): every lane's bank sees the same indices in the same
// cycles, so its busy flags and LVT equal every other lane's; only the
// data differ.  CTRL = 1 builds the whole bank (lane 0); CTRL = 0 a bank of
// data only (lanes 1 ..): the RAMs and the bypass, without busy flags
// (busy_o all zero, idle_o 1) and without LVT, whose choice it takes from
// lane 0 (lvt_*_i).  Its read data equal those of a CTRL = 1 bank with the
// same writes, provided the LVT changes alike in every lane: the host
// writes one lane at a time, so with lanes (HOST_ALL = 1) its write goes
// into the RAMs of all four ports of the lane it selects (ports 0, 1 and 3
// are idle while the machine is stopped, as port 2 is) and leaves the LVT
// alone, which then names a RAM holding the host's word whatever it says.
// With HOST_ALL = 0 (one lane) the host writes port 2's RAMs only and its
// LVT entry names port 2.  Synthesis would remove or merge the repeated flags and
// tables anyway; a Verilated model does not (every register is kept and
// evaluated each cycle: 256 flags, LVT entries and their decoders per lane
// of the 8-context build), so CTRL = 0 is what keeps many-lane models fast.
`default_nettype none
module fp3_regfile #(
  parameter integer ENTRIES     = 32,
  parameter integer XW          = 5,
  parameter integer READ_STAGES = 1,
  parameter integer FLAGS_AHEAD = 0,
  parameter integer CTRL        = 1,
  parameter integer HOST_ALL    = 0,
  parameter integer WB_PORTS    = 4
) (
  input  wire               clk_i,
  input  wire               rst_i,
  input  wire [XW-1:0]      ra_i,
  input  wire [XW-1:0]      rb_i,
  output wire [31:0]        ra_data_o,
  output wire [31:0]        rb_data_o,
  output wire [ENTRIES-1:0] busy_o,
  input  wire               set_i,
  input  wire [XW-1:0]      set_idx_i,
  input  wire               clr0_valid_i,
  input  wire [XW-1:0]      clr0_idx_i,
  input  wire               clr1_valid_i,
  input  wire [XW-1:0]      clr1_idx_i,
  input  wire               clr2_valid_i,
  input  wire [XW-1:0]      clr2_idx_i,
  input  wire               clr3_valid_i,
  input  wire [XW-1:0]      clr3_idx_i,
  input  wire               wb0_valid_i,
  input  wire [XW-1:0]      wb0_idx_i,
  input  wire [31:0]        wb0_data_i,
  input  wire               wb1_valid_i,
  input  wire [XW-1:0]      wb1_idx_i,
  input  wire [31:0]        wb1_data_i,
  input  wire               wb2_valid_i,
  input  wire [XW-1:0]      wb2_idx_i,
  input  wire [31:0]        wb2_data_i,
  input  wire               wb3_valid_i,
  input  wire [XW-1:0]      wb3_idx_i,
  input  wire [31:0]        wb3_data_i,
  input  wire               wb0_in2_valid_i,
  input  wire [XW-1:0]      wb0_in2_idx_i,
  input  wire               wb1_in2_valid_i,
  input  wire [XW-1:0]      wb1_in2_idx_i,
  input  wire               wb2_in2_valid_i,
  input  wire [XW-1:0]      wb2_in2_idx_i,
  input  wire               wb3_in2_valid_i,
  input  wire [XW-1:0]      wb3_in2_idx_i,
  input  wire               host_sel_i,
  input  wire               host_we_i,
  input  wire [XW-1:0]      host_idx_i,
  input  wire [31:0]        host_wdata_i,
  output wire               idle_o,
  output wire [3:0]         lvt_a_o,
  output wire [3:0]         lvt_b_o,
  input  wire [3:0]         lvt_a_i,
  input  wire [3:0]         lvt_b_i
);

  // ---- WB_PORTS = 1: the units' write-backs as one port -------------------
  // The four units' write-backs, announcements and clears never share a
  // cycle (the same latency, one issue per cycle: fp3_top WB_PORTS), so
  // each group is one port: port 0 carries whichever is valid (an AND-OR
  // of the valid ones), ports 1 .. 3 are idle, and the LVT, which would
  // always name port 0, is not built (g_lvt_none, g_ctrl).  Port 2 still
  // carries the host's write, to the bypass (its RAMs are not built: the
  // host writes port 0's, as with HOST_ALL).
  localparam [0:0] ONE = WB_PORTS == 1;
  function [XW:0] vidx;   // {valid, index if valid}
    input          v;
    input [XW-1:0] i;
    begin
      vidx = {v, {XW{v}} & i};
    end
  endfunction
  wire          m0_valid, m1_valid, m2_valid, m3_valid, n0_valid, n1_valid, n2_valid, n3_valid;
  wire          k0_valid, k1_valid, k2_valid, k3_valid;
  wire [XW-1:0] m0_idx, m1_idx, m2_idx, m3_idx, n0_idx, n1_idx, n2_idx, n3_idx;
  wire [XW-1:0] k0_idx, k1_idx, k2_idx, k3_idx;
  wire [31:0]   m0_data, m1_data, m2_data, m3_data;
  generate
    if (ONE) begin : g_wb_one
      assign {m0_valid, m0_idx} = vidx(wb0_valid_i, wb0_idx_i) | vidx(wb1_valid_i, wb1_idx_i) |
                                  vidx(wb2_valid_i, wb2_idx_i) | vidx(wb3_valid_i, wb3_idx_i);
      assign m0_data = {32{wb0_valid_i}} & wb0_data_i | {32{wb1_valid_i}} & wb1_data_i |
                       {32{wb2_valid_i}} & wb2_data_i | {32{wb3_valid_i}} & wb3_data_i;
      assign {n0_valid, n0_idx} = vidx(wb0_in2_valid_i, wb0_in2_idx_i) |
                                  vidx(wb1_in2_valid_i, wb1_in2_idx_i) |
                                  vidx(wb2_in2_valid_i, wb2_in2_idx_i) |
                                  vidx(wb3_in2_valid_i, wb3_in2_idx_i);
      assign {k0_valid, k0_idx} = vidx(clr0_valid_i, clr0_idx_i) | vidx(clr1_valid_i, clr1_idx_i) |
                                  vidx(clr2_valid_i, clr2_idx_i) | vidx(clr3_valid_i, clr3_idx_i);
      assign {m1_valid, m2_valid, m3_valid, n1_valid, n2_valid, n3_valid} = 6'd0;
      assign {k1_valid, k2_valid, k3_valid} = 3'd0;
      assign {m1_idx, m2_idx, m3_idx, n1_idx, n2_idx, n3_idx, k1_idx, k2_idx, k3_idx} =
             {9*XW{1'b0}};
      assign {m1_data, m2_data, m3_data} = 96'd0;
`ifdef FP3_SCHED_CHECK
      // The ports never share a cycle (formal/sched.sby bmc_wb1).
      wire [3:0] f_wv = {wb3_valid_i, wb2_valid_i, wb1_valid_i, wb0_valid_i};
      wire [3:0] f_nv = {wb3_in2_valid_i, wb2_in2_valid_i, wb1_in2_valid_i, wb0_in2_valid_i};
      wire [3:0] f_kv = {clr3_valid_i, clr2_valid_i, clr1_valid_i, clr0_valid_i};
      always @(*) begin
        wb_one_port:  assert ((f_wv & (f_wv - 4'd1)) == 4'd0);
        in2_one_port: assert ((f_nv & (f_nv - 4'd1)) == 4'd0);
        clr_one_port: assert ((f_kv & (f_kv - 4'd1)) == 4'd0);
      end
`endif
    end else begin : g_wb_four
      assign {m0_valid, m0_idx, m0_data} = {wb0_valid_i, wb0_idx_i, wb0_data_i};
      assign {m1_valid, m1_idx, m1_data} = {wb1_valid_i, wb1_idx_i, wb1_data_i};
      assign {m2_valid, m2_idx, m2_data} = {wb2_valid_i, wb2_idx_i, wb2_data_i};
      assign {m3_valid, m3_idx, m3_data} = {wb3_valid_i, wb3_idx_i, wb3_data_i};
      assign {n0_valid, n0_idx} = {wb0_in2_valid_i, wb0_in2_idx_i};
      assign {n1_valid, n1_idx} = {wb1_in2_valid_i, wb1_in2_idx_i};
      assign {n2_valid, n2_idx} = {wb2_in2_valid_i, wb2_in2_idx_i};
      assign {n3_valid, n3_idx} = {wb3_in2_valid_i, wb3_in2_idx_i};
      assign {k0_valid, k0_idx} = {clr0_valid_i, clr0_idx_i};
      assign {k1_valid, k1_idx} = {clr1_valid_i, clr1_idx_i};
      assign {k2_valid, k2_idx} = {clr2_valid_i, clr2_idx_i};
      assign {k3_valid, k3_idx} = {clr3_valid_i, clr3_idx_i};
    end
  endgenerate

  // Port 2 carries the move path, or the host's write while stopped.  The
  // host's write is registered first (it lands a cycle later; a read in
  // between gets it through the bypass), which keeps the bus interface's
  // decode out of the register file's write paths.
  reg           hwe_q;
  reg  [XW-1:0] hidx_q;
  reg  [31:0]   hdata_q;
  always @(posedge clk_i) begin
    hwe_q   <= !rst_i && host_we_i;
    hidx_q  <= host_idx_i;
    hdata_q <= host_wdata_i;
  end
  wire          w2_valid = m2_valid || hwe_q;
  wire [XW-1:0] w2_idx   = m2_valid ? m2_idx  : hidx_q;
  wire [31:0]   w2_data  = m2_valid ? m2_data : hdata_q;
  // ... and with HOST_ALL, ports 0 and 1 carry it too (their RAMs only;
  // the bypass takes the host's word from port 2).
  wire          hwe_all  = (HOST_ALL != 0 || ONE) && hwe_q;
  wire          w0_valid = m0_valid || hwe_all;
  wire [XW-1:0] w0_idx   = m0_valid || !hwe_all ? m0_idx  : hidx_q;
  wire [31:0]   w0_data  = m0_valid || !hwe_all ? m0_data : hdata_q;
  wire          w1_valid = m1_valid || hwe_all;
  wire [XW-1:0] w1_idx   = m1_valid || !hwe_all ? m1_idx  : hidx_q;
  wire [31:0]   w1_data  = m1_valid || !hwe_all ? m1_data : hdata_q;
  wire          w3_valid = m3_valid || hwe_all;
  wire [XW-1:0] w3_idx   = m3_valid || !hwe_all ? m3_idx  : hidx_q;
  wire [31:0]   w3_data  = m3_valid || !hwe_all ? m3_data : hdata_q;
  wire          hwe_lvt  = HOST_ALL == 0 && !ONE && hwe_q;   // the host's write in the LVT
  wire [XW-1:0] a_idx    = host_sel_i ? host_idx_i : ra_i;

  // ---- the RAMs: [write port][read port] -----------------------------------
  // READ_STAGES = 4: RAM read over two cycles (fp3_ram READ_STAGES 2).
  localparam integer RAM_READ = (READ_STAGES == 4) ? 2 : 1;
  wire [31:0] q00, q01, q10, q11, q20, q21, q30, q31;
  fp3_ram #(.DEPTH(ENTRIES), .AW(XW), .WIDTH(32), .READ_STAGES(RAM_READ)) u_ram00 (
    .clk_i(clk_i), .we_i(w0_valid), .waddr_i(w0_idx), .wdata_i(w0_data),
    .raddr_i(a_idx), .rdata_o(q00));
  fp3_ram #(.DEPTH(ENTRIES), .AW(XW), .WIDTH(32), .READ_STAGES(RAM_READ)) u_ram01 (
    .clk_i(clk_i), .we_i(w0_valid), .waddr_i(w0_idx), .wdata_i(w0_data),
    .raddr_i(rb_i), .rdata_o(q01));
  generate
    if (!ONE) begin : g_ram_ports
      fp3_ram #(.DEPTH(ENTRIES), .AW(XW), .WIDTH(32), .READ_STAGES(RAM_READ)) u_ram10 (
        .clk_i(clk_i), .we_i(w1_valid), .waddr_i(w1_idx), .wdata_i(w1_data),
        .raddr_i(a_idx), .rdata_o(q10));
      fp3_ram #(.DEPTH(ENTRIES), .AW(XW), .WIDTH(32), .READ_STAGES(RAM_READ)) u_ram11 (
        .clk_i(clk_i), .we_i(w1_valid), .waddr_i(w1_idx), .wdata_i(w1_data),
        .raddr_i(rb_i), .rdata_o(q11));
      fp3_ram #(.DEPTH(ENTRIES), .AW(XW), .WIDTH(32), .READ_STAGES(RAM_READ)) u_ram20 (
        .clk_i(clk_i), .we_i(w2_valid), .waddr_i(w2_idx), .wdata_i(w2_data),
        .raddr_i(a_idx), .rdata_o(q20));
      fp3_ram #(.DEPTH(ENTRIES), .AW(XW), .WIDTH(32), .READ_STAGES(RAM_READ)) u_ram21 (
        .clk_i(clk_i), .we_i(w2_valid), .waddr_i(w2_idx), .wdata_i(w2_data),
        .raddr_i(rb_i), .rdata_o(q21));
      fp3_ram #(.DEPTH(ENTRIES), .AW(XW), .WIDTH(32), .READ_STAGES(RAM_READ)) u_ram30 (
        .clk_i(clk_i), .we_i(w3_valid), .waddr_i(w3_idx), .wdata_i(w3_data),
        .raddr_i(a_idx), .rdata_o(q30));
      fp3_ram #(.DEPTH(ENTRIES), .AW(XW), .WIDTH(32), .READ_STAGES(RAM_READ)) u_ram31 (
        .clk_i(clk_i), .we_i(w3_valid), .waddr_i(w3_idx), .wdata_i(w3_data),
        .raddr_i(rb_i), .rdata_o(q31));
    end else begin : g_ram_port0
      // (Ports 1 .. 3 write nothing: no RAMs; the LVT always names port 0.)
      assign {q10, q11, q20, q21, q30, q31} = {6{32'd0}};
      wire unused_w = &{1'b0, w1_valid, w1_idx, w1_data, w3_valid, w3_idx, w3_data};
    end
  endgenerate

  // The write-back ports' valid and index of the next cycle (READ_STAGES
  // = 4; the tag lines' own stage, which Yosys merges with these).
  reg [3:0]    nx_v;
  reg [XW-1:0] nx_i0, nx_i1, nx_i2, nx_i3;
  always @(posedge clk_i) begin
    nx_v  <= rst_i ? 4'd0 : {n3_valid, n2_valid, n1_valid,
                             n0_valid};
    nx_i0 <= n0_idx;
    nx_i1 <= n1_idx;
    nx_i2 <= n2_idx;
    nx_i3 <= n3_idx;
  end

  // ---- read stages: LVT choice and bypass --------------------------------
  // The read addresses and the write-backs of cycle t are registered; in
  // cycle t + 1 the LVT (which by then includes the writes of cycle t)
  // picks the RAM, and a write-back of cycle t to the same register (which
  // the RAM read at the same edge missed) replaces the RAM data.  Nothing
  // of this sits behind the issue arbiter in cycle t.
  reg [XW-1:0] a_idx_q, b_idx_q;
  reg [31:0]   wd0_q, wd1_q, wd2_q, wd3_q;    // the data written in the last cycle
  always @(posedge clk_i) begin
    a_idx_q <= a_idx;
    b_idx_q <= rb_i;
    wd0_q   <= m0_data;
    wd1_q   <= m1_data;
    wd2_q   <= w2_data;
    wd3_q   <= m3_data;
  end
  wire [ENTRIES-1:0] lvt_lo, lvt_hi;  // the LVT: entry r is {lvt_hi[r], lvt_lo[r]}

  // The word of twelve (w[32k +: 32]) that the one-hot sel[k] names.
  function [31:0] pick12;
    input [11:0]  sel;
    input [383:0] w;
    integer k;
    begin
      pick12 = 32'd0;
      for (k = 0; k < 12; k = k + 1) pick12 = pick12 | ({32{sel[k]}} & w[32*k +: 32]);
    end
  endfunction

  function [3:0] lvt1h;   // an LVT entry (port 0 .. 3) one-hot: {3, 2, 1, 0}
    input [1:0] p;
    begin
      lvt1h = {p == 2'd3, p == 2'd2, p == 2'd1, p == 2'd0};
    end
  endfunction

  generate
    if (READ_STAGES == 1) begin : g_read1
      // Cycle t + 1: the writes of cycle t (they missed the RAMs' read)
      // replace the RAM data the LVT entry of the index (it includes
      // them) names.
      reg [3:0]    wv_q;                // the writes of the last cycle
      reg [XW-1:0] wi0_q, wi1_q, wi2_q, wi3_q;
      always @(posedge clk_i) begin
        wv_q  <= rst_i ? 4'd0 : {m3_valid, w2_valid, m1_valid, m0_valid};
        wi0_q <= m0_idx;
        wi1_q <= m1_idx;
        wi2_q <= w2_idx;
        wi3_q <= m3_idx;
      end
      // Bypass of one write-back cycle: {hit, data} for index x.
`define FP3_BYPASS(x) \
  ((wv_q[0] && wi0_q == (x)) ? {1'b1, wd0_q} : \
   (wv_q[1] && wi1_q == (x)) ? {1'b1, wd1_q} : \
   (wv_q[2] && wi2_q == (x)) ? {1'b1, wd2_q} : \
   (wv_q[3] && wi3_q == (x)) ? {1'b1, wd3_q} : {33{1'b0}})
      wire [3:0]  a_lvt, b_lvt;             // one LVT read per port, one-hot
      if (ONE) begin : g_lvt_none
        assign a_lvt = 4'b0001;
        assign b_lvt = 4'b0001;
        wire unused_lvt_i = &{1'b0, lvt_a_i, lvt_b_i};
      end else if (CTRL != 0) begin : g_lvt_own
        assign a_lvt = lvt1h({lvt_hi[a_idx_q], lvt_lo[a_idx_q]});
        assign b_lvt = lvt1h({lvt_hi[b_idx_q], lvt_lo[b_idx_q]});
        wire unused_lvt_i = &{1'b0, lvt_a_i, lvt_b_i};
      end else begin : g_lvt_lane0
        assign a_lvt = lvt_a_i;
        assign b_lvt = lvt_b_i;
      end
      wire [32:0] a_byp = `FP3_BYPASS(a_idx_q);
      wire [32:0] b_byp = `FP3_BYPASS(b_idx_q);
`undef FP3_BYPASS
      wire unused_nx   = &{1'b0, nx_v, nx_i0, nx_i1, nx_i2, nx_i3};   // no stage looks ahead
      assign ra_data_o = a_byp[32] ? a_byp[31:0] : a_lvt[0] ? q00 : a_lvt[1] ? q10 :
                         a_lvt[2] ? q20 : q30;
      assign rb_data_o = b_byp[32] ? b_byp[31:0] : b_lvt[0] ? q01 : b_lvt[1] ? q11 :
                         b_lvt[2] ? q21 : q31;
      assign lvt_a_o   = a_lvt;
      assign lvt_b_o   = b_lvt;
    end else if (READ_STAGES == 4) begin : g_read4
      // Cycle t: the read indices compared with the writes known then,
      // registered (*_hits_q): those of cycle t (the ports' inputs, the
      // host's write included, for its reads), of t + 1 (nx_*, a cycle
      // ahead) and of t + 2 (wb*_in2_*, two cycles ahead).  Cycle t + 1
      // (the RAMs read at their registered address copies; their writes
      // land a cycle late, so the read has the writes up to cycle t - 1):
      // with the write-backs of cycle t + 3 (wb*_in2_* then), the newest
      // of the sixteen hits, one-hot, registered.  So cycle t + 1 compares
      // four indices, not sixteen.  (The host writes only while stopped.)
      function [3:0] in2_hits;    // x among the write-backs two cycles ahead
        input [XW-1:0] x;
        begin
          in2_hits = {n0_valid && n0_idx == x,
                      n1_valid && n1_idx == x,
                      n2_valid && n2_idx == x,
                      n3_valid && n3_idx == x};
        end
      endfunction
      function [11:0] hits_known;  // {t + 2, t + 1, t: port 0, 1, 2, 3 each}
        input [XW-1:0] x;
        begin
          hits_known = {in2_hits(x),
                        nx_v[0] && nx_i0 == x, nx_v[1] && nx_i1 == x, nx_v[2] && nx_i2 == x,
                        nx_v[3] && nx_i3 == x,
                        m0_valid && m0_idx == x, m1_valid && m1_idx == x,
                        w2_valid && w2_idx == x, m3_valid && m3_idx == x};
        end
      endfunction
      function [15:0] byp_sel;    // {t + 3, t + 2, t + 1, t: port 0, 1, 2, 3 each}
        input [XW-1:0] x;
        input [11:0]   known;     // hits_known(x), a cycle old
        reg   [15:0]   h;
        integer        j;
        begin
          h = {in2_hits(x), known};
          byp_sel = h;
          for (j = 1; j < 16; j = j + 1) byp_sel = byp_sel & ~(h >> j);
        end
      endfunction
      reg [11:0]   a_hits_q, b_hits_q;
      reg [15:0]   a_hit_q, b_hit_q;
      // Beside the hits, two summaries of them, registered from the same
      // compares rather than reduced from *_hit_q in cycle t + 2: no hit
      // at all (the RAM the LVT names: *_ram_q) and a hit among the writes
      // known in cycle t (the bypass word: *_bdv_q), so the read select
      // meets a flip-flop, not a 12-input OR.
      reg          a_ram_q, b_ram_q, a_bdv_q, b_bdv_q;
      reg [XW-1:0] a_idx_qq, b_idx_qq;   // the indices in cycle t + 2
      always @(posedge clk_i) begin
        a_hits_q <= rst_i ? 12'd0 : hits_known(a_idx);
        b_hits_q <= rst_i ? 12'd0 : hits_known(rb_i);
        a_hit_q  <= rst_i ? 16'd0 : byp_sel(a_idx_q, a_hits_q);
        b_hit_q  <= rst_i ? 16'd0 : byp_sel(b_idx_q, b_hits_q);
        a_ram_q  <= rst_i || ~|{in2_hits(a_idx_q), a_hits_q};
        b_ram_q  <= rst_i || ~|{in2_hits(b_idx_q), b_hits_q};
        a_bdv_q  <= !rst_i && |a_hits_q && ~|in2_hits(a_idx_q);
        b_bdv_q  <= !rst_i && |b_hits_q && ~|in2_hits(b_idx_q);
        a_idx_qq <= a_idx_q;
        b_idx_qq <= b_idx_q;
      end
      // The LVT entry, read in cycle t + 1 (it has the writes up to cycle
      // t; one of cycle t is taken from the bypass), one-hot ({port 3, 2,
      // 1, 0}), in two halves: in cycle t + 1 the low index bits pick an
      // entry in every group of 16, registered one-hot, in cycle t + 2 the
      // high bits pick the group (a multiplexer per bit, nothing behind it
      // but the gate with a_ram_q).
      wire [3:0] a_lvt2, b_lvt2;
      if (ONE) begin : g_lvt_none
        // (One write port: port 0's RAMs.)
        assign a_lvt2 = 4'b0001;
        assign b_lvt2 = 4'b0001;
        wire unused_lvt = &{1'b0, a_idx_qq, b_idx_qq, lvt_a_i, lvt_b_i};
      end else if (CTRL == 0) begin : g_lvt_lane0
        assign a_lvt2 = lvt_a_i;
        assign b_lvt2 = lvt_b_i;
        wire unused_lvt = &{1'b0, a_idx_qq, b_idx_qq};
      end else if (XW > 4) begin : g_lvt_split
        localparam integer NG = ENTRIES / 16;
        // The low index bits for this read from copies of a_idx_q[3:0]
        // and b_idx_q[3:0] of their own (kept apart as in fp3_ram): they
        // drive the LVT's 16:1 multiplexers across the die, and the
        // bypass compares keep the originals (a read index placed by the
        // LVT, far from its compares, was a critical path).
        reg [3:0] a_lo_q, b_lo_q;
        initial begin
          a_lo_q = 4'd0;
          b_lo_q = 4'd0;
        end
        (* keep *) always @(posedge clk_i) begin
          a_lo_q <= a_idx[3:0];
          b_lo_q <= rb_i[3:0];
        end
        reg [4*NG-1:0] a_pre_q, b_pre_q;
        integer gi;
        always @(posedge clk_i) begin
          for (gi = 0; gi < NG; gi = gi + 1) begin
            a_pre_q[4*gi +: 4] <= lvt1h({lvt_hi[16*gi + {28'd0, a_lo_q}],
                                         lvt_lo[16*gi + {28'd0, a_lo_q}]});
            b_pre_q[4*gi +: 4] <= lvt1h({lvt_hi[16*gi + {28'd0, b_lo_q}],
                                         lvt_lo[16*gi + {28'd0, b_lo_q}]});
          end
        end
        assign a_lvt2 = a_pre_q[4*a_idx_qq[XW-1:4] +: 4];
        assign b_lvt2 = b_pre_q[4*b_idx_qq[XW-1:4] +: 4];
        // (the low index bits were used in cycle t + 1)
        wire unused_lvt = &{1'b0, a_idx_qq[3:0], b_idx_qq[3:0]};
      end else begin : g_lvt_whole
        // In cycle t + 2 the entry has the writes of cycle t + 1 too: a
        // read of such a register takes the bypass word.
        assign a_lvt2 = lvt1h({lvt_hi[a_idx_qq], lvt_lo[a_idx_qq]});
        assign b_lvt2 = lvt1h({lvt_hi[b_idx_qq], lvt_lo[b_idx_qq]});
      end
      if (CTRL != 0 && !ONE) begin : g_lvt_in
        wire unused_lvt_i = &{1'b0, lvt_a_i, lvt_b_i};
      end
      assign lvt_a_o = a_lvt2;
      assign lvt_b_o = b_lvt2;
      // Cycle t + 2, registered for cycle t + 3: the RAMs' words, the
      // bypass word (a write of cycle t, t + 1 or t + 2, chosen by the
      // hits of cycle t + 1), and a one-hot choice of the word for cycle
      // t + 3, in the order of pick12's words: a write-back of cycle t + 3
      // (a hit of cycle t + 1, two cycles older), else the bypass word,
      // else the RAM the LVT names.
      reg  [31:0] wd0_qq, wd1_qq, wd2_qq, wd3_qq;   // the writes of cycle t
      always @(posedge clk_i) begin
        wd0_qq <= wd0_q;
        wd1_qq <= wd1_q;
        wd2_qq <= wd2_q;
        wd3_qq <= wd3_q;
      end
      wire [383:0] bw = {m0_data, m1_data, m2_data, m3_data,
                         wd0_q, wd1_q, wd2_q, wd3_q, wd0_qq, wd1_qq, wd2_qq, wd3_qq};
      reg  [31:0] qa0_q, qa1_q, qa2_q, qa3_q, qb0_q, qb1_q, qb2_q, qb3_q;
      reg  [31:0] a_bd_q, b_bd_q;
      reg  [8:0]  a_sel_q, b_sel_q;
      reg  [31:0] a_out_q, b_out_q;
      always @(posedge clk_i) begin
        qa0_q   <= q00;
        qa1_q   <= q10;
        qa2_q   <= q20;
        qa3_q   <= q30;
        qb0_q   <= q01;
        qb1_q   <= q11;
        qb2_q   <= q21;
        qb3_q   <= q31;
        a_bd_q  <= pick12(a_hit_q[11:0], bw);
        b_bd_q  <= pick12(b_hit_q[11:0], bw);
        a_sel_q <= {a_hit_q[15:12], a_bdv_q,
                    {4{a_ram_q}} & {a_lvt2[0], a_lvt2[1], a_lvt2[2], a_lvt2[3]}};
        b_sel_q <= {b_hit_q[15:12], b_bdv_q,
                    {4{b_ram_q}} & {b_lvt2[0], b_lvt2[1], b_lvt2[2], b_lvt2[3]}};
      end
      wire [31:0] a_nx = pick12({3'b000, a_sel_q},
                                {96'd0, m0_data, m1_data, m2_data, m3_data,
                                 a_bd_q, qa0_q, qa1_q, qa2_q, qa3_q});
      wire [31:0] b_nx = pick12({3'b000, b_sel_q},
                                {96'd0, m0_data, m1_data, m2_data, m3_data,
                                 b_bd_q, qb0_q, qb1_q, qb2_q, qb3_q});
      always @(posedge clk_i) begin
        a_out_q <= a_nx;
        b_out_q <= b_nx;
      end
      assign ra_data_o = a_out_q;
      assign rb_data_o = b_out_q;
    end else begin : g_bad_read_stages
      // Elaboration error on purpose: READ_STAGES must be 1 or 4.
      fp3_regfile_error_READ_STAGES_must_be_1_or_4 u_error ();
    end
  endgenerate

  // ---- LVT and busy flags, one register at a time --------------------------
  // This cycle's writes per port, one-hot over the registers.  With
  // READ_STAGES = 4 they are decoded a cycle ahead (from nx_*) and
  // registered, so that no index compare sits in front of the LVT; the
  // host's write is decoded from its register, and so reaches the LVT a
  // cycle after the RAM (a read in between takes it from the bypass:
  // the writes of cycle t).  Port 2's two writers are decoded apart.
  // (The decoders and the per-register updates below are written as
  // whole-vector operations: the same logic per register for synthesis,
  // and a few word operations per cycle for a Verilated model instead of
  // one statement per register.)
  function [ENTRIES-1:0] dec;   // one-hot of idx if valid
    input          valid;
    input [XW-1:0] idx;
    begin
      dec = {{(ENTRIES-1){1'b0}}, valid} << idx;
    end
  endfunction
  // The two halves of dec (READ_STAGES = 4): an index's high HW bits
  // one-hot if valid, and its low LW bits one-hot.
  localparam integer LW = XW / 2;
  localparam integer HW = XW - LW;
  function [(1<<HW)-1:0] dec_hi;
    input          valid;
    input [HW-1:0] hi;
    integer d;
    begin
      for (d = 0; d < (1 << HW); d = d + 1) dec_hi[d] = valid && hi == d[HW-1:0];
    end
  endfunction
  function [(1<<LW)-1:0] dec_lo;
    input [LW-1:0] lo;
    integer d;
    begin
      for (d = 0; d < (1 << LW); d = d + 1) dec_lo[d] = lo == d[LW-1:0];
    end
  endfunction
  // Joins the halves: register e is hit when its high half's bit and its
  // low half's bit are (e = {high, low}).
  function [ENTRIES-1:0] dec_join;
    input [(1<<HW)-1:0] hi;
    input [(1<<LW)-1:0] lo;
    integer g;
    begin
      for (g = 0; g < (1 << HW); g = g + 1) dec_join[g*(1<<LW) +: (1<<LW)] = {(1<<LW){hi[g]}} & lo;
    end
  endfunction
  wire [ENTRIES-1:0] h0, h1, h2, h3;
  generate
    if (CTRL == 0 || ONE) begin : g_hit_none    // no LVT (lanes 1 .., or one port)
      assign {h0, h1, h2, h3} = {4*ENTRIES{1'b0}};
    end else if (READ_STAGES == 4) begin : g_hit_ahead
      // Decoded in two halves from the indices nx_* and hidx_q register:
      // the index's high bits (a write-back's with its valid bit), one-hot
      // over 2**(XW - XW/2), and its low bits, one-hot over 2**(XW/2)
      // (dec_hi, dec_lo).  A flag is then one LUT of two registers, or on
      // port 2 of five (the host's write brings its valid bit, hwe_q: its
      // address checks sit in front of that register).  (One 8-bit compare
      // per flag behind a single index register was the critical path:
      // 256 flags across the die, 6.8 of 8.2 ns routing.)
      reg [(1<<HW)-1:0] hh0_q, hh1_q, hh2_q, hh3_q, hhh_q;   // high halves
      reg [(1<<LW)-1:0] hl0_q, hl1_q, hl2_q, hl3_q, hlh_q;   // low halves
      always @(posedge clk_i) begin
        hh0_q <= dec_hi(!rst_i && n0_valid, n0_idx[XW-1:LW]);
        hh1_q <= dec_hi(!rst_i && n1_valid, n1_idx[XW-1:LW]);
        hh2_q <= dec_hi(!rst_i && n2_valid, n2_idx[XW-1:LW]);
        hh3_q <= dec_hi(!rst_i && n3_valid, n3_idx[XW-1:LW]);
        hhh_q <= dec_hi(1'b1, host_idx_i[XW-1:LW]);
        hl0_q <= dec_lo(n0_idx[LW-1:0]);
        hl1_q <= dec_lo(n1_idx[LW-1:0]);
        hl2_q <= dec_lo(n2_idx[LW-1:0]);
        hl3_q <= dec_lo(n3_idx[LW-1:0]);
        hlh_q <= dec_lo(host_idx_i[LW-1:0]);
      end
      reg [ENTRIES-1:0] h0_q, h1_q, h2_q, h3_q;
      always @(posedge clk_i) begin
        h0_q <= rst_i ? {ENTRIES{1'b0}} : dec_join(hh0_q, hl0_q);
        h1_q <= rst_i ? {ENTRIES{1'b0}} : dec_join(hh1_q, hl1_q);
        h2_q <= rst_i ? {ENTRIES{1'b0}} : dec_join(hh2_q, hl2_q) |
                                          dec_join({(1<<HW){hwe_lvt}} & hhh_q, hlh_q);
        h3_q <= rst_i ? {ENTRIES{1'b0}} : dec_join(hh3_q, hl3_q);
      end
      assign {h0, h1, h2, h3} = {h0_q, h1_q, h2_q, h3_q};
    end else begin : g_hit_now
      assign h0 = dec(m0_valid, m0_idx);
      assign h1 = dec(m1_valid, m1_idx);
      assign h2 = dec(m2_valid, m2_idx) | dec(hwe_lvt, hidx_q);
      assign h3 = dec(m3_valid, m3_idx);
    end
  endgenerate

  // The busy flags' set and clear, one-hot over the registers.
  wire [ENTRIES-1:0] fset, fclr;
  generate
    if (CTRL == 0) begin : g_flags_none         // no busy flags (lanes 1 ..)
      assign {fset, fclr} = {2*ENTRIES{1'b0}};
    end else if (FLAGS_AHEAD != 0) begin : g_flags_ahead
      // The clears from the announcements of the next cycle, decoded in
      // two halves (as the write hits above) and registered.  The set
      // from the instruction picked, registered as it is (a copy of the
      // issue register's destination that drives only this decode: kept,
      // or Yosys would merge it with the issue register) and decoded in
      // halves after it, so that the pick's multiplexer drives only
      // flip-flops.  (A flag behind four 8-bit compares with the issue
      // register's destination and the tag lines' indices was a critical
      // path: some 5.8 ns of routing to the flags' enables across the
      // die; the set's halves decoded behind the pick's multiplexer were
      // the next, 5.3 ns.)
      wire          sv_q;
      wire [XW-1:0] si_q;
      fp3_keep #(.W(1 + XW)) u_set_copy (
        .clk_i (clk_i),
        .d_i   ({!rst_i && set_i, set_idx_i}),
        .q_o   ({sv_q, si_q})
      );
      wire [(1<<HW)-1:0] sh = dec_hi(sv_q, si_q[XW-1:LW]);
      wire [(1<<LW)-1:0] sl = dec_lo(si_q[LW-1:0]);
      reg [(1<<HW)-1:0] ch0_q, ch1_q, ch2_q, ch3_q;   // high halves
      reg [(1<<LW)-1:0] cl0_q, cl1_q, cl2_q, cl3_q;   // low halves
      always @(posedge clk_i) begin
        ch0_q <= dec_hi(!rst_i && k0_valid, k0_idx[XW-1:LW]);
        ch1_q <= dec_hi(!rst_i && k1_valid, k1_idx[XW-1:LW]);
        ch2_q <= dec_hi(!rst_i && k2_valid, k2_idx[XW-1:LW]);
        ch3_q <= dec_hi(!rst_i && k3_valid, k3_idx[XW-1:LW]);
        cl0_q <= dec_lo(k0_idx[LW-1:0]);
        cl1_q <= dec_lo(k1_idx[LW-1:0]);
        cl2_q <= dec_lo(k2_idx[LW-1:0]);
        cl3_q <= dec_lo(k3_idx[LW-1:0]);
      end
      assign fset = dec_join(sh, sl);
      assign fclr = dec_join(ch0_q, cl0_q) | dec_join(ch1_q, cl1_q) | dec_join(ch2_q, cl2_q) |
                    dec_join(ch3_q, cl3_q);
    end else begin : g_flags_now
      assign fset = dec(set_i, set_idx_i);
      assign fclr = dec(k0_valid, k0_idx) | dec(k1_valid, k1_idx) |
                    dec(k2_valid, k2_idx) | dec(k3_valid, k3_idx);
    end
  endgenerate

  genvar ag;   // idle_o's groups of 16 flags (g_ctrl)
  // The WAW stall guarantees that the write ports name distinct registers,
  // so the priority below never matters for a legal sequence.
  generate
    if (CTRL != 0) begin : g_ctrl
      // Register r: LVT entry {lvt_hi_q[r], lvt_lo_q[r]} (0 .. 3: the
      // port that wrote it last; a lower port wins over a higher one), busy
      // flag busy_q[r] (the set wins over a clear).  The RAMs start at zero.
      reg  [ENTRIES-1:0] busy_q;
      wire [ENTRIES-1:0] busy_d = busy_q & ~fclr | fset;
      always @(posedge clk_i) busy_q <= rst_i ? {ENTRIES{1'b0}} : busy_d;
      assign busy_o = busy_q;
      if (ONE) begin : g_no_lvt
        // (One write port: nothing to choose.)
        assign {lvt_lo, lvt_hi} = {2*ENTRIES{1'b0}};
        wire unused_hits = &{1'b0, h0, h1, h2, h3, hwe_lvt, lvt_lo, lvt_hi};
      end else begin : g_lvt
        reg  [ENTRIES-1:0] lvt_lo_q, lvt_hi_q;
        wire [ENTRIES-1:0] hit  = h0 | h1 | h2 | h3;
        wire [ENTRIES-1:0] won1 = h1 & ~h0;
        wire [ENTRIES-1:0] won2 = h2 & ~h1 & ~h0;
        wire [ENTRIES-1:0] won3 = h3 & ~h2 & ~h1 & ~h0;
        always @(posedge clk_i) begin
          lvt_lo_q <= rst_i ? {ENTRIES{1'b0}} : lvt_lo_q & ~hit | won1 | won3;
          lvt_hi_q <= rst_i ? {ENTRIES{1'b0}} : lvt_hi_q & ~hit | won2 | won3;
        end
        assign lvt_lo = lvt_lo_q;
        assign lvt_hi = lvt_hi_q;
      end
      // idle_o, a cycle late, from a register of its own: the flags' next
      // state ORed in groups of 16 and registered (any_q: a group's flags
      // now), then joined and registered (idle_q: no flag in the last
      // cycle).  Both ORs stay beside the flags, and only idle_q's one
      // wire crosses the die to the scheduler's run control, which it
      // enters at the start of the cycle.  (A NOR of the flags on the
      // scheduler's side of that wire was a critical path.)  The cost:
      // the ORs take the flags' next state instead of the flags, and one
      // flip-flop more.
      localparam integer GN = (ENTRIES + 15) / 16;
      // (Each group one reduction OR of a part-select, not a loop over the
      // bits: the same logic, which Verilator evaluates a word at a time.)
      wire [GN-1:0] any_d;
      reg  [GN-1:0] any_q;
      reg           idle_q;
      for (ag = 0; ag < GN; ag = ag + 1) begin : g_any
        localparam integer AHI = (16 * ag + 16 < ENTRIES) ? 16 * ag + 16 : ENTRIES;
        assign any_d[ag] = |busy_d[AHI-1:16*ag];
      end
      always @(posedge clk_i) begin
        any_q  <= rst_i ? {GN{1'b0}} : any_d;
        idle_q <= rst_i || !(|any_q);
      end
      assign idle_o = idle_q;
`ifdef FP3_SCHED_CHECK
      // idle_o is exactly "no busy flag in the last cycle" (formal/sched.sby).
      reg f_idle_past = 1'b0, f_idle_ref = 1'b1;
      always @(posedge clk_i) begin
        f_idle_past <= 1'b1;
        f_idle_ref  <= rst_i || !(|busy_q);
      end
      always @(*) if (f_idle_past) idle_exact: assert (idle_o == f_idle_ref);
`endif
    end else begin : g_data_only
      // Lanes 1 ..: lane 0's flags are the scoreboard, its LVT chooses.
      assign busy_o   = {ENTRIES{1'b0}};
      assign idle_o   = 1'b1;
      assign {lvt_lo, lvt_hi} = {2*ENTRIES{1'b0}};
      wire unused_ctrl = &{1'b0, lvt_lo, lvt_hi, h0, h1, h2, h3, fset, fclr, hwe_lvt, set_i,
                           set_idx_i, k0_valid, k0_idx, k1_valid, k1_idx,
                           k2_valid, k2_idx, k3_valid, k3_idx};
    end
  endgenerate
endmodule
`default_nettype wire
