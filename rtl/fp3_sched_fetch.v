// fp3_sched_fetch -- the scheduler's fetch step (paper §4, the workload
// scheduler's instruction fetch; one fetch port shared by the contexts of
// §6.3): the instruction memory and its host write port, every context's
// fetch PC, and the round-robin fetch arbiter that grants one memory read
// per cycle.
//
// Instruction memory: IMEM_DEPTH words of 64 bits (the ISA's instruction
// word, rtl/fp3_isa.vh), each stored beside its decoded bits (SCH_SW,
// rtl/fp3_sched.vh), decided as the host writes the word: from the word
// and its address (a program does not change while it runs), so that no
// decode sits in front of the memory or behind it.  A word is legal when
// its opcode is known and its unit built (HAS_ADD, HAS_SUB, HAS_MUL,
// HAS_DIV, HAS_SQRT, HAS_SIGN), each
// used register field names a register < NUM_REGS, each unused field is
// zero, an endi's target is inside the memory and a beq's target is
// inside it and ahead of the beq.  Entries never written read as zero:
// the nop, decoded.  A host write lands in the memory a cycle later
// (FETCH_STAGE: two), before the first read of a run that a START in the
// next cycle begins.
//
// Fetch: a context may fetch when it is active in the next cycle, has a
// free queue slot in the next cycle not counting the one its head may
// free if granted now (that would put the issue arbiter in front of the
// memory address), no read in flight, has not fetched the memory's last
// word (fend) and is not behind an unresolved beq (bwait).  Round robin
// among those (fp3_rr_arbiter), one read per cycle; the context granted
// in the last cycle is masked behind the arbiter's carry chain (it has a
// read in flight).  The fetch PC follows the words as they arrive: the
// next address, or an endi's loop target.  A resolved beq (br_i, two
// cycles after its issue) releases its context and, if taken, moves its
// fetch PC to the target (legal targets are inside the memory).  A word
// that arrives for a context no longer active is dropped (its slot is
// written but not made valid: fp3_sched_queue).
//
// Generate branches (FETCH_STAGE, set by fp3_top's FMAX_PIPE):
//   g_write_reg / g_write_now  FETCH_STAGE = 1 registers the host's write
//       once more before the decode: the host's data register meets only
//       flip-flops, not the decode.  Costs a cycle of write latency (no
//       run can read the word earlier anyway).
//   u_fgrant, u_next, u_arrive (fp_pipe DEPTH = FETCH_STAGE), u_imem
//       READ_STAGES = 1 + FETCH_STAGE, g_word_reg / g_word_now:
//       FETCH_STAGE = 1 registers the fetch grant, then the selected fetch
//       PC (in the memory's address register), reads the block RAM into
//       its output register and registers the word once more in the
//       fabric (fw_q): the word arrives four cycles after the grant
//       instead of one.  Buys: the arbiter, the PC multiplexer, the block
//       RAM's read and its long route into the fabric are each a path of
//       their own.  Costs: a context fetches at most every fifth cycle
//       (FP3_FMAX_PIPE_ISSUE_SPACING), a beq's outcome reaches the fetch
//       later.  g_word_reg also keeps copies of the word's register
//       fields, one for the queue's flag lookup (lk_fields_o) and one per
//       context (cf_o), each placed beside its loads (fw_q's fields to the
//       lookup's multiplexers and every context's compares was a critical
//       path); the branch without passes the word's fields through.
//
// Parameters
//   NUM_CONTEXTS  contexts, >= 1; CW = clog2, >= 1 (NC below)
//   NUM_REGS      registers per context; IW = clog2(NUM_REGS)
//   IMEM_DEPTH    instruction memory words; AW = clog2(IMEM_DEPTH)
//   HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV, HAS_SQRT, HAS_SIGN  units built:
//                 an instruction for a missing one is illegal (HAS_SIGN:
//                 abs, neg, min, max)
//   FETCH_STAGE   0 or 1 (above)
// Ports (one-hot vectors: bit c for context c)
//   clk_i, rst_i      clock (rising edge), synchronous reset
//   running_i         a run is in progress (fp3_sched_loop); the fetch
//                     state is held at its start values while not
//   imem_we_i, imem_waddr_i [AW], imem_wdata_i [64]  host program write
//   act_i [NC]        contexts active now (fp3_sched_loop)
//   act_next_i [NC]   ... in the next cycle
//   h_end_i [NC]      the context's head stops it if granted now
//   full_k_i [NC]     both queue slots valid in the next cycle if the head
//                     is kept (not granted now) (fp3_sched_queue)
//   full_g_i [NC]     ... if the head is granted now
//   gone_i [NC]       the head granted now (fp3_sched_issue)
//   br_i [NC], br_taken_i, br_target_i [AW]  a beq resolved (fp3_simd):
//                     its context, outcome and target
//   actx_o [CW], aword_o [64], adec_o [SCH_DW], apc_o [AW]  the word
//                     arriving now: its context, the word, its decoded bits
//                     (SCH_DW format, rtl/fp3_sched.vh) and its address
//   lk_fields_o [3*IW]  its {rd, rb, ra} fields, for the flag lookup
//   cf_o [NC*3*IW]    ... one copy per context, for its compares
//   narr_o [NC]       the context whose word arrives in the next cycle
//   nctx_o [CW]       ... encoded
//   fctx_o [CW]       the context of the read issued now (FETCH_STAGE: the
//                     one arriving two cycles later), for the lookup's copies
//   fr_o [CW]         the context whose fetch PC is read now
// Errors: none detected here; an illegal word is marked in its decoded bits
// (and faults its context at the head of its queue, fp3_sched_loop), a PC
// past the memory's end in the word's ovf bit.
`default_nettype none
module fp3_sched_fetch #(
  parameter integer NUM_CONTEXTS = 1,
  parameter integer CW           = 1,
  parameter integer NUM_REGS     = 32,
  parameter integer IW           = 5,
  parameter integer IMEM_DEPTH   = 256,
  parameter integer AW           = 8,
  parameter integer HAS_ADD      = 1,
  parameter integer HAS_SUB      = 1,
  parameter integer HAS_MUL      = 1,
  parameter integer HAS_DIV      = 1,
  parameter integer HAS_SQRT     = 1,
  parameter integer HAS_SIGN     = 1,
  parameter integer FETCH_STAGE  = 0
) (
  input  wire                    clk_i,
  input  wire                    rst_i,
  input  wire                    running_i,
  input  wire                    imem_we_i,
  input  wire [AW-1:0]           imem_waddr_i,
  input  wire [63:0]             imem_wdata_i,
  input  wire [NUM_CONTEXTS-1:0] act_i,
  input  wire [NUM_CONTEXTS-1:0] act_next_i,
  input  wire [NUM_CONTEXTS-1:0] h_end_i,
  input  wire [NUM_CONTEXTS-1:0] full_k_i,
  input  wire [NUM_CONTEXTS-1:0] full_g_i,
  input  wire [NUM_CONTEXTS-1:0] gone_i,
  input  wire [NUM_CONTEXTS-1:0] br_i,
  input  wire                    br_taken_i,
  input  wire [AW-1:0]           br_target_i,
  output wire [CW-1:0]           actx_o,
  output wire [63:0]             aword_o,
  output wire [15:0]             adec_o,   // SCH_DW bits
  output wire [AW-1:0]           apc_o,
  output wire [3*IW-1:0]         lk_fields_o,
  output wire [NUM_CONTEXTS*3*IW-1:0] cf_o,
  output wire [NUM_CONTEXTS-1:0] narr_o,
  output wire [CW-1:0]           nctx_o,
  output wire [CW-1:0]           fctx_o,
  output wire [CW-1:0]           fr_o
);
`include "fp3_isa.vh"
  localparam integer NC = NUM_CONTEXTS;
