// fp3_sched_loop -- the scheduler's integration loop, run control and
// status (paper §4: the workload scheduler counts the integrations of its
// object and stops it after the last; one set per context, §6.3): which
// contexts are active, RUNNING and DONE, the integrations done, the
// errors, and the cycle, issue and stall counters.
//
// A program is a prologue (run once) and a loop body ending in `endi L`.
// Each endi closes one integration of its context: if it was the last of
// the STEPS requested (final_q), the context stops issuing; otherwise
// its fetch follows the loop (fp3_sched_fetch).  A START with STEPS == 0
// or CONTEXTS out of range (0 or > NUM_CONTEXTS) is refused: every
// context's error is ERR_BAD_STEPS or ERR_BAD_CONTEXTS, DONE a cycle
// later.  Else RUNNING is set and contexts 0 .. CONTEXTS - 1 start.
// A context stops at its halt or last endi (granted), or faults: an
// illegal head (ERR_ILLEGAL_INSN; unknown opcode, a nonzero unused field,
// a register >= NUM_REGS, an endi target outside the memory, a beq target
// not ahead of it or outside the memory: decided as the host wrote the
// word) or a granted head that would run off the end of the memory
// (ERR_PC_OVERFLOW); its faulting PC is recorded (error codes:
// rtl/fp3_isa.vh).  A run ends (RUNNING clear, DONE set) when no context
// is active and no result is in flight: nothing issuing or picked, and
// DRAIN cycles passed without a busy flag or an issue.
//
// State in three groups, so that the START decision drives few
// flip-flops:
//   run control  RUNNING, DONE, the active contexts and what the first
//                cycle of a run needs: decided in the START cycle;
//   run state    queues, fetch, arbiters (the other fp3_sched_* modules):
//                held at their start values while no run is in progress;
//   results      counters, integrations done, errors (the host reads them
//                after a run): cleared in the run's first cycle (start_q),
//                in which nothing can have issued yet, or set a cycle after
//                a refused START (bad_q).
// What a grant implies here (a stop, an endi's count, a PC overflow) is
// registered or counted a cycle after the grant, so that the issue
// arbiter drives no counter, error register or active-context next state.
//
// Generate-time choices (FETCH_STAGE and PICK_STAGES, set by fp3_top's
// FMAX_PIPE; expressions, no generate blocks):
//   FETCH_STAGE = 1 starts the contexts a cycle after START, from its
//       register (start_q; RUNNING is set at START as without), so that
//       the host port's address decode meets the run control's few
//       flip-flops only, not the active contexts' and the fetch requests'
//       next state.  Costs a cycle per run (FP3_FMAX_PIPE_START_STAGES).
//   PICK_STAGES = 2: a granted instruction not yet issued (grant_q) also
//       keeps the run going.
//
// Parameters
//   NUM_CONTEXTS  contexts, >= 1; CW = clog2, >= 1 (NC below)
//   AW            instruction address width (faulting PCs)
//   PICK_STAGES   0 or 2; FETCH_STAGE 0 or 1 (above)
//   DRAIN         cycles from a write-back's announcement to the write-back, >= 1
//   RUN_COPIES    copies of RUNNING in run_copy_o, >= 1
// Ports (one-hot vectors: bit c for context c)
//   clk_i, rst_i      clock (rising edge), synchronous reset
//   start_i, clear_i  host: START, CLEAR (clears the errors while stopped)
//   steps_zero_i, steps_one_i, steps_last2_i [32]  STEPS == 0, == 1, STEPS - 2
//   contexts_bad_i    CONTEXTS == 0 or > NUM_CONTEXTS
//   contexts_run_i [NC]  the contexts a START runs
//   sel_ctx_i [CW]    context of the *_sel_o
//   idle_i            no busy flag in the last cycle (fp3_regfile)
//   gone_i [NC], grant_i  the head granted now (fp3_sched_issue)
//   gone_q_i [NC], grant_q_i  ... in the last cycle, while running
//   issue_i           an instruction issues now
//   holds_i, legal_i, h_halt_i, h_endi_i, h_ovf_i [NC], h_pc_i [NC*AW]
//                     the queues' heads (fp3_sched_queue): present, legal,
//                     halt, endi, would run off the memory, PC
//   l_endi_i, l_ovf_i [NC], l_pc_i [NC*AW]  the last heads' (granted in the
//                     last cycle)
//   running_o, done_o RUNNING, DONE
//   run_copy_o [RUN_COPIES]  RUNNING again, bit for bit, from flip-flops
//                     of their own (fp3_keep): one per lane's register
//                     file, whose read address chooses the host's index
//                     while stopped.  RUNNING alone drove every lane's
//                     address multiplexers, across the die (the clock-rate
//                     build's critical path); each copy is placed by its
//                     lane.  Cost: RUN_COPIES flip-flops.
//   any_error_o       some context's error is not ERR_NONE
//   error_sel_o [4], fault_pc_sel_o [32], steps_done_sel_o [32]  context
//                     sel_ctx_i's error, faulting PC, integrations done
//   cycles_o, issued_o, stalls_o [64]  cycles of the run, instructions
//                     issued, cycles without issue while an active context
//                     held an instruction; cleared by START
//   act_o [NC]        contexts active now
//   act_next_o [NC]   ... in the next cycle
//   h_end_o [NC]      the head stops its context if granted (halt, last
//                     endi, PC overflow), while running
`default_nettype none
module fp3_sched_loop #(
  parameter integer NUM_CONTEXTS = 1,
  parameter integer CW           = 1,
  parameter integer AW           = 8,
  parameter integer PICK_STAGES  = 0,
  parameter integer FETCH_STAGE  = 0,
  parameter integer DRAIN        = 1,
  parameter integer RUN_COPIES   = 1
) (
  input  wire                       clk_i,
  input  wire                       rst_i,
  input  wire                       start_i,
  input  wire                       clear_i,
  input  wire                       steps_zero_i,
  input  wire                       steps_one_i,
  input  wire [31:0]                steps_last2_i,
  input  wire                       contexts_bad_i,
  input  wire [NUM_CONTEXTS-1:0]    contexts_run_i,
  input  wire [CW-1:0]              sel_ctx_i,
  input  wire                       idle_i,
  input  wire [NUM_CONTEXTS-1:0]    gone_i,
  input  wire                       grant_i,
  input  wire [NUM_CONTEXTS-1:0]    gone_q_i,
  input  wire                       grant_q_i,
  input  wire                       issue_i,
  input  wire [NUM_CONTEXTS-1:0]    holds_i,
  input  wire [NUM_CONTEXTS-1:0]    legal_i,
  input  wire [NUM_CONTEXTS-1:0]    h_halt_i,
  input  wire [NUM_CONTEXTS-1:0]    h_endi_i,
  input  wire [NUM_CONTEXTS-1:0]    h_ovf_i,
  input  wire [NUM_CONTEXTS*AW-1:0] h_pc_i,
  input  wire [NUM_CONTEXTS-1:0]    l_endi_i,
  input  wire [NUM_CONTEXTS-1:0]    l_ovf_i,
  input  wire [NUM_CONTEXTS*AW-1:0] l_pc_i,
  output reg                        running_o,
  output reg                        done_o,
  output wire [RUN_COPIES-1:0]      run_copy_o,
  output wire                       any_error_o,
  output wire [3:0]                 error_sel_o,
  output wire [31:0]                fault_pc_sel_o,
  output wire [31:0]                steps_done_sel_o,
  output reg  [63:0]                cycles_o,
  output reg  [63:0]                issued_o,
  output reg  [63:0]                stalls_o,
  output wire [NUM_CONTEXTS-1:0]    act_o,
  output wire [NUM_CONTEXTS-1:0]    act_next_o,
  output wire [NUM_CONTEXTS-1:0]    h_end_o
);
`include "fp3_isa.vh"
  localparam integer NC = NUM_CONTEXTS;
  localparam [7:0]   LULL8 = DRAIN[7:0] - 8'd1;  // (lull_q, below)

  wire [NC-1:0] gone    = gone_i;
  wire [NC-1:0] gone_q  = gone_q_i;
  wire          grant   = grant_i;
  wire          grant_q = grant_q_i;
  wire          two     = PICK_STAGES == 2;

  // ---- per-context state ---------------------------------------------------
  reg [NC-1:0] active_q;            // fetching and issuing, but for stop_q (act)
  reg [NC-1:0] stop_q;              // the head granted in the last cycle stopped its context
  wire [NC-1:0] act;                // active: active_q & ~stop_q
  reg [31:0]   sdone_q[0:NC-1];     // integrations completed
  reg [NC-1:0] final_q;             // the next endi is the last of the run
  reg [3:0]    err_q  [0:NC-1];
  reg [AW-1:0] epc_q  [0:NC-1];     // faulting PC
  // ---- shared state --------------------------------------------------------
  reg [31:0]   last2_q;             // STEPS - 2: sdone_q before the last endi but one
  reg [NC-1:0] near_q;              // sdone_q == last2_q (a cycle old)
  reg [7:0]    lull_q;              // cycles without busy flag or issue, to DRAIN - 1, a cycle late
  reg          lull_full_q;         // lull_q == DRAIN - 1, registered with it
  reg          iss_q;               // issue_i a cycle late (as idle_i is)

  wire start_ok = start_i && !running_o && !steps_zero_i && !contexts_bad_i;

  // ---- selected-context status ---------------------------------------------
  wire [NC-1:0] err_any;
  genvar c;
  generate
    for (c = 0; c < NC; c = c + 1) begin : g_err
      assign err_any[c] = err_q[c] != ERR_NONE;
    end
  endgenerate
  assign any_error_o      = |err_any;
  assign error_sel_o      = err_q[sel_ctx_i];
  assign fault_pc_sel_o   = {{(32-AW){1'b0}}, epc_q[sel_ctx_i]};
  assign steps_done_sel_o = sdone_q[sel_ctx_i];

  // ---- run control ---------------------------------------------------------
  wire          bad_start = start_i && !running_o && !start_ok;
  wire [NC-1:0] illegal   = act & holds_i & ~legal_i;
  reg           start_q, bad_q;  // a START taken / refused in the last cycle
  reg  [3:0]    bad_err_q;       // ... why it was refused
  // start_q's copy for the run's end (RUNNING's and DONE's next state, the
  // quiet-cycle count lull_q), kept: placed beside them, not among
  // start_q's few hundred other loads (the run's first cycle clears every
  // counter).
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
  wire run_end = act == {NC{1'b0}} && !issue_i && !(two && grant_q) && !start_e &&
                 idle_i && !iss_q && lull_full_q;
  // RUNNING's next state: the flag and its copies are all registered from
  // this one expression, so they agree bit for bit.
  wire running_d = !rst_i && (running_o ? !run_end : start_ok);
  always @(posedge clk_i) running_o <= running_d;
  genvar rc;
  generate
    for (rc = 0; rc < RUN_COPIES; rc = rc + 1) begin : g_run_copy
      fp3_keep #(.W(1)) u_run_copy (
        .clk_i (clk_i),
        .d_i   (running_d),
        .q_o   (run_copy_o[rc])
      );
    end
  endgenerate
  integer k;
  always @(posedge clk_i) begin
    if (rst_i) begin
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
          done_o    <= 1'b0;
        end else if (start_i || clear_i) begin
          done_o <= 1'b0;        // a refused START: DONE in the next cycle
        end else if (bad_q) begin
          done_o <= 1'b1;
        end
      end else begin
        for (k = 0; k < NC; k = k + 1) begin
          if (gone_q[k] && l_endi_i[k]) final_q[k] <= near_q[k];
        end
        if (run_end) done_o <= 1'b1;
      end
    end
  end
  // lull_q(t + 1) counts the quiet cycles before cycle t (see run_end),
  // none before the run's first cycle.  Whether it is full is registered
  // beside it (lull_full_q), so that the end-of-run test compares no count.
  always @(posedge clk_i) begin
    if (rst_i || !running_o) begin
      lull_q      <= 8'd0;
      lull_full_q <= LULL8 == 8'd0;
    end else if (start_e || !idle_i || iss_q) begin
      lull_q      <= 8'd0;
      lull_full_q <= LULL8 == 8'd0;
    end else if (!lull_full_q) begin
      lull_q      <= lull_q + 8'd1;
      lull_full_q <= lull_q == LULL8 - 8'd1;
    end
  end

  // ---- the active contexts -------------------------------------------------
  // Started by START, stopped by their halt or last endi, a PC overflow or
  // an illegal head.  A head granted in cycle t that stops its context is
  // registered (stop_q) and taken off act in cycle t + 1, and off
  // active_q in t + 2: so the grant drives one flip-flop, not the active
  // contexts' next state.  While stopped no context is active (a run ends
  // with none, START starts them), so held_d is not gated with RUNNING.
  assign act = active_q & ~stop_q;
  // START (from the host's write) is the last multiplexer in front of the
  // registers: held_d is their next state without it.
  wire          start_now = (FETCH_STAGE != 0 ? start_q && running_o : start_ok) && !rst_i;
  wire [NC-1:0] held_d    = rst_i ? {NC{1'b0}} : act & ~illegal;
  wire [NC-1:0] active_d  = start_now ? contexts_run_i : held_d;
  // The head stops its context if granted (stop_d): a halt, the run's
  // last endi, or a PC overflow.
  wire [NC-1:0] h_stop    = h_halt_i | (h_endi_i & final_q);
  wire [NC-1:0] h_end     = (h_stop | h_ovf_i) & {NC{running_o && !rst_i}};
  wire [NC-1:0] stop_d    = gone & h_end;
  always @(posedge clk_i) begin
    active_q <= active_d;
    stop_q   <= stop_d;
  end

  // ---- results -------------------------------------------------------------
  // Issues and stalls are counted a cycle late (grant_q, stall_q), so
  // that the grant drives no counter: the run goes on for a cycle after
  // either (a context was active, with work), and in its first cycle, in
  // which the results are cleared, there was none in the one before.
  reg stall_q;              // a stall in the last cycle
  // An illegal head is recorded a cycle later too (ill_q), so that the
  // heads' decode drives no error register (which sits by the host's
  // read, across the die).  Its context left the active set at once
  // (held_d), so its head stays in its slot (h_pc_i) and the run goes on
  // for that cycle.
  reg [NC-1:0] ill_q;
  always @(posedge clk_i) begin
    ill_q   <= illegal & {NC{running_o}};
    stall_q <= running_o && !grant && |(act & holds_i);
    iss_q   <= issue_i;
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
        if (gone_q[k] && l_endi_i[k]) sdone_q[k] <= sdone_q[k] + 32'd1;
        if (gone_q[k] && l_ovf_i[k]) begin
          err_q[k] <= ERR_PC_OVERFLOW;
          epc_q[k] <= l_pc_i[k*AW +: AW];
        end
        if (ill_q[k]) begin
          err_q[k] <= ERR_ILLEGAL_INSN;
          epc_q[k] <= h_pc_i[k*AW +: AW];
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

  assign act_o      = act;
  assign act_next_o = active_d;
  assign h_end_o    = h_end;
endmodule
`default_nettype wire
