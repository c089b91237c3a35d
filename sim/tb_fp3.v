// tb_fp3 -- self-checking Icarus Verilog testbench of the FP3 processor
// (rtl/fp3_top.v): `make wave`.
//
// It does what a driver does, through the host port only: reset, check
// the ID register, load the program into every instruction-memory entry,
// write every register of every context it runs (+contexts=N, default 1;
// every lane of each, NUM_LANES; all run the same scene), write STEPS,
// CONTEXTS and START, then watch the
// trace port while the machine runs freely, and read status, counters and
// registers back when it is done.  All inputs come from `fp3 tbgen`
// (sw/cli/cmd_tbgen.h) in $readmemh format, in the directory given by +dir=DIR:
//
//   program.hex   the assembled program (64-bit words)
//   init.hex      the registers before the run
//   run.hex       32 words: steps, word counts, expected status, the
//                 registers and names of the two state variables checked
//   expected.hex  final registers, then those two after every integration
//
// The two checked are the model's first two state variables (the ship's
// v and s, the spring's x and v; one of a one-state model): the messages
// name them as run.hex does.
//
// Checks (each mismatch is printed; the last line is PASS or FAIL):
//   - the two state variables of every context and lane after every
//     integration, bit for bit,
//     tagged with their integration exactly as sw/engine/engine_rtl.c does (one
//     FIFO of {context, integration} per unit, pushed at issue, popped at
//     write-back, which must name the same context);
//   - every register of every context and lane at the end; STATUS (DONE,
//     ERROR), FAULT_PC, STEPS_DONE per context, ISSUED (contexts x the
//     ISS's) and FLAGS per lane against the instruction-set simulator;
//   - CYCLES and STALLS against the Verilated model of the same RTL, when
//     it was built with the same latencies (one context only);
//   - no write-back without an issue, nothing left in flight at the end.
// Watchdogs end a hung run with the cycle and the PC: no issue and no
// write-back for STALL_LIMIT cycles, or more cycles than the run can take
// (ISSUED x (longest latency + 1) + 100; +watchdog=N overrides).
//
// Plusargs
//   +dir=DIR        input files (default build/wave)
//   +wave=FILE      write the waveform to FILE (vvp -fst: FST, else VCD)
//   +dump_load      include reset and the program load in the waveform
//                   (default: from START on)
//   +contexts=N     run N contexts (1 .. NUM_CONTEXTS), all the same scene
//   +steps=N        write N to STEPS instead of the generated count
//                   (for the watchdog test; results past the generated
//                   ones are not checked)
//   +watchdog=N     total cycle budget of the run
//
// The dbg_* signals exist for the waveform (sim/fp3.gtkw): stall and its
// cause, the mnemonic at the PC, pipeline valid bits, values as reals.
// Verilog-2005; $finish_and_return under Icarus gives vvp an exit status.
// No `timescale here (the RTL has none): mk/wave.mk gives every module
// 1 ns through an iverilog command file (+timescale+1ns/1ns).
`default_nettype none
module tb_fp3 #(
  parameter integer NUM_CONTEXTS = 8,      // as rtl/fp3_top.v
  parameter integer NUM_LANES   = 1,
  parameter integer NUM_REGS    = 32,
  parameter integer IMEM_DEPTH  = 256,
  parameter integer ADD_LATENCY = 4,
  parameter integer MUL_LATENCY = 3,
  parameter integer ROUND       = 0,
  parameter integer FTZ         = 0,
  parameter integer HAS_ADD     = 1,
  parameter integer HAS_SUB     = 1,
  parameter integer HAS_MUL     = 1,
  parameter integer HAS_DIV     = 1,
  parameter integer HAS_SQRT    = 1,
  parameter integer DIV_LATENCY = 8,
  parameter integer FMAX_PIPE   = 0,
  parameter integer WB_PORTS    = 4,
  parameter integer HALF_PERIOD = 5,       // ns: a 100 MHz clock
  parameter integer MAX_CHECK   = 100000,  // = TBGEN_MAX_CHECK (sw/cli/cmd_tbgen.h)
  parameter integer STALL_LIMIT = 1000     // cycles without progress = hang
);
`include "fp3_isa.vh"

  localparam integer AW       = (IMEM_DEPTH <= 2) ? 1 : $clog2(IMEM_DEPTH);
  localparam integer NC       = NUM_CONTEXTS;
  localparam integer NL       = NUM_LANES;
  localparam integer IW       = (NUM_REGS <= 2) ? 1 : $clog2(NUM_REGS);  // as fp3_top
  localparam integer MAX_AM   = ADD_LATENCY > MUL_LATENCY ? ADD_LATENCY : MUL_LATENCY;
  localparam integer MAX_LAT  = MAX_AM > DIV_LATENCY ? MAX_AM : DIV_LATENCY;
  localparam integer READ     = 1 + 3 * FMAX_PIPE;   // operand-read stages
  localparam integer LD       = NUM_LANES > 1 ? 2 : 0; // lanes: their broadcast stages (fp3_top LD)
  localparam integer HREAD    = READ + (NUM_LANES > 1 ? 1 : 0);   // host read cycles
  // run.hex layout (sw/cli/cmd_tbgen.h, format version TBGEN_VERSION):
  // R_REG_V, R_REG_S the registers of the model's state variables 0 and
  // 1 (32'hFFFFFFFF: none, a one-state model), R_NAME_V, R_NAME_S their
  // names, NAME_WORDS words each, a Verilog string.
  localparam integer RUN_WORDS = 32, RUN_VERSION = 2, NAME_WORDS = 8;
  localparam integer R_MAGIC = 0, R_VERSION = 1, R_NWORDS = 2, R_NUM_REGS = 3,
                     R_STEPS = 4, R_ERROR = 5, R_FAULT_PC = 6, R_STEPS_DONE = 7,
                     R_ISSUED = 8, R_FLAGS = 9, R_REG_V = 10, R_REG_S = 11,
                     R_NCHECK = 12, R_RTL_LAT = 13, R_RTL_CYCLES = 14,
                     R_RTL_STALLS = 15, R_NAME_V = 16, R_NAME_S = 24;
  localparam integer FIFO_DEPTH = 64;                // > longest latency + 1
  localparam integer TAG_CTX    = 26;                // FIFO entry: {ctx, integration}
  localparam integer MAX_REPORT = 10;                // mismatches printed

  // ---- the design ----------------------------------------------------------
  reg         clk = 1'b0;
  reg         rst = 1'b1;
  reg         host_we = 1'b0;
  reg  [11:0] host_addr = 12'd0;
  reg  [31:0] host_wdata = 32'd0;
  wire [31:0] host_rdata;
  wire        running, done;
  wire        tr_issue, tr_endi;
  wire [5:0]  tr_issue_ctx, tr_add_ctx, tr_mul_ctx, tr_mov_ctx, tr_div_ctx;
  wire [2:0]  tr_issue_unit;
  wire        tr_add_valid, tr_mul_valid, tr_mov_valid, tr_div_valid;
  wire [7:0]  tr_add_reg, tr_mul_reg, tr_mov_reg, tr_div_reg;
  wire [32*NL-1:0] tr_add_data, tr_mul_data, tr_mov_data, tr_div_data;   // lane l: [32l +: 32]

  fp3_top #(
    .NUM_CONTEXTS (NUM_CONTEXTS),
    .NUM_LANES   (NUM_LANES),
    .NUM_REGS    (NUM_REGS),
    .IMEM_DEPTH  (IMEM_DEPTH),
    .ADD_LATENCY (ADD_LATENCY),
    .MUL_LATENCY (MUL_LATENCY),
    .ROUND       (ROUND),
    .FTZ         (FTZ),
    .HAS_ADD     (HAS_ADD),
    .HAS_SUB     (HAS_SUB),
    .HAS_MUL     (HAS_MUL),
    .HAS_DIV     (HAS_DIV),
    .HAS_SQRT    (HAS_SQRT),
    .DIV_LATENCY (DIV_LATENCY),
    .FMAX_PIPE   (FMAX_PIPE),
    .WB_PORTS    (WB_PORTS)
  ) dut (
    .clk_i           (clk),
    .rst_i           (rst),
    .host_we_i       (host_we),
    .host_addr_i     (host_addr),
    .host_wdata_i    (host_wdata),
    .host_wsel_i     (8'd0),        // (HOST_WSEL = 0: decoded in the core)
    .host_rdata_o    (host_rdata),
    .running_o       (running),
    .done_o          (done),
    .tr_issue_o      (tr_issue),
    .tr_issue_ctx_o  (tr_issue_ctx),
    .tr_issue_unit_o (tr_issue_unit),
    .tr_endi_o       (tr_endi),
    .tr_add_valid_o  (tr_add_valid),
    .tr_add_ctx_o    (tr_add_ctx),
    .tr_add_reg_o    (tr_add_reg),
    .tr_add_data_o   (tr_add_data),
    .tr_mul_valid_o  (tr_mul_valid),
    .tr_mul_ctx_o    (tr_mul_ctx),
    .tr_mul_reg_o    (tr_mul_reg),
    .tr_mul_data_o   (tr_mul_data),
    .tr_mov_valid_o  (tr_mov_valid),
    .tr_mov_ctx_o    (tr_mov_ctx),
    .tr_mov_reg_o    (tr_mov_reg),
    .tr_mov_data_o   (tr_mov_data),
    .tr_div_valid_o  (tr_div_valid),
    .tr_div_ctx_o    (tr_div_ctx),
    .tr_div_reg_o    (tr_div_reg),
    .tr_div_data_o   (tr_div_data)
  );

  always #(HALF_PERIOD) clk = !clk;

  // ---- inputs ----------------------------------------------------------------
  reg [8*256-1:0] dir, wave;  // paths up to 256 characters
  reg [63:0]  prog    [0:IMEM_DEPTH-1];
  reg [31:0]  init    [0:NUM_REGS-1];
  reg [31:0]  run     [0:RUN_WORDS-1];
  reg [31:0]  expect_ [0:NUM_REGS + 2*MAX_CHECK - 1];  // final regs, then v, s pairs
  reg [31:0]  steps_run;        // STEPS written to the machine
  integer     watchdog_limit;

  // ---- debug view (sim/fp3.gtkw) -------------------------------------------
  function [8*4-1:0] mnemonic;  // text of an opcode, for the ASCII trace
    input [7:0] opc;
    begin
      case (opc)
        OP_NOP:  mnemonic = "nop";
        OP_ADD:  mnemonic = "add";
        OP_SUB:  mnemonic = "sub";
        OP_MUL:  mnemonic = "mul";
        OP_LI:   mnemonic = "li";
        OP_MOV:  mnemonic = "mov";
        OP_ENDI: mnemonic = "endi";
        OP_HALT: mnemonic = "halt";
        default: mnemonic = "???";
      endcase
    end
  endfunction

  function real f32_real;  // a binary32 pattern as a real (inf, NaN: +-1e39)
    input [31:0] b;
    real mag;
    begin
      if (b[30:23] == 8'hFF)      mag = 1.0e39;
      else if (b[30:23] == 8'h00) mag = b[22:0] * (2.0 ** -149);
      else                        mag = (8388608.0 + b[22:0]) * (2.0 ** ($signed({1'b0, b[30:23]}) - 150));
      f32_real = b[31] ? -mag : mag;
    end
  endfunction

  // ---- probes: the only references into the design's hierarchy ----------
  // The waveform view (sim/fp3.gtkw) names tb_fp3 signals only: the ports
  // above and these dbg_* probes.  When the RTL's internals change, this
  // block is what follows them (tests/test_wave.sh checks that every
  // signal of the .gtkw file is in the waveform).  Per-context vectors have
  // bit c for context c; registers and busy flags are shown for context 0,
  // values for lane 0 and for the last lane (NUM_LANES - 1: lane 0 again
  // without lanes), as the trace port carries every lane.
  wire           dbg_issue     = dut.u_sched.grant;      // granted (issues now; next cycle with FMAX_PIPE)
  wire [AW-1:0]  dbg_pc        = dut.u_sched.u_queue.p_q[2*dut.u_sched.u_issue.g + dut.u_sched.u_queue.hp_q[dut.u_sched.u_issue.g]];  // PC of the issuing instruction
  wire [63:0]    dbg_insn      = dut.u_sched.u_queue.w_q[2*dut.u_sched.u_issue.g + dut.u_sched.u_queue.hp_q[dut.u_sched.u_issue.g]];  // its word
  wire [7:0]     dbg_opc       = dbg_insn[ISA_OPC_LSB +: ISA_OPC_WIDTH];
  wire [AW-1:0]  dbg_pc0       = dut.u_sched.u_queue.p_q[dut.u_sched.u_queue.hp_q[0]];  // context 0: PC of its queue's head
  wire [NC-1:0]  dbg_active    = dut.u_sched.act;        // contexts fetching and issuing
  wire [NC-1:0]  dbg_waiting   = dut.u_sched.act & dut.u_sched.holds;  // hold an instruction
  wire [NC-1:0]  dbg_ready     = dut.u_sched.u_queue.ready_q;    // ... found ready last cycle
  wire [NC-1:0]  dbg_raw;                                // waits for a source (RAW)
  wire [NC-1:0]  dbg_waw;                                // waits for its destination (WAW)
  wire [31:0]    dbg_steps_done = dut.u_sched.u_loop.sdone_q[0];
  wire [63:0]    dbg_cycles    = dut.u_sched.cycles_o;
  wire [63:0]    dbg_issued    = dut.u_sched.issued_o;
  wire [63:0]    dbg_stalls    = dut.u_sched.stalls_o;
  wire [NUM_REGS-1:0] dbg_busy = dut.busy[NUM_REGS-1:0];  // context 0
  wire [7:0]     dbg_lanes     = NUM_LANES[7:0];         // lanes per context
  wire [31:0]    dbg_add_data  = tr_add_data[31:0];      // lane 0's results
  wire [31:0]    dbg_mul_data  = tr_mul_data[31:0];
  wire [31:0]    dbg_mov_data  = tr_mov_data[31:0];
  wire [31:0]    dbg_add_last  = tr_add_data[32*(NL-1) +: 32];   // the last lane's results
  wire [31:0]    dbg_mul_last  = tr_mul_data[32*(NL-1) +: 32];
  wire [31:0]    dbg_mov_last  = tr_mov_data[32*(NL-1) +: 32];
  wire           wbn0_v = dut.adda_valid;   // write-backs announced (fp3_wb_tag)
  wire           wbn1_v = dut.mula_valid;
  wire           wbn2_v = dut.mova_valid;
  wire [31:0]    wbn0_x = dut.adda_idx;
  wire [31:0]    wbn1_x = dut.mula_idx;
  wire [31:0]    wbn2_x = dut.mova_idx;
  // Issued add/sub and mul operations, bit k: issued k + 1 cycles ago; an
  // operation is in core stage s READ + LD + s + 1 cycles after its issue
  // (the last lane's cores: LD broadcast stages behind the scheduler).
  localparam integer RL = READ + LD;
  reg [RL+ADD_LATENCY-1:0] add_line = {(RL+ADD_LATENCY){1'b0}};
  reg [RL+MUL_LATENCY-1:0] mul_line = {(RL+MUL_LATENCY){1'b0}};
  always @(posedge clk) begin
    add_line <= {add_line[RL+ADD_LATENCY-2:0], tr_issue && tr_issue_unit == UNIT_ADD};
    mul_line <= {mul_line[RL+MUL_LATENCY-2:0], tr_issue && tr_issue_unit == UNIT_MUL};
  end
  wire [ADD_LATENCY-1:0] dbg_add_pipe = add_line[RL+ADD_LATENCY-1:RL];  // bit s: stage s
  wire [MUL_LATENCY-1:0] dbg_mul_pipe = mul_line[RL+MUL_LATENCY-1:RL];
  genvar gs;
  generate
    // A waiting context's hazard, as the scheduler's ready step sees it: a
    // used source busy and its write-back not announced in this cycle, or
    // the destination of its instruction in the issue register or being picked (FMAX_PIPE)
    // (RAW), or its destination so (WAW).
    // (No function here: Icarus re-evaluates a continuous assignment only
    // when a function's arguments change, not the signals it reads.)
    for (gs = 0; gs < NC; gs = gs + 1) begin : g_hazard
      // The head: its slot's word and decoded bits (x_q: bit 10 use_rb,
      // 9 use_ra, 8 use_rd).
      wire        hp  = dut.u_sched.u_queue.hp_q[gs];
      wire [63:0] hw  = dut.u_sched.u_queue.w_q[2*gs+hp];
      wire [11:0] hx  = dut.u_sched.u_queue.x_q[2*gs+hp];
      wire use_ra = hx[9], use_rb = hx[10], use_rd = hx[8];
      wire [31:0] xa = gs * (1 << IW) + hw[ISA_RA_LSB +: IW];
      wire [31:0] xb = gs * (1 << IW) + hw[ISA_RB_LSB +: IW];
      wire [31:0] xd = gs * (1 << IW) + hw[ISA_RD_LSB +: IW];
      wire wa = (wbn0_v && wbn0_x == xa) || (wbn1_v && wbn1_x == xa) || (wbn2_v && wbn2_x == xa);
      wire wb = (wbn0_v && wbn0_x == xb) || (wbn1_v && wbn1_x == xb) || (wbn2_v && wbn2_x == xb);
      wire wd = (wbn0_v && wbn0_x == xd) || (wbn1_v && wbn1_x == xd) || (wbn2_v && wbn2_x == xd);
      wire pend = FMAX_PIPE != 0 && dut.u_sched.issue_o &&
                  dut.u_sched.issue_unit_o != UNIT_NONE && dut.u_sched.issue_ctx_o == gs;
      wire [31:0] pend_x = dut.u_sched.rd_o;
      // ... or of the one granted in the last cycle, being picked.
      wire pick = FMAX_PIPE != 0 && dut.u_sched.u_issue.p_grant &&
                  dut.u_sched.u_issue.g_unit != UNIT_NONE && dut.u_sched.u_issue.p_g == gs;
      wire [31:0] pick_x = gs * (1 << IW) + dut.u_sched.u_issue.g_rd;
      assign dbg_raw[gs] = dbg_waiting[gs] &&
        ((use_ra && ((dut.u_sched.busy_i[xa] && !wa) || (pend && pend_x == xa) ||
                     (pick && pick_x == xa))) ||
         (use_rb && ((dut.u_sched.busy_i[xb] && !wb) || (pend && pend_x == xb) ||
                     (pick && pick_x == xb))));
      assign dbg_waw[gs] = dbg_waiting[gs] && use_rd &&
        ((dut.u_sched.busy_i[xd] && !wd) || (pend && pend_x == xd) || (pick && pick_x == xd));
    end
  endgenerate
  // ---- derived debug signals -------------------------------------------------
  // A stall is a cycle without issue while some context holds an
  // instruction (the STALLS counter); its cause as text: RAW, WAW, or
  // FRONT when no waiting context has a hazard (the front end: a context
  // that issued last cycle, or whose word arrived last cycle, is decided
  // in this one).  dbg_free_q: contexts that, by this testbench's own
  // hazard view, were free to issue at the previous edge and did not.
  wire [NC-1:0]  dbg_gone      = dut.u_sched.gone;
  wire           dbg_stall     = running && !dbg_issue && (|dbg_waiting);
  wire           dbg_stall_raw = dbg_stall && (|dbg_raw);
  wire           dbg_stall_waw = dbg_stall && (|dbg_waw);
  wire [8*7-1:0] dbg_stall_why = dbg_stall_raw && dbg_stall_waw ? "RAW+WAW" :
                                 dbg_stall_raw ? "RAW" : dbg_stall_waw ? "WAW" :
                                 dbg_stall ? "FRONT" : "";
  reg  [NC-1:0]  dbg_free_q;
  always @(posedge clk) begin
    dbg_free_q <= dbg_waiting & ~dbg_raw & ~dbg_waw & ~dbg_gone;
  end
  wire [8*4-1:0] dbg_op        = dbg_issue ? mnemonic(dbg_opc) : "";
  real       dbg_add_real, dbg_mul_real, dbg_mov_real, dbg_v_real, dbg_s_real;
  reg [31:0] dbg_v, dbg_s;         // state variables 0 and 1 (run.hex) of context 0
  reg [31:0] dbg_v_last, dbg_s_last;   // ... of its last lane
  always @(*) begin
    dbg_add_real = f32_real(tr_add_data[31:0]);
    dbg_mul_real = f32_real(tr_mul_data[31:0]);
    dbg_mov_real = f32_real(tr_mov_data[31:0]);
  end
  // Register r of context 0 in lane 0 and in the last lane, after the
  // clock edge, as the register file holds it: the word of the RAM of the
  // write-back port that wrote it last (the LVT, lane 0's, chooses for
  // every lane; with WB_PORTS = 1 there is one port and no LVT): one
  // pair of functions per register-file shape, g_dbg_regs.
  generate
    if (WB_PORTS == 1) begin : g_dbg_regs
      function [31:0] reg0;
        input [31:0] r;
        reg0 = r < NUM_REGS ? dut.u_lanes.g_lane[0].u_lane.u_regs.u_ram00.g_any.mem[r] : 32'd0;
      endfunction
      function [31:0] reg_last;
        input [31:0] r;
        reg_last = r < NUM_REGS ? dut.u_lanes.g_lane[NL-1].u_lane.u_regs.u_ram00.g_any.mem[r] : 32'd0;
      endfunction
    end else begin : g_dbg_regs
      function [1:0] lvt;
        input [31:0] r;
        lvt = {dut.u_lanes.g_lane[0].u_lane.u_regs.lvt_hi[r], dut.u_lanes.g_lane[0].u_lane.u_regs.lvt_lo[r]};
      endfunction
      function [31:0] reg0;
        input [31:0] r;
        begin
          case (lvt(r))
            2'd0:    reg0 = dut.u_lanes.g_lane[0].u_lane.u_regs.u_ram00.g_any.mem[r];
            2'd1:    reg0 = dut.u_lanes.g_lane[0].u_lane.u_regs.g_ram_ports.u_ram10.g_any.mem[r];
            2'd2:    reg0 = dut.u_lanes.g_lane[0].u_lane.u_regs.g_ram_ports.u_ram20.g_any.mem[r];
            default: reg0 = dut.u_lanes.g_lane[0].u_lane.u_regs.g_ram_ports.u_ram30.g_any.mem[r];
          endcase
          if (r >= NUM_REGS) reg0 = 32'd0;
        end
      endfunction
      function [31:0] reg_last;
        input [31:0] r;
        begin
          case (lvt(r))
            2'd0:    reg_last = dut.u_lanes.g_lane[NL-1].u_lane.u_regs.u_ram00.g_any.mem[r];
            2'd1:    reg_last = dut.u_lanes.g_lane[NL-1].u_lane.u_regs.g_ram_ports.u_ram10.g_any.mem[r];
            2'd2:    reg_last = dut.u_lanes.g_lane[NL-1].u_lane.u_regs.g_ram_ports.u_ram20.g_any.mem[r];
            default: reg_last = dut.u_lanes.g_lane[NL-1].u_lane.u_regs.g_ram_ports.u_ram30.g_any.mem[r];
          endcase
          if (r >= NUM_REGS) reg_last = 32'd0;
        end
      endfunction
    end
  endgenerate
  always @(posedge clk) begin
    #1;
    dbg_v = g_dbg_regs.reg0(run[R_REG_V]);
    dbg_s = g_dbg_regs.reg0(run[R_REG_S]);
    dbg_v_last = g_dbg_regs.reg_last(run[R_REG_V]);
    dbg_s_last = g_dbg_regs.reg_last(run[R_REG_S]);
    dbg_v_real = f32_real(dbg_v);
    dbg_s_real = f32_real(dbg_s);
  end

  // ---- checking on the trace port -----------------------------------------
  integer errors = 0, mismatches = 0, checked = 0;
  integer cycle = 0;               // clock edges since reset
  integer run_cycle = 0;           // cycles of the run (0 = first running)
  integer quiet = 0;               // cycles without issue or write-back
  integer probe_stalls = 0;        // stall cycles the dbg_* probes saw
  integer beqs = 0;                // beq issues of the run
  integer endis_total = 0, cyc_first = 0, cyc_last = 0;
  integer contexts;                // contexts run
  // The Verilated model's cycle counts (tbgen) apply: one context, the
  // same latencies and pipeline, and lanes here if it had lanes.
  // (Set once run.hex and +contexts are read.)
  reg rtl_timed = 1'b0;
  reg         started = 1'b0;
  reg [31:0]  cur     [0:2*NC*NL-1];  // latest state 0, 1 of context c, lane l: [(2c + w) NL + l]
  reg [8*4*NAME_WORDS-1:0] sname [0:1];  // their names (run.hex)
  integer     next_k  [0:2*NC*NL-1];  // next integration to finalise
  integer     endis   [0:NC-1];    // endi issued per context
  reg [31:0]  tagq    [0:5*FIFO_DEPTH-1];  // unit u: u*FIFO_DEPTH ..
  integer     tag_head [0:4];
  integer     tag_cnt  [0:4];

  task fail_msg;  // count and print one error
    input [8*160-1:0] text;
    begin
      errors = errors + 1;
      if (errors <= MAX_REPORT) $display("ERROR: %0s", text);
    end
  endtask

  // Result w (state variable 0 or 1) of context c, lane l after
  // integrations next_k .. upto-1 is its latest value (none without its
  // register).
  task finalise;
    input integer c;
    input integer l;
    input integer w;
    input integer upto;
    reg [31:0] want;
    integer i2;
    begin
      i2 = (2*c + w) * NL + l;
      while (run[R_REG_V + w] < NUM_REGS && next_k[i2] < upto && next_k[i2] <= run[R_NCHECK]) begin
        want = expect_[NUM_REGS + 2*(next_k[i2]-1) + w];
        checked = checked + 1;
        if (cur[i2] !== want) begin
          mismatches = mismatches + 1;
          errors = errors + 1;
          if (mismatches <= MAX_REPORT && NL == 1)
            $display("MISMATCH: context %0d, integration %0d: %0s = %h (%g), expected %h (%g)",
                     c, next_k[i2], sname[w], cur[i2], f32_real(cur[i2]), want,
                     f32_real(want));
          else if (mismatches <= MAX_REPORT)
            $display("MISMATCH: context %0d, lane %0d, integration %0d: %0s = %h (%g), expected %h (%g)",
                     c, l, next_k[i2], sname[w], cur[i2], f32_real(cur[i2]), want,
                     f32_real(want));
        end
        next_k[i2] = next_k[i2] + 1;
      end
    end
  endtask

  task write_back;  // a result leaves unit u (1 add, 2 mul, 3 move, 4 div/sqrt), every lane
    input integer u;
    input [5:0]   ctx;
    input [7:0]   r;
    input [32*NL-1:0] value;
    reg [31:0] tag;
    integer w, l;
    begin
      if (tag_cnt[u] == 0) begin
        fail_msg("write-back without an issue");
        $display("       unit %0d, context %0d, r%0d, cycle %0d", u, ctx, r, run_cycle);
      end else begin
        tag = tagq[u*FIFO_DEPTH + tag_head[u]];
        tag_head[u] = (tag_head[u] + 1) % FIFO_DEPTH;
        tag_cnt[u] = tag_cnt[u] - 1;
        if ({26'd0, ctx} != tag >> TAG_CTX) begin
          fail_msg("write-back to another context than the issue's");
          $display("       unit %0d, context %0d, issued by context %0d, cycle %0d", u, ctx,
                   tag >> TAG_CTX, run_cycle);
        end else begin
          for (w = 0; w < 2; w = w + 1)
            if ({24'd0, r} == run[R_REG_V + w])
              for (l = 0; l < NL; l = l + 1) begin
                finalise(ctx, l, w, tag & ((32'd1 << TAG_CTX) - 1));
                cur[(2*ctx + w) * NL + l] = value[32*l +: 32];
              end
        end
      end
    end
  endtask

  task hang;  // the watchdog ends the run
    input [8*80-1:0] why;
    begin
      $display("WATCHDOG: %0s at cycle %0d of the run (clock edge %0d, t = %0t ns): pc %0d (context 0), insn %h, %0d of %0d integrations done (context 0), active contexts %b, busy %h",
               why, run_cycle, cycle, $time, dbg_pc0, dut.u_sched.u_queue.w_q[dut.u_sched.u_queue.hp_q[0]], dbg_steps_done,
               steps_run, dbg_active, dbg_busy);
      $display("FAIL: tb_fp3: the run hung (watchdog)");
      finish(2);
    end
  endtask

  always @(posedge clk) begin
    cycle <= cycle + 1;
    if (started && running) begin
      // write-backs of this cycle belong to instructions issued earlier
      if (tr_add_valid) write_back(1, tr_add_ctx, tr_add_reg, tr_add_data);
      if (tr_mul_valid) write_back(2, tr_mul_ctx, tr_mul_reg, tr_mul_data);
      if (tr_mov_valid) write_back(3, tr_mov_ctx, tr_mov_reg, tr_mov_data);
      if (tr_div_valid) write_back(4, tr_div_ctx, tr_div_reg, tr_div_data);
      if (tr_issue && {26'd0, tr_issue_ctx} >= contexts) fail_msg("issue from a context not started");
      else if (tr_issue && tr_issue_unit != UNIT_NONE) begin
        if (tag_cnt[tr_issue_unit] == FIFO_DEPTH) fail_msg("tag FIFO overflow");
        else begin
          tagq[tr_issue_unit*FIFO_DEPTH + (tag_head[tr_issue_unit] + tag_cnt[tr_issue_unit]) % FIFO_DEPTH] =
            ({26'd0, tr_issue_ctx} << TAG_CTX) | (endis[tr_issue_ctx] + 1);
          tag_cnt[tr_issue_unit] = tag_cnt[tr_issue_unit] + 1;
        end
      end
      if (tr_issue && tr_endi && {26'd0, tr_issue_ctx} < contexts) begin
        endis[tr_issue_ctx] = endis[tr_issue_ctx] + 1;
        endis_total = endis_total + 1;
        if (endis_total == 1) cyc_first = run_cycle;
        cyc_last = run_cycle;
      end
      // the waveform's stall probes agree with the STALLS counter, and no
      // stall leaves out a context that was free to issue (the scheduler
      // is work-conserving)
      if (dbg_stall) probe_stalls = probe_stalls + 1;
      if (tr_issue && dut.beq) beqs = beqs + 1;
      if (dbg_stall && |(dbg_free_q & dbg_waiting)) fail_msg("a stall while a context was free to issue");
      if (tr_issue || tr_add_valid || tr_mul_valid || tr_mov_valid || tr_div_valid) quiet = 0;
      else quiet = quiet + 1;
      if (quiet >= STALL_LIMIT) hang("no issue and no write-back for STALL_LIMIT cycles");
      if (run_cycle >= watchdog_limit) hang("run not done within the cycle budget");
      run_cycle = run_cycle + 1;
    end
  end

  // ---- host port -------------------------------------------------------------
  task host_write;
    input [11:0] addr;
    input [31:0] data;
    begin
      @(negedge clk);
      host_we = 1'b1;
      host_addr = addr;
      host_wdata = data;
      @(negedge clk);
      host_we = 1'b0;
    end
  endtask

  task host_read;  // data for addr is registered: valid HREAD edges later
    input  [11:0] addr;
    output [31:0] data;
    begin
      @(negedge clk);
      host_we = 1'b0;
      host_addr = addr;
      repeat (HREAD) @(posedge clk);
      #1 data = host_rdata;
    end
  endtask

  task finish;
    input integer code;
    begin
      if (wave != 0) $dumpflush;
`ifdef __ICARUS__
      $finish_and_return(code);
`else
      if (code != 0) $display("(exit status %0d)", code);
      $finish;
`endif
    end
  endtask

  // Open a file or stop: $readmemh only warns about a missing one.
  task need_file;
    input [8*280-1:0] path;
    integer fd;
    begin
      fd = $fopen(path, "r");
      if (fd == 0) begin
        $display("FAIL: tb_fp3: cannot open %0s (run fp3 tbgen first)", path);
        finish(1);
      end
      $fclose(fd);
    end
  endtask

  task expect_eq;  // one value read back against its expected value
    input [8*24-1:0] what;
    input [31:0]     got;
    input [31:0]     want;
    begin
      if (got !== want) begin
        errors = errors + 1;
        $display("ERROR: %0s = %0d (0x%h), expected %0d (0x%h)", what, got, got, want, want);
      end
    end
  endtask

  // ---- the test --------------------------------------------------------------
  integer i, u, c, l;
  reg [31:0] rd, status, cycles_lo, stalls_lo, issued_want;
  reg [63:0] w;
  initial begin
    if (!$value$plusargs("dir=%s", dir)) dir = "build/wave";
    if (!$value$plusargs("wave=%s", wave)) wave = 0;
    if (!$value$plusargs("contexts=%d", contexts)) contexts = 1;
    if (contexts < 1 || contexts > NC) begin
      $display("FAIL: tb_fp3: +contexts=%0d: this build has 1 .. %0d contexts", contexts, NC);
      finish(1);
    end
    for (u = 0; u < 5; u = u + 1) begin
      tag_head[u] = 0;
      tag_cnt[u] = 0;
    end
    for (c = 0; c < NC; c = c + 1) endis[c] = 0;
    for (i = 0; i < RUN_WORDS; i = i + 1) run[i] = 32'hFFFF_FFFF;
    need_file({dir, "/run.hex"});
    $readmemh({dir, "/run.hex"}, run, 0, RUN_WORDS - 1);
    rtl_timed = contexts == 1 && run[R_RTL_LAT][31:18] == 14'd0 &&
                run[R_RTL_LAT][16:0] == {FMAX_PIPE[0], MUL_LATENCY[7:0], ADD_LATENCY[7:0]} &&
                (NL > 1 || !run[R_RTL_LAT][17]);
    if (run[R_MAGIC] !== ID_VALUE || run[R_VERSION] !== RUN_VERSION) begin
      $display("FAIL: tb_fp3: %0s/run.hex is not an fp3 tbgen file of version %0d (run fp3 tbgen again)",
               dir, RUN_VERSION);
      finish(1);
    end
    for (u = 0; u < 2; u = u + 1)
      for (i = 0; i < NAME_WORDS; i = i + 1)
        sname[u][32*(NAME_WORDS-1-i) +: 32] = run[(u == 0 ? R_NAME_V : R_NAME_S) + i];
    if (run[R_NUM_REGS] != NUM_REGS || run[R_NWORDS] > IMEM_DEPTH || run[R_NWORDS] == 0 ||
        run[R_NCHECK] > MAX_CHECK) begin
      $display("FAIL: tb_fp3: the files are for %0d registers and %0d words (%0d checked integrations); this build has %0d registers, %0d words (%0d)",
               run[R_NUM_REGS], run[R_NWORDS], run[R_NCHECK], NUM_REGS, IMEM_DEPTH, MAX_CHECK);
      finish(1);
    end
    for (i = 0; i < IMEM_DEPTH; i = i + 1) prog[i] = 64'd0;
    need_file({dir, "/program.hex"});
    $readmemh({dir, "/program.hex"}, prog, 0, run[R_NWORDS] - 1);
    need_file({dir, "/init.hex"});
    $readmemh({dir, "/init.hex"}, init, 0, NUM_REGS - 1);
    need_file({dir, "/expected.hex"});
    $readmemh({dir, "/expected.hex"}, expect_, 0, NUM_REGS + 2*run[R_NCHECK] - 1);
    for (c = 0; c < NC; c = c + 1)
      for (u = 0; u < 2; u = u + 1)
        for (l = 0; l < NL; l = l + 1) begin
          cur[(2*c + u) * NL + l] = run[R_REG_V + u] < NUM_REGS ? init[run[R_REG_V + u]] : 32'd0;
          next_k[(2*c + u) * NL + l] = 1;
        end
    if (!$value$plusargs("steps=%d", steps_run)) steps_run = run[R_STEPS];
    issued_want = run[R_ISSUED] * contexts;
    if (!$value$plusargs("watchdog=%d", watchdog_limit))
      watchdog_limit = issued_want * (MAX_LAT + 1) + 100;

    if (wave != 0) begin
      $dumpfile(wave);
      $dumpvars(0, tb_fp3);
      if (!$test$plusargs("dump_load")) $dumpoff;
    end

    // reset, identity, configuration
    repeat (2) @(posedge clk);
    @(negedge clk) rst = 1'b0;
    host_read(HR_ID, rd);
    expect_eq("ID", rd, ID_VALUE);
    host_read(HR_INFO0, rd);
    expect_eq("INFO0", rd, {IMEM_DEPTH[15:0], NUM_REGS[15:0]});
    host_read(HR_INFO2, rd);
    // (HAS_SIGN 1: fp3_top's default)
    expect_eq("INFO2", rd, {NL[7:0], 1'b0, WB_PORTS == 1, 1'b1, HAS_SQRT[0], HAS_DIV[0], HAS_MUL[0],
                            HAS_SUB[0], HAS_ADD[0], NC[15:0]});

    // program (every entry), registers of each context, steps, start
    for (i = 0; i < IMEM_DEPTH; i = i + 1) begin
      w = prog[i];
      host_write(HR_IMEM_BASE + {i[10:0], 1'b0}, w[31:0]);
      host_write(HR_IMEM_BASE + {i[10:0], 1'b1}, w[63:32]);
    end
    for (c = 0; c < contexts; c = c + 1) begin
      host_write(HR_CTX, c);
      for (l = 0; l < NL; l = l + 1) begin
        host_write(HR_LANE, l);
        for (i = 0; i < NUM_REGS; i = i + 1) host_write(HR_REG_BASE + i[11:0], init[i]);
      end
    end
    host_write(HR_CONTEXTS, contexts);
    host_write(HR_STEPS, steps_run);
    host_read(HR_STEPS, rd);
    expect_eq("STEPS read back", rd, steps_run);
    if (wave != 0) $dumpon;
    $display("tb_fp3: %0d program words, %0d context(s) x %0d lane(s) of %0d registers, STEPS %0d, ADD_LATENCY %0d, MUL_LATENCY %0d; START at t = %0t ns",
             run[R_NWORDS], contexts, NL, NUM_REGS, steps_run, ADD_LATENCY, MUL_LATENCY, $time);
    host_write(HR_CTRL, CTRL_START);
    started = 1'b1;

    // the run: the always block above checks every cycle
    @(posedge clk);
    while (running) @(posedge clk);
    #1;
    for (c = 0; c < contexts; c = c + 1)
      for (l = 0; l < NL; l = l + 1)
        for (u = 0; u < 2; u = u + 1) finalise(c, l, u, run[R_NCHECK] + 1);
    for (u = 1; u < 5; u = u + 1)
      if (tag_cnt[u] != 0) begin
        errors = errors + 1;
        $display("ERROR: run ended with %0d results of unit %0d not written back", tag_cnt[u], u);
      end

    // status, counters, registers
    host_read(HR_ISSUED_LO, rd);
    expect_eq("ISSUED", rd, issued_want);
    for (l = 0; l < NL; l = l + 1) begin   // (of context CTX, each lane)
      host_write(HR_LANE, l);
      host_read(HR_FLAGS, rd);
      expect_eq("FLAGS", rd, run[R_FLAGS]);
    end
    host_read(HR_CYCLES_LO, cycles_lo);
    host_read(HR_STALLS_LO, stalls_lo);
    expect_eq("CYCLES vs the trace", cycles_lo, run_cycle);
    expect_eq("STALLS vs the probes", stalls_lo, probe_stalls);
    if (rtl_timed) begin
      // (A Verilated model of one lane against lanes here: the end of the
      // run and each beq come later by the lanes' broadcast stages:
      // fp3_top LD, FP3_LANES_STAGE_CYCLES and FP3_LANES_BEQ_CYCLES.  Of
      // lanes against lanes: the same.)
      expect_eq("CYCLES vs Verilator", cycles_lo,
                run[R_RTL_CYCLES] + (NL > 1 && !run[R_RTL_LAT][17] ? LD + beqs * (LD + 1) : 0));
      expect_eq("STALLS vs Verilator", stalls_lo, run[R_RTL_STALLS]);
    end
    for (c = 0; c < contexts; c = c + 1) begin
      host_write(HR_CTX, c);
      host_read(HR_STATUS, status);
      expect_eq("STATUS.DONE", {31'd0, status[1]}, 32'd1);
      expect_eq("STATUS.ERROR", {28'd0, status[11:8]}, run[R_ERROR]);
      if (status[11:8] != 4'd0) begin
        host_read(HR_FAULT_PC, rd);
        expect_eq("FAULT_PC", rd, run[R_FAULT_PC]);
      end
      host_read(HR_STEPS_DONE, rd);
      expect_eq("STEPS_DONE", rd, run[R_STEPS_DONE]);
      for (l = 0; l < NL; l = l + 1) begin
        host_write(HR_LANE, l);
        for (i = 0; i < NUM_REGS; i = i + 1) begin
          host_read(HR_REG_BASE + i[11:0], rd);
          if (rd !== expect_[i]) begin
            errors = errors + 1;
            if (NL == 1)
              $display("ERROR: context %0d: r%0d = %h (%g) at the end, expected %h (%g)",
                       c, i, rd, f32_real(rd), expect_[i], f32_real(expect_[i]));
            else
              $display("ERROR: context %0d, lane %0d: r%0d = %h (%g) at the end, expected %h (%g)",
                       c, l, i, rd, f32_real(rd), expect_[i], f32_real(expect_[i]));
          end
        end
      end
    end

    $display("tb_fp3: %0d cycles, %0d stalls, %0d integrations; first endi in cycle %0d",
             cycles_lo, stalls_lo, endis_total, cyc_first);
    if (contexts == 1 && endis_total >= 2)
      $display("tb_fp3: first integration %0d cycles, later %0d.%02d per integration",
               cyc_first + 1, (cyc_last - cyc_first) / (endis_total - 1),
               ((cyc_last - cyc_first) * 100 / (endis_total - 1)) % 100);
    if (endis_total >= 1)
      $display("tb_fp3: %0d.%02d cycles per object-step over the whole run",
               cycles_lo / endis_total, (cycles_lo * 100 / endis_total) % 100);
    if (rtl_timed)
      $display("tb_fp3: Verilator: %0d cycles, %0d stalls", run[R_RTL_CYCLES], run[R_RTL_STALLS]);
    else
      $display("tb_fp3: no Verilator cycle count for this configuration: cycles not compared");
    if (errors == 0) begin
      if (run[R_REG_S] < NUM_REGS)
        $display("PASS: tb_fp3: %0d context(s) x %0d integrations, %0s and %0s bit-exact after each (%0d values), %0d registers each, status and counters as expected, %0d lane(s) per context",
                 contexts, run[R_STEPS_DONE], sname[0], sname[1], checked, NUM_REGS, NL);
      else
        $display("PASS: tb_fp3: %0d context(s) x %0d integrations, %0s bit-exact after each (%0d values), %0d registers each, status and counters as expected, %0d lane(s) per context",
                 contexts, run[R_STEPS_DONE], sname[0], checked, NUM_REGS, NL);
      finish(0);
    end else begin
      $display("FAIL: tb_fp3: %0d errors (%0d state mismatches in %0d values)", errors, mismatches, checked);
      finish(1);
    end
  end
endmodule
`default_nettype wire
