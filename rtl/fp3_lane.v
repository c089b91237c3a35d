// fp3_lane -- one lane of the FP3 processor: a register bank
// (fp3_regfile: RAMs, live value table, bypass) and an arithmetic unit
// (fp3_arith: add/sub core, mul core, move path, div/sqrt unit) of its own.
//
// fp3_top instantiates NUM_LANES of these side by side.  Every lane
// receives the same operation stream: the same register indices, unit,
// immediate and write-back indices (one scheduler, one set of write-back
// tag lines), so lane l of context c holds one object and all lanes of a
// context execute each issued instruction in the same cycle (SIMD; the
// issue slot, fetch, decode and scoreboard are paid for once).  What a
// lane has alone is its data: the register values, the results and their
// exception flags.  The host writes only the lane it selects (host_we_i,
// gated by fp3_top with LANE) and reads a lane's registers through its
// read port A.
//
// Cost per lane: one fp_add, one fp_mul (4 MULT18X18D on ECP5 for a
// binary32 significand product), the move path's registers, fp_div and
// fp_sqrt when built (HAS_DIV, HAS_SQRT), and eight register RAMs of
// 2**XW x 32 bits (block RAM: fp3_ram; the div/sqrt port's two are never
// written without the unit and synthesize away), plus the read stages'
// bypass.  The register file's busy flags and live value table
// would be identical in every lane (they see the same indices), so only
// lane 0 has them (CTRL = 1): fp3_top uses its busy flags (busy_o,
// idle_o) as the scoreboard, and lanes 1 .. (CTRL = 0) take its LVT
// choice of each read (lvt_*_o of lane 0 into their lvt_*_i) and have no
// flags of their own (fp3_regfile CTRL).  With more than one lane the
// host's register writes, which reach one lane, leave the shared LVT alone
// (fp3_regfile HOST_ALL).
//
// Parameters: those of fp3_regfile (ENTRIES, XW, READ_STAGES,
// FLAGS_AHEAD, CTRL, HOST_ALL) and fp3_arith (ADD_LATENCY, MUL_LATENCY,
// MOV_LATENCY, DIV_LATENCY, ROUND, FTZ, HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV,
// HAS_SQRT, HAS_SIGN), passed through unchanged.
// Ports: fp3_regfile's (index ports shared by all lanes) and fp3_arith's
// operation inputs; imm_i/imm_val_i choose the immediate as the first
// operand (li), as the read stage gives it.  ra_data_o is this lane's
// port A operand READ_STAGES cycles after the issue (the host's read),
// eq_o whether ports A and B read the same bit pattern (beq), in the same
// cycle; {add,mul,mov,div}_data_o and _flags_o are its results,
// in the cycle the tag lines' write-back valid names.
`default_nettype none
module fp3_lane #(
  parameter integer ENTRIES     = 256,
  parameter integer XW          = 8,
  parameter integer READ_STAGES = 1,
  parameter integer FLAGS_AHEAD = 0,
  parameter integer CTRL        = 1,
  parameter integer HOST_ALL    = 0,
  parameter integer ADD_LATENCY = 4,
  parameter integer MUL_LATENCY = 3,
  parameter integer MOV_LATENCY = 1,
  parameter integer DIV_LATENCY = 8,
  parameter integer ROUND       = 0,
  parameter integer FTZ         = 0,
  parameter integer HAS_ADD     = 1,
  parameter integer HAS_SUB     = 1,
  parameter integer HAS_MUL     = 1,
  parameter integer HAS_DIV     = 1,
  parameter integer HAS_SQRT    = 1,
  parameter integer HAS_SIGN    = 1
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

  fp3_regfile #(.ENTRIES(ENTRIES), .XW(XW), .READ_STAGES(READ_STAGES),
                .FLAGS_AHEAD(FLAGS_AHEAD), .CTRL(CTRL),
                .HOST_ALL(HOST_ALL)) u_regs (
    .clk_i           (clk_i),
    .rst_i           (rst_i),
    .ra_i            (ra_i),
    .rb_i            (rb_i),
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
    .wb0_valid_i     (wb0_valid_i),
    .wb0_idx_i       (wb0_idx_i),
    .wb0_data_i      (add_data),
    .wb1_valid_i     (wb1_valid_i),
    .wb1_idx_i       (wb1_idx_i),
    .wb1_data_i      (mul_data),
    .wb2_valid_i     (wb2_valid_i),
    .wb2_idx_i       (wb2_idx_i),
    .wb2_data_i      (mov_data),
    .wb3_valid_i     (wb3_valid_i),
    .wb3_idx_i       (wb3_idx_i),
    .wb3_data_i      (div_data),
    .wb0_in2_valid_i (wb0_in2_valid_i),
    .wb0_in2_idx_i   (wb0_in2_idx_i),
    .wb1_in2_valid_i (wb1_in2_valid_i),
    .wb1_in2_idx_i   (wb1_in2_idx_i),
    .wb2_in2_valid_i (wb2_in2_valid_i),
    .wb2_in2_idx_i   (wb2_in2_idx_i),
    .wb3_in2_valid_i (wb3_in2_valid_i),
    .wb3_in2_idx_i   (wb3_in2_idx_i),
    .host_sel_i      (host_sel_i),
    .host_we_i       (host_we_i),
    .host_idx_i      (host_idx_i),
    .host_wdata_i    (host_wdata_i),
    .idle_o          (idle_o),
    .lvt_a_o         (lvt_a_o),
    .lvt_b_o         (lvt_b_o),
    .lvt_a_i         (lvt_a_i),
    .lvt_b_i         (lvt_b_i)
  );

  // The units' own valid bits equal the shared tag lines' (same depth from
  // the same issue); fp3_top uses the tag lines'.
  wire add_valid, mul_valid, mov_valid, div_valid;
  fp3_arith #(.ADD_LATENCY(ADD_LATENCY), .MUL_LATENCY(MUL_LATENCY), .ROUND(ROUND), .FTZ(FTZ),
              .MOV_LATENCY(MOV_LATENCY), .DIV_LATENCY(DIV_LATENCY), .HAS_ADD(HAS_ADD),
              .HAS_SUB(HAS_SUB), .HAS_MUL(HAS_MUL), .HAS_DIV(HAS_DIV), .HAS_SQRT(HAS_SQRT),
              .HAS_SIGN(HAS_SIGN)) u_arith (
    .clk_i       (clk_i),
    .rst_i       (rst_i),
    .valid_i     (valid_i),
    .unit_i      (unit_i),
    .sub_i       (sub_i),
    .sop_i       (sop_i),
    .a_i         (imm_i ? imm_val_i : ra_data),
    .b_i         (rb_data),
    .add_valid_o (add_valid),
    .add_data_o  (add_data),
    .add_flags_o (add_flags_o),
    .mul_valid_o (mul_valid),
    .mul_data_o  (mul_data),
    .mul_flags_o (mul_flags_o),
    .mov_valid_o (mov_valid),
    .mov_data_o  (mov_data),
    .mov_flags_o (mov_flags_o),
    .div_valid_o (div_valid),
    .div_data_o  (div_data),
    .div_flags_o (div_flags_o)
  );
  wire unused_valid = add_valid ^ mul_valid ^ mov_valid ^ div_valid;

  assign ra_data_o  = ra_data;
  // beq's compare in the lane, beside its operands: one wire a lane to
  // fp3_top's branch resolution instead of both 32-bit operands.
  assign eq_o       = ra_data == rb_data;
  assign add_data_o = add_data;
  assign mul_data_o = mul_data;
  assign mov_data_o = mov_data;
  assign div_data_o = div_data;
endmodule
`default_nettype wire
