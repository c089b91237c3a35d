// fp3_scheduler -- the workload scheduler (paper §4): instruction memory,
// PC, decode, hazard check against the register file's busy flags, in-order
// single issue, the integration loop, run status and counters.
//
// A program is a prologue (run once) and a loop body ending in `endi L`.
// Each endi closes one integration: if it was the last of the STEPS
// requested, issue stops; otherwise the PC jumps to L.  The fetch address
// is the next PC computed in the issue cycle, so the synchronous
// instruction memory delivers the right instruction the next cycle and a
// taken endi costs no bubble.
//
// An instruction issues when it is legal and ready: its sources are not
// busy or are being written back this cycle (RAW, with bypass) and its
// destination is not busy (WAW).  WAR needs no check: operands are read at
// issue, in order.  A cycle in which the instruction waits is a stall.
//
// A run ends (DONE) when issue has stopped -- last endi, halt or an error
// -- and no result is in flight.  Errors: an illegal instruction (unknown
// opcode, a nonzero unused field, a register >= NUM_REGS, an endi target
// outside the memory) or a PC running off the end of the memory stop issue
// and record the faulting PC.
//
// Parameters
//   NUM_REGS    registers; IW = clog2(NUM_REGS) index width
//   IMEM_DEPTH  instruction memory entries; AW = clog2(IMEM_DEPTH)
// Ports: see the groups below; counters are 64 bits, cleared by START.
`default_nettype none
module fp3_scheduler #(
  parameter integer NUM_REGS   = 32,
  parameter integer IW         = 5,
  parameter integer IMEM_DEPTH = 256,
  parameter integer AW         = 8
) (
  input  wire          clk_i,
  input  wire          rst_i,
  // host: program load and run control
  input  wire          imem_we_i,
  input  wire [AW-1:0] imem_waddr_i,
  input  wire [63:0]   imem_wdata_i,
  input  wire          start_i,
  input  wire          clear_i,
  input  wire [31:0]   steps_i,
  // status and counters
  output reg           running_o,
  output reg           done_o,
  output reg  [3:0]    error_o,
  output reg  [31:0]   fault_pc_o,
  output reg  [31:0]   steps_done_o,
  output reg  [63:0]   cycles_o,
  output reg  [63:0]   issued_o,
  output reg  [63:0]   stalls_o,
  // register file: operand indices, readiness, busy flags
  output wire [IW-1:0] ra_o,
  output wire [IW-1:0] rb_o,
  output wire [IW-1:0] rd_o,
  input  wire          ra_ready_i,
  input  wire          rb_ready_i,
  input  wire          rd_busy_i,
  input  wire          idle_i,
  // issue to the arithmetic unit
  output wire          issue_o,
  output wire [1:0]    issue_unit_o,
  output wire          issue_sub_o,
  output wire          issue_imm_o,    // the move path takes the immediate
  output wire [31:0]   imm_o,
  output wire          endi_o          // an endi issues this cycle
);
`include "fp3_isa.vh"

  // ---- state ---------------------------------------------------------------
  reg          issuing_q;   // fetching and issuing (else draining or idle)
  reg [AW-1:0] pc_q;        // PC of the instruction on insn
  reg [31:0]   steps_q;     // integrations requested

  // ---- fetch ---------------------------------------------------------------
  wire [63:0]   insn;
  wire [AW-1:0] fetch_addr;
  fp3_imem #(.DEPTH(IMEM_DEPTH), .AW(AW), .WIDTH(64)) u_imem (
    .clk_i   (clk_i),
    .we_i    (imem_we_i),
    .waddr_i (imem_waddr_i),
    .wdata_i (imem_wdata_i),
    .raddr_i (fetch_addr),
    .insn_o  (insn)
  );

  // ---- decode (table-driven: isa_decode from fp3_isa.vh) -------------------
  wire [7:0]  opc = insn[ISA_OPC_LSB +: ISA_OPC_WIDTH];
  wire [7:0]  rd8 = insn[ISA_RD_LSB  +: ISA_REG_WIDTH];
  wire [7:0]  ra8 = insn[ISA_RA_LSB  +: ISA_REG_WIDTH];
  wire [7:0]  rb8 = insn[ISA_RB_LSB  +: ISA_REG_WIDTH];
  wire [31:0] imm = insn[0 +: ISA_IMM_WIDTH];
  wire [6:0]  dec = isa_decode(opc);
  wire        known = dec[6];
  wire [1:0]  unit  = dec[5:4];
  wire        use_rd = dec[0], use_ra = dec[1], use_rb = dec[2], use_imm = dec[3];

  function reg_ok;  // a used field names a register, an unused one is zero
    input       used;
    input [7:0] r;
    begin
      reg_ok = used ? ({24'd0, r} < NUM_REGS) : (r == 8'd0);
    end
  endfunction

  wire is_endi = opc == OP_ENDI;
  wire is_halt = opc == OP_HALT;
  wire legal = known && reg_ok(use_rd, rd8) && reg_ok(use_ra, ra8) && reg_ok(use_rb, rb8) &&
               (use_imm || imm == 32'd0) && (!is_endi || imm < IMEM_DEPTH);
  wire ready = (!use_ra || ra_ready_i) && (!use_rb || rb_ready_i) && (!use_rd || !rd_busy_i);

  wire active  = running_o && issuing_q;
  wire fire    = active && legal && ready;
  wire illegal = active && !legal;
  wire last    = is_endi && (steps_done_o + 32'd1 == steps_q);
  wire jump    = is_endi && !last;
  wire stop    = is_halt || last;
  wire at_end  = {{(32-AW){1'b0}}, pc_q} == IMEM_DEPTH - 1;
  wire overflow = fire && !stop && !jump && at_end;

  wire [AW-1:0] pc_d = !fire ? pc_q : jump ? imm[AW-1:0] : pc_q + {{(AW-1){1'b0}}, 1'b1};
  wire          start_ok = start_i && !running_o && steps_i != 32'd0;
  assign fetch_addr = start_ok ? {AW{1'b0}} : pc_d;

  assign ra_o         = ra8[IW-1:0];
  assign rb_o         = rb8[IW-1:0];
  assign rd_o         = rd8[IW-1:0];
  assign issue_o      = fire;
  assign issue_unit_o = unit;
  assign issue_sub_o  = opc == OP_SUB;
  assign issue_imm_o  = opc == OP_LI;
  assign imm_o        = imm;
  assign endi_o       = fire && is_endi;

  // Upper bits of wide fields are checked by `legal`, not used as indices.
  wire unused_ok = &{1'b0, rd8, ra8, rb8, imm};

  // ---- control, status and counters ----------------------------------------
  always @(posedge clk_i) begin
    if (rst_i) begin
      running_o    <= 1'b0;
      issuing_q    <= 1'b0;
      done_o       <= 1'b0;
      error_o      <= ERR_NONE;
      fault_pc_o   <= 32'd0;
      steps_done_o <= 32'd0;
      steps_q      <= 32'd0;
      pc_q         <= {AW{1'b0}};
      cycles_o     <= 64'd0;
      issued_o     <= 64'd0;
      stalls_o     <= 64'd0;
    end else if (!running_o) begin
      if (start_i && steps_i == 32'd0) begin
        done_o  <= 1'b1;
        error_o <= ERR_BAD_STEPS;
      end else if (start_i) begin
        running_o    <= 1'b1;
        issuing_q    <= 1'b1;
        done_o       <= 1'b0;
        error_o      <= ERR_NONE;
        fault_pc_o   <= 32'd0;
        steps_done_o <= 32'd0;
        steps_q      <= steps_i;
        pc_q         <= {AW{1'b0}};
        cycles_o     <= 64'd0;
        issued_o     <= 64'd0;
        stalls_o     <= 64'd0;
      end else if (clear_i) begin
        done_o  <= 1'b0;
        error_o <= ERR_NONE;
      end
    end else begin
      cycles_o <= cycles_o + 64'd1;
      pc_q     <= pc_d;
      if (fire)                  issued_o     <= issued_o + 64'd1;
      if (active && legal && !ready) stalls_o <= stalls_o + 64'd1;
      if (fire && is_endi)       steps_done_o <= steps_done_o + 32'd1;
      if (fire && stop)          issuing_q    <= 1'b0;
      if (illegal || overflow) begin
        issuing_q  <= 1'b0;
        error_o    <= illegal ? ERR_ILLEGAL_INSN : ERR_PC_OVERFLOW;
        fault_pc_o <= {{(32-AW){1'b0}}, pc_q};
      end
      if (!issuing_q && idle_i) begin
        running_o <= 1'b0;
        done_o    <= 1'b1;
      end
    end
  end
endmodule
`default_nettype wire
