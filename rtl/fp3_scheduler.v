// fp3_scheduler -- the workload scheduler (paper §4, and the many schedulers
// sharing one arithmetic unit of §6.3): instruction memory, one context per
// object (PC, instruction queue, integration counter, status), decode,
// hazard check against the register file's busy flags, and an arbiter that
// issues one ready instruction per cycle from one context.  All contexts
// run the same program on their own register bank.
//
// This module is the composition of four parts, one per file, each a
// step of the front end ending in registers, so that no path runs from
// the instruction memory through the hazard check to the arbiter (the
// long path of a one-cycle design):
//
//   fp3_sched_fetch  fetch: the instruction memory (words decoded as the
//                    host writes them), every context's fetch PC (it
//                    follows endi's loop and a taken beq), and the
//                    round-robin fetch arbiter (one read per cycle).
//   fp3_sched_queue  ready: each context's two-entry instruction queue and
//                    its head's hazard check (legal, no RAW, no WAW; the
//                    scoreboard's ready step), from wait bits kept per
//                    queue entry, registered for the next cycle's pick.
//   fp3_sched_issue  issue: the round-robin issue arbiter among the ready
//                    heads, the pick of the granted head's fields and the
//                    issue to the register file and the arithmetic unit.
//   fp3_sched_loop   the integration loop (endi counts, the last one stops
//                    its context), run control (RUNNING, DONE, the active
//                    contexts), errors and counters.
//
// Formats shared by the parts: rtl/fp3_sched.vh.  Each part's header says
// what its PICK_STAGES / FETCH_STAGE branches (fp3_top's FMAX_PIPE) buy
// and cost.  Timing of the issue (from the grant): PICK_STAGES = 0: the
// granted instruction issues in the cycle of the grant, and a context
// issues at most every other cycle; PICK_STAGES = 2: the arbiter's
// decision, the grant and the picked fields are registered, it issues two
// cycles after the grant, and a context is granted at most every third
// cycle.  Two or more contexts keep the arithmetic unit busy every cycle.
//
// Parameters
//   NUM_CONTEXTS  contexts (objects in flight), >= 1; CW = clog2, >= 1
//   NUM_REGS      registers per context; IW = clog2(NUM_REGS) index width
//   IMEM_DEPTH    instruction memory entries; AW = clog2(IMEM_DEPTH)
//   HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV, HAS_SQRT, HAS_SIGN  units built
//                 (fp3_top): an instruction for a missing one is illegal
//                 (HAS_SIGN: abs, neg, min, max on the move path)
//   PICK_STAGES   0 or 2: cycles from the grant to the issue
//   FETCH_STAGE   0 or 1: the fetch grant registered, then the fetch PC
//                 selected and registered before the instruction memory,
//                 which is read over two cycles (fp3_ram READ_STAGES 2),
//                 and the word registered again after it: the word
//                 arrives four cycles after the grant instead of one
//   DRAIN         cycles from a write-back's announcement (ahead_*_i) to
//                 the write-back, >= 1
//   RUN_COPIES    copies of RUNNING (run_copy_o: fp3_sched_loop), >= 1
//   MOV_LONG      0: the move path's tag line is the shortest, 1 + PICK_STAGES
//                 cycles (its announcement is its pick); 1: it is as long
//                 as the add line's (fp3_top WB_PORTS = 1), and counts as
//                 one of the long lines (fp3_sched_queue MOV_LONG)
// Ports: see the groups below; counters are 64 bits, cleared by START.
// Program writes (imem_*) land in the memory a cycle later (FETCH_STAGE:
// two; registered and decoded first).  Register indices towards the
// register file are {context, register} (XW = CW + IW bits).
// Errors, per context (fp3_sched_loop): an illegal instruction at the head
// of its queue, or a PC running off the end of the memory, stop that
// context and record its faulting PC; a START with STEPS == 0 or CONTEXTS
// out of range is refused.
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
  parameter integer HAS_DIV      = 1,
  parameter integer HAS_SQRT     = 1,
  parameter integer HAS_SIGN     = 1,
  parameter integer PICK_STAGES  = 0,
  parameter integer FETCH_STAGE  = 0,
  parameter integer DRAIN        = 1,
  parameter integer RUN_COPIES   = 1,
  parameter integer MOV_LONG     = 0
) (
  input  wire                         clk_i,
  input  wire                         rst_i,
  // host: program load and run control
  input  wire                         imem_we_i,
  input  wire [AW-1:0]                imem_waddr_i,
  input  wire [63:0]                  imem_wdata_i,
  input  wire                         start_i,
  input  wire                         clear_i,
  // STEPS and CONTEXTS, decided as the host writes them (fp3_host), so
  // that no 32-bit compare sits between START and the run state
  input  wire                         steps_zero_i,  // STEPS == 0
  input  wire                         steps_one_i,   // STEPS == 1
  input  wire [31:0]                  steps_last2_i, // STEPS - 2
  input  wire                         contexts_bad_i, // CONTEXTS == 0 or > NUM_CONTEXTS
  input  wire [NUM_CONTEXTS-1:0]      contexts_run_i, // contexts a START runs: k < CONTEXTS
  input  wire [CW-1:0]                sel_ctx_i,     // context of the *_sel_o
  // status and counters
  output wire                         running_o,
  output wire [RUN_COPIES-1:0]        run_copy_o,    // RUNNING, one flip-flop each
  output wire                         done_o,
  output wire                         any_error_o,
  output wire [3:0]                   error_sel_o,
  output wire [31:0]                  fault_pc_sel_o,
  output wire [31:0]                  steps_done_sel_o,
  output wire [63:0]                  cycles_o,
  output wire [63:0]                  issued_o,
  output wire [63:0]                  stalls_o,
  // register file: busy flags; write-backs announced this cycle
  input  wire [(1<<(CW+IW))-1:0]      busy_i,
  input  wire [3:0]                   ahead_valid_i, // add, mul, move, div/sqrt ports
  input  wire [4*(CW+IW)-1:0]         ahead_idx_i,
  input  wire [3:0]                   early_valid_i, // ... those of the next cycle
  input  wire [4*(CW+IW)-1:0]         early_idx_i,
  input  wire [3:0]                   pre_valid_i,   // ... those of the cycle after
  input  wire [4*(CW+IW)-1:0]         pre_idx_i,     //     (early_*_i a cycle ahead)
  // ... two and three cycles ahead of early_*_i, as far as their tag
  // lines reach (fp3_wb_tag; used with PICK_STAGES = 2; the move port's
  // only with MOV_LONG)
  input  wire [3:0]                   pre2_valid_i,
  input  wire [4*(CW+IW)-1:0]         pre2_idx_i,
  input  wire [3:0]                   pre3_valid_i,
  input  wire [4*(CW+IW)-1:0]         pre3_idx_i,
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
  output wire [2:0]                   issue_unit_o,
  output wire                         issue_sub_o,
  output wire [2:0]                   issue_sop_o,   // sign group: {abs/neg/min/max, fp_sign op}
  output wire                         issue_imm_o,   // the move path takes the immediate
  output wire [31:0]                  imm_o,
  output wire                         endi_o,        // the issued instruction is an endi
  output wire                         beq_o,         // ... a beq
  // the instruction picked, which issues in the next cycle (PICK_STAGES =
  // 2; with 0, the one issuing now): it writes a register (add, mul,
  // move or div/sqrt: issue_o && issue_unit_o != UNIT_NONE then), which ({context,
  // register}: rd_o then), and its unit (issue_unit_o then)
  output wire                         pick_wr_o,
  output wire [CW+IW-1:0]             pick_rd_o,
  output wire [2:0]                   pick_unit_o
);
  localparam integer NC = NUM_CONTEXTS;
