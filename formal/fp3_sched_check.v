// fp3_sched_check -- scoreboard and issue properties of the scheduler
// (rtl/fp3_scheduler.v and its fp3_sched_* parts) as it runs inside
// fp3_top, against a reference model of its own: the program as the host
// wrote it, a program counter per context, and, per register, the cycles
// until the last write-back claimed for it.  fp3_top instantiates it under
// `ifdef FP3_SCHED_CHECK (formal/sched.sby), so that the write-back
// announcements, the busy flags and the bypass are the processor's own:
// the tag lines (fp3_wb_tag), the register file (fp3_regfile) and the
// pick stages of FMAX_PIPE.  The FP cores (fp3_arith) are cut out by the
// .sby script: their results are free values, so the branches' outcomes
// (a compare of register values) are free too.
//
// Environment (assumptions): reset in the first cycle only (a write to the
// instruction memory still in its write pipeline when a later reset came
// would be lost, which the model's copy does not follow); the host's inputs
// are free, except that a START comes only once every word of the
// instruction memory has been written (so that the model's copy of the
// program is the memory's).  The program, STEPS, CONTEXTS, CTX, the
// register window and the order of the host's writes are otherwise any.
//
// Properties (an operation issued in cycle t by unit U, one of the four
// write-back ports add, mul, move and div/sqrt, is written back in cycle
// W = t + READ + L(U), fp3_top "Pipeline"; rem(x) is W - now for the last
// write claimed for register x, 0 when none is pending):
//   order   an issue belongs to a running context of the run (k <
//           CONTEXTS), whose beq has resolved and whose last endi has not
//           issued; it is the word at that context's program counter
//           (opcode's unit, endi, beq, the used register fields, li's
//           immediate), a known opcode of a built unit (div and sqrt
//           only with HAS_DIV, HAS_SQRT); the counter then
//           moves as the ISA says (next word; endi: to its immediate; beq:
//           wait for the outcome, then to its immediate or the next word)
//   RAW     a source register of an issue has rem <= READ - 1: its value
//           is written back by the last operand-read stage (from the
//           register file's bypass when rem > 0, or in the default build
//           the write-back of the issue cycle itself)
//   WAW     a destination's new write-back comes after its pending one
//           (rem < READ + L): register writes land in program order
//   busy    the busy flag of every register is set exactly while its last
//           write is claimed and not yet announced: rem >= AHEAD, from the
//           cycle after the issue to the cycle of the announcement AHEAD
//           cycles before the write-back (with FLAGS_AHEAD, FMAX_PIPE, the
//           register file takes the set from the pick and the clear from
//           the early announcement, a cycle ahead, and registers both: the
//           same cycles)
//   wb      the write-back port of the claiming unit writes the register
//           in cycle W
//   drain   no write-back is pending while no run is in progress
//   endi    each context's STEPS_DONE (the one CTX selects) equals the
//           number of its endi issued in the run: an endi counts once
//   issued  the ISSUED counter counts each issue once
// Covers: a stall, an operand taken the cycle of its write-back or from
// the bypass, two contexts issuing in consecutive cycles, a second
// integration step, a taken beq, a run that ends, a div/sqrt written
// back, an operand taken from a div/sqrt the cycle of its write-back or
// from the bypass.
//
// Parameters: fp3_top's, as it derives them (CW, IW, AW; READ, AHEAD, the
// latencies in cycles; FLAGS_AHEAD = FMAX_PIPE; HAS_DIV, HAS_SQRT).
// Mutants (tests/test_formal_mutant.sh): FP3_MUTANT_ANNOUNCE_EARLY makes
// rtl/fp3_wb_tag.v's line a stage short, so every write-back is announced
// (and its index written back) a cycle early; FP3_MUTANT_DIV_TAG_SHORT
// does so to the div/sqrt unit's line only (rtl/fp3_top.v): the busy and
// write-back properties fail.
`default_nettype none
module fp3_sched_check #(
  parameter integer NUM_CONTEXTS = 2,
  parameter integer CW           = 1,
  parameter integer IW           = 2,
  parameter integer IMEM_DEPTH   = 4,
  parameter integer AW           = 2,
  parameter integer READ         = 1,
  parameter integer AHEAD        = 1,
  parameter integer ADD_LATENCY  = 4,
  parameter integer MUL_LATENCY  = 3,
  parameter integer MOV_LATENCY  = 1,
  parameter integer DIV_LATENCY  = 8,
  parameter integer HAS_DIV      = 1,
  parameter integer HAS_SQRT     = 1,
  parameter integer FLAGS_AHEAD  = 0
) (
  input  wire                    clk_i,
  input  wire                    rst_i,
  // the host's program writes and run control, as fp3_top takes them
  input  wire                    prog_we_i,
  input  wire [AW-1:0]           prog_addr_i,
  input  wire [63:0]             prog_word_i,
  input  wire                    start_i,
  input  wire                    running_i,
  input  wire [NUM_CONTEXTS-1:0] contexts_run_i,
  input  wire [31:0]             steps_i,
  input  wire [CW-1:0]           sel_ctx_i,
  input  wire [31:0]             steps_done_sel_i,
  input  wire [63:0]             issued_i,
  input  wire [63:0]             stalls_i,
  // the scheduler's issue
  input  wire                    issue_i,
  input  wire [CW-1:0]           issue_ctx_i,
  input  wire [CW+IW-1:0]        ra_i,
  input  wire [CW+IW-1:0]        rb_i,
  input  wire [CW+IW-1:0]        rd_i,
  input  wire [2:0]              issue_unit_i,
  input  wire                    issue_imm_i,
  input  wire [31:0]             imm_i,
  input  wire                    endi_i,
  input  wire                    beq_i,
  // the scoreboard's flags, the write-backs, the beq outcomes
  input  wire [(1<<(CW+IW))-1:0] busy_i,
  input  wire                    add_valid_i,
  input  wire [CW+IW-1:0]        add_idx_i,
  input  wire                    mul_valid_i,
  input  wire [CW+IW-1:0]        mul_idx_i,
  input  wire                    mov_valid_i,
  input  wire [CW+IW-1:0]        mov_idx_i,
  input  wire                    div_valid_i,
  input  wire [CW+IW-1:0]        div_idx_i,
  input  wire [NUM_CONTEXTS-1:0] br_i,
  input  wire                    br_taken_i
);
`include "fp3_isa.vh"
  localparam integer NC = NUM_CONTEXTS;
  localparam integer XW = CW + IW;
  localparam integer NX = 1 << XW;
  // rem's width: holds READ + the longest latency
  localparam integer LMAX = (ADD_LATENCY > MUL_LATENCY ? ADD_LATENCY : MUL_LATENCY) >
                            (DIV_LATENCY > MOV_LATENCY ? DIV_LATENCY : MOV_LATENCY) ?
                            (ADD_LATENCY > MUL_LATENCY ? ADD_LATENCY : MUL_LATENCY) :
                            (DIV_LATENCY > MOV_LATENCY ? DIV_LATENCY : MOV_LATENCY);
  localparam integer RW = $clog2(READ + LMAX + 1);
  localparam integer L_ADD = READ + ADD_LATENCY, L_MUL = READ + MUL_LATENCY,
                     L_DIV = READ + DIV_LATENCY, L_MOV = READ + MOV_LATENCY;
  localparam integer R_LAST = READ - 1;   // rem of an operand read in the last read stage

  // ---- the program as written ---------------------------------------------
  reg [63:0]         mem_q [0:IMEM_DEPTH-1];
  reg [IMEM_DEPTH-1:0] written_q;
  initial written_q = {IMEM_DEPTH{1'b0}};
  always @(posedge clk_i) begin
    if (prog_we_i && !rst_i) begin   // (the memory takes no write in reset)
      mem_q[prog_addr_i]     <= prog_word_i;
      written_q[prog_addr_i] <= 1'b1;
    end
  end

  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;
  always @(*) assume (rst_i == !f_past_valid);   // reset in the first cycle only
  always @(*) if (start_i) assume (&written_q);

  // ---- the issued word, by the model's program counter --------------------
  reg  [AW:0]   pc_q   [0:NC-1];   // next word of each context (AW + 1 bits: off the end)
  reg  [NC-1:0] pend_q;            // a beq of the context awaits its outcome
  reg  [31:0]   cnt_q  [0:NC-1];   // endi issued in this run
  wire [AW:0]   ipc    = pc_q[issue_ctx_i];
  wire [63:0]   w      = mem_q[ipc[AW-1:0]];
  wire [7:0]    w_opc  = w[ISA_OPC_LSB +: ISA_OPC_WIDTH];
  wire [IW-1:0] w_rd   = w[ISA_RD_LSB +: IW];   // (the register fields' used bits)
  wire [IW-1:0] w_ra   = w[ISA_RA_LSB +: IW];
  wire [IW-1:0] w_rb   = w[ISA_RB_LSB +: IW];
  wire [31:0]   w_imm  = w[0 +: ISA_IMM_WIDTH];
  wire [7:0]    w_dec  = isa_decode(w_opc);   // {known, unit[2:0], uses: imm rb ra rd}
  wire [2:0]    w_unit = w_dec[6:4];
  wire          u_rd   = w_dec[0];
  wire          u_ra   = w_dec[1];
  wire          u_rb   = w_dec[2];
  wire          unused_word = &{1'b0, w, w_dec[3]};   // (the register fields' other bits)
  wire          w_endi = w_opc == OP_ENDI;
  wire          w_beq  = w_opc == OP_BEQ;
  // the issue's write-back: cycles from the issue
  wire [RW-1:0] lat    = (issue_unit_i == UNIT_ADD) ? L_ADD[RW-1:0] :
                         (issue_unit_i == UNIT_MUL) ? L_MUL[RW-1:0] :
                         (issue_unit_i == UNIT_DIV) ? L_DIV[RW-1:0] : L_MOV[RW-1:0];
  // a div or sqrt is legal in a build with its core
  wire          w_built = w_unit != UNIT_DIV || (w_opc == OP_DIV ? HAS_DIV != 0 : HAS_SQRT != 0);
  wire          iwr    = issue_i && issue_unit_i != UNIT_NONE;   // the issue writes rd_i

  // each context's beq target: the immediate of the word at its counter
  wire [NC*AW-1:0] br_target;
  genvar gc;
  generate
    for (gc = 0; gc < NC; gc = gc + 1) begin : g_target
      wire [AW-1:0] tpc = pc_q[gc][AW-1:0];
      assign br_target[gc*AW +: AW] = mem_q[tpc][AW-1:0];
    end
  endgenerate
  integer c;
  always @(posedge clk_i) begin
    if (rst_i || !running_i) begin
      for (c = 0; c < NC; c = c + 1) begin
        pc_q[c]  <= {(AW+1){1'b0}};
        cnt_q[c] <= 32'd0;
      end
      pend_q <= {NC{1'b0}};
    end else begin
      for (c = 0; c < NC; c = c + 1) begin
        if (br_i[c]) begin
          pend_q[c] <= 1'b0;
          pc_q[c]   <= br_taken_i ? {1'b0, br_target[c*AW +: AW]} : pc_q[c] + 1'b1;
        end
      end
      if (issue_i) begin
        if (w_beq) pend_q[issue_ctx_i] <= 1'b1;
        else pc_q[issue_ctx_i] <= w_endi ? {1'b0, w_imm[AW-1:0]} : ipc + 1'b1;
        if (w_endi) cnt_q[issue_ctx_i] <= cnt_q[issue_ctx_i] + 32'd1;
      end
    end
  end

  // ---- per register: the last write claimed --------------------------------
  reg [RW-1:0] rem_q [0:NX-1];   // cycles to its write-back (0: none pending)
  reg [2:0]    unit_q [0:NX-1];  // ... its unit
  reg [NX-1:0] due_q;            // written back this cycle (rem was 1)
  reg [2:0]    due_unit_q [0:NX-1];
  integer x;
  always @(posedge clk_i) begin
    for (x = 0; x < NX; x = x + 1) begin
      due_q[x]      <= !rst_i && rem_q[x] == 1;
      due_unit_q[x] <= unit_q[x];
      if (rst_i) begin
        rem_q[x]  <= {RW{1'b0}};
        unit_q[x] <= UNIT_NONE;
      end else if (iwr && rd_i == x[XW-1:0]) begin
        rem_q[x]  <= lat - 1'b1;
        unit_q[x] <= issue_unit_i;
      end else if (rem_q[x] != 0) begin
        rem_q[x]  <= rem_q[x] - 1'b1;
      end
    end
  end

  // ---- properties ------------------------------------------------------------
  always @(*) begin
    if (f_past_valid && !rst_i && issue_i) begin
      // order
      order_running: assert (running_i && contexts_run_i[issue_ctx_i]);
      order_beq_resolved: assert (!pend_q[issue_ctx_i]);
      order_steps_left: assert (cnt_q[issue_ctx_i] < steps_i);
      order_pc_in_memory: assert (ipc < IMEM_DEPTH[AW:0]);
      order_known_opcode: assert (w_dec[7] && w_built);
      order_unit: assert (issue_unit_i == w_unit);
      order_endi_beq: assert (endi_i == w_endi && beq_i == w_beq);
      order_li: assert (issue_imm_i == (w_opc == OP_LI));
      if (w_opc == OP_LI) order_imm: assert (imm_i == w_imm);
      if (u_rd) order_rd: assert (rd_i == {issue_ctx_i, w_rd});
      if (u_ra) order_ra: assert (ra_i == {issue_ctx_i, w_ra});
      if (u_rb) order_rb: assert (rb_i == {issue_ctx_i, w_rb});
      // RAW: the operands are written back by the last read stage
      if (u_ra) raw_ra: assert (rem_q[ra_i] <= R_LAST[RW-1:0]);
      if (u_rb) raw_rb: assert (rem_q[rb_i] <= R_LAST[RW-1:0]);
      // WAW: register writes land in program order
      if (iwr) waw_in_order: assert (rem_q[rd_i] < lat);
    end
  end
  wire [NX-1:0] div_due;         // due_q of a div or sqrt (the covers)
  genvar gx;
  generate
    for (gx = 0; gx < NX; gx = gx + 1) begin : g_reg
      assign div_due[gx] = due_unit_q[gx] == UNIT_DIV;
      always @(*) begin
        if (f_past_valid && !rst_i) begin
          // busy: set by exactly the claim, cleared by exactly its announcement
          assert (busy_i[gx] == (rem_q[gx] >= AHEAD[RW-1:0]));
          // wb: the claiming unit writes the register back in cycle W
          if (due_q[gx])
            case (due_unit_q[gx])
              UNIT_ADD: assert (add_valid_i && add_idx_i == gx[XW-1:0]);
              UNIT_MUL: assert (mul_valid_i && mul_idx_i == gx[XW-1:0]);
              UNIT_DIV: assert (div_valid_i && div_idx_i == gx[XW-1:0]);
              default:  assert (mov_valid_i && mov_idx_i == gx[XW-1:0]);
            endcase
          // drain
          if (!running_i) assert (rem_q[gx] == 0);
        end
      end
    end
  endgenerate
  // endi: STEPS_DONE of the selected context counts its endi, once each.
  // The scheduler counts an instruction a cycle after its grant: in the
  // default build the grant is the issue, so the count shows two cycles
  // after it; with the pick stages the grant is two cycles ahead of the
  // issue, so the count shows in the issue's cycle.  ISSUED likewise.
  reg [31:0] cnt_d_q [0:NC-1];   // cnt_q a cycle late
  reg [2:0]  run_q;              // running_i in the last three cycles (not in reset)
  reg [1:0]  iss_q;              // issue_i one and two cycles ago
  always @(posedge clk_i) begin
    for (c = 0; c < NC; c = c + 1) cnt_d_q[c] <= cnt_q[c];
    run_q <= {run_q[1:0], running_i && !rst_i};
    iss_q <= {iss_q[0], issue_i && !rst_i};
  end
  wire        sel_endi  = issue_i && endi_i && issue_ctx_i == sel_ctx_i;
  wire [31:0] sdone_exp = (FLAGS_AHEAD != 0) ? cnt_q[sel_ctx_i] + {31'd0, sel_endi}
                                             : cnt_d_q[sel_ctx_i];
  always @(*)
    if (f_past_valid && !rst_i && running_i && run_q[0])
      endi_counted_once: assert (steps_done_sel_i == sdone_exp);
  // issued: one count per issue
  always @(posedge clk_i)
    if (f_past_valid && !rst_i && running_i && &run_q)
      issued_once: assert (issued_i == $past(issued_i) + {63'd0, (FLAGS_AHEAD != 0) ? issue_i : iss_q[1]});

  // ---- covers ------------------------------------------------------------------
  reg [CW-1:0] last_ctx_q;
  reg          last_issue_q;
  reg          ran_q = 1'b0;   // an instruction has issued since reset
  always @(posedge clk_i) begin
    last_ctx_q   <= issue_ctx_i;
    last_issue_q <= issue_i && !rst_i;
    ran_q        <= !rst_i && (ran_q || issue_i);
  end
  always @(posedge clk_i) begin
    if (f_past_valid && !rst_i) begin
      c_stall: cover (running_i && stalls_i != $past(stalls_i) && $past(running_i));   // a stall
      // an operand taken the cycle of its write-back or from the bypass
      c_bypass: cover (issue_i && u_ra && (rem_q[ra_i] != 0 || due_q[ra_i]));
      c_two_contexts: cover (issue_i && last_issue_q && issue_ctx_i != last_ctx_q);
      c_second_step: cover (issue_i && cnt_q[issue_ctx_i] == 32'd1);
      c_beq_taken: cover (|(br_i & pend_q) && br_taken_i);     // a beq of the run taken
      c_run_ends: cover ($past(running_i) && !running_i && ran_q); // a run that issued ends
      // a div or sqrt written back, and an operand taken from one the
      // cycle of its write-back or from the bypass
      c_div_wb: cover (|(due_q & div_due));
      c_div_bypass: cover (issue_i && u_ra && unit_q[ra_i] == UNIT_DIV &&
                           (rem_q[ra_i] != 0 || due_q[ra_i]));
    end
  end
endmodule
`default_nettype wire