`include "fp3_sched.vh"
  localparam integer DW = SCH_DW;
  localparam integer SW = SCH_SW;

  wire [NC-1:0] act = act_i;

  // ---- instruction memory --------------------------------------------------
  // A block RAM: the address presented in cycle t is read at the edge
  // ending cycle t, the word is here in cycle t + 1 (FETCH_STAGE: read
  // over two cycles, fp3_ram READ_STAGES = 2: in cycle t + 2).  The host's
  // write is decoded and registered, and written a cycle later (a run
  // starts two cycles after a write at the earliest).  FETCH_STAGE: the
  // write is registered once more before the decode and lands a cycle
  // later still, before a run's first read: a START in the cycle after the
  // write starts the contexts a cycle after it, and the first fetch PC
  // reaches the memory a cycle after their first grant.
  wire [63:0]   imem_word;
  wire [SW-1:0] imem_sdec;
  reg  [AW-1:0] fpc_sel;    // the fetch address (fetch, below)
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

  // ---- decode, once, as a word is written ---------------------------------
  function reg_ok;  // a used field names a register, an unused one is zero
    input       used;
    input [7:0] r;
    begin
      // r < NUM_REGS as r's high bits zero when NUM_REGS is a power of
      // two: Yosys maps a compare with a constant to a carry chain, which
      // the host's program write would then have to pass.
      reg_ok = used ? ((r >> IW) == 8'd0 && (NUM_REGS == (1 << IW) || {24'd0, r} < NUM_REGS))
                    : (r == 8'd0);
    end
  endfunction
  // The stored bits (SW, rtl/fp3_sched.vh) are completed as the word joins
  // its queue with ovf: it would run off the end of the memory (not a halt
  // or an endi, which leave or jump, at the last address).
  wire [7:0]    w_opc   = dwd[ISA_OPC_LSB +: ISA_OPC_WIDTH];
  wire          w_endi  = w_opc == OP_ENDI;
  wire          w_beq   = w_opc == OP_BEQ;
  wire [7:0]    w_rd8   = dwd[ISA_RD_LSB +: ISA_REG_WIDTH];
  wire [7:0]    w_ra8   = dwd[ISA_RA_LSB +: ISA_REG_WIDTH];
  wire [7:0]    w_rb8   = dwd[ISA_RB_LSB +: ISA_REG_WIDTH];
  wire [31:0]   w_imm   = dwd[0 +: ISA_IMM_WIDTH];
  wire [7:0]    w_dec   = isa_decode(w_opc);   // {known, unit[2:0], uses: imm rb ra rd}
  // The issue path carries the decode's 3-bit unit (w_dec[6:4]); div and
  // sqrt share the div/sqrt unit, a sqrt marked by the sub bit.  The sign group
  // (abs, neg, min, max) runs on the move path: w_sop is {sign group,
  // fp_sign's op_i: 0 abs, 1 neg, 2 min, 3 max}, carried to the issue
  // beside the unit (issue_sop_o).
  wire          w_sign  = w_opc == OP_ABS || w_opc == OP_NEG || w_opc == OP_MIN ||
                          w_opc == OP_MAX;
  wire [2:0]    w_sop   = {w_sign, w_opc == OP_MIN || w_opc == OP_MAX,
                           w_opc == OP_NEG || w_opc == OP_MAX};
  wire          w_built = (w_dec[6:4] != UNIT_ADD || HAS_ADD != 0) &&
                          (w_opc != OP_SUB || HAS_SUB != 0) &&
                          (w_dec[6:4] != UNIT_MUL || HAS_MUL != 0) &&
                          (w_opc != OP_DIV || HAS_DIV != 0) &&
                          (w_opc != OP_SQRT || HAS_SQRT != 0) &&
                          (!w_sign || HAS_SIGN != 0);
  // w_imm < IMEM_DEPTH, without a carry chain when IMEM_DEPTH is 2**AW
  wire          w_in    = (w_imm >> AW) == 32'd0 &&
                          (IMEM_DEPTH == (1 << AW) || w_imm < IMEM_DEPTH);
  wire          w_legal = w_dec[7] && w_built && reg_ok(w_dec[0], w_rd8) &&
                          reg_ok(w_dec[1], w_ra8) && reg_ok(w_dec[2], w_rb8) &&
                          (w_dec[3] || w_imm == 32'd0) &&
                          (!w_endi || w_in) &&
                          (!w_beq || (w_in && w_imm[AW-1:0] > dwa));
  assign wsdec = {w_sop, !w_legal, w_dec[2], w_dec[1], w_dec[0], w_dec[6:4],
                  w_opc == OP_SUB || w_opc == OP_SQRT,
                  w_opc == OP_LI, w_endi, w_beq, w_opc == OP_HALT};

  // ---- the word in flight --------------------------------------------------
  // A read's context and PC follow the word: to the cycle before it
  // arrives (u_next), and to its arrival (u_arrive).  A context has one
  // word in flight, from its grant to its arrival.
  reg           fvalid_q;   // a fetched word arrives (FETCH_STAGE: two cycles later)
  reg  [CW-1:0] fctx_q;     // ... for this context
  reg  [AW-1:0] fpcq_q;     // ... from this address
  wire          avalid;     // a fetched word arrives now
  wire [CW-1:0] actx;       // ... for this context
  wire [63:0]   aword;
  wire [SW-1:0] asdec;      // ... its stored decoded bits
  wire [AW-1:0] apc;
  wire          a_atend;    // ... at the memory's last address (compared a cycle ahead)
  wire [NC-1:0] arriving;   // ... one-hot
  wire          a_endi  = asdec[2];
  wire          a_beq   = asdec[1];
  wire          a_halt  = asdec[0];
  wire [DW-1:0] adec    = {asdec[SW-1 -: 3], !asdec[SW-4], asdec[SW-5:0],
                           a_atend && !a_halt && !a_endi};
  wire          nvalid;     // the word arriving in the next cycle (FETCH_STAGE)
  wire [CW-1:0] nfctx;      // ... its context
  wire [AW-1:0] npc;        // ... its PC
  fp_pipe #(.WIDTH(CW + AW), .DEPTH(FETCH_STAGE)) u_next (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running_i),
    .valid_i (fvalid_q),
    .data_i  ({fctx_q, fpcq_q}),
    .valid_o (nvalid),
    .data_o  ({nfctx, npc})
  );
  wire          n_atend = {{(32-AW){1'b0}}, npc} == IMEM_DEPTH - 1;
  fp_pipe #(.WIDTH(CW + AW + 1), .DEPTH(FETCH_STAGE)) u_arrive (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running_i),
    .valid_i (nvalid),
    .data_i  ({nfctx, npc, n_atend}),
    .valid_o (avalid),
    .data_o  ({actx, apc, a_atend})
  );
  wire [IW-1:0] a_ra = aword[ISA_RA_LSB +: IW];
  wire [IW-1:0] a_rb = aword[ISA_RB_LSB +: IW];
  wire [IW-1:0] a_rd = aword[ISA_RD_LSB +: IW];
  genvar c;
  generate
    if (FETCH_STAGE != 0) begin : g_word_reg
      // The word registered in the fabric (fw_q), and copies of its
      // register fields for the queue's lookup and for each context's
      // compares, each kept and placed beside its own loads.
      reg [SW+63:0] fw_q;
      always @(posedge clk_i) fw_q <= {imem_sdec, imem_word};
      assign {asdec, aword} = fw_q;
      wire [3*IW-1:0] wf = {imem_word[ISA_RD_LSB +: IW], imem_word[ISA_RB_LSB +: IW],
                            imem_word[ISA_RA_LSB +: IW]};
      fp3_keep #(.W(3*IW)) u_lk_fields (
        .clk_i (clk_i),
        .d_i   (wf),
        .q_o   (lk_fields_o)
      );
      for (c = 0; c < NC; c = c + 1) begin : g_cf
        fp3_keep #(.W(3*IW)) u_ctx_fields (
          .clk_i (clk_i),
          .d_i   (wf),
          .q_o   (cf_o[c*3*IW +: 3*IW])
        );
      end
      wire unused_fields = &{1'b0, a_rd, a_rb, a_ra};   // (the copies are used)
    end else begin : g_word_now
      assign {asdec, aword} = {imem_sdec, imem_word};
      assign lk_fields_o = {a_rd, a_rb, a_ra};
      assign cf_o = {NC{a_rd, a_rb, a_ra}};
    end
  endgenerate
  assign arriving = sch_onehot(avalid, actx);

  // ---- fetch requests and the fetch arbiter --------------------------------
  // The grant of the last cycle is a register (fg_q), so nothing follows
  // the arbiter's grant but flip-flops: the words in flight are fg_q and
  // those granted before it (infl_q), and the rest of the request is
  // decided a cycle ahead (mfk_q, mfg_q) for either outcome of the issue
  // step (mf_k, mf_g, kept as nets in synthesis) and chosen in front of
  // the arbiter by a copy of the issue grant (gf_q), so that no logic
  // follows the issue arbiter here.  What else holds a context's fetch
  // (fend_q, bwait_q) is its own register, joined in front of the arbiter
  // too, so that a resolved beq and an arriving word are not in the
  // request's cone.  While stopped no context is active (a run ends with
  // none, START starts them), so act_next_i needs no gate with RUNNING.
  wire          fread;      // a fetch granted (FETCH_STAGE: in the last cycle) for fr1
  wire [NC-1:0] fr1;
  reg  [NC-1:0] fg_q;       // granted a fetch in the last cycle
  reg  [NC-1:0] infl_q;     // granted before that, the word not yet in its queue
  reg  [NC-1:0] mfk_q, mfg_q; // may fetch, but for fg_q, fend_q and bwait_q: if
                            // the head was kept / granted in the last cycle
  wire [NC-1:0] gf_q;       // ... which: the last issue grant, a copy (below)
  reg  [NC-1:0] fend_q;     // fetched the last word of the memory
  reg  [NC-1:0] bwait_q;    // fetched a beq, not yet resolved
  reg  [AW-1:0] fpc_q [0:NC-1];  // next fetch address
  wire [NC-1:0] infl_n = (infl_q | fg_q) & ~arriving;
  wire [NC-1:0] mfk_n, mfg_n;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_mf
      (* keep *) wire mf_k;
      (* keep *) wire mf_g;
      assign mf_k = act_next_i[c] && !infl_n[c] && !full_k_i[c];
      assign mf_g = act_next_i[c] && !infl_n[c] && !full_g_i[c] && !h_end_i[c];
      assign mfk_n[c] = mf_k;
      assign mfg_n[c] = mf_g;
    end
  endgenerate
  always @(posedge clk_i) begin
    mfk_q <= mfk_n;
    mfg_q <= mfg_n;
  end
  // The issue grant as it is (not gated with RUNNING: the choice is the
  // one made in the last cycle), kept: placed by the fetch arbiter.
  fp3_keep #(.W(NC)) u_gone_fetch (
    .clk_i (clk_i),
    .d_i   (gone_i),
    .q_o   (gf_q)
  );
  // The fetch arbiter: round robin, with the last fetch grant (fg_q, which
  // may not fetch) masked only behind the carry chain.  The pick from
  // {freq, freq} is a context after the last grant g, else the first
  // context with a request.  Only the latter can be g itself, when no
  // other context requests (none is after g, and none before g, or it
  // would be the first): so masking g after the pick leaves no grant, as
  // it should.
  wire [NC-1:0] freq  = (gf_q & mfg_q | ~gf_q & mfk_q) & ~fend_q & ~bwait_q;   // the requests
  wire          fetch = (|(freq & ~fg_q)) && running_i;
  wire [NC-1:0] fpick, fgnt;
  fp3_rr_arbiter #(.N(NC)) u_fetch_arb (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running_i),
    .req_i   (freq),
    .pick_o  (fpick),
    .take_i  (fetch),
    .taken_i (fgnt)
  );
  assign fgnt = fpick & ~fg_q;
  fp_pipe #(.WIDTH(NC), .DEPTH(FETCH_STAGE)) u_fgrant (
    .clk_i   (clk_i),
    .rst_i   (rst_i || !running_i),
    .valid_i (fetch),
    .data_i  (fgnt),
    .valid_o (fread),
    .data_o  (fr1)
  );
  // The granted context's fetch PC, selected by the one-hot grant (fr1):
  // the memory's address (FETCH_STAGE: the memory registers it, a copy
  // per 4-bit lane of the word, and reads in the next cycle; fpcq_q, the
  // same address, goes with the word).
  wire [NC*AW-1:0] fpcs;    // every context's fetch PC
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_fpcs
      assign fpcs[c*AW +: AW] = fpc_q[c];
    end
  endgenerate
  integer q;
  always @(*) begin
    fpc_sel = {AW{1'b0}};
    for (q = 0; q < NC; q = q + 1) fpc_sel = fpc_sel | ({AW{fr1[q]}} & fpcs[q*AW +: AW]);
  end
  wire [CW-1:0] fr = sch_encode(fr1);
  // The word arriving in the next cycle (u_arrive's input).
  assign narr_o = FETCH_STAGE != 0 ? sch_onehot(nvalid, nfctx) : sch_onehot(fread, fr);
  assign nctx_o = FETCH_STAGE != 0 ? nfctx : fr;

  // ---- the fetch PC and what holds a context's fetch ------------------------
  // The arriving word decides where its context fetches next.
  wire [AW-1:0] a_next  = a_endi ? aword[AW-1:0] : apc + {{(AW-1){1'b0}}, 1'b1};
  // A context stops fetching when it has fetched the memory's last word
  // (fend) or a beq (bwait), as its word arrives; a resolved beq releases
  // it (its word arrived at least three cycles ago, so no arriving word
  // competes), and a taken one moves it to its target.
  wire [NC-1:0] fend_d, bwait_d;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_fflags
      wire arr = arriving[c] && act[c];
      wire br  = br_i[c];
      assign fend_d[c]  = (rst_i || !running_i)  ? 1'b0 :
                          (br && br_taken_i)      ? 1'b0 :
                          (arr && !a_endi && a_atend) ? 1'b1 : fend_q[c];
      assign bwait_d[c] = (rst_i || !running_i)  ? 1'b0 :
                          br                      ? 1'b0 :
                          (arr && a_beq)          ? 1'b1 : bwait_q[c];
    end
  endgenerate
  integer k;
  always @(posedge clk_i) begin
    fend_q  <= fend_d;
    bwait_q <= bwait_d;
  end
  always @(posedge clk_i) begin
    if (rst_i || !running_i) begin
      fg_q     <= {NC{1'b0}};
      infl_q   <= {NC{1'b0}};
      fvalid_q <= 1'b0;
      for (k = 0; k < NC; k = k + 1) fpc_q[k] <= {AW{1'b0}};
    end else begin
      for (k = 0; k < NC; k = k + 1) begin
        // The fetch PC: after the arriving word, or a taken beq's target.
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
    end
  end

  assign actx_o  = actx;
  assign aword_o = aword;
  assign adec_o  = adec;
  assign apc_o   = apc;
  assign fctx_o  = fctx_q;
  assign fr_o    = fr;
endmodule
`default_nettype wire
