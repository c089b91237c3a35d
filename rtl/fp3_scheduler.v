// fp3_scheduler -- the workload scheduler (paper §4, and the many schedulers
// sharing one arithmetic unit of §6.3): instruction memory, one context per
// object (PC, instruction buffer, integration counter, status), decode,
// hazard check against the register file's busy flags, and an arbiter that
// issues one ready instruction per cycle from one context.
//
// A program is a prologue (run once) and a loop body ending in `endi L`.
// Each endi closes one integration of its context: if it was the last of
// the STEPS requested, the context stops issuing; otherwise its PC jumps to
// L.  All contexts run the same program on their own register bank.
//
// Issue: a context's instruction is a candidate when it is legal and ready:
// its sources are not busy or are being written back this cycle (RAW, with
// bypass) and its destination is not busy or is being written back (WAW).
// WAR needs no check: operands are read at issue, in order.  Among the
// candidates a round-robin arbiter grants one per cycle (a context that
// issued has the lowest priority next cycle), so no context with ready
// work starves.  A cycle without issue while some context waits on a
// hazard is a stall.
//
// Fetch: the instruction memory has one synchronous read port.  Each cycle
// it reads for one context that needs an instruction -- the one that issues
// (at its next PC, computed in the same cycle, so a taken endi costs no
// bubble) or one whose buffer is empty -- chosen round-robin.  The word
// arrives the next cycle and can issue at once; if it does not, the
// context's buffer keeps it.  With one context this is exactly an in-order
// pipeline with no fetch bubbles.
//
// A run ends (DONE) when every started context has stopped -- last endi,
// halt or an error -- and no result is in flight.  Errors, per context: an
// illegal instruction (unknown opcode, a nonzero unused field, a register
// >= NUM_REGS, an endi target outside the memory) or a PC running off the
// end of the memory stop that context and record its faulting PC.
//
// Parameters
//   NUM_CONTEXTS  contexts (objects in flight), >= 1; CW = clog2, >= 1
//   NUM_REGS      registers per context; IW = clog2(NUM_REGS) index width
//   IMEM_DEPTH    instruction memory entries; AW = clog2(IMEM_DEPTH)
// Ports: see the groups below; counters are 64 bits, cleared by START.
// Register indices towards the register file are {context, register}.
`default_nettype none
module fp3_scheduler #(
  parameter integer NUM_CONTEXTS = 1,
  parameter integer CW           = 1,
  parameter integer NUM_REGS     = 32,
  parameter integer IW           = 5,
  parameter integer IMEM_DEPTH   = 256,
  parameter integer AW           = 8
) (
  input  wire                         clk_i,
  input  wire                         rst_i,
  // host: program load and run control
  input  wire                         imem_we_i,
  input  wire [AW-1:0]                imem_waddr_i,
  input  wire [63:0]                  imem_wdata_i,
  input  wire                         start_i,
  input  wire                         clear_i,
  input  wire [31:0]                  steps_i,
  input  wire [31:0]                  contexts_i,    // contexts a START runs
  input  wire [CW-1:0]                sel_ctx_i,     // context of the *_sel_o
  // status and counters
  output reg                          running_o,
  output reg                          done_o,
  output wire                         any_error_o,
  output wire [3:0]                   error_sel_o,
  output wire [31:0]                  fault_pc_sel_o,
  output wire [31:0]                  steps_done_sel_o,
  output reg  [63:0]                  cycles_o,
  output reg  [63:0]                  issued_o,
  output reg  [63:0]                  stalls_o,
  // register file: busy flags and write-back ports (for readiness)
  input  wire [(1<<(CW+IW))-1:0]     busy_i,
  input  wire                         wb0_valid_i,
  input  wire [CW+IW-1:0]             wb0_idx_i,
  input  wire                         wb1_valid_i,
  input  wire [CW+IW-1:0]             wb1_idx_i,
  input  wire                         wb2_valid_i,
  input  wire [CW+IW-1:0]             wb2_idx_i,
  input  wire                         idle_i,
  // issue to the register file and the arithmetic unit
  output wire                         issue_o,
  output wire [CW-1:0]                issue_ctx_o,
  output wire [CW+IW-1:0]             ra_o,
  output wire [CW+IW-1:0]             rb_o,
  output wire [CW+IW-1:0]             rd_o,
  output wire [1:0]                   issue_unit_o,
  output wire                         issue_sub_o,
  output wire                         issue_imm_o,   // the move path takes the immediate
  output wire [31:0]                  imm_o,
  output wire                         endi_o         // the issued instruction is an endi
);
`include "fp3_isa.vh"

  localparam integer NC = NUM_CONTEXTS;
  localparam integer XW = CW + IW;

  // ---- per-context state ---------------------------------------------------
  reg [NC-1:0] active_q;            // fetching and issuing
  reg [NC-1:0] ibv_q;               // buffer holds the instruction at pc
  reg [63:0]   ib_q   [0:NC-1];     // instruction buffer
  reg [AW-1:0] pc_q   [0:NC-1];     // PC of the buffered / arriving instruction
  reg [31:0]   sdone_q[0:NC-1];     // integrations completed
  reg [3:0]    err_q  [0:NC-1];
  reg [AW-1:0] fpc_q  [0:NC-1];     // faulting PC
  // ---- shared state --------------------------------------------------------
  reg [31:0]   steps_q;
  reg [CW-1:0] grr_q;               // issue arbiter: highest priority
  reg [CW-1:0] frr_q;               // fetch arbiter: highest priority
  reg          fvalid_q;            // a fetched word arrives this cycle
  reg [CW-1:0] fctx_q;              // ... for this context

  // ---- fetch ---------------------------------------------------------------
  wire [63:0]   imem_word;
  reg  [AW-1:0] fetch_addr;
  // The instruction memory (a block RAM): the address presented in cycle
  // t is read at the edge ending cycle t, the word is here in cycle t + 1.
  // Entries never written read as zero, the nop.
  fp3_ram #(.DEPTH(IMEM_DEPTH), .AW(AW), .WIDTH(64)) u_imem (
    .clk_i   (clk_i),
    .we_i    (imem_we_i),
    .waddr_i (imem_waddr_i),
    .wdata_i (imem_wdata_i),
    .raddr_i (fetch_addr),
    .rdata_o (imem_word)
  );

  // ---- decode and hazards, every context -----------------------------------
  function reg_ok;  // a used field names a register, an unused one is zero
    input       used;
    input [7:0] r;
    begin
      reg_ok = used ? ({24'd0, r} < NUM_REGS) : (r == 8'd0);
    end
  endfunction

  // A write-back port writes index x in this cycle.  A plain expression,
  // not a function: a continuous assignment is re-evaluated only when its
  // operands change, and a function's body is not an operand.
`define FP3_WRITTEN(x) \
  ((wb0_valid_i && wb0_idx_i == (x)) || (wb1_valid_i && wb1_idx_i == (x)) || \
   (wb2_valid_i && wb2_idx_i == (x)))

  wire [NC-1:0] have;     // an instruction is available (buffered or arriving)
  wire [NC-1:0] legal;
  wire [NC-1:0] ready;
  wire [63:0]   insn [0:NC-1];

  genvar c;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_ctx
      localparam [CW-1:0] CTX = c[CW-1:0];
      wire        arriving = fvalid_q && fctx_q == CTX;
      assign insn[c] = arriving ? imem_word : ib_q[c];
      assign have[c] = ibv_q[c] || arriving;

      wire [7:0]  opc = insn[c][ISA_OPC_LSB +: ISA_OPC_WIDTH];
      wire [7:0]  rd8 = insn[c][ISA_RD_LSB  +: ISA_REG_WIDTH];
      wire [7:0]  ra8 = insn[c][ISA_RA_LSB  +: ISA_REG_WIDTH];
      wire [7:0]  rb8 = insn[c][ISA_RB_LSB  +: ISA_REG_WIDTH];
      wire [31:0] imm = insn[c][0 +: ISA_IMM_WIDTH];
      wire [6:0]  dec = isa_decode(opc);
      wire use_rd = dec[0], use_ra = dec[1], use_rb = dec[2], use_imm = dec[3];

      assign legal[c] = dec[6] && reg_ok(use_rd, rd8) && reg_ok(use_ra, ra8) &&
                        reg_ok(use_rb, rb8) && (use_imm || imm == 32'd0) &&
                        (opc != OP_ENDI || imm < IMEM_DEPTH);

      wire [XW-1:0] xa = {CTX, ra8[IW-1:0]};
      wire [XW-1:0] xb = {CTX, rb8[IW-1:0]};
      wire [XW-1:0] xd = {CTX, rd8[IW-1:0]};
      // The unit is decoded again for the granted context only.
      wire unused_unit = &{1'b0, dec[5:4]};
      assign ready[c] = (!use_ra || !busy_i[xa] || `FP3_WRITTEN(xa)) &&
                        (!use_rb || !busy_i[xb] || `FP3_WRITTEN(xb)) &&
                        (!use_rd || !busy_i[xd] || `FP3_WRITTEN(xd));
    end
  endgenerate

