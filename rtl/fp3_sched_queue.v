// fp3_sched_queue -- the scheduler's per-context instruction queues and
// ready step (paper §4: the workload scheduler's hazard check against the
// register file's busy flags, the scoreboard; per context, §6.3): for the
// instruction at the head of each context's queue, whether it may issue
// in the next cycle.
//
// Queues: two slots per context (slot e of context c is entry 2c + e),
// used as a ring with a head pointer (hp_q): a granted head only flips
// hp_q and clears its valid bit, and an arriving word is written into the
// free slot (the head's if the queue is empty, else the other), chosen a
// cycle ahead (wsel_q), which does not depend on the grant: no word moves
// and the grant drives few flip-flops.  A slot is valid once its word is
// written into it while its context is active, until it is granted.  A
// granted head stays in its slot for a cycle (the last head, l_*): its
// integration, PC overflow and issue fields are taken from there.
//
// Ready step: the head is ready when it is legal and no field it uses
// waits: sources (RAW) and destination (WAW); WAR needs no check (operands
// are read at issue, in order).  Registered (ready_q): valid for the
// issue arbiter's pick in the next cycle.  Nothing is decoded or looked up
// here: a word arrives decoded (fp3_sched_fetch), and each queue entry
// keeps three wait bits, one per register field (ra, rb, rd): the
// register's busy flag, kept up to date by the entry itself.  Only a
// context's own instructions make its registers busy, so a wait bit is
//   set    as the word joins: the flag (busy_i), or the destination of
//          the instruction in the issue register (PICK_STAGES = 2: its flag
//          is set at the end of this cycle), or of the head granted in this
//          cycle or (PICK_STAGES = 2) in the last one; later: when the head
//          ahead of it is granted and writes it (taken in the cycle after
//          the grant);
//   clear  when the register's write-back is announced (ahead_*_i; the
//          flag clears in the same cycle), compared in the cycle before
//          with the announcement to come (early_*_i) and registered.
// An announcement in this cycle counts as free already (the operand read
// takes the value from the bypass: fp3_regfile, fp3_wb_tag).
//
// An arriving word's wait bits are found over three cycles.  In cycle
// a - 1 (the word is being read: its context is known, nctx_i) its
// context's flags as they will be in cycle a, less those freed in cycle
// a, are decided and registered (bq_q).  In cycle a, when it arrives, the
// flags of its fields are looked up in bq_q (lk_q) and this cycle's other
// changes to them are compared (pending destinations: pd_q; its context's
// head's destination: hw_q, taken if that head is granted now), all
// registered; in cycle a + 1, when it is in its slot (fresh: fr_q), they
// are combined.  So no lookup, compare and queue update share a cycle,
// and the word meets the flags of its own context only.
//
// Generate branches (PICK_STAGES and FETCH_STAGE, set by fp3_top's
// FMAX_PIPE):
//   g_ready_reg / g_ready_now (per slot)  PICK_STAGES = 2 registers each
//       slot's readiness for both outcomes (rk_q: its context was not
//       granted; rg_q: it was) and chooses a cycle later by the grants of
//       the last two cycles (gr_q, gr2_q).  Buys: the loop from a grant
//       through the wait bits to ready_q holds a register more (with the
//       registered decision of fp3_sched_issue, two more).  Costs: a
//       context is granted at most every third cycle, and a readiness
//       registered a cycle early misses the wait bits cleared in that
//       cycle (an instruction may issue later, never earlier); the add and
//       mul lines give the lateness back by announcing two cycles earlier
//       (g_copy, below), a move's consumer and a word just arrived wait
//       two cycles more.
//   g_copy / g_shared (per context and announcement line)  PICK_STAGES =
//       2: the announcements of the next cycle as a per-context copy,
//       registered from pre3_*_i (add, mul, div/sqrt, and move with
//       MOV_LONG: two cycles earlier than early_*_i would show, for the
//       registered readiness above) and pre_*_i (the short move line), kept, so that the four tag lines' indices do not
//       each fan out to every context's compares across the die.
//       Without: early_*_i directly.  (g_no_lead: nothing to copy.)
//   g_bctx_copy / g_bctx_now  FETCH_STAGE = 1: the lookup's context as a
//       kept copy of the fetch context, placed by the flags' multiplexer.
//   g_mask_ahead / g_mask_now  FETCH_STAGE = 1 and PICK_STAGES = 2: the
//       arriving word's context's flags and the changes to them (set by
//       the issue register, cleared and announced by the tag lines) are
//       selected and registered a cycle earlier, from the picked
//       instruction and the announcements shown a cycle ahead, so that
//       bq_q meets no multiplexer of every context's flags (spread with
//       the register file) and no pick multiplexer.  Costs the registers
//       (4 x 2**IW flags and two context copies).
//
// Parameters
//   NUM_CONTEXTS  contexts, >= 1; CW = clog2, >= 1 (NC below)
//   IW            register index width (2**IW flags per context)
//   AW            instruction address width
//   PICK_STAGES   0 or 2; FETCH_STAGE 0 or 1 (above)
//   MOV_LONG      0: the move line is the shortest (1 + PICK_STAGES: its
//                 announcement is its pick); 1: it is as long as the add
//                 line (fp3_top WB_PORTS = 1) and counts among the long
//                 lines (LONG, below)
// Ports (one-hot vectors: bit c for context c; indices {context, register},
// XW = CW + IW bits)
//   clk_i, rst_i      clock (rising edge), synchronous reset
//   running_i         a run is in progress; the queues are held empty while not
//   act_i [NC]        contexts active (fp3_sched_loop)
//   gone_i [NC]       the head granted now (fp3_sched_issue)
//   gone_q_i [NC]     ... granted in the last cycle, while running
//   actx_i [CW], aword_i [64], adec_i [SCH_DW], apc_i [AW]  the word
//                     arriving now (fp3_sched_fetch)
//   lk_fields_i [3*IW], cf_i [NC*3*IW]  its {rd, rb, ra}: the lookup's copy,
//                     each context's copy
//   narr_i [NC], nctx_i [CW]  the context whose word arrives next cycle
//   fctx_i [CW], fr_i [CW]    the fetch's contexts (FETCH_STAGE copies)
//   busy_i [2**XW]    the register file's busy flags
//   ahead_valid_i [4], ahead_idx_i [4*XW]  write-backs announced now
//                     (add, mul, move, div/sqrt); early_* next cycle; pre_*
//                     the cycle after; pre2_*, pre3_* [4], [4*XW] (add,
//                     mul, div/sqrt) two and three cycles after early_*
//                     (fp3_wb_tag)
//   issue_i, issue_unit_i [3], rd_i [XW]  the instruction issuing now
//                     (fp3_sched_issue)
//   ready_o [NC]      the head was ready (ready_q, found last cycle)
//   hp_o [NC]         head slot of each queue
//   fields_o [2*NC*SCH_FW]  every slot's issue fields (rtl/fp3_sched.vh)
//   holds_o [NC]      the queue holds a word (valid head)
//   legal_o, h_halt_o, h_endi_o, h_ovf_o [NC], h_pc_o [NC*AW]  the head's
//                     decoded bits and PC
//   l_endi_o, l_ovf_o [NC], l_pc_o [NC*AW]  ... the last head's
//   full_k_o, full_g_o [NC]  both slots valid next cycle if the head is
//                     kept / granted now (fp3_sched_fetch's requests)
// Errors: none; an illegal head is reported (legal_o) and handled by
// fp3_sched_loop.
`default_nettype none
module fp3_sched_queue #(
  parameter integer NUM_CONTEXTS = 1,
  parameter integer CW           = 1,
  parameter integer IW           = 5,
  parameter integer AW           = 8,
  parameter integer PICK_STAGES  = 0,
  parameter integer FETCH_STAGE  = 0,
  parameter integer MOV_LONG     = 0
) (
  input  wire                         clk_i,
  input  wire                         rst_i,
  input  wire                         running_i,
  input  wire [NUM_CONTEXTS-1:0]      act_i,
  input  wire [NUM_CONTEXTS-1:0]      gone_i,
  input  wire [NUM_CONTEXTS-1:0]      gone_q_i,
  input  wire [CW-1:0]                actx_i,
  input  wire [63:0]                  aword_i,
  input  wire [15:0]                  adec_i,     // SCH_DW bits
  input  wire [AW-1:0]                apc_i,
  input  wire [3*IW-1:0]              lk_fields_i,
  input  wire [NUM_CONTEXTS*3*IW-1:0] cf_i,
  input  wire [NUM_CONTEXTS-1:0]      narr_i,
  input  wire [CW-1:0]                nctx_i,
  input  wire [CW-1:0]                fctx_i,
  input  wire [CW-1:0]                fr_i,
  input  wire [(1<<(CW+IW))-1:0]      busy_i,
  input  wire [3:0]                   ahead_valid_i,
  input  wire [4*(CW+IW)-1:0]         ahead_idx_i,
  input  wire [3:0]                   early_valid_i,
  input  wire [4*(CW+IW)-1:0]         early_idx_i,
  input  wire [3:0]                   pre_valid_i,
  input  wire [4*(CW+IW)-1:0]         pre_idx_i,
  input  wire [3:0]                   pre2_valid_i,
  input  wire [4*(CW+IW)-1:0]         pre2_idx_i,
  input  wire [3:0]                   pre3_valid_i,
  input  wire [4*(CW+IW)-1:0]         pre3_idx_i,
  input  wire                         issue_i,
  input  wire [2:0]                   issue_unit_i,
  input  wire [CW+IW-1:0]             rd_i,
  output wire [NUM_CONTEXTS-1:0]      ready_o,
  output wire [NUM_CONTEXTS-1:0]      hp_o,
  output wire [2*NUM_CONTEXTS*(3*IW+42)-1:0] fields_o,   // 2 * NC * SCH_FW
  output wire [NUM_CONTEXTS-1:0]      holds_o,
  output wire [NUM_CONTEXTS-1:0]      legal_o,
  output wire [NUM_CONTEXTS-1:0]      h_halt_o,
  output wire [NUM_CONTEXTS-1:0]      h_endi_o,
  output wire [NUM_CONTEXTS-1:0]      h_ovf_o,
  output wire [NUM_CONTEXTS*AW-1:0]   h_pc_o,
  output wire [NUM_CONTEXTS-1:0]      l_endi_o,
  output wire [NUM_CONTEXTS-1:0]      l_ovf_o,
  output wire [NUM_CONTEXTS*AW-1:0]   l_pc_o,
  output wire [NUM_CONTEXTS-1:0]      full_k_o,
  output wire [NUM_CONTEXTS-1:0]      full_g_o
);
`include "fp3_isa.vh"
  localparam integer NC = NUM_CONTEXTS;
  localparam integer XW = CW + IW;
