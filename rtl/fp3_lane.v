// fp3_lane -- one lane of the FP3 processor: a register bank
// (fp3_regfile: RAMs, live value table, bypass) and an arithmetic unit
// (fp3_arith: add/sub core, mul core, move path, div/sqrt unit) of its own.
//
// fp3_simd instantiates NUM_LANES of these side by side.  Every lane
// receives the same operation stream: the same register indices, unit,
// immediate and write-back indices (one scheduler, one set of write-back
// tag lines), so lane l of context c holds one object and all lanes of a
// context execute each issued instruction in the same cycle (SIMD; the
// issue slot, fetch, decode and scoreboard are paid for once).  What a
// lane has alone is its data: the register values, the results and their
// exception flags.  The host writes only the lane it selects (host_we_i,
// gated by fp3_host with LANE) and reads a lane's registers through its
// read port A.
//
// Cost per lane: one fp_add, one fp_mul (4 MULT18X18D on ECP5 for a
// binary32 significand product), the move path's registers, fp_div and
// fp_sqrt when built (HAS_DIV, HAS_SQRT), and eight register RAMs of
// 2**XW x 32 bits (block RAM: fp3_ram; the div/sqrt port's two are never
// written without the unit and synthesize away; WB_PORTS = 1: two), plus
// the read stages' bypass.  The register file's busy flags and live value table
// would be identical in every lane (they see the same indices), so only
// lane 0 has them (CTRL = 1): fp3_simd uses its busy flags (busy_o,
// idle_o) as the scoreboard, and lanes 1 .. (CTRL = 0) take its LVT
// choice of each read (lvt_*_o of lane 0 into their lvt_*_i) and have no
// flags of their own (fp3_regfile CTRL).  With more than one lane the
// host's register writes, which reach one lane, leave the shared LVT alone
// (fp3_regfile HOST_ALL).
//
// Broadcast stages (IN_STAGES, OUT_STAGES, EQ_STAGE, HOST_STAGES): with lanes, the
// operation stream fans out from one scheduler across the die to every
// lane, and lane 0's LVT choice to every other lane; registering it at each
// lane's inputs makes those wires register-to-register paths.  The
// operation stream (read indices, write-back tags and their two-ahead
// announcements, the operation and its immediate) passes IN_STAGES
// registers, the last of them this lane's own (fp3_keep: placed beside the
// lane, not merged with another lane's copy); so the whole lane runs
// IN_STAGES cycles behind the scheduler, and its bypass and LVT see reads
// and writes at the same distances as without.  What stays in the
// scheduler's time: the busy flags' set and clear (set_i, clr*_i: the
// scoreboard).  OUT_STAGES registers delay the results, their flags, eq_o
// and ra_data_o further (lane 0 is staged once less than the others, so
// that its LVT choice reaches them through a register: fp3_simd), EQ_STAGE
// registers the beq compare before it leaves the lane, and HOST_STAGES
// registers the host port's inputs (lanes 1 .., which read a cycle after
// lane 0 so that its LVT choice of the same read reaches them through that
// register).  The cost: about 140 flip-flops per input stage, 180 per
// output stage and 43 for the host's, and beq, the end of a run and host
// reads a few cycles later (fp3_simd).
//
// Parameters: those of fp3_regfile (ENTRIES, XW, READ_STAGES,
// FLAGS_AHEAD, CTRL, HOST_ALL, WB_PORTS) and fp3_arith (ADD_LATENCY, MUL_LATENCY,
// MUL_FEED, MOV_LATENCY, DIV_LATENCY, ROUND, FTZ, HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV,
// HAS_SQRT, HAS_SIGN), passed through unchanged; IN_STAGES (0 .. 2),
// OUT_STAGES, EQ_STAGE and HOST_STAGES (0 or 1 each), the broadcast stages
// above (0: none, the lane of a one-lane build).
// Ports: fp3_regfile's (index ports shared by all lanes) and fp3_arith's
// operation inputs; imm_i/imm_val_i choose the immediate as the first
// operand (li), as the read stage gives it.  ra_data_o is this lane's
// port A operand HOST_STAGES + READ_STAGES + OUT_STAGES cycles after the
// host's read address (while host_sel_i), eq_o whether ports A and B
// read the same bit pattern (beq), IN_STAGES + OUT_STAGES + EQ_STAGE cycles
// after the read stage gives them;
// {add,mul,mov,div}_data_o and _flags_o are its results, IN_STAGES +
// OUT_STAGES cycles after the cycle the tag lines' write-back valid names.
`default_nettype none
module fp3_lane #(
  parameter integer ENTRIES     = 256,
  parameter integer XW          = 8,
  parameter integer READ_STAGES = 1,
  parameter integer FLAGS_AHEAD = 0,
  parameter integer CTRL        = 1,
  parameter integer HOST_ALL    = 0,
  parameter integer WB_PORTS    = 4,
  parameter integer ADD_LATENCY = 4,
  parameter integer MUL_LATENCY = 3,
  parameter integer MUL_FEED    = 0,
  parameter integer MOV_LATENCY = 1,
  parameter integer DIV_LATENCY = 8,
  parameter integer ROUND       = 0,
  parameter integer FTZ         = 0,
  parameter integer HAS_ADD     = 1,
  parameter integer HAS_SUB     = 1,
  parameter integer HAS_MUL     = 1,
  parameter integer HAS_DIV     = 1,
  parameter integer HAS_SQRT    = 1,
  parameter integer HAS_SIGN    = 1,
  parameter integer IN_STAGES   = 0,
  parameter integer OUT_STAGES  = 0,
  parameter integer EQ_STAGE    = 0,
  parameter integer HOST_STAGES = 0
) (
  input  wire               clk_i,
  input  wire               rst_i,
  // register file (see fp3_regfile)
  input  wire [XW-1:0]      ra_i,
  input  wire [XW-1:0]      rb_i,
  output wire [31:0]        ra_data_o,
  output wire               eq_o,        // port A's operand == port B's (beq)
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
  input  wire               wb1_valid_i,
  input  wire [XW-1:0]      wb1_idx_i,
  input  wire               wb2_valid_i,
  input  wire [XW-1:0]      wb2_idx_i,
  input  wire               wb3_valid_i,
  input  wire [XW-1:0]      wb3_idx_i,
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
  input  wire [3:0]         lvt_b_i,
  // arithmetic unit (see fp3_arith), operands from this lane's read stage
  input  wire               valid_i,
  input  wire [2:0]         unit_i,
  input  wire               sub_i,
  input  wire [2:0]         sop_i,
  input  wire               imm_i,
  input  wire [31:0]        imm_val_i,
  output wire [31:0]        add_data_o,
  output wire [4:0]         add_flags_o,
  output wire [31:0]        mul_data_o,
  output wire [4:0]         mul_flags_o,
  output wire [31:0]        mov_data_o,
  output wire [4:0]         mov_flags_o,
  output wire [31:0]        div_data_o,
  output wire [4:0]         div_flags_o
);
  wire [31:0] ra_data, rb_data;
  wire [31:0] add_data, mul_data, mov_data, div_data;
  wire [4:0]  add_flags, mul_flags, mov_flags, div_flags;

  generate
    if (IN_STAGES < 0 || IN_STAGES > 2 || OUT_STAGES < 0 || OUT_STAGES > 1 ||
        EQ_STAGE < 0 || EQ_STAGE > 1 || HOST_STAGES < 0 || HOST_STAGES > 1) begin : g_bad_stages
      // Elaboration error on purpose: the broadcast stages are 0 .. 2 in,
      // 0 or 1 out, for the compare and for the host's read.
      fp3_lane_error_IN_STAGES_0_to_2_OUT_EQ_HOST_STAGES_0_or_1 u_error ();
    end
  endgenerate

  // ---- the host port, HOST_STAGES cycles late -----------------------------
  wire          h_sel, h_we;
  wire [XW-1:0] h_idx;
  wire [31:0]   h_wdata;
  fp_pipe #(.WIDTH(1 + XW + 32), .DEPTH(HOST_STAGES)) u_host (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (host_we_i),
    .data_i  ({host_sel_i, host_idx_i, host_wdata_i}),
    .valid_o (h_we),
    .data_o  ({h_sel, h_idx, h_wdata})
  );

  // ---- input stages: the operation stream, IN_STAGES cycles late ----------
  // One word: {ra, rb, the four write-back ports' valid and index, their
  // valid and index two ahead, valid, unit, sub, sop, imm, immediate}.  The
  // valid bits are cleared by the reset at every stage.
  localparam integer BW = 2*XW + 8*(1 + XW) + 1 + 3 + 1 + 3 + 1 + 32;
  localparam integer VB = 1 + XW;   // a port's {valid, index}
  localparam integer OP_VALID = 32 + 1 + 3 + 1 + 3;   // valid_i's bit: above imm, sop, sub, unit
  function [BW-1:0] valids_off;     // w with every valid bit cleared
    input [BW-1:0] w;
    integer p;
    begin
      valids_off = w;
      for (p = 0; p < 8; p = p + 1) valids_off[BW - 2*XW - VB*p - 1] = 1'b0;
      valids_off[OP_VALID] = 1'b0;
    end
  endfunction
  wire [BW-1:0] bc_in = {ra_i, rb_i,
                         wb0_valid_i, wb0_idx_i, wb1_valid_i, wb1_idx_i,
                         wb2_valid_i, wb2_idx_i, wb3_valid_i, wb3_idx_i,
                         wb0_in2_valid_i, wb0_in2_idx_i, wb1_in2_valid_i, wb1_in2_idx_i,
                         wb2_in2_valid_i, wb2_in2_idx_i, wb3_in2_valid_i, wb3_in2_idx_i,
                         valid_i, unit_i, sub_i, sop_i, imm_i, imm_val_i};
  wire [BW*(IN_STAGES+1)-1:0] bc_s;   // stage s in [BW*s +: BW]
  assign bc_s[BW-1:0] = bc_in;
  genvar st;
  generate
    for (st = 1; st <= IN_STAGES; st = st + 1) begin : g_in
      wire [BW-1:0] d = rst_i ? valids_off(bc_s[BW*(st-1) +: BW]) : bc_s[BW*(st-1) +: BW];
      if (st < IN_STAGES) begin : g_shared
        // (an earlier stage: a flattening synthesis may merge it with
        // another lane's)
        reg [BW-1:0] q;
        always @(posedge clk_i) q <= d;
        assign bc_s[BW*st +: BW] = q;
      end else begin : g_own
        fp3_keep #(.W(BW)) u_stage (
          .clk_i (clk_i),
          .d_i   (d),
          .q_o   (bc_s[BW*st +: BW])
        );
      end
    end
  endgenerate
  wire [XW-1:0] s_ra, s_rb;
  wire          s_wb0_valid, s_wb1_valid, s_wb2_valid, s_wb3_valid;
  wire [XW-1:0] s_wb0_idx, s_wb1_idx, s_wb2_idx, s_wb3_idx;
  wire          s_in20_valid, s_in21_valid, s_in22_valid, s_in23_valid;
  wire [XW-1:0] s_in20_idx, s_in21_idx, s_in22_idx, s_in23_idx;
  wire          s_valid, s_sub, s_imm;
  wire [2:0]    s_unit, s_sop;
  wire [31:0]   s_imm_val;
  assign {s_ra, s_rb,
          s_wb0_valid, s_wb0_idx, s_wb1_valid, s_wb1_idx,
          s_wb2_valid, s_wb2_idx, s_wb3_valid, s_wb3_idx,
          s_in20_valid, s_in20_idx, s_in21_valid, s_in21_idx,
          s_in22_valid, s_in22_idx, s_in23_valid, s_in23_idx,
          s_valid, s_unit, s_sub, s_sop, s_imm, s_imm_val} = bc_s[BW*IN_STAGES +: BW];

  fp3_regfile #(.ENTRIES(ENTRIES), .XW(XW), .READ_STAGES(READ_STAGES),
                .FLAGS_AHEAD(FLAGS_AHEAD), .CTRL(CTRL),
                .HOST_ALL(HOST_ALL), .WB_PORTS(WB_PORTS)) u_regs (
    .clk_i           (clk_i),
    .rst_i           (rst_i),
    .ra_i            (s_ra),
    .rb_i            (s_rb),
    .ra_data_o       (ra_data),
    .rb_data_o       (rb_data),
    .busy_o          (busy_o),
    .set_i           (set_i),
    .set_idx_i       (set_idx_i),
    .clr0_valid_i    (clr0_valid_i),
    .clr0_idx_i      (clr0_idx_i),
    .clr1_valid_i    (clr1_valid_i),
    .clr1_idx_i      (clr1_idx_i),
    .clr2_valid_i    (clr2_valid_i),
    .clr2_idx_i      (clr2_idx_i),
    .clr3_valid_i    (clr3_valid_i),
    .clr3_idx_i      (clr3_idx_i),
    .wb0_valid_i     (s_wb0_valid),
    .wb0_idx_i       (s_wb0_idx),
    .wb0_data_i      (add_data),
    .wb1_valid_i     (s_wb1_valid),
    .wb1_idx_i       (s_wb1_idx),
    .wb1_data_i      (mul_data),
    .wb2_valid_i     (s_wb2_valid),
    .wb2_idx_i       (s_wb2_idx),
    .wb2_data_i      (mov_data),
    .wb3_valid_i     (s_wb3_valid),
    .wb3_idx_i       (s_wb3_idx),
    .wb3_data_i      (div_data),
    .wb0_in2_valid_i (s_in20_valid),
    .wb0_in2_idx_i   (s_in20_idx),
    .wb1_in2_valid_i (s_in21_valid),
    .wb1_in2_idx_i   (s_in21_idx),
    .wb2_in2_valid_i (s_in22_valid),
    .wb2_in2_idx_i   (s_in22_idx),
    .wb3_in2_valid_i (s_in23_valid),
    .wb3_in2_idx_i   (s_in23_idx),
    .host_sel_i      (h_sel),
    .host_we_i       (h_we),
    .host_idx_i      (h_idx),
    .host_wdata_i    (h_wdata),
    .idle_o          (idle_o),
    .lvt_a_o         (lvt_a_o),
    .lvt_b_o         (lvt_b_o),
    .lvt_a_i         (lvt_a_i),
    .lvt_b_i         (lvt_b_i)
  );

  // The units' own valid bits equal the shared tag lines' (same depth from
  // the same issue); fp3_simd uses the tag lines'.
  wire add_valid, mul_valid, mov_valid, div_valid;
  fp3_arith #(.ADD_LATENCY(ADD_LATENCY), .MUL_LATENCY(MUL_LATENCY), .MUL_FEED(MUL_FEED),
              .ROUND(ROUND), .FTZ(FTZ),
              .MOV_LATENCY(MOV_LATENCY), .DIV_LATENCY(DIV_LATENCY), .HAS_ADD(HAS_ADD),
              .HAS_SUB(HAS_SUB), .HAS_MUL(HAS_MUL), .HAS_DIV(HAS_DIV), .HAS_SQRT(HAS_SQRT),
              .HAS_SIGN(HAS_SIGN)) u_arith (
    .clk_i       (clk_i),
    .rst_i       (rst_i),
    .valid_i     (s_valid),
    .unit_i      (s_unit),
    .sub_i       (s_sub),
    .sop_i       (s_sop),
    .a_i         (s_imm ? s_imm_val : ra_data),
    .b_i         (rb_data),
    .add_valid_o (add_valid),
    .add_data_o  (add_data),
    .add_flags_o (add_flags),
    .mul_valid_o (mul_valid),
    .mul_data_o  (mul_data),
    .mul_flags_o (mul_flags),
    .mov_valid_o (mov_valid),
    .mov_data_o  (mov_data),
    .mov_flags_o (mov_flags),
    .div_valid_o (div_valid),
    .div_data_o  (div_data),
    .div_flags_o (div_flags)
  );
  wire unused_valid = add_valid ^ mul_valid ^ mov_valid ^ div_valid;

  // beq's compare in the lane, beside its operands: one wire a lane to
  // fp3_simd's branch resolution instead of both 32-bit operands (with
  // EQ_STAGE registered, so that the wire leaves a flip-flop).
  wire eq = ra_data == rb_data;
  wire eq_s;
  generate
    if (EQ_STAGE != 0) begin : g_eq_reg
      reg eq_q;
      always @(posedge clk_i) eq_q <= eq;
      assign eq_s = eq_q;
    end else begin : g_eq_now
      assign eq_s = eq;
    end
  endgenerate
  // ---- output stages: results, flags and eq_o, OUT_STAGES cycles late -----
  wire out_valid;
  fp_pipe #(.WIDTH(32 + 1 + 4*32 + 4*5), .DEPTH(OUT_STAGES)) u_out (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (1'b0),
    .data_i  ({ra_data, eq_s, add_data, mul_data, mov_data, div_data,
               add_flags, mul_flags, mov_flags, div_flags}),
    .valid_o (out_valid),
    .data_o  ({ra_data_o, eq_o, add_data_o, mul_data_o, mov_data_o, div_data_o,
               add_flags_o, mul_flags_o, mov_flags_o, div_flags_o})
  );
  wire unused_out = out_valid;
endmodule
`default_nettype wire