`undef FP3_WRITTEN

  wire [NC-1:0] waiting = active_q & have & legal;   // legal work to issue
  wire [NC-1:0] cand    = waiting & ready;
  wire [NC-1:0] illegal = active_q & have & ~legal;

  // ---- round-robin pick: the first set bit at or after `from` --------------
  function [CW:0] rr_pick;  // {found, index}
    input [NC-1:0] req;
    input [CW-1:0] from;
    integer p;
    reg found;
    begin
      rr_pick = {1'b0, {CW{1'b0}}};
      found   = 1'b0;
      for (p = 0; p < NC; p = p + 1) begin   // from, from+1, ..., NC-1
        if (!found && req[p] && p >= {{(32-CW){1'b0}}, from}) begin
          rr_pick = {1'b1, p[CW-1:0]};
          found   = 1'b1;
        end
      end
      for (p = 0; p < NC; p = p + 1) begin   // then 0, 1, ..., from-1
        if (!found && req[p]) begin
          rr_pick = {1'b1, p[CW-1:0]};
          found   = 1'b1;
        end
      end
    end
  endfunction

  function [CW-1:0] next_ctx;  // the context after x, cyclically
    input [CW-1:0] x;
    begin
      next_ctx = ({{(32-CW){1'b0}}, x} == NC - 1) ? {CW{1'b0}} : x + {{(CW-1){1'b0}}, 1'b1};
    end
  endfunction

  // ---- issue ---------------------------------------------------------------
  wire [CW:0]   gpick = rr_pick(cand, grr_q);
  wire          grant = gpick[CW];
  wire [CW-1:0] g     = gpick[CW-1:0];
  wire [63:0]   gi    = insn[g];

  wire [7:0]  g_opc  = gi[ISA_OPC_LSB +: ISA_OPC_WIDTH];
  wire [7:0]  g_rd8  = gi[ISA_RD_LSB  +: ISA_REG_WIDTH];
  wire [7:0]  g_ra8  = gi[ISA_RA_LSB  +: ISA_REG_WIDTH];
  wire [7:0]  g_rb8  = gi[ISA_RB_LSB  +: ISA_REG_WIDTH];
  wire [31:0] g_imm  = gi[0 +: ISA_IMM_WIDTH];
  wire [6:0]  g_dec  = isa_decode(g_opc);
  wire        g_endi = g_opc == OP_ENDI;
  wire        g_last = g_endi && (sdone_q[g] + 32'd1 == steps_q);
  wire        g_jump = g_endi && !g_last;
  wire        g_stop = (g_opc == OP_HALT) || g_last;
  wire [AW-1:0] g_pc = pc_q[g];
  wire        g_at_end = {{(32-AW){1'b0}}, g_pc} == IMEM_DEPTH - 1;
  wire        g_overflow = grant && !g_stop && !g_jump && g_at_end;
  wire [AW-1:0] g_next = g_jump ? g_imm[AW-1:0] : g_pc + {{(AW-1){1'b0}}, 1'b1};

  assign issue_o      = grant;
  assign issue_ctx_o  = g;
  assign ra_o         = {g, g_ra8[IW-1:0]};
  assign rb_o         = {g, g_rb8[IW-1:0]};
  assign rd_o         = {g, g_rd8[IW-1:0]};
  assign issue_unit_o = g_dec[5:4];
  assign issue_sub_o  = g_opc == OP_SUB;
  assign issue_imm_o  = g_opc == OP_LI;
  assign imm_o        = g_imm;
  assign endi_o       = grant && g_endi;

  // ---- fetch arbitration ---------------------------------------------------
  // A context needs a word when it is active and has none, or when it
  // issues now and goes on.  Contexts stopping or faulting this cycle do not.
  reg  [NC-1:0] need;
  integer n;
  always @(*) begin
    for (n = 0; n < NC; n = n + 1) begin
      if (grant && g == n[CW-1:0])
        need[n] = !g_stop && !g_overflow;
      else
        need[n] = active_q[n] && !have[n];
    end
  end
  wire [CW:0]   fpick   = rr_pick(need, frr_q);
  wire          fetch   = fpick[CW] && running_o;
  wire [CW-1:0] f       = fpick[CW-1:0];
  wire          start_ok = start_i && !running_o && steps_i != 32'd0 &&
                           contexts_i != 32'd0 && contexts_i <= NC;
  wire [AW-1:0] f_pc = pc_q[f];
  always @(*) begin
    if (start_ok)                   fetch_addr = {AW{1'b0}};
    else if (grant && f == g)       fetch_addr = g_next;
    else                            fetch_addr = f_pc;
  end

  // ---- selected-context status ---------------------------------------------
  wire [NC-1:0] err_any;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_err
      assign err_any[c] = err_q[c] != ERR_NONE;
    end
  endgenerate
  assign any_error_o      = |err_any;
  assign error_sel_o      = err_q[sel_ctx_i];
  assign fault_pc_sel_o   = {{(32-AW){1'b0}}, fpc_q[sel_ctx_i]};
  assign steps_done_sel_o = sdone_q[sel_ctx_i];

  // Upper bits of wide fields are checked by `legal`, not used as indices.
  wire unused_ok = &{1'b0, g_rd8, g_ra8, g_rb8, g_dec[6], g_dec[3:0]};

  // ---- control, status and counters ----------------------------------------
  wire bad_start = start_i && !running_o && !start_ok;
  integer k;
  always @(posedge clk_i) begin
    if (rst_i) begin
      running_o <= 1'b0;
      done_o    <= 1'b0;
      active_q  <= {NC{1'b0}};
      ibv_q     <= {NC{1'b0}};
      fvalid_q  <= 1'b0;
      fctx_q    <= {CW{1'b0}};
      grr_q     <= {CW{1'b0}};
      frr_q     <= {CW{1'b0}};
      steps_q   <= 32'd0;
      cycles_o  <= 64'd0;
      issued_o  <= 64'd0;
      stalls_o  <= 64'd0;
      for (k = 0; k < NC; k = k + 1) begin
        pc_q[k]    <= {AW{1'b0}};
        sdone_q[k] <= 32'd0;
        err_q[k]   <= ERR_NONE;
        fpc_q[k]   <= {AW{1'b0}};
      end
    end else if (!running_o) begin
      if (bad_start) begin
        done_o <= 1'b1;
        for (k = 0; k < NC; k = k + 1) begin
          err_q[k]   <= (steps_i == 32'd0) ? ERR_BAD_STEPS : ERR_BAD_CONTEXTS;
          sdone_q[k] <= 32'd0;
        end
      end else if (start_ok) begin
        running_o <= 1'b1;
        done_o    <= 1'b0;
        steps_q   <= steps_i;
        cycles_o  <= 64'd0;
        issued_o  <= 64'd0;
        stalls_o  <= 64'd0;
        ibv_q     <= {NC{1'b0}};
        fvalid_q  <= 1'b1;          // context 0's first word is read now
        fctx_q    <= {CW{1'b0}};
        grr_q     <= {CW{1'b0}};
        frr_q     <= (NC > 1) ? {{(CW-1){1'b0}}, 1'b1} : {CW{1'b0}};
        for (k = 0; k < NC; k = k + 1) begin
          active_q[k] <= k < contexts_i;
          pc_q[k]     <= {AW{1'b0}};
          sdone_q[k]  <= 32'd0;
          err_q[k]    <= ERR_NONE;
          fpc_q[k]    <= {AW{1'b0}};
        end
      end else if (clear_i) begin
        done_o <= 1'b0;
        for (k = 0; k < NC; k = k + 1) err_q[k] <= ERR_NONE;
      end
    end else begin
      cycles_o <= cycles_o + 64'd1;
      if (grant) issued_o <= issued_o + 64'd1;
      if (!grant && |waiting) stalls_o <= stalls_o + 64'd1;

      // Words arriving for a context that does not issue them are kept.
      for (k = 0; k < NC; k = k + 1) begin
        if (fvalid_q && fctx_q == k[CW-1:0]) begin
          ib_q[k]  <= imem_word;
          ibv_q[k] <= 1'b1;
        end
      end
      // The issuing context consumed its word and moves to its next PC.
      if (grant) begin
        ibv_q[g] <= 1'b0;
        pc_q[g]  <= g_next;
        grr_q    <= next_ctx(g);
        if (g_endi) sdone_q[g] <= sdone_q[g] + 32'd1;
        if (g_stop) active_q[g] <= 1'b0;
        if (g_overflow) begin
          active_q[g] <= 1'b0;
          err_q[g]    <= ERR_PC_OVERFLOW;
          fpc_q[g]    <= g_pc;
        end
      end
      for (k = 0; k < NC; k = k + 1) begin
        if (illegal[k]) begin
          active_q[k] <= 1'b0;
          err_q[k]    <= ERR_ILLEGAL_INSN;
          fpc_q[k]    <= pc_q[k];
        end
      end
      // The word read now arrives next cycle.
      fvalid_q <= fetch;
      fctx_q   <= f;
      if (fetch) frr_q <= next_ctx(f);

      if (active_q == {NC{1'b0}} && idle_i) begin
        running_o <= 1'b0;
        done_o    <= 1'b1;
        fvalid_q  <= 1'b0;
      end
    end
  end

`ifdef FORMAL
  // The granted context is a candidate, and is active.
  always @(*) if (grant) assert (cand[g] && active_q[g]);
`endif
endmodule
`default_nettype wire
