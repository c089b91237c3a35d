// fp3_scheduler -- the workload scheduler (paper §4, and the many schedulers
// sharing one arithmetic unit of §6.3): instruction memory, one context per
// object (PC, instruction queue, integration counter, status), decode,
// hazard check against the register file's busy flags, and an arbiter that
// issues one ready instruction per cycle from one context.
//
// A program is a prologue (run once) and a loop body ending in `endi L`.
// Each endi closes one integration of its context: if it was the last of
// the STEPS requested, the context stops issuing; otherwise its PC jumps to
// L.  All contexts run the same program on their own register bank.
//
// The front end is three pipelined steps, each ending in registers, so
// that no path runs from the instruction memory through the hazard check
// to the arbiter (the long path of a one-cycle design):
//
//   fetch   One instruction-memory read per cycle, for one context chosen
//           round-robin among those with room in their two-entry queue (a
//           ring of two slots and a head pointer, so that a grant moves no
//           word) and no read in flight.  Words are decoded as they are
//           written into the memory, and their decoded bits are stored
//           beside them.  The fetch PC follows the words as they
//           arrive: after an endi it is the loop target (the last endi's
//           extra words are dropped when the context stops).  Behind a
//           beq its context fetches nothing until the branch is resolved:
//           the operands are compared in the read stage (fp3_top) and the
//           outcome, registered, comes back (br_i, br_taken_i,
//           br_target_i) two cycles after the issue; a taken beq moves
//           the fetch PC to its target.
//   ready   For the instruction at the head of each queue: legal, sources
//           not busy (RAW) and destination not busy (WAW), where a busy
//           register whose write-back is announced in this cycle counts as
//           free (the announcements come from the units' tag lines,
//           fp3_wb_tag, early enough for the operand read to take the
//           value from the bypass).  Registered: valid for the pick in the
//           next cycle.  Nothing of this is decoded or looked up here: a
//           word is decoded (legality included) as it joins its queue, and
//           each queue entry keeps a wait bit per register field, set from
//           the busy flags as it joins (and by the head ahead of it when
//           that is granted; with the pick stages, also the destinations
//           of the instructions granted but not yet issued, and of the one
//           issuing, whose flag is set at the end of the cycle), cleared by
//           the announcements.
//   issue   Among the contexts whose head was ready, a round-robin arbiter
//           grants one per cycle (the granted context has the lowest
//           priority next), so no context with ready work starves.  A
//           context that was granted in the previous cycle is not a
//           candidate: its ready bit belonged to the instruction it just
//           issued.  So one context issues at most every other cycle, and
//           two or more contexts keep the arithmetic unit busy every cycle.
//           PICK_STAGES = 0: the granted instruction issues (its register
//           addresses go to the register file) in the cycle of the grant;
//           PICK_STAGES = 2 (for clock rate): the grant is registered, the
//           granted instruction's fields are picked in the next cycle and
//           registered, and it issues in the cycle after that.  So neither
//           the arbiter nor a wide multiplexer sits in front of the
//           register file, and no multiplexer behind the arbiter.
//           PICK_STAGES = 2 also cuts the loop of ready and issue twice:
//           each queue slot's readiness is registered before the choice by
//           the last grants, and the arbiter's decision is registered
//           before it is the grant.  A context is then granted at most
//           every third cycle, and its head's readiness, two cycles later
//           than it would be, sees the add and multiply lines'
//           announcements two cycles earlier (fp3_wb_tag pre3_*), which
//           gives the two cycles back to their consumers; a move's
//           consumer and a word that has just arrived wait two cycles
//           more ("The issue loop's registered stages", below).
//
// WAR needs no check: operands are read at issue, in order.  A cycle
// without issue while some active context holds an instruction is a stall.
//
// A run ends (DONE) when every started context has stopped -- last endi,
// halt or an error -- and no result is in flight: no busy flag, nothing in
// the issue register, and DRAIN cycles passed since the last announced
// write-back.  Errors, per context: an
// illegal instruction (unknown opcode, a nonzero unused field, a register
// >= NUM_REGS, an endi target outside the memory, a beq target not ahead of
// it or outside the memory) at the head of its queue,
// or a PC running off the end of the memory, stop that context and record
// its faulting PC.
//
// Parameters
//   NUM_CONTEXTS  contexts (objects in flight), >= 1; CW = clog2, >= 1
//   NUM_REGS      registers per context; IW = clog2(NUM_REGS) index width
//   IMEM_DEPTH    instruction memory entries; AW = clog2(IMEM_DEPTH)
//   HAS_ADD, HAS_SUB, HAS_MUL, HAS_SIGN  units built (fp3_top): an
//                 instruction for a missing one is illegal (HAS_SIGN: abs,
//                 neg, min, max on the move path)
//   PICK_STAGES   0 or 2: cycles from the grant to the issue
//   FETCH_STAGE   0 or 1: the fetch grant registered, then the fetch PC
//                 selected and registered before the instruction memory,
//                 which is read over two cycles (fp3_ram READ_STAGES 2),
//                 and the word registered again after it: the word
//                 arrives four cycles after the grant instead of one
//   DRAIN         cycles from a write-back's announcement (ahead_*_i) to
//                 the write-back, >= 1
// Ports: see the groups below; counters are 64 bits, cleared by START.
// Program writes (imem_*) land in the memory a cycle later (registered and
// decoded first).
// Register indices towards the register file are {context, register}.
`default_nettype none
module fp3_scheduler #(
  parameter integer NUM_CONTEXTS = 1,
  parameter integer CW           = 1,
  parameter integer NUM_REGS     = 32,
  parameter integer IW           = 5,
  parameter integer IMEM_DEPTH   = 256,
  parameter integer AW           = 8,
  parameter integer HAS_ADD      = 1,
  parameter integer HAS_SUB      = 1,
  parameter integer HAS_MUL      = 1,
  parameter integer HAS_SIGN     = 1,
  parameter integer PICK_STAGES  = 0,
  parameter integer FETCH_STAGE  = 0,
  parameter integer DRAIN        = 1
) (
  input  wire                         clk_i,
  input  wire                         rst_i,
  // host: program load and run control
  input  wire                         imem_we_i,
  input  wire [AW-1:0]                imem_waddr_i,
  input  wire [63:0]                  imem_wdata_i,
  input  wire                         start_i,
  input  wire                         clear_i,
  // STEPS and CONTEXTS, decided as the host writes them (fp3_top), so
  // that no 32-bit compare sits between START and the run state
  input  wire                         steps_zero_i,  // STEPS == 0
  input  wire                         steps_one_i,   // STEPS == 1
  input  wire [31:0]                  steps_last2_i, // STEPS - 2
  input  wire                         contexts_bad_i, // CONTEXTS == 0 or > NUM_CONTEXTS
  input  wire [NUM_CONTEXTS-1:0]      contexts_run_i, // contexts a START runs: k < CONTEXTS
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
  // register file: busy flags; write-backs announced this cycle
  input  wire [(1<<(CW+IW))-1:0]      busy_i,
  input  wire [2:0]                   ahead_valid_i, // add, mul, move ports
  input  wire [3*(CW+IW)-1:0]         ahead_idx_i,
  input  wire [2:0]                   early_valid_i, // ... those of the next cycle
  input  wire [3*(CW+IW)-1:0]         early_idx_i,
  input  wire [2:0]                   pre_valid_i,   // ... those of the cycle after
  input  wire [3*(CW+IW)-1:0]         pre_idx_i,     //     (early_*_i a cycle ahead)
  // ... two and three cycles ahead of early_*_i, add and mul ports only,
  // as far as their tag lines reach (fp3_wb_tag; used with PICK_STAGES = 2)
  input  wire [1:0]                   pre2_valid_i,
  input  wire [2*(CW+IW)-1:0]         pre2_idx_i,
  input  wire [1:0]                   pre3_valid_i,
  input  wire [2*(CW+IW)-1:0]         pre3_idx_i,
  input  wire                         idle_i,        // no busy flag in the last cycle
  // a beq issued two cycles ago, resolved: its context (one-hot; none if
  // no beq was) and outcome
  input  wire [NC-1:0]                br_i,
  input  wire                         br_taken_i,
  input  wire [AW-1:0]                br_target_i,
  // issue to the register file and the arithmetic unit
  output wire                         issue_o,
  output wire [CW-1:0]                issue_ctx_o,
  output wire [CW+IW-1:0]             ra_o,
  output wire [CW+IW-1:0]             rb_o,
  output wire [CW+IW-1:0]             rd_o,
  output wire [1:0]                   issue_unit_o,
  output wire                         issue_sub_o,
  output wire [2:0]                   issue_sop_o,   // sign group: {abs/neg/min/max, fp_sign op}
  output wire                         issue_imm_o,   // the move path takes the immediate
  output wire [31:0]                  imm_o,
  output wire                         endi_o,        // the issued instruction is an endi
  output wire                         beq_o,         // ... a beq
  // the instruction picked, which issues in the next cycle (PICK_STAGES =
  // 2; with 0, the one issuing now): it writes a register (add, mul or
  // move: issue_o && issue_unit_o != UNIT_NONE then), which ({context,
  // register}: rd_o then), and its unit (issue_unit_o then)
  output wire                         pick_wr_o,
  output wire [CW+IW-1:0]             pick_rd_o,
  output wire [1:0]                   pick_unit_o
);
`include "fp3_isa.vh"

  localparam integer NC = NUM_CONTEXTS;
  localparam integer XW = CW + IW;
  localparam [7:0]   LULL8 = DRAIN[7:0] - 8'd1;  // (lull_q, below)
  localparam integer DW = 15;       // a queue entry's decoded bits (adec)

  // ---- per-context state ---------------------------------------------------
  reg [NC-1:0] active_q;            // fetching and issuing, but for stop_q (act)
  reg [NC-1:0] stop_q;              // the head granted in the last cycle stopped its context
  wire [NC-1:0] act;                // active: active_q & ~stop_q (run control, below)
  // Each queue has two slots (slot e of context c is entry 2c + e), used
  // as a ring: hp_q points to the head.  A granted head only flips hp_q and
  // clears its valid bit, and an arriving word is written into the free
  // slot, which does not depend on the grant: so no word moves and the
  // grant drives few flip-flops.
  reg [NC-1:0]   hp_q;              // head slot
  reg [2*NC-1:0] v_q;               // slot valid
  reg [63:0]     w_q [0:2*NC-1];    // slot words
  reg [DW-1:0]   x_q [0:2*NC-1];    // ... decoded as they joined (DW: below)
  reg [2:0]      s_q [0:2*NC-1];    // ... their wait bits (ready step)
  reg [AW-1:0]   p_q [0:2*NC-1];    // ... and their PCs
  reg [AW-1:0] fpc_q[0:NC-1];       // next fetch address
  reg [NC-1:0] fend_q;              // fetched the last word of the memory
  reg [NC-1:0] bwait_q;             // fetched a beq, not yet resolved
  reg [NC-1:0] ready_q;             // head was ready (computed last cycle)
  reg [31:0]   sdone_q[0:NC-1];     // integrations completed
  reg [NC-1:0] final_q;             // the next endi is the last of the run
  reg [3:0]    err_q  [0:NC-1];
  reg [AW-1:0] epc_q  [0:NC-1];     // faulting PC
  // ---- shared state --------------------------------------------------------
  reg [31:0]   last2_q;             // STEPS - 2: sdone_q before the last endi but one
  reg [NC-1:0] near_q;              // sdone_q == last2_q (a cycle old)
  reg          fvalid_q;            // a fetched word arrives (FETCH_STAGE: two cycles later)
  reg [CW-1:0] fctx_q;              // ... for this context
  reg [AW-1:0] fpcq_q;              // ... from this address
  reg [7:0]    lull_q;              // cycles without busy flag or issue, to DRAIN - 1, a cycle late
  reg          lull_full_q;         // lull_q == DRAIN - 1, registered with it
  reg          iss_q;               // issue_o a cycle late (as idle_i is)

  // ---- instruction memory --------------------------------------------------
  // A block RAM: the address presented in cycle t is read at the edge
  // ending cycle t, the word is here in cycle t + 1 (FETCH_STAGE: read
  // over two cycles, fp3_ram READ_STAGES = 2: in cycle t + 2).  Each word
  // is stored with its decoded bits (SW, below), decided as it is written: the
  // host's write is decoded and registered, and written a cycle later (a
  // run starts two cycles after a write at the earliest); so no decode
  // sits in front of the memory.  FETCH_STAGE: the write is registered
  // once more before the decode (the host's data register meets only
  // flip-flops) and lands a cycle later still, before a run's first read:
  // a START in the cycle after the write starts the contexts a cycle after
  // it, and the first fetch PC reaches the memory a cycle after their
  // first grant.  Entries never written read as zero: the nop, decoded.
  localparam integer SW = DW - 1;   // stored decoded bits
  wire [63:0]   imem_word;
  wire [SW-1:0] imem_sdec;
  reg  [AW-1:0] fpc_sel;    // the fetch address (fetch step, below)
  reg           we_q;
  reg  [AW-1:0] wa_q;
  reg  [63:0]   wd_q;
  wire [SW-1:0] wsdec;      // the word being written, decoded
  reg  [SW-1:0] ws_q;
  wire          dwe;        // the write being decoded
  wire [AW-1:0] dwa;
  wire [63:0]   dwd;
  generate
    if (FETCH_STAGE != 0) begin : g_write_reg
      reg           iwe_q;
      reg  [AW-1:0] iwa_q;
      reg  [63:0]   iwd_q;
      always @(posedge clk_i) begin
        iwe_q <= imem_we_i && !rst_i;
        iwa_q <= imem_waddr_i;
        iwd_q <= imem_wdata_i;
      end
      assign {dwe, dwa, dwd} = {iwe_q, iwa_q, iwd_q};
    end else begin : g_write_now
      assign {dwe, dwa, dwd} = {imem_we_i, imem_waddr_i, imem_wdata_i};
    end
  endgenerate
  always @(posedge clk_i) begin
    we_q <= dwe && !rst_i;
    wa_q <= dwa;
    wd_q <= dwd;
    ws_q <= wsdec;
  end
  fp3_ram #(.DEPTH(IMEM_DEPTH), .AW(AW), .WIDTH(SW + 64), .READ_STAGES(1 + FETCH_STAGE)) u_imem (
    .clk_i   (clk_i),
    .we_i    (we_q),
    .waddr_i (wa_q),
    .wdata_i ({ws_q, wd_q}),
    .raddr_i (fpc_sel),
    .rdata_o ({imem_sdec, imem_word})
  );

  // ---- decode helpers ------------------------------------------------------
  function reg_ok;  // a used field names a register, an unused one is zero
    input       used;
    input [7:0] r;
    begin
      // r < NUM_REGS as r's high bits zero when NUM_REGS is a power of
      // two: Yosys maps a compare with a constant to a carry chain (the
      // host's program write -> this chain was a critical path).
      reg_ok = used ? ((r >> IW) == 8'd0 && (NUM_REGS == (1 << IW) || {24'd0, r} < NUM_REGS))
                    : (r == 8'd0);
    end
  endfunction

  // Register x of this context (g_ctx) is among the three write-backs
  // announced in the next cycle (early_*_i), as this context's copy has
  // them (ev: valid and of this context, er: the registers).  A plain
  // expression, not a function: a continuous assignment is re-evaluated
  // only when its operands change, and a function's body is not an
  // operand (Icarus).
`define FP3_FREED(x) \
  ((ev[0] && er[0*IW +: IW] == (x)) || (ev[1] && er[1*IW +: IW] == (x)) || \
   (ev[2] && er[2*IW +: IW] == (x)))

  // ---- decode, once, as a word is written ---------------------------------
  // Everything the ready and issue steps need of a word beyond its raw
  // fields is decided as it is written into the instruction memory (from
  // the word and its address: a program does not change while it runs),
  // stored beside it (SW bits: {sop, illegal, use_rb, use_ra, use_rd, unit,
  // sub, li, endi, beq, halt}; a zero word's are zero), completed as it joins
  // its queue with ovf (it would run off the end of the memory: not a halt
  // or an endi, which leave or jump, at the last address) and kept in its
  // queue entry (DW bits: {legal, ..., halt, ovf}).  So neither the ready
  // step nor the arrival decodes anything.
  wire [7:0]    w_opc   = dwd[ISA_OPC_LSB +: ISA_OPC_WIDTH];
  wire          w_endi  = w_opc == OP_ENDI;
  wire          w_beq   = w_opc == OP_BEQ;
  wire [7:0]    w_rd8   = dwd[ISA_RD_LSB +: ISA_REG_WIDTH];
  wire [7:0]    w_ra8   = dwd[ISA_RA_LSB +: ISA_REG_WIDTH];
  wire [7:0]    w_rb8   = dwd[ISA_RB_LSB +: ISA_REG_WIDTH];
  wire [31:0]   w_imm   = dwd[0 +: ISA_IMM_WIDTH];
  wire [7:0]    w_dec   = isa_decode(w_opc);   // {known, unit[2:0], uses: imm rb ra rd}
  // The issue path carries units 0 .. 3 (2 bits: w_dec[5:4]).  The
  // div/sqrt unit (UNIT_DIV) has no issue path in this scheduler: its words
  // are illegal (fp3_top builds with HAS_DIV = HAS_SQRT = 0, and the host
  // refuses such a program first), so their 2-bit unit is never used.  The
  // sign group (abs, neg, min, max) runs on the move path: w_sop is
  // {sign group, fp_sign's op_i: 0 abs, 1 neg, 2 min, 3 max}, carried to
  // the issue beside the unit (issue_sop_o).
  wire          w_sign  = w_opc == OP_ABS || w_opc == OP_NEG || w_opc == OP_MIN ||
                          w_opc == OP_MAX;
  wire [2:0]    w_sop   = {w_sign, w_opc == OP_MIN || w_opc == OP_MAX,
                           w_opc == OP_NEG || w_opc == OP_MAX};
  wire          w_built = (w_dec[6:4] != {1'b0, UNIT_ADD} || HAS_ADD != 0) &&
                          (w_opc != OP_SUB || HAS_SUB != 0) &&
                          (w_dec[6:4] != {1'b0, UNIT_MUL} || HAS_MUL != 0) &&
                          w_dec[6:4] != UNIT_DIV && (!w_sign || HAS_SIGN != 0);
  // w_imm < IMEM_DEPTH, without a carry chain when IMEM_DEPTH is 2**AW
  wire          w_in    = (w_imm >> AW) == 32'd0 &&
                          (IMEM_DEPTH == (1 << AW) || w_imm < IMEM_DEPTH);
  wire          w_legal = w_dec[7] && w_built && reg_ok(w_dec[0], w_rd8) &&
                          reg_ok(w_dec[1], w_ra8) && reg_ok(w_dec[2], w_rb8) &&
                          (w_dec[3] || w_imm == 32'd0) &&
                          (!w_endi || w_in) &&
                          (!w_beq || (w_in && w_imm[AW-1:0] > dwa));
  assign wsdec = {w_sop, !w_legal, w_dec[2], w_dec[1], w_dec[0], w_dec[5:4], w_opc == OP_SUB,
                  w_opc == OP_LI, w_endi, w_beq, w_opc == OP_HALT};

  wire          avalid;     // a fetched word arrives (fetch step, below)
  wire [CW-1:0] actx;       // ... for this context
  wire [63:0]   aword;
  wire [SW-1:0] asdec;      // ... its stored decoded bits
  wire [AW-1:0] apc;
  wire [NC-1:0] arriving;   // ... one-hot
  wire [NC-1:0] gone;       // the head granted in this cycle (issue step)
  reg  [2*NC-1:0] wsel_q;   // the slot the arriving word is written into
  wire [2*NC-1:0] wsel_d;   // ... next (fetch step, below)
  wire [CW-1:0]   fr;       // the context granted a fetch (fetch step, below)
  wire [2*NC-1:0] wslot;    // ... and becomes valid (its context active)
  wire          a_endi  = asdec[2];
  wire          a_beq   = asdec[1];
  wire          a_halt  = asdec[0];
  wire          a_atend;    // ... at the memory's last address (compared a cycle ahead: u_arrive)
  wire [DW-1:0] adec    = {asdec[SW-1 -: 3], !asdec[SW-4], asdec[SW-5:0],
                           a_atend && !a_halt && !a_endi};

  // ---- ready step: the head of every queue ---------------------------------
  // Each queue entry carries three wait bits, one per operand field (ra,
  // rb, rd): the register's busy flag, kept up to date by the entry itself
  // so that the ready step reads no busy flag.  Only a context's own
  // instructions make its registers busy, so an entry's wait bit is
  //   set    as the word joins: the flag (busy_i), or the destination of
  //          the instruction in the issue register (PICK_STAGES = 2: its
  //          flag is set at the end of this cycle), or of the head granted
  //          in this cycle or (PICK_STAGES = 2) in the last one;
  //          later: when the head ahead of it is granted and writes it
  //          (taken in the cycle after the grant);
  //   clear  when the register's write-back is announced (ahead_*_i; the
  //          flag clears in the same cycle), compared in the cycle before
  //          with the announcement to come (early_*_i) and registered.
  // An announcement in this cycle counts as free already.  So the head is
  // ready when it is legal and no used field waits: sources (RAW) and the
  // destination (WAW).  Registered: valid for the pick in the next cycle.
  //
  // The issue loop's registered stages (PICK_STAGES = 2).  On the default
  // build one cycle holds the loop from a grant through the wait bits of
  // the slots behind it and their readiness (ready_q) to the arbiter and
  // the next grant.  Here the loop holds two more registers: each slot's
  // readiness is registered for both outcomes (rk_q: its context was not
  // granted; rg_q: it was, with the bits by_q sets) and chosen a cycle
  // later by the grants of the last two cycles (gr_q, gr2_q); and the
  // arbiter's decision is registered (dec_q, issue step) before it is the
  // grant.  A context is then granted at most every third cycle, so at
  // most one of those two grants is its own, and by_q (the destination of
  // its head a cycle before, the same head unless that head was granted
  // then) is that grant's either way.  A readiness registered a cycle
  // early misses only wait bits cleared in that cycle: an instruction may
  // issue later than its operands allow, never earlier.  The lateness is
  // given back by hearing of write-backs earlier: an announcement of cycle
  // z reaches a grant in cycle z + 3 instead of z + 1, so the add and mul
  // lines' per-context copies are registered from announcements two
  // cycles ahead (pre3_*_i, as far ahead as the tag line reaches:
  // fp3_wb_tag), and the lookup of an arriving word takes off those of the
  // next two cycles, which its slot's compares do not see (bq_q).  The
  // move line (MOV_LATENCY = 1 + PICK_STAGES) is too short for any lead: a
  // move's consumer waits two cycles more; so does a word that has just
  // arrived (its readiness is first registered in the cycle after it
  // reaches its slot).
  wire [NC-1:0] legal;      // the head is legal
  wire [NC-1:0] ready_d;
  wire [NC-1:0] h_stop;     // the head is a halt or the run's last endi
  wire [NC-1:0] h_ovf;      // ... would run off the end of the memory
  wire [NC*AW-1:0] h_pc;    // ... its PC
  // The head granted in the last cycle (gone_q), still in its slot (the
  // one hp_q no longer points to: a word is written only into a free
  // slot): its integration (sdone_q, final_q) and PC overflow (err_q,
  // epc_q) are counted and recorded a cycle after the grant, so that the
  // grant drives no counter or error register.
  wire [NC-1:0] l_endi;     // the last head is an endi
  wire [NC-1:0] l_ovf;      // ... would run off the end of the memory
  wire [NC*AW-1:0] l_pc;    // ... its PC
  // Issue fields of every slot: {sop, ra, rb, rd, unit, sub, li,
  // immediate, endi, beq}.
  localparam integer FW = 3 + 3 * IW + 2 + 1 + 1 + 32 + 1 + 1;
  localparam [FW-1:0] IMM_BITS = {{(FW-34){1'b0}}, {32{1'b1}}, 2'b00};   // the immediate in a field word
  wire [2*NC*FW-1:0] fields;
  wire [NC*FW-1:0]   h_fields;  // ... of the heads
  wire [NC*FW-1:0]   l_fields;  // ... of the last heads
  wire [2*NC*3-1:0]  s_d;   // the wait bits after this cycle ({rd, rb, ra})
  wire [NC*AW-1:0] fpcs;    // every context's fetch PC
  // A word's wait bits are found over three cycles.  In cycle a - 1 (the
  // word is being read: its context is known, narr) its context's flags
  // as they will be in cycle a, less those freed in cycle a, are decided
  // and registered (bq_q, below).  In cycle a, when it arrives, the flags
  // of its fields are looked up in bq_q (lk_q) and this cycle's other
  // changes to them are compared (pending destinations: pd_q; its
  // context's head's destination: hw_q, taken if that head is granted
  // now, gone_q), all registered; in cycle a + 1, when it is in its slot
  // (marked fresh: fr_q), they are combined.  So no lookup, compare and
  // queue update share a cycle, and the word, which leaves the
  // instruction memory's output register, meets 32 flip-flops of its own
  // context, not the flags of every context.
  wire [IW-1:0] a_ra = aword[ISA_RA_LSB +: IW];
  wire [IW-1:0] a_rb = aword[ISA_RB_LSB +: IW];
  wire [IW-1:0] a_rd = aword[ISA_RD_LSB +: IW];
  // The same fields for the lookup (lk_*) and for context c's compares
  // (cf_q, {rd, rb, ra} per context): with FETCH_STAGE, copies of the
  // word register's fields (fw_q), kept, each placed beside its own loads.
  // (fw_q's fields, read by the lookup's 32:1 multiplexers and by every
  // context's compares, were the critical path of two of nine
  // placements of 2026-11-23's seed sweep, 6 ns of routing.)
  wire [IW-1:0]      lk_ra, lk_rb, lk_rd;
  wire [NC*3*IW-1:0] cf_q;
  wire          iss_dst = PICK_STAGES != 0 && issue_o && issue_unit_o != UNIT_NONE;
  reg  [2*NC-1:0] fr_q;           // the slot's word arrived last cycle
  reg  [NC-1:0] gone_q;           // the grant of the last cycle
  wire [NC-1:0] gr_q;             // ... its copy for the ready step (below)
  reg  [NC-1:0] gr2_q;            // ... gr_q a cycle late: the grant two cycles ago
  always @(posedge clk_i) gr2_q <= gr_q;
  wire [NC-1:0] hpi_q;            // hp_q's copy for the immediate's pick (below)
  wire [2:0]    a_pend  = {3{iss_dst}} & {rd_o == {actx, a_rd}, rd_o == {actx, a_rb},
                                          rd_o == {actx, a_ra}};
  // The arriving word's flags, a cycle ahead.  busy_i is the register
  // file's flag register (fp3_regfile): a flag is set at the edge ending
  // the issue of an instruction that writes it (issue_o, issue_unit_o !=
  // UNIT_NONE, rd_o; the set wins) and cleared at the edge ending its
  // write-back's announcement (ahead_*_i), which early_*_i show a cycle
  // before.  So in cycle a - 1, for the context whose word arrives in
  // cycle a (nctx), flag r is in cycle a
  //   set(a - 1) or (busy(a - 1) and not announced(a - 1)),
  // and counts as free if it is announced in cycle a (early_*_i now).
  // The flags set and announced in cycle a - 1 (smask, cmask) are found
  // by the issue step (below), as one-hot masks over the context's
  // registers.
  localparam integer RN = 1 << IW;  // flags per context
  // With the issue loop's registered stages (PICK_STAGES = 2) a wait bit
  // may be cleared by an announcement up to two cycles before it is made
  // (above): the lookup also takes off the add and mul lines'
  // announcements of cycles a + 1 and a + 2 (pre_*_i and pre2_*_i now),
  // the ones that the word's compares in its slot, from cycle a + 1 on,
  // see no more.
  localparam [0:0] LEAD = PICK_STAGES == 2;
  wire [CW-1:0] nctx;               // (the fetch step's narr, encoded)
  wire [RN-1:0] smask, cmask;
  reg  [RN-1:0] bq_q;               // the arriving word's context's flags (cycle a)
  // One flag of a context, one-hot (none unless v).
  function [RN-1:0] flag1;
    input          v;
    input [IW-1:0] r;
    integer d;
    begin
      for (d = 0; d < RN; d = d + 1) flag1[d] = v && r == d[IW-1:0];
    end
  endfunction
  // The flags of context x among three announcements (valid v, indices i).
  function [RN-1:0] ann3;
    input [2:0]      v;
    input [3*XW-1:0] i;
    input [CW-1:0]   x;
    begin
      ann3 = flag1(v[0] && i[0*XW+IW +: CW] == x, i[0*XW +: IW]) |
             flag1(v[1] && i[1*XW+IW +: CW] == x, i[1*XW +: IW]) |
             flag1(v[2] && i[2*XW+IW +: CW] == x, i[2*XW +: IW]);
    end
  endfunction
  // With FETCH_STAGE, nctx's copy for bq_q (bctx), kept: placed beside
  // the flags' multiplexer (unless g_mask_ahead, below, selects the flags
  // a cycle earlier) and the announcements' compares it selects, not with
  // nctx's other loads (nctx's route to them was a critical
  // path).  nctx is fctx_q a cycle late (u_next), so is the copy.
  wire [CW-1:0] bctx;
  generate
    if (FETCH_STAGE != 0) begin : g_bctx_copy
      fp3_keep #(.W(CW)) u_bctx (
        .clk_i (clk_i),
        .d_i   (fctx_q),
        .q_o   (bctx)
      );
      wire unused_nctx = &{1'b0, nctx};   // (bctx is its copy)
    end else begin : g_bctx_now
      assign bctx = nctx;
    end
  endgenerate
  // The context's flags in cycle a - 1 (bflags) and the announcements of
  // cycle a (bann), for it: read now (busy_i, early_*_i), or, with
  // FETCH_STAGE and PICK_STAGES = 2, assembled from registers of cycle
  // a - 2 (g_mask_ahead, below).
  wire [RN-1:0] bflags, bann;
  always @(posedge clk_i)
    bq_q <= (smask | (bflags & ~cmask)) & ~bann
            & ~ann3({1'b0, pre_valid_i[1:0] & {2{LEAD}}}, pre_idx_i, bctx)
            & ~ann3({1'b0, pre2_valid_i & {2{LEAD}}}, {{XW{1'b0}}, pre2_idx_i}, bctx);
  // The lookup: the flags of the arriving word's fields, less the
  // announcements of this cycle (used by the context whose word it is).
  reg  [2:0]    lk_q;
  always @(posedge clk_i) lk_q <= {bq_q[lk_rd], bq_q[lk_rb], bq_q[lk_ra]};
  // PICK_STAGES = 2: the head granted in the last cycle, per context: it
  // writes a register (pg_w) and which (pg_rd) -- the instruction picked
  // now, which issues in the next cycle.
  wire [NC-1:0]    pg_w;
  wire [NC*IW-1:0] pg_rd;
  // The announcements the per-context copies (below) register: add and
  // mul three cycles ahead of early_*_i (pre3_*_i), move a cycle ahead
  // (pre_*_i: its line is the shortest, MOV_LATENCY = 1 + PICK_STAGES, and
  // its announcement is its pick; fp3_top).
  wire [2:0]      cp_valid = {pre_valid_i[2], pre3_valid_i};
  wire [3*XW-1:0] cp_idx   = {pre_idx_i[2*XW +: XW], pre3_idx_i};
  genvar c, e, l;
  generate
    if (PICK_STAGES != 2) begin : g_no_lead
      // (No copies and no registered stages in the issue loop.)
      wire unused_lead = &{1'b0, cp_valid, cp_idx, pre2_valid_i, pre2_idx_i, gr2_q};
    end
    for (c = 0; c < NC; c = c + 1) begin : g_ctx
      localparam [CW-1:0] CTX = c[CW-1:0];
      wire          hp = hp_q[c];
      // The head's decoded bits, destination and PC.
      wire [DW-1:0] xh = hp ? x_q[2*c+1] : x_q[2*c];
      wire [63:0]   wh = hp ? w_q[2*c+1] : w_q[2*c];
      wire [IW-1:0] rdh = wh[ISA_RD_LSB +: IW];
      wire          unused_h = &{1'b0, wh, xh};
      // The next cycle's announcements (early_*_i) for this context's
      // compares: with PICK_STAGES = 2 a copy of their own, registered
      // from pre_*_i and kept, so that the three tag lines' indices do not
      // each fan out to every context's compares across the die (a
      // critical path: 5.4-5.8 ns of routing).  The add and mul lines'
      // copies are registered from pre3_*_i: they show the announcements
      // two cycles early, for the issue loop's registered stages (below).
      wire [2:0]      ev;
      wire [3*IW-1:0] er;
      for (l = 0; l < 3; l = l + 1) begin : g_line
        if (PICK_STAGES == 2) begin : g_copy
          fp3_keep #(.W(1 + IW)) u_early_copy (
            .clk_i (clk_i),
            .d_i   ({!rst_i && cp_valid[l] && cp_idx[l*XW + IW +: CW] == CTX,
                     cp_idx[l*XW +: IW]}),
            .q_o   ({ev[l], er[l*IW +: IW]})
          );
        end else begin : g_shared
          assign ev[l] = early_valid_i[l] && early_idx_i[l*XW + IW +: CW] == CTX;
          assign er[l*IW +: IW] = early_idx_i[l*XW +: IW];
          wire unused_pre = &{1'b0, pre_valid_i[l], pre_idx_i[l*XW +: XW]};  // (no copy)
        end
      end
      wire          wrh = xh[7:6] != UNIT_NONE;   // it writes rdh
      assign legal[c]  = xh[11];
      assign h_stop[c] = xh[1] || (xh[3] && final_q[c]);
      assign h_ovf[c]  = xh[0];
      assign h_pc[c*AW +: AW] = hp ? p_q[2*c+1] : p_q[2*c];
      wire [DW-1:0] xl = hp ? x_q[2*c] : x_q[2*c+1];
      wire          unused_l = &{1'b0, xl};
      assign l_endi[c] = xl[3];
      assign l_ovf[c]  = xl[0];
      assign l_pc[c*AW +: AW] = hp ? p_q[2*c] : p_q[2*c+1];
      assign fpcs[c*AW +: AW] = fpc_q[c];

      // The head, if granted now, making its destination busy for the entries behind it: the one in the queue
      // and an arriving word (the compare with the head's destination,
      // hw_q, is registered, and the grant is taken in the next cycle
      // from gone_q).  With PICK_STAGES = 2, the head granted in the
      // last cycle (gone_q; destination rdg_q, if it writes one: wrg_q)
      // sets its flag only when it issues, in the next cycle: an arriving
      // word waits for it too.  That and the destination in the issue
      // register (a_pend) are kept together, in pd_q.
      reg  [2:0]    hw_q, pd_q;
      reg           wrg_q;
      reg  [IW-1:0] rdg_q;
      wire          pgv = PICK_STAGES == 2 && wrg_q && gone_q[c];
      // The arriving word's fields, this context's copy (cf_q, above).
      wire [IW-1:0] c_ra = cf_q[c*3*IW +: IW];
      wire [IW-1:0] c_rb = cf_q[c*3*IW + IW +: IW];
      wire [IW-1:0] c_rd = cf_q[c*3*IW + 2*IW +: IW];
      always @(posedge clk_i) begin
        hw_q  <= {3{wrh}} & {c_rd == rdh, c_rb == rdh, c_ra == rdh};
        pd_q  <= a_pend | ({3{pgv}} & {c_rd == rdg_q, c_rb == rdg_q, c_ra == rdg_q});
        wrg_q <= wrh;
        rdg_q <= rdh;
      end
      assign pg_w[c] = pgv;
      assign pg_rd[c*IW +: IW] = rdg_q;
      // The fresh word's wait bits: flag not freed, or pending, or written
      // by the head granted in its arrival cycle (sj_g: if it was).
      wire [2:0] sj_k = lk_q | pd_q;
      wire [2:0] sj_g = sj_k | hw_q;
      // Whether the head was granted in the last cycle (gr_q[c]) is the
      // last choice, of the wait bits and of the head's readiness, each
      // decided for both outcomes (s_k, s_g; rdy_k, rdy_g): one LUT
      // follows it.  (gone_q in front of the wait bits, the readiness and the
      // head select was a critical path.)
      wire [1:0] srdy_k, srdy_g;   // the slots' words are ready, by outcome
      // The arriving word's fields among the announcements of the next
      // cycle (early_*_i now), for whichever of this context's slots it
      // is written into (fresh there in the next cycle: fr_q).
      reg  [2:0] fa_q;
      always @(posedge clk_i)
        fa_q <= {`FP3_FREED(c_rd),
                 `FP3_FREED(c_rb),
                 `FP3_FREED(c_ra)};

      for (e = 0; e < 2; e = e + 1) begin : g_slot
        localparam integer I = 2 * c + e;       // this slot
        wire [63:0]   insn = w_q[I];
        wire [IW-1:0] rd = insn[ISA_RD_LSB +: IW];
        wire [IW-1:0] ra = insn[ISA_RA_LSB +: IW];
        wire [IW-1:0] rb = insn[ISA_RB_LSB +: IW];
        wire [31:0]   imm = insn[0 +: ISA_IMM_WIDTH];
        // (The opcode and the registers' high bits were decoded at arrival.)
        wire          unused_insn = &{1'b0, insn};
        wire          lgl, use_ra, use_rb, use_rd, d_sub, d_li, d_endi, d_beq, d_halt, d_ovf;
        wire [1:0]    d_unit;
        wire [2:0]    d_sop;
        assign {d_sop, lgl, use_rb, use_ra, use_rd, d_unit, d_sub, d_li, d_endi, d_beq, d_halt,
                d_ovf} = x_q[I];
        wire          unused_x = &{1'b0, d_halt, d_ovf};
        assign fields[I*FW +: FW] = {d_sop, ra, rb, rd, d_unit, d_sub, d_li, imm, d_endi, d_beq};
        // This cycle's announcements of the fields the slot holds, compared
        // in the cycle before (early_*_i) and registered; a word arriving
        // in that cycle has its own (fa_q), taken while it is fresh.  So
        // no slot select sits in front of the compares.
        reg  [2:0]    fq_q;
        always @(posedge clk_i)
          fq_q <= {`FP3_FREED(rd),
                   `FP3_FREED(rb),
                   `FP3_FREED(ra)};
        // The other slot, if it is the head and granted, writes its
        // destination: this word waits for it.  Compared in every cycle
        // (by_q), taken in the next if the head was granted (gr_q: this
        // slot is the head then), so that the grant drives no wait bit.
        reg  [2:0] by_q;
        always @(posedge clk_i)
          by_q <= {3{wrh && hp != e}} & {rd == rdh, rb == rdh, ra == rdh};
        // The wait bits, with this cycle's announcements taken off.
        wire [2:0] s_k = fr_q[I] ? sj_k & ~fa_q : s_q[I] & ~fq_q;
        wire [2:0] s_g = fr_q[I] ? sj_g & ~fa_q : (s_q[I] | by_q) & ~fq_q;
        wire [2:0] u   = {use_rd, use_rb, use_ra};
        if (PICK_STAGES == 2) begin : g_ready_reg
          // The slot's readiness for either outcome, registered and chosen
          // a cycle later by whether its context was granted in either of
          // the last two cycles (with issue spacing 3, in one at most); a
          // fresh slot's is not known yet (its word was not in the slot a
          // cycle ago).  See "The issue loop's registered stages".
          reg rk_q, rg_q;
          always @(posedge clk_i) begin
            rk_q <= lgl && !(|(u & s_k));
            rg_q <= lgl && !(|(u & s_g));
          end
          wire ok = !fr_q[I] && (gr_q[c] || gr2_q[c] ? rg_q : rk_q);
          assign srdy_k[e] = ok;
          assign srdy_g[e] = ok;
        end else begin : g_ready_now
          assign srdy_k[e] = lgl && !(|(u & s_k));
          assign srdy_g[e] = lgl && !(|(u & s_g));
        end
        assign s_d[I*3 +: 3] = gr_q[c] ? s_g : s_k;
      end
      // The head's fields, and the last head's (hp_q has moved on if it
      // was granted).
      assign h_fields[c*FW +: FW] = hp ? fields[(2*c+1)*FW +: FW] : fields[2*c*FW +: FW];
      // (The immediate's bits by hpi_q, hp_q a cycle late: the slot the
      // head was in, which for a context granted in the last cycle is the
      // last head's; for the others the pick does not read them.)
      wire [FW-1:0] f_e0 = fields[2*c*FW +: FW];
      wire [FW-1:0] f_e1 = fields[(2*c+1)*FW +: FW];
      assign l_fields[c*FW +: FW] = (hp ? f_e0 : f_e1) & ~IMM_BITS |
                                    (hpi_q[c] ? f_e1 : f_e0) & IMM_BITS;
      (* keep *) wire rdy_k;
      (* keep *) wire rdy_g;
      assign rdy_k = act[c] && (hp ? v_q[2*c+1] && srdy_k[1] : v_q[2*c] && srdy_k[0]);
      assign rdy_g = act[c] && (hp ? v_q[2*c+1] && srdy_g[1] : v_q[2*c] && srdy_g[0]);
      assign ready_d[c] = gr_q[c] ? rdy_g : rdy_k;
    end
  endgenerate
`undef FP3_FREED

  function [CW-1:0] encode;     // index of a one-hot x (0 if none)
    input [NC-1:0] x;
    integer p;
    begin
      encode = {CW{1'b0}};
      for (p = 0; p < NC; p = p + 1) if (x[p]) encode = encode | p[CW-1:0];
    end
  endfunction

  function [NC-1:0] onehot;
    input          valid;
    input [CW-1:0] x;
    integer p;
    begin
      for (p = 0; p < NC; p = p + 1) onehot[p] = valid && x == p[CW-1:0];
    end
  endfunction

  // ---- issue step ----------------------------------------------------------
  // Round robin (fp3_rr_arbiter) among the ready heads (ready_q, a
  // register: the pick starts at flip-flops).  The context granted in the
  // last cycle is no candidate: its ready bit belonged to the instruction
  // that left.  It is masked behind the carry chain (gl_q, a copy of the
  // last grant for this mask), as in the fetch arbiter, so that ready_q's
  // next state does not wait for the grant: the pick starts after the
  // last grant, so it is that context only when no other is ready, and
  // masking it then leaves no grant, as it should (grant, the candidates
  // decided from registers alone, agrees).
  // The copy takes the grant as it is, not gated with RUNNING as gone_q
  // is: while stopped ready_q is clear (no context is active in a run's
  // last cycle, and the run state is held clear), so a stale mask masks
  // nothing, and the grant meets the flip-flop with no gate between
  // (the gate was on the critical path of a placement, seed 1 of
  // 2026-11-23's sweep of d3eaf1f).
  wire [NC-1:0] gl_q;
  fp3_keep #(.W(NC)) u_gone_copy (
    .clk_i (clk_i),
    .d_i   (gone),
    .q_o   (gl_q)
  );
  // PICK_STAGES = 2: the arbiter's decision is registered (dec_q) before
  // it is the grant (gone), so that the loop from ready_q through the
  // arbiter's carry chain ends at a register of its own.  The context
  // decided in the last cycle (dec_q, the grant of this cycle) and the one
  // decided before (gl_q, the last grant) are no candidates: the ready step
  // heard of neither when it made ready_q (it chooses by the grant of the
  // last cycle).  So a context is granted at most every third cycle.  The
  // round-robin position moves with the grant, a cycle after the decision.
  wire [NC-1:0] ipick;
  wire          grant;        // a context is granted (one-hot: gone)
  wire [NC-1:0] arb_req;      // the arbiter's requests, ...
  wire          arb_take;     // ... whether its pick is taken, ...
  wire [NC-1:0] arb_taken;    // ... and which (its position moves there)
  fp3_rr_arbiter #(.N(NC)) u_issue_arb (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running_o),
    .req_i   (arb_req),
    .pick_o  (ipick),
    .take_i  (arb_take),
    .taken_i (arb_taken)
  );
  generate
    if (PICK_STAGES == 2) begin : g_grant_reg
      reg  [NC-1:0] dec_q;
      reg           dec_any_q;
      wire [NC-1:0] cand = ready_q & ~gl_q & ~dec_q;
      // (While stopped ready_q is clear, so cand and ipick are.)
      always @(posedge clk_i) begin
        if (rst_i) begin
          dec_q     <= {NC{1'b0}};
          dec_any_q <= 1'b0;
        end else begin
          dec_q     <= ipick;
          dec_any_q <= |cand;
        end
      end
      assign arb_req   = cand;
      assign arb_take  = dec_any_q;
      assign arb_taken = dec_q;
      assign gone      = dec_q;     // the head leaves its queue
      assign grant     = dec_any_q;
    end else begin : g_grant_now
      wire [NC-1:0] cand = ready_q & ~gl_q;   // (the ready step counts only active contexts)
      assign arb_req   = ready_q;
      assign arb_take  = grant;
      assign arb_taken = gone;
      assign grant     = |cand;
      assign gone      = ipick & ~gl_q;   // the head leaves its queue
    end
  endgenerate
  wire [CW-1:0] g     = encode(gone);
  // The granted head's fields, picked from the heads' fields (selected by
  // the head pointers beside the arbiter, from registers only) by the
  // one-hot grant: this cycle's (PICK_STAGES = 0), or the last cycle's,
  // registered (PICK_STAGES = 2; the granted word stays in its slot for a
  // cycle: the next word to arrive takes the other slot or, if the queue
  // is empty, the new head's).
  reg           grant_q;
  always @(posedge clk_i) begin
    gone_q  <= gone & {NC{running_o}};
    grant_q <= grant && running_o;
  end
  // hp_q's copy for the last heads' immediates (l_fields), the 32-bit
  // half of the pick's multiplexer (its grant from gpi_q), kept: placed
  // beside that multiplexer.  (hp_q, placed with its context's queue,
  // across the die to the immediate's pick was a critical path.)  It is
  // hp_q a cycle late, the head's slot in the grant's cycle, not hp_q's
  // next state (hp_q ^ gone): the grant crossed the die to this copy
  // through a gate, the end of six of twelve placements of ec498be (the
  // grant's route to the copy in five, the copy's route to the pick in
  // one).
  fp3_keep #(.W(NC)) u_hp_imm (
    .clk_i (clk_i),
    .d_i   (hp_q),
    .q_o   (hpi_q)
  );
  // gone_q's copy for the ready step (the wait bits' and ready_q's last
  // choice), kept: placed beside it, not with gone_q's other loads.  It
  // takes the grant ungated, as gl_q does (while stopped ready_q is clear,
  // so there is no grant to gate; the gate was on the critical path of a
  // placement, seed 2 of 2026-11-23's sweep of e9ea445).
  fp3_keep #(.W(NC)) u_gone_ready (
    .clk_i (clk_i),
    .d_i   (gone),
    .q_o   (gr_q)
  );
  // With PICK_STAGES = 2 the pick multiplexer takes the last grant from
  // copies of gone_q of its own, one for the immediate (32 bits) and one
  // for the other fields: each drives some 30 LUTs beside the heads'
  // fields instead of one register driving 53 of them and the contexts'
  // logic (a grant bit across the die to the immediate was a critical
  // path).  The copies take the grant as it is, not gated with running_o
  // as gone_q is: the pick's valid bit (grant_q) is gated, and fields
  // picked while stopped are not used.  (Gated alike, the three shared
  // one AND gate, which the placer put between them: a critical path.)
  // The process is kept so that Yosys does not merge the two equal
  // copies (as in fp3_ram); their initial value only defines them in
  // simulation before the first clock.
  reg [NC-1:0] gpi_q, gpf_q;
  initial begin
    gpi_q = {NC{1'b0}};
    gpf_q = {NC{1'b0}};
  end
  (* keep *) always @(posedge clk_i) begin
    gpi_q <= gone;
    gpf_q <= gone;
  end
  wire          two     = PICK_STAGES == 2;
  wire [NC-1:0] p_seli  = two ? gpi_q : gone;
  wire [NC-1:0] p_self  = two ? gpf_q : gone;
  wire          p_grant = two ? grant_q : grant;
  // (The granted context's number, encoded from the grant's copy in the
  // pick cycle: registered as encoded, Yosys made the grant a synchronous
  // reset of its register, behind the arbiter: a critical path.)
  wire [CW-1:0] p_g     = two ? encode(gpf_q) : g;
  reg  [FW-1:0] gf;
  integer q;
  always @(*) begin
    gf = {FW{1'b0}};
    for (q = 0; q < NC; q = q + 1)
      gf = gf | (({FW{p_seli[q]}} & IMM_BITS | {FW{p_self[q]}} & ~IMM_BITS) &
                 (two ? l_fields[q*FW +: FW] : h_fields[q*FW +: FW]));
  end

  wire [IW-1:0] g_ra, g_rb, g_rd;
  wire [1:0]    g_unit;
  wire          g_sub, g_li, g_endi, g_beq;
  wire [2:0]    g_sop;
  wire [31:0]   g_imm;
  assign {g_sop, g_ra, g_rb, g_rd, g_unit, g_sub, g_li, g_imm, g_endi, g_beq} = gf;

  // The granted instruction, as it issues: {valid, ctx, ra, rb, rd, unit,
  // sub, sop, imm (li), immediate, endi, beq}.
  localparam integer IS_W = 1 + CW + 3 * XW + 2 + 1 + 3 + 1 + 32 + 1 + 1;
  wire [IS_W-1:0] is_d = {p_grant, p_g, p_g, g_ra, p_g, g_rb, p_g, g_rd, g_unit, g_sub, g_sop, g_li,
                          g_imm, p_grant && g_endi, p_grant && g_beq};
  wire [IS_W-1:0] is_w;
  // (The issue register is cleared while stopped, below.)
  assign pick_wr_o = p_grant && g_unit != UNIT_NONE &&
                     (PICK_STAGES == 0 || (!rst_i && running_o));
  assign pick_rd_o = {p_g, g_rd};
  assign pick_unit_o = g_unit;
  generate
    if (PICK_STAGES == 0) begin : g_pick0
      assign is_w = is_d;
    end else if (PICK_STAGES == 2) begin : g_pick2
      reg [IS_W-1:0] is_q;
      always @(posedge clk_i) begin
        if (rst_i || !running_o) is_q <= {IS_W{1'b0}};
        else                     is_q <= is_d;
      end
      assign is_w = is_q;
    end else begin : g_bad_pick_stages
      // Elaboration error on purpose: PICK_STAGES must be 0 or 2.
      fp3_scheduler_error_PICK_STAGES_must_be_0_or_2 u_error ();
    end
  endgenerate
  assign {issue_o, issue_ctx_o, ra_o, rb_o, rd_o, issue_unit_o, issue_sub_o, issue_sop_o, issue_imm_o,
          imm_o, endi_o, beq_o} = is_w;

  // The flags of the arriving word's context set and announced in cycle
  // a - 1 (bq_q, above).  With FETCH_STAGE and PICK_STAGES = 2 they are
  // decided in cycle a - 2 and registered: the instruction that issues in
  // a - 1 is picked in a - 2 (is_d; its context's pg_w, pg_rd), the
  // announcements of a - 1 are shown in a - 2 (early_*_i), and the
  // context (nfctx in a - 1) is fctx_q in a - 2.  So the flags meet
  // flip-flops of their own, not the issue register's and the tag lines'
  // compares, and the mask is not behind the pick's multiplexer.  (If no
  // run goes on in a - 2, no word arrives in a.)
  //   So are the context's flags themselves (bflags) and the
  // announcements of cycle a (bann): in cycle a - 2 its flags are selected
  // from busy_i and registered (bsel_q), with the flags set and announced
  // in a - 2 (sset_q: the issue register now; sclr_q: ahead_*_i) and the
  // add and mul lines' announcements of cycle a (sann_q: pre_*_i in a - 2,
  // which shows what early_*_i shows in a - 1: the tag line's stage in
  // front of it, or its pick, which issues in the next cycle).  The move
  // line's is still early_*_i in a - 1: its pre_*_i is the pick's
  // multiplexer (a critical path into sann_q, 7.4 ns).  So bq_q meets no
  // multiplexer of every context's flags, which are spread with the
  // register file (the lookup's select bctx -> busy_i -> bq_q was the
  // critical path of six of sixteen placements, 2026-11-24).
  generate
    if (FETCH_STAGE != 0 && PICK_STAGES == 2) begin : g_mask_ahead
      reg [RN-1:0] smask_q, cmask_q;
      // fctx_q's copy for these masks, kept (fctx_q also goes with the
      // fetch address to the memory's side: its route back to the masks
      // was a critical path)
      wire [CW-1:0] fcm_q;
      fp3_keep #(.W(CW)) u_fctx_copy (
        .clk_i (clk_i),
        .d_i   ((!rst_i && running_o) ? fr : fcm_q),
        .q_o   (fcm_q)
      );
      always @(posedge clk_i) begin
        smask_q <= flag1(!rst_i && running_o && pg_w[fcm_q], pg_rd[fcm_q*IW +: IW]);
        cmask_q <= ann3(early_valid_i, early_idx_i, fcm_q);
      end
      assign smask = smask_q;
      assign cmask = cmask_q;
      // The flags, two cycles ahead: fctx_q's copy for their multiplexer
      // (kept: placed by the flags, not by the masks' loads above).
      wire [CW-1:0] fcb_q;
      fp3_keep #(.W(CW)) u_fctx_flags (
        .clk_i (clk_i),
        .d_i   ((!rst_i && running_o) ? fr : fcb_q),
        .q_o   (fcb_q)
      );
      reg [RN-1:0] bsel_q, sset_q, sclr_q, sann_q;
      always @(posedge clk_i) begin
        bsel_q <= busy_i[fcb_q*RN +: RN];
        sset_q <= flag1(issue_o && issue_unit_o != UNIT_NONE && rd_o[IW +: CW] == fcm_q,
                        rd_o[IW-1:0]);
        sclr_q <= ann3(ahead_valid_i, ahead_idx_i, fcm_q);
        sann_q <= ann3({1'b0, pre_valid_i[1:0]}, pre_idx_i, fcm_q);
      end
      // The register file's update of the edge ending a - 2 (the set wins).
      assign bflags = sset_q | (bsel_q & ~sclr_q);
      assign bann   = sann_q | ann3({early_valid_i[2], 2'b00}, early_idx_i, bctx);
    end else begin : g_mask_now
      assign smask = flag1(issue_o && issue_unit_o != UNIT_NONE && rd_o[IW +: CW] == nctx,
                           rd_o[IW-1:0]);
      assign cmask = ann3(ahead_valid_i, ahead_idx_i, nctx);
      assign bflags = busy_i[bctx*RN +: RN];
      assign bann   = ann3(early_valid_i, early_idx_i, bctx);
      wire unused_pg = &{1'b0, pg_w, pg_rd};  // (the issue register, now)
    end
  endgenerate

  // ---- fetch step ----------------------------------------------------------
  // A context may fetch when it has room for the word (an entry free, not
  // counting one it may issue now: that would put the arbiter in front of
  // the memory address) and no read in flight.
  // FETCH_STAGE: the fetch grant is registered, the granted context's
  // fetch PC is selected in the next cycle and registered (by the memory,
  // and in fpcq_q), the memory reads it in the cycle after that into its
  // output register, and the word is registered once more, in the fabric
  // (fw_q): it arrives four cycles after the grant.  So nothing but that
  // register meets the memory's output, and the block RAM's long route
  // into the fabric is a path of its own.  The word's context and PC
  // follow it: to the cycle before it arrives (u_next: narr), and to its
  // arrival (u_arrive).  A context has one word in flight, from its
  // grant to its arrival.
  wire          nvalid;     // the word arriving in the next cycle (FETCH_STAGE)
  wire [CW-1:0] nfctx;      // ... its context
  wire [AW-1:0] npc;        // ... its PC
  fp_pipe #(.WIDTH(CW + AW), .DEPTH(FETCH_STAGE)) u_next (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running_o),
    .valid_i (fvalid_q),
    .data_i  ({fctx_q, fpcq_q}),
    .valid_o (nvalid),
    .data_o  ({nfctx, npc})
  );
  wire          n_atend = {{(32-AW){1'b0}}, npc} == IMEM_DEPTH - 1;
  fp_pipe #(.WIDTH(CW + AW + 1), .DEPTH(FETCH_STAGE)) u_arrive (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running_o),
    .valid_i (nvalid),
    .data_i  ({nfctx, npc, n_atend}),
    .valid_o (avalid),
    .data_o  ({actx, apc, a_atend})
  );
  generate
    if (FETCH_STAGE != 0) begin : g_word_reg
      reg [SW+63:0] fw_q;
      always @(posedge clk_i) fw_q <= {imem_sdec, imem_word};
      assign {asdec, aword} = fw_q;
      wire [3*IW-1:0] wf = {imem_word[ISA_RD_LSB +: IW], imem_word[ISA_RB_LSB +: IW],
                            imem_word[ISA_RA_LSB +: IW]};
      fp3_keep #(.W(3*IW)) u_lk_fields (
        .clk_i (clk_i),
        .d_i   (wf),
        .q_o   ({lk_rd, lk_rb, lk_ra})
      );
      for (c = 0; c < NC; c = c + 1) begin : g_cf
        fp3_keep #(.W(3*IW)) u_ctx_fields (
          .clk_i (clk_i),
          .d_i   (wf),
          .q_o   (cf_q[c*3*IW +: 3*IW])
        );
      end
    end else begin : g_word_now
      assign {asdec, aword} = {imem_sdec, imem_word};
      assign {lk_rd, lk_rb, lk_ra} = {a_rd, a_rb, a_ra};
      assign cf_q = {NC{a_rd, a_rb, a_ra}};
    end
  endgenerate
  assign arriving = onehot(avalid, actx);
  wire          fread;      // a fetch granted (FETCH_STAGE: in the last cycle) for fr1
  wire [NC-1:0] fr1;
  // A context may fetch when it has room for the word and no read in
  // flight.  The grant of the last cycle is a register (fg_q), so nothing
  // follows the arbiter's grant but flip-flops: the words in flight are
  // fg_q and those granted before it (infl_q), and the rest of the
  // request is decided a cycle ahead (mfk_q, mfg_q, with the active contexts,
  // below).
  reg  [NC-1:0] fg_q;       // granted a fetch in the last cycle
  reg  [NC-1:0] infl_q;     // granted before that, the word not yet in its queue
  reg  [NC-1:0] mfk_q, mfg_q; // may fetch, but for fg_q, fend_q and bwait_q: if
                            // the head was kept / granted in the last cycle
  wire [NC-1:0] gf_q;       // ... which: the last grant (gone), a copy (below)
  wire [2*NC-1:0] v_k, v_g; // the slots' valid bits, next: head kept / granted now
  wire [NC-1:0] holds;      // ... at least one (the head)
  // An arriving word is written into a free slot: the head's if the queue
  // is empty, else the other (a context fetches only with a slot free and
  // one word in flight, so at most one slot is taken then, and a lone
  // word is the head).  Which slot does not depend on a grant (a grant
  // empties a queue of one and moves the head to the other slot), so it
  // is chosen a cycle ahead, as the word is read, and registered (wsel_q):
  // the slot's word, decoded bits and PC are written on a flip-flop's
  // output, whether or not the context is still active (the slot is
  // free), and only its valid bit waits for that (wslot).
  // A slot is valid once a word is written into it (wslot), until its
  // head is granted (gone).
  wire [NC-1:0] infl_n = (infl_q | fg_q) & ~arriving;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_fill
      assign holds[c] = v_q[2*c] || v_q[2*c+1];
      for (e = 0; e < 2; e = e + 1) begin : g_free
        assign wslot[2*c+e] = wsel_q[2*c+e] && act[c];
        assign v_k[2*c+e]   = wslot[2*c+e] || v_q[2*c+e];
        assign v_g[2*c+e]   = wslot[2*c+e] || (v_q[2*c+e] && hp_q[c] != e[0]);
      end
    end
  endgenerate
  // The fetch arbiter: round robin (fp3_rr_arbiter), with the last
  // grant (fg_q, which may not fetch) masked only behind the carry chain.
  // The pick from {freq, freq} is a context after the last grant g, else
  // the first context with a request.  Only the latter can be g itself,
  // when no other context requests (none is after g, and none before g,
  // or it would be the first): so masking g after the pick leaves no
  // grant, as it should.
  wire [NC-1:0] freq  = (gf_q & mfg_q | ~gf_q & mfk_q) & ~fend_q & ~bwait_q;   // the requests
  wire          fetch = (|(freq & ~fg_q)) && running_o;
  wire [NC-1:0] fpick, fgnt;
  fp3_rr_arbiter #(.N(NC)) u_fetch_arb (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running_o),
    .req_i   (freq),
    .pick_o  (fpick),
    .take_i  (fetch),
    .taken_i (fgnt)
  );
  assign fgnt = fpick & ~fg_q;
  fp_pipe #(.WIDTH(NC), .DEPTH(FETCH_STAGE)) u_fgrant (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running_o),
    .valid_i (fetch),
    .data_i  (fgnt),
    .valid_o (fread),
    .data_o  (fr1)
  );
  // The granted context's fetch PC, selected by the one-hot grant (fr1):
  // the memory's address (FETCH_STAGE: the memory registers it, a copy
  // per 4-bit lane of the word, and reads in the next cycle; fpcq_q, the
  // same address, goes with the word).
  always @(*) begin
    fpc_sel = {AW{1'b0}};
    for (q = 0; q < NC; q = q + 1) fpc_sel = fpc_sel | ({AW{fr1[q]}} & fpcs[q*AW +: AW]);
  end
  assign fr = encode(fr1);
  // The word arriving in the next cycle (u_arrive's input).
  wire [NC-1:0] narr = FETCH_STAGE != 0 ? onehot(nvalid, nfctx) : onehot(fread, fr);
  // The slot the word arriving next is written into (wsel_q, below).
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_wsel
      for (e = 0; e < 2; e = e + 1) begin : g_slot
        assign wsel_d[2*c+e] = narr[c] && (hp_q[c] ^ holds[c]) == e[0];
      end
    end
  endgenerate
  assign nctx = FETCH_STAGE != 0 ? nfctx : fr;

  // The arriving word decides where its context fetches next.
  wire [AW-1:0] a_next  = a_endi ? aword[AW-1:0] : apc + {{(AW-1){1'b0}}, 1'b1};

  // A context stops fetching when it has fetched the memory's last word
  // (fend) or a beq (bwait), as its word arrives; a resolved beq releases
  // it (its word arrived at least three cycles ago, so no arriving word
  // competes), and a taken one moves it to its target (inside the
  // memory: legal targets are).  Next state; registered below.
  wire [NC-1:0] fend_d, bwait_d;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_fflags
      wire arr = arriving[c] && act[c];
      wire br  = br_i[c];
      assign fend_d[c]  = (rst_i || !running_o)  ? 1'b0 :
                          (br && br_taken_i)      ? 1'b0 :
                          (arr && !a_endi && a_atend) ? 1'b1 : fend_q[c];
      assign bwait_d[c] = (rst_i || !running_o)  ? 1'b0 :
                          br                      ? 1'b0 :
                          (arr && a_beq)          ? 1'b1 : bwait_q[c];
    end
  endgenerate

  wire start_ok = start_i && !running_o && !steps_zero_i && !contexts_bad_i;

  // ---- selected-context status ---------------------------------------------
  wire [NC-1:0] err_any;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_err
      assign err_any[c] = err_q[c] != ERR_NONE;
    end
  endgenerate
  assign any_error_o      = |err_any;
  assign error_sel_o      = err_q[sel_ctx_i];
  assign fault_pc_sel_o   = {{(32-AW){1'b0}}, epc_q[sel_ctx_i]};
  assign steps_done_sel_o = sdone_q[sel_ctx_i];

  // Upper bits of wide fields are checked by `legal`, not used as indices.
  wire unused_ok = &{1'b0, aword[31:AW]};

  // ---- control, status and counters ----------------------------------------
  // Three groups of state, so that the START decision drives few flip-flops:
  //   run control  RUNNING, DONE, the active contexts and what the first
  //                cycle of a run needs: decided in the START cycle;
  //   run state    queues, fetch, arbiters: held at their start values
  //                while no run is in progress;
  //   results      counters, integrations done, errors (the host reads them
  //                after a run): cleared in the run's first cycle (start_q),
  //                in which nothing can have issued yet, or set a cycle
  //                after a refused START (bad_q).
  wire          bad_start = start_i && !running_o && !start_ok;
  wire [NC-1:0] illegal   = act & holds & ~legal;
  reg           start_q, bad_q;  // a START taken / refused in the last cycle
  reg  [3:0]    bad_err_q;       // ... why it was refused
  // start_q's copy for the run's end (RUNNING's and DONE's next state, the
  // quiet-cycle count lull_q), kept: placed beside them, not among
  // start_q's few hundred other loads (the run's first cycle clears every
  // counter).  start_q across the die to the end-of-run test in front of
  // RUNNING was the critical path of two of nine placements (2026-11-23).
  wire          start_e;
  fp3_keep #(.W(1)) u_start_end (
    .clk_i (clk_i),
    .d_i   (start_ok && !rst_i),
    .q_o   (start_e)
  );
  // The run ends: no context active and nothing in flight once DRAIN
  // cycles passed without a busy flag or an issue: the last of them was
  // cycle t - 1 (idle_i, iss_q), the DRAIN - 1 before it are counted in
  // lull_q, and cycle t - 1 was one of the run (not start_q).  So no flag
  // is busy now either (this cycle's flags are not needed): none was set
  // in t - 1, as nothing issued.
  wire run_end = act == {NC{1'b0}} && !issue_o && !(two && grant_q) && !start_e &&
                 idle_i && !iss_q && lull_full_q;
  integer k;
  always @(posedge clk_i) begin
    if (rst_i) begin
      running_o <= 1'b0;
      done_o    <= 1'b0;
      start_q   <= 1'b0;
      bad_q     <= 1'b0;
      bad_err_q <= ERR_NONE;
      final_q   <= {NC{1'b0}};
      last2_q   <= 32'd0;
    end else begin
      start_q   <= start_ok;
      bad_q     <= bad_start;
      bad_err_q <= steps_zero_i ? ERR_BAD_STEPS : ERR_BAD_CONTEXTS;
      if (!running_o) begin
        // What the run needs of STEPS follows it while stopped (the
        // values taken at START's edge are the run's), so that START's
        // decode does not enable these 40 flip-flops.
        last2_q <= steps_last2_i;
        final_q <= {NC{steps_one_i}};
        if (start_ok) begin
          running_o <= 1'b1;
          done_o    <= 1'b0;
        end else if (start_i || clear_i) begin
          done_o <= 1'b0;        // a refused START: DONE in the next cycle
        end else if (bad_q) begin
          done_o <= 1'b1;
        end
      end else begin
        for (k = 0; k < NC; k = k + 1) begin
          if (gone_q[k] && l_endi[k]) final_q[k] <= near_q[k];
        end
        if (run_end) begin
          running_o <= 1'b0;
          done_o    <= 1'b1;
        end
      end
    end
  end

  // The active contexts (act): started by START, stopped by their halt or
  // last endi, a PC overflow or an illegal head.  A head granted in cycle
  // t that stops its context is registered (stop_q) and taken off act in
  // cycle t + 1, and off active_q in t + 2: so the grant drives one
  // flip-flop, not the active contexts' next state.  The fetch arbiter
  // has a register of its own, so that its requests start at flip-flops
  // placed beside it rather than at ones shared with the ready step, the
  // queues and the run control: mfk_q, mfg_q, the contexts active in the
  // next cycle (act) with a free slot in the next cycle and no read in
  // flight but the last grant's, one for either outcome of the issue step
  // (mf_k, mf_g, kept as nets in synthesis), chosen in the next cycle in
  // front of the arbiter (freq) by a copy of the grant (gf_q), so that no
  // logic follows the issue arbiter here (its grant -> a fetch request
  // was a critical path).  What else holds a context's fetch (past the
  // memory's last word, waiting on a beq: fend_q, bwait_q, the fetch
  // step) is its own register, joined to them in front of the arbiter
  // too, not decided in their cone: a resolved beq and an arriving
  // word were in front of it (critical paths).  While stopped no context
  // is active (a run ends with none, START starts them), so neither
  // held_d nor the slots' write (wslot) is gated with RUNNING, a signal
  // of the whole scheduler.  The queues' next state (v_q) is decided for
  // either outcome of the issue step too (v_k, v_g) and chosen by the
  // grant (gone), so that one LUT follows the issue arbiter.
  assign act = active_q & ~stop_q;
  // START (from the host's write) is the last multiplexer in front of
  // the registers: held_d is their next state without it.  With
  // FETCH_STAGE the contexts start a cycle after START, from its register
  // (start_q; RUNNING is set at START as without), so that the host
  // port's address decode (start_ok) meets the run control's few
  // flip-flops only, not the active contexts' and the fetch requests'
  // next state: the run's first cycle passes with no context active.
  wire          start_now = (FETCH_STAGE != 0 ? start_q && running_o : start_ok) && !rst_i;
  wire [NC-1:0] held_d    = rst_i ? {NC{1'b0}} : act & ~illegal;
  wire [NC-1:0] active_d  = start_now ? contexts_run_i : held_d;
  // The head stops its context if granted (stop_d).
  wire [NC-1:0] h_end     = (h_stop | h_ovf) & {NC{running_o && !rst_i}};
  wire [NC-1:0] stop_d    = gone & h_end;
  wire [NC-1:0] fok_n     = start_now ? contexts_run_i : held_d;
  wire [NC-1:0] mfk_n, mfg_n;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_mf
      (* keep *) wire mf_k;
      (* keep *) wire mf_g;
      assign mf_k = fok_n[c] && !infl_n[c] && !(v_k[2*c] && v_k[2*c+1]);
      assign mf_g = fok_n[c] && !infl_n[c] && !(v_g[2*c] && v_g[2*c+1]) && !h_end[c];
      assign mfk_n[c] = mf_k;
      assign mfg_n[c] = mf_g;
    end
  endgenerate
  always @(posedge clk_i) begin
    active_q <= active_d;
    stop_q   <= stop_d;
    mfk_q    <= mfk_n;
    mfg_q    <= mfg_n;
  end
  // The grant as it is (not gated with RUNNING: the choice is the one
  // made in the last cycle), kept: placed by the fetch arbiter.
  fp3_keep #(.W(NC)) u_gone_fetch (
    .clk_i (clk_i),
    .d_i   (gone),
    .q_o   (gf_q)
  );

  // Queue slots' contents: the arriving word, in the slot chosen for it
  // (wsel_q, below).
  always @(posedge clk_i) begin
    for (k = 0; k < 2 * NC; k = k + 1)
      if (wsel_q[k]) begin
        w_q[k] <= aword;
        x_q[k] <= adec;
        p_q[k] <= apc;
      end
  end

  always @(posedge clk_i) begin
    fend_q  <= fend_d;
    bwait_q <= bwait_d;
  end
  always @(posedge clk_i) begin
    if (rst_i || !running_o) begin
      hp_q     <= {NC{1'b0}};
      v_q      <= {(2*NC){1'b0}};
      ready_q  <= {NC{1'b0}};
      fr_q     <= {(2*NC){1'b0}};
      wsel_q   <= {(2*NC){1'b0}};
      fg_q     <= {NC{1'b0}};
      infl_q   <= {NC{1'b0}};
      fvalid_q <= 1'b0;
      lull_q   <= 8'd0;
      lull_full_q <= LULL8 == 8'd0;
      for (k = 0; k < NC; k = k + 1) fpc_q[k] <= {AW{1'b0}};
    end else begin
      ready_q <= ready_d;
      fr_q    <= wslot;
      for (k = 0; k < 2 * NC; k = k + 1) s_q[k] <= s_d[k*3 +: 3];

      // Queues: the granted head leaves (the head pointer moves on), an
      // arriving word is written into its slot (above) and is valid there
      // (wslot); the slot of the word arriving next is chosen.
      for (k = 0; k < 2 * NC; k = k + 1) v_q[k] <= gone[k/2] ? v_g[k] : v_k[k];
      wsel_q <= wsel_d;
      for (k = 0; k < NC; k = k + 1) begin
        if (gone[k]) hp_q[k] <= !hp_q[k];
        // The fetch PC: after the arriving word, or a taken beq's target
        // (fend_d, bwait_d).
        if (arriving[k] && act[k]) fpc_q[k] <= a_next;
        if (br_i[k] && br_taken_i) fpc_q[k] <= br_target_i;
      end

      // The word read now arrives next cycle (FETCH_STAGE: the PC is
      // read in the next cycle, the word arrives two cycles after that).
      fvalid_q <= fread;
      fctx_q   <= fr;
      fpcq_q   <= fpc_sel;
      fg_q     <= fgnt;   // (none without fetch: the arbiter's; no synchronous reset from fetch)
      infl_q   <= infl_n;

      // lull_q(t + 1) counts the quiet cycles before cycle t (see the run
      // control), none before the run's first cycle.  Whether it is full
      // is registered beside it (lull_full_q), so that the end-of-run test
      // compares no count (lull_q -> its compare -> RUNNING's and DONE's
      // enables was 4 LUTs deep).
      if (start_e || !idle_i || iss_q) begin
        lull_q      <= 8'd0;
        lull_full_q <= LULL8 == 8'd0;
      end else if (!lull_full_q) begin
        lull_q      <= lull_q + 8'd1;
        lull_full_q <= lull_q == LULL8 - 8'd1;
      end
    end
  end

  // Issues and stalls are counted a cycle late (grant_q, stall_q), so
  // that the grant drives no counter: the run goes on for a cycle after
  // either (a context was active, with work), and in its first cycle, in
  // which the results are cleared, there was none in the one before.
  reg stall_q;              // a stall in the last cycle
  // An illegal head is recorded a cycle later too (ill_q), so that the
  // heads' decode drives no error register (which sits by the host's
  // read, across the die: a critical path).  Its context left the active
  // set at once (held_d), so its head stays in its slot (h_pc) and the
  // run goes on for that cycle.
  reg [NC-1:0] ill_q;
  always @(posedge clk_i) begin
    ill_q   <= illegal & {NC{running_o}};
    stall_q <= running_o && !grant && |(act & holds);
    iss_q   <= issue_o;
  end

  always @(posedge clk_i) begin
    if (rst_i || start_q) begin
      // Reset, or the run's first cycle (counted; no issue or stall in it).
      cycles_o <= {63'd0, !rst_i};
      issued_o <= 64'd0;
      stalls_o <= 64'd0;
      for (k = 0; k < NC; k = k + 1) begin
        sdone_q[k] <= 32'd0;
        err_q[k]   <= ERR_NONE;
        epc_q[k]   <= {AW{1'b0}};
      end
    end else if (bad_q) begin
      for (k = 0; k < NC; k = k + 1) begin
        err_q[k]   <= bad_err_q;
        sdone_q[k] <= 32'd0;
      end
    end else if (running_o) begin
      cycles_o <= cycles_o + 64'd1;
      if (grant_q) issued_o <= issued_o + 64'd1;
      if (stall_q) stalls_o <= stalls_o + 64'd1;
      // Integration counters and errors: each context's own, so that
      // nothing wide sits behind the arbiter, counted and recorded a cycle
      // after the grant (the last head; its context, stopped by a PC
      // overflow at the grant, is not active now: no illegal head).
      for (k = 0; k < NC; k = k + 1) begin
        if (gone_q[k] && l_endi[k]) sdone_q[k] <= sdone_q[k] + 32'd1;
        if (gone_q[k] && l_ovf[k]) begin
          err_q[k] <= ERR_PC_OVERFLOW;
          epc_q[k] <= l_pc[k*AW +: AW];
        end
        if (ill_q[k]) begin
          err_q[k] <= ERR_ILLEGAL_INSN;
          epc_q[k] <= h_pc[k*AW +: AW];
        end
      end
    end else if (clear_i) begin
      for (k = 0; k < NC; k = k + 1) err_q[k] <= ERR_NONE;
    end
  end

  // Whether the next endi of a context is the last but one, compared a
  // cycle ahead: sdone_q changes only when an endi is counted, in the
  // cycle after its grant, and final_q is decided then too.  A context is
  // granted at most every other cycle (and its first endi comes cycles
  // after START), so in the cycle after an endi's grant near_q compares
  // sdone_q of the grant's cycle: its earlier endis counted, not it.  And
  // final_q is up to date at the next endi's grant.
  integer n;
  always @(posedge clk_i) begin
    for (n = 0; n < NC; n = n + 1) near_q[n] <= sdone_q[n] == last2_q;
  end

`ifdef FORMAL
  // The granted context is the one granted and active (with PICK_STAGES
  // = 2, decided a cycle before: it has not issued since, so it has not
  // stopped); the arbiter picks only among its requests, the candidates
  // (on the default build ready_q, of which gone masks gl_q: so the grant
  // is a candidate, as before the registered stages).
  always @(*) if (grant) assert (gone[g] && act[g]);
  always @(*) assert ((ipick & ~arb_req) == {NC{1'b0}});
`endif
endmodule
`default_nettype wire