`include "fp3_sched.vh"
  localparam integer DW = SCH_DW;
  localparam integer FW = SCH_FW;

  wire [NC-1:0] act = act_i;
  wire [NC-1:0] gone = gone_i;
  wire [NC-1:0] gone_q = gone_q_i;

  // ---- queue state ---------------------------------------------------------
  reg [NC-1:0]   hp_q;              // head slot
  reg [2*NC-1:0] v_q;               // slot valid
  reg [63:0]     w_q [0:2*NC-1];    // slot words
  reg [DW-1:0]   x_q [0:2*NC-1];    // ... decoded as they joined
  reg [2:0]      s_q [0:2*NC-1];    // ... their wait bits ({rd, rb, ra})
  reg [AW-1:0]   p_q [0:2*NC-1];    // ... and their PCs
  reg [NC-1:0]   ready_q;           // head was ready (computed last cycle)
  reg [2*NC-1:0] fr_q;              // the slot's word arrived last cycle
  reg [2*NC-1:0] wsel_q;            // the slot the arriving word is written into
  wire [2*NC-1:0] wsel_d;           // ... next
  wire [2*NC-1:0] wslot;            // ... and becomes valid (its context active)
  wire [2*NC-1:0] v_k, v_g;         // the slots' valid bits, next: head kept / granted now
  wire [NC-1:0] holds;              // ... at least one (the head)
  wire [NC-1:0] ready_d;
  wire [2*NC*3-1:0] s_d;            // the wait bits after this cycle ({rd, rb, ra})
  wire [2*NC*FW-1:0] fields;        // every slot's issue fields

  // Register x of this context (g_ctx) is among the four write-backs
  // announced in the next cycle, as this context's copy has them (ev:
  // valid and of this context, er: the registers).  A plain expression,
  // not a function: a continuous assignment is re-evaluated only when its
  // operands change, and a function's body is not an operand (Icarus).
`define FP3_FREED(x) \
  ((ev[0] && er[0*IW +: IW] == (x)) || (ev[1] && er[1*IW +: IW] == (x)) || \
   (ev[2] && er[2*IW +: IW] == (x)) || (ev[3] && er[3*IW +: IW] == (x)))

  // ---- the arriving word's flags (the lookup) -------------------------------
  wire [IW-1:0] a_ra = aword_i[ISA_RA_LSB +: IW];
  wire [IW-1:0] a_rb = aword_i[ISA_RB_LSB +: IW];
  wire [IW-1:0] a_rd = aword_i[ISA_RD_LSB +: IW];
  wire [IW-1:0] lk_ra, lk_rb, lk_rd;
  assign {lk_rd, lk_rb, lk_ra} = lk_fields_i;
  wire          iss_dst = PICK_STAGES != 0 && issue_i && issue_unit_i != UNIT_NONE;
  wire [NC-1:0] gr_q;             // the grant of the last cycle, a copy for the ready step
  reg  [NC-1:0] gr2_q;            // ... gr_q a cycle late: the grant two cycles ago
  always @(posedge clk_i) gr2_q <= gr_q;
  // The destination of the instruction in the issue register, among the
  // arriving word's fields.
  wire [2:0]    a_pend  = {3{iss_dst}} & {rd_i == {actx_i, a_rd}, rd_i == {actx_i, a_rb},
                                          rd_i == {actx_i, a_ra}};
  // The arriving word's flags, a cycle ahead.  busy_i is the register
  // file's flag register (fp3_regfile): a flag is set at the edge ending
  // the issue of an instruction that writes it (issue_i, issue_unit_i !=
  // UNIT_NONE, rd_i; the set wins) and cleared at the edge ending its
  // write-back's announcement (ahead_*_i), which early_*_i show a cycle
  // before.  So in cycle a - 1, for the context whose word arrives in
  // cycle a (nctx_i), flag r is in cycle a
  //   set(a - 1) or (busy(a - 1) and not announced(a - 1)),
  // and counts as free if it is announced in cycle a (early_*_i now).
  // The flags set and announced in cycle a - 1 (smask, cmask) are one-hot
  // masks over the context's registers.
  localparam integer RN = 1 << IW;  // flags per context
  // With the registered readiness (PICK_STAGES = 2) a wait bit may be
  // cleared by an announcement up to two cycles before it is made
  // (g_ready_reg): the lookup also takes off the add, mul and div/sqrt lines'
  // announcements of cycles a + 1 and a + 2 (pre_*_i and pre2_*_i now),
  // the ones that the word's compares in its slot, from cycle a + 1 on,
  // see no more.
  localparam [0:0] LEAD = PICK_STAGES == 2;
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
  // The flags of context x among four announcements (valid v, indices i:
  // the lines' order, add, mul, move, div/sqrt).
  function [RN-1:0] ann4;
    input [3:0]      v;
    input [4*XW-1:0] i;
    input [CW-1:0]   x;
    begin
      ann4 = flag1(v[0] && i[0*XW+IW +: CW] == x, i[0*XW +: IW]) |
             flag1(v[1] && i[1*XW+IW +: CW] == x, i[1*XW +: IW]) |
             flag1(v[2] && i[2*XW+IW +: CW] == x, i[2*XW +: IW]) |
             flag1(v[3] && i[3*XW+IW +: CW] == x, i[3*XW +: IW]);
    end
  endfunction
  // The long lines, which announce two cycles ahead of their pick
  // (add, mul, div/sqrt; the move line too with MOV_LONG), one bit per
  // line in ann4's order; the short move line's announcement is its pick.
  localparam [3:0] LONG = MOV_LONG != 0 ? 4'b1111 : 4'b1011;
  // The lookup's context (bctx): with FETCH_STAGE a kept copy of nctx_i,
  // which is fctx_i a cycle late, placed beside the flags' multiplexer
  // (unless g_mask_ahead selects the flags a cycle earlier) and the
  // announcements' compares it selects, not with nctx_i's other loads.
  wire [CW-1:0] bctx;
  generate
    if (FETCH_STAGE != 0) begin : g_bctx_copy
      fp3_keep #(.W(CW)) u_bctx (
        .clk_i (clk_i),
        .d_i   (fctx_i),
        .q_o   (bctx)
      );
      wire unused_nctx = &{1'b0, nctx_i};   // (bctx is its copy)
    end else begin : g_bctx_now
      assign bctx = nctx_i;
      wire unused_fctx = &{1'b0, fctx_i};   // (no copy)
    end
  endgenerate
  // The context's flags in cycle a - 1 (bflags) and the announcements of
  // cycle a (bann), for it: read now (busy_i, early_*_i), or, with
  // FETCH_STAGE and PICK_STAGES = 2, assembled from registers of cycle
  // a - 2 (g_mask_ahead, below).
  wire [RN-1:0] bflags, bann;
  always @(posedge clk_i)
    bq_q <= (smask | (bflags & ~cmask)) & ~bann
            & ~ann4(pre_valid_i & LONG & {4{LEAD}}, pre_idx_i, bctx)
            & ~ann4(pre2_valid_i & LONG & {4{LEAD}}, pre2_idx_i, bctx);
  // The lookup: the flags of the arriving word's fields, less the
  // announcements of this cycle (used by the context whose word it is).
  reg  [2:0]    lk_q;
  always @(posedge clk_i) lk_q <= {bq_q[lk_rd], bq_q[lk_rb], bq_q[lk_ra]};
  // PICK_STAGES = 2: the head granted in the last cycle, per context: it
  // writes a register (pg_w) and which (pg_rd) -- the instruction picked
  // now, which issues in the next cycle.
  wire [NC-1:0]    pg_w;
  wire [NC*IW-1:0] pg_rd;
  // The announcements the per-context copies (g_copy) register: the long
  // lines' three cycles ahead of early_*_i (pre3_*_i), the short move
  // line's a cycle ahead (pre_*_i: MOV_LATENCY = 1 + PICK_STAGES, and its
  // announcement is its pick; fp3_top).
  wire [3:0]      cp_valid = pre3_valid_i & LONG | pre_valid_i & ~LONG;
  wire [4*XW-1:0] cp_idx   = {pre3_idx_i[3*XW +: XW],
                              MOV_LONG != 0 ? pre3_idx_i[2*XW +: XW] : pre_idx_i[2*XW +: XW],
                              pre3_idx_i[0 +: 2*XW]};

  // ---- every context's queue and its head's readiness -----------------------
  genvar c, e, l;
  generate
    if (PICK_STAGES != 2) begin : g_no_lead
      // (No copies and no registered readiness.)
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
      // The next cycle's announcements for this context's compares (ev,
      // er): a copy per context with PICK_STAGES = 2 (g_copy), else
      // early_*_i.
      wire [3:0]      ev;
      wire [4*IW-1:0] er;
      for (l = 0; l < 4; l = l + 1) begin : g_line
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
      wire          wrh = xh[8:6] != UNIT_NONE;   // it writes rdh
      assign legal_o[c]  = xh[12];
      assign h_halt_o[c] = xh[1];
      assign h_endi_o[c] = xh[3];
      assign h_ovf_o[c]  = xh[0];
      assign h_pc_o[c*AW +: AW] = hp ? p_q[2*c+1] : p_q[2*c];
      // The last head: in the slot hp_q no longer points to (a word is
      // written only into a free slot).
      wire [DW-1:0] xl = hp ? x_q[2*c] : x_q[2*c+1];
      wire          unused_l = &{1'b0, xl};
      assign l_endi_o[c] = xl[3];
      assign l_ovf_o[c]  = xl[0];
      assign l_pc_o[c*AW +: AW] = hp ? p_q[2*c] : p_q[2*c+1];

      // The head, if granted now, making its destination busy for the
      // entries behind it: the one in the queue and an arriving word (the
      // compare with the head's destination, hw_q, is registered, and the
      // grant is taken in the next cycle from gone_q).  With PICK_STAGES =
      // 2, the head granted in the last cycle (gone_q; destination rdg_q,
      // if it writes one: wrg_q) sets its flag only when it issues, in the
      // next cycle: an arriving word waits for it too.  That and the
      // destination in the issue register (a_pend) are kept together, in
      // pd_q.
      reg  [2:0]    hw_q, pd_q;
      reg           wrg_q;
      reg  [IW-1:0] rdg_q;
      wire          pgv = PICK_STAGES == 2 && wrg_q && gone_q[c];
      // The arriving word's fields, this context's copy.
      wire [IW-1:0] c_ra = cf_i[c*3*IW +: IW];
      wire [IW-1:0] c_rb = cf_i[c*3*IW + IW +: IW];
      wire [IW-1:0] c_rd = cf_i[c*3*IW + 2*IW +: IW];
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
      // follows it.
      wire [1:0] srdy_k, srdy_g;   // the slots' words are ready, by outcome
      // The arriving word's fields among the announcements of the next
      // cycle, for whichever of this context's slots it is written into
      // (fresh there in the next cycle: fr_q).
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
        wire [2:0]    d_unit;
        wire [2:0]    d_sop;
        assign {d_sop, lgl, use_rb, use_ra, use_rd, d_unit, d_sub, d_li, d_endi, d_beq, d_halt,
                d_ovf} = x_q[I];
        wire          unused_x = &{1'b0, d_halt, d_ovf};
        assign fields[I*FW +: FW] = {d_sop, ra, rb, rd, d_unit, d_sub, d_li, imm, d_endi, d_beq};
        // This cycle's announcements of the fields the slot holds, compared
        // in the cycle before and registered; a word arriving in that cycle
        // has its own (fa_q), taken while it is fresh.  So no slot select
        // sits in front of the compares.
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
          // the last two cycles (with issue spacing 3, in one at most, so
          // by_q is that grant's either way); a fresh slot's is not known
          // yet (its word was not in the slot a cycle ago).
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
      (* keep *) wire rdy_k;
      (* keep *) wire rdy_g;
      assign rdy_k = act[c] && (hp ? v_q[2*c+1] && srdy_k[1] : v_q[2*c] && srdy_k[0]);
      assign rdy_g = act[c] && (hp ? v_q[2*c+1] && srdy_g[1] : v_q[2*c] && srdy_g[0]);
      assign ready_d[c] = gr_q[c] ? rdy_g : rdy_k;
    end
  endgenerate
`undef FP3_FREED

  // The grant of the last cycle for the ready step (the wait bits' and
  // ready_q's last choice), kept: placed beside it, not with the grant's
  // other loads.  It takes the grant ungated: while stopped ready_q is
  // clear, so there is no grant to gate.
  fp3_keep #(.W(NC)) u_gone_ready (
    .clk_i (clk_i),
    .d_i   (gone),
    .q_o   (gr_q)
  );

  // The flags of the arriving word's context set and announced in cycle
  // a - 1 (bq_q, above).  g_mask_ahead (FETCH_STAGE and PICK_STAGES = 2):
  // decided in cycle a - 2 and registered: the instruction that issues in
  // a - 1 is picked in a - 2 (its context's pg_w, pg_rd), the
  // announcements of a - 1 are shown in a - 2 (early_*_i), and the
  // context (nctx_i in a - 1) is fr_i in a - 2.  (If no run goes on in
  // a - 2, no word arrives in a.)  So are the context's flags themselves
  // (bflags) and the announcements of cycle a (bann): in cycle a - 2 its
  // flags are selected from busy_i and registered (bsel_q), with the flags
  // set and announced in a - 2 (sset_q: the issue register now; sclr_q:
  // ahead_*_i) and the add and mul lines' announcements of cycle a
  // (sann_q: pre_*_i in a - 2, which shows what early_*_i shows in a - 1).
  // The move line's is still early_*_i in a - 1: its pre_*_i is the pick's
  // multiplexer.
  generate
    if (FETCH_STAGE != 0 && PICK_STAGES == 2) begin : g_mask_ahead
      reg [RN-1:0] smask_q, cmask_q;
      // The fetch context's copy for these masks, kept (the fetch context
      // also goes with the fetch address to the memory's side).
      wire [CW-1:0] fcm_q;
      fp3_keep #(.W(CW)) u_fctx_copy (
        .clk_i (clk_i),
        .d_i   ((!rst_i && running_i) ? fr_i : fcm_q),
        .q_o   (fcm_q)
      );
      always @(posedge clk_i) begin
        smask_q <= flag1(!rst_i && running_i && pg_w[fcm_q], pg_rd[fcm_q*IW +: IW]);
        cmask_q <= ann4(early_valid_i, early_idx_i, fcm_q);
      end
      assign smask = smask_q;
      assign cmask = cmask_q;
      // The flags, two cycles ahead: the fetch context's copy for their
      // multiplexer (kept: placed by the flags, not by the masks' loads).
      wire [CW-1:0] fcb_q;
      fp3_keep #(.W(CW)) u_fctx_flags (
        .clk_i (clk_i),
        .d_i   ((!rst_i && running_i) ? fr_i : fcb_q),
        .q_o   (fcb_q)
      );
      reg [RN-1:0] bsel_q, sset_q, sclr_q, sann_q;
      always @(posedge clk_i) begin
        bsel_q <= busy_i[fcb_q*RN +: RN];
        sset_q <= flag1(issue_i && issue_unit_i != UNIT_NONE && rd_i[IW +: CW] == fcm_q,
                        rd_i[IW-1:0]);
        sclr_q <= ann4(ahead_valid_i, ahead_idx_i, fcm_q);
        sann_q <= ann4(pre_valid_i & LONG, pre_idx_i, fcm_q);
      end
      // The register file's update of the edge ending a - 2 (the set wins).
      assign bflags = sset_q | (bsel_q & ~sclr_q);
      assign bann   = sann_q | ann4(early_valid_i & ~LONG, early_idx_i, bctx);
    end else begin : g_mask_now
      assign smask = flag1(issue_i && issue_unit_i != UNIT_NONE && rd_i[IW +: CW] == nctx_i,
                           rd_i[IW-1:0]);
      assign cmask = ann4(ahead_valid_i, ahead_idx_i, nctx_i);
      assign bflags = busy_i[bctx*RN +: RN];
      assign bann   = ann4(early_valid_i, early_idx_i, bctx);
      wire unused_pg = &{1'b0, pg_w, pg_rd, fr_i};  // (the issue register, now)
    end
  endgenerate

  // ---- slots: which is written, which is valid ------------------------------
  // An arriving word is written into a free slot: the head's if the queue
  // is empty, else the other (a context fetches only with a slot free and
  // one word in flight, so at most one slot is taken then, and a lone
  // word is the head).  Which slot does not depend on a grant (a grant
  // empties a queue of one and moves the head to the other slot), so it
  // is chosen a cycle ahead, as the word is read, and registered (wsel_q):
  // the slot's word, decoded bits and PC are written on a flip-flop's
  // output, whether or not the context is still active (the slot is
  // free), and only its valid bit waits for that (wslot).  The queues'
  // next state is decided for either outcome of the issue step (v_k, v_g)
  // and chosen by the grant, so that one LUT follows the issue arbiter.
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_fill
      assign holds[c] = v_q[2*c] || v_q[2*c+1];
      for (e = 0; e < 2; e = e + 1) begin : g_free
        assign wslot[2*c+e] = wsel_q[2*c+e] && act[c];
        assign v_k[2*c+e]   = wslot[2*c+e] || v_q[2*c+e];
        assign v_g[2*c+e]   = wslot[2*c+e] || (v_q[2*c+e] && hp_q[c] != e[0]);
        assign wsel_d[2*c+e] = narr_i[c] && (hp_q[c] ^ holds[c]) == e[0];
      end
      assign full_k_o[c] = v_k[2*c] && v_k[2*c+1];
      assign full_g_o[c] = v_g[2*c] && v_g[2*c+1];
    end
  endgenerate

  integer k;
  // Slots' contents: the arriving word, in the slot chosen for it.
  always @(posedge clk_i) begin
    for (k = 0; k < 2 * NC; k = k + 1)
      if (wsel_q[k]) begin
        w_q[k] <= aword_i;
        x_q[k] <= adec_i;
        p_q[k] <= apc_i;
      end
  end
  always @(posedge clk_i) begin
    if (rst_i || !running_i) begin
      hp_q     <= {NC{1'b0}};
      v_q      <= {(2*NC){1'b0}};
      ready_q  <= {NC{1'b0}};
      fr_q     <= {(2*NC){1'b0}};
      wsel_q   <= {(2*NC){1'b0}};
    end else begin
      ready_q <= ready_d;
      fr_q    <= wslot;
      for (k = 0; k < 2 * NC; k = k + 1) s_q[k] <= s_d[k*3 +: 3];
      // The granted head leaves (the head pointer moves on), an arriving
      // word is valid in its slot (wslot); the slot of the word arriving
      // next is chosen.
      for (k = 0; k < 2 * NC; k = k + 1) v_q[k] <= gone[k/2] ? v_g[k] : v_k[k];
      wsel_q <= wsel_d;
      for (k = 0; k < NC; k = k + 1)
        if (gone[k]) hp_q[k] <= !hp_q[k];
    end
  end

  assign ready_o  = ready_q;
  assign hp_o     = hp_q;
  assign fields_o = fields;
  assign holds_o  = holds;
endmodule
`default_nettype wire