`include "fp3_sched.vh"

  // ---- between the parts (one-hot vectors: bit c for context c) -----------
  wire [NC-1:0]           act, act_next;   // contexts active now, next cycle
  wire [NC-1:0]           h_end;           // the head stops its context if granted
  wire [NC-1:0]           full_k, full_g;  // queue full next cycle: head kept / granted
  wire [NC-1:0]           gone, gone_q;    // the head granted now / last cycle (running)
  wire                    grant, grant_q;  // ... any
  wire [CW-1:0]           actx;            // the word arriving now: its context,
  wire [63:0]             aword;           // ... the word,
  wire [SCH_DW-1:0]       adec;            // ... its decoded bits,
  wire [AW-1:0]           apc;             // ... its address,
  wire [3*IW-1:0]         lk_fields;       // ... its fields for the flag lookup,
  wire [NC*3*IW-1:0]      cf;              // ... and for each context's compares
  wire [NC-1:0]           narr;            // the word arriving next cycle: its context
  wire [CW-1:0]           nctx;            // ... encoded
  wire [CW-1:0]           fctx, fr;        // the fetch's contexts (the lookup's copies)
  wire [NC-1:0]           ready;           // the heads found ready
  wire [NC-1:0]           hp;              // the queues' head slots
  wire [2*NC*SCH_FW-1:0]  fields;          // every slot's issue fields
  wire [NC-1:0]           holds, legal, h_halt, h_endi, h_ovf, l_endi, l_ovf;
  wire [NC*AW-1:0]        h_pc, l_pc;

  fp3_sched_fetch #(.NUM_CONTEXTS(NUM_CONTEXTS), .CW(CW), .NUM_REGS(NUM_REGS), .IW(IW),
                    .IMEM_DEPTH(IMEM_DEPTH), .AW(AW), .HAS_ADD(HAS_ADD), .HAS_SUB(HAS_SUB),
                    .HAS_MUL(HAS_MUL), .HAS_DIV(HAS_DIV), .HAS_SQRT(HAS_SQRT),
                    .HAS_SIGN(HAS_SIGN), .FETCH_STAGE(FETCH_STAGE)) u_fetch (
    .clk_i        (clk_i),
    .rst_i        (rst_i),
    .running_i    (running_o),
    .imem_we_i    (imem_we_i),
    .imem_waddr_i (imem_waddr_i),
    .imem_wdata_i (imem_wdata_i),
    .act_i        (act),
    .act_next_i   (act_next),
    .h_end_i      (h_end),
    .full_k_i     (full_k),
    .full_g_i     (full_g),
    .gone_i       (gone),
    .br_i         (br_i),
    .br_taken_i   (br_taken_i),
    .br_target_i  (br_target_i),
    .actx_o       (actx),
    .aword_o      (aword),
    .adec_o       (adec),
    .apc_o        (apc),
    .lk_fields_o  (lk_fields),
    .cf_o         (cf),
    .narr_o       (narr),
    .nctx_o       (nctx),
    .fctx_o       (fctx),
    .fr_o         (fr)
  );

  fp3_sched_queue #(.NUM_CONTEXTS(NUM_CONTEXTS), .CW(CW), .IW(IW), .AW(AW),
                    .PICK_STAGES(PICK_STAGES), .FETCH_STAGE(FETCH_STAGE),
                    .MOV_LONG(MOV_LONG)) u_queue (
    .clk_i         (clk_i),
    .rst_i         (rst_i),
    .running_i     (running_o),
    .act_i         (act),
    .gone_i        (gone),
    .gone_q_i      (gone_q),
    .actx_i        (actx),
    .aword_i       (aword),
    .adec_i        (adec),
    .apc_i         (apc),
    .lk_fields_i   (lk_fields),
    .cf_i          (cf),
    .narr_i        (narr),
    .nctx_i        (nctx),
    .fctx_i        (fctx),
    .fr_i          (fr),
    .busy_i        (busy_i),
    .ahead_valid_i (ahead_valid_i),
    .ahead_idx_i   (ahead_idx_i),
    .early_valid_i (early_valid_i),
    .early_idx_i   (early_idx_i),
    .pre_valid_i   (pre_valid_i),
    .pre_idx_i     (pre_idx_i),
    .pre2_valid_i  (pre2_valid_i),
    .pre2_idx_i    (pre2_idx_i),
    .pre3_valid_i  (pre3_valid_i),
    .pre3_idx_i    (pre3_idx_i),
    .issue_i       (issue_o),
    .issue_unit_i  (issue_unit_o),
    .rd_i          (rd_o),
    .ready_o       (ready),
    .hp_o          (hp),
    .fields_o      (fields),
    .holds_o       (holds),
    .legal_o       (legal),
    .h_halt_o      (h_halt),
    .h_endi_o      (h_endi),
    .h_ovf_o       (h_ovf),
    .h_pc_o        (h_pc),
    .l_endi_o      (l_endi),
    .l_ovf_o       (l_ovf),
    .l_pc_o        (l_pc),
    .full_k_o      (full_k),
    .full_g_o      (full_g)
  );

  fp3_sched_issue #(.NUM_CONTEXTS(NUM_CONTEXTS), .CW(CW), .IW(IW),
                    .PICK_STAGES(PICK_STAGES)) u_issue (
    .clk_i        (clk_i),
    .rst_i        (rst_i),
    .running_i    (running_o),
    .ready_i      (ready),
    .hp_i         (hp),
    .fields_i     (fields),
    .gone_o       (gone),
    .grant_o      (grant),
    .gone_q_o     (gone_q),
    .grant_q_o    (grant_q),
    .issue_o      (issue_o),
    .issue_ctx_o  (issue_ctx_o),
    .ra_o         (ra_o),
    .rb_o         (rb_o),
    .rd_o         (rd_o),
    .issue_unit_o (issue_unit_o),
    .issue_sub_o  (issue_sub_o),
    .issue_sop_o  (issue_sop_o),
    .issue_imm_o  (issue_imm_o),
    .imm_o        (imm_o),
    .endi_o       (endi_o),
    .beq_o        (beq_o),
    .pick_wr_o    (pick_wr_o),
    .pick_rd_o    (pick_rd_o),
    .pick_unit_o  (pick_unit_o)
  );

  fp3_sched_loop #(.NUM_CONTEXTS(NUM_CONTEXTS), .CW(CW), .AW(AW), .PICK_STAGES(PICK_STAGES),
                   .FETCH_STAGE(FETCH_STAGE), .DRAIN(DRAIN), .RUN_COPIES(RUN_COPIES)) u_loop (
    .clk_i            (clk_i),
    .rst_i            (rst_i),
    .start_i          (start_i),
    .clear_i          (clear_i),
    .steps_zero_i     (steps_zero_i),
    .steps_one_i      (steps_one_i),
    .steps_last2_i    (steps_last2_i),
    .contexts_bad_i   (contexts_bad_i),
    .contexts_run_i   (contexts_run_i),
    .sel_ctx_i        (sel_ctx_i),
    .idle_i           (idle_i),
    .gone_i           (gone),
    .grant_i          (grant),
    .gone_q_i         (gone_q),
    .grant_q_i        (grant_q),
    .issue_i          (issue_o),
    .holds_i          (holds),
    .legal_i          (legal),
    .h_halt_i         (h_halt),
    .h_endi_i         (h_endi),
    .h_ovf_i          (h_ovf),
    .h_pc_i           (h_pc),
    .l_endi_i         (l_endi),
    .l_ovf_i          (l_ovf),
    .l_pc_i           (l_pc),
    .running_o        (running_o),
    .done_o           (done_o),
    .run_copy_o       (run_copy_o),
    .any_error_o      (any_error_o),
    .error_sel_o      (error_sel_o),
    .fault_pc_sel_o   (fault_pc_sel_o),
    .steps_done_sel_o (steps_done_sel_o),
    .cycles_o         (cycles_o),
    .issued_o         (issued_o),
    .stalls_o         (stalls_o),
    .act_o            (act),
    .act_next_o       (act_next),
    .h_end_o          (h_end)
  );

`ifdef FORMAL
  // The granted context is the one granted and active (with PICK_STAGES
  // = 2, decided a cycle before: it has not issued since, so it has not
  // stopped).  (The issue arbiter's own check: fp3_sched_issue.)
  wire [CW-1:0] g = sch_encode(gone);
  always @(*) if (grant) assert (gone[g] && act[g]);
`endif
endmodule
`default_nettype wire
