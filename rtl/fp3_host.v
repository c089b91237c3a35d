// fp3_host -- the host port of the FP3 processor: the registers the host
// writes (CTRL, STEPS, CONTEXTS, CTX, LANE, the program window's low
// word), the write strobes towards the scheduler (program load, START,
// CLEAR) and the lanes' register files (the register window), and the
// registered read multiplexer over status, counters, configuration,
// FLAGS and the register window.
//
// The port's behaviour, its map and its read latency are fp3_top's
// ("Host port"): writes take effect at the clock edge, reads return
// READ_STAGES + HOST_STAGES cycles after the address, and the registers,
// the register window and the program window take writes only while no
// run is in progress (the register window reads as zero while running:
// the register file's read ports belong to the issue pipeline then).
// fp3_host_dec decodes which writable register an address names (or the
// writer does: HOST_WSEL).
//
// What a START needs of STEPS and CONTEXTS is decided here as the host
// writes them, so that the scheduler's START compares nothing 32 bits
// wide.  CTX is kept in copies placed by their loads (fp3_keep): the
// scheduler's selected-context words and the flags' context multiplexers.
//
// Parameters
//   NUM_CONTEXTS  contexts, >= 1; CW = clog2, >= 1 (fp3_top's)
//   NUM_LANES     lanes, 1 .. 64; LANE is LW = clog2 bits, >= 1
//   NUM_REGS      registers per context; IW = clog2(NUM_REGS) (fp3_top's)
//   IMEM_DEPTH    instruction memory entries; AW = clog2 (fp3_top's)
//   READ_STAGES   the register file's read stages (fp3_top READ): cycles
//                 from a read's address to its data; with 2 or more the
//                 read multiplexer is split by a register (HSPLIT, below)
//   HOST_STAGES   0 or 1: the lanes' host read takes one more (fp3_simd
//                 BCAST: lanes 1 .. register the host's address)
//   ADD_LATENCY, MUL_LATENCY, DIV_LATENCY, ROUND, FTZ, FMAX_PIPE,
//   HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV, HAS_SQRT, HAS_SIGN, WB_PORTS
//                 fp3_top's, reported in INFO0 .. INFO2
//   CTX_CHECKED   0: a write to CTX of a number >= NUM_CONTEXTS, or to LANE
//                 of one >= NUM_LANES, is ignored here; 1: the writer never
//                 makes one (fp3_top)
//   HOST_WSEL     0: a write's register is decoded here from host_addr_i;
//                 1: the writer decodes it and gives it on host_wsel_i
//                 (fp3_top)
// Ports
//   host_*        fp3_top's host port (host_rdata_o registered, as above)
//   imem_we_o, imem_waddr_o, imem_wdata_o  a program word written (its
//                 high half completes it), start_o, clear_o: CTRL's bits,
//                 to fp3_scheduler
//   steps_o       STEPS as written (the scheduler's formal checker)
//   steps_zero_o, steps_one_o, steps_last2_o, contexts_bad_o,
//   contexts_run_o  STEPS == 0, == 1, STEPS - 2, CONTEXTS outside
//                 1 .. NUM_CONTEXTS, the contexts a START runs (bit k:
//                 k < CONTEXTS), registered as the host writes them
//   sel_ctx_o     CTX, the scheduler's copy (its *_sel_o words)
//   running_i .. stalls_i  the scheduler's status and counters: RUNNING,
//                 DONE, some context's error, and those of context
//                 sel_ctx_o: ERROR, FAULT_PC, STEPS_DONE; the counters
//   reg_we_o      per lane: a write of the register window to that lane
//                 (LANE's); reg_idx_o its index {CTX, register}, also the
//                 read's (fp3_simd host_*_i; the data are host_wdata_i)
//   reg_rdata_i   every lane's read of reg_idx_o (fp3_simd host_rdata_o),
//                 READ_STAGES + HOST_STAGES cycles after the address
//   flags_clr_o   the run's first cycle, a cycle after a START taken: the
//                 sticky flags clear
//   flags_ctx_o   CTX, the flags' copy; flags_i every lane's sticky flags
//                 of that context (fp3_simd flags_o)
`default_nettype none
module fp3_host #(
  parameter integer NUM_CONTEXTS = 8,
  parameter integer CW           = 3,
  parameter integer NUM_LANES    = 1,
  parameter integer NUM_REGS     = 32,
  parameter integer IW           = 5,
  parameter integer IMEM_DEPTH   = 256,
  parameter integer AW           = 8,
  parameter integer READ_STAGES  = 1,
  parameter integer HOST_STAGES  = 0,
  parameter integer ADD_LATENCY  = 4,
  parameter integer MUL_LATENCY  = 3,
  parameter integer DIV_LATENCY  = 8,
  parameter integer ROUND        = 0,
  parameter integer FTZ          = 0,
  parameter integer FMAX_PIPE    = 0,
  parameter integer HAS_ADD      = 1,
  parameter integer HAS_SUB      = 1,
  parameter integer HAS_MUL      = 1,
  parameter integer HAS_DIV      = 1,
  parameter integer HAS_SQRT     = 1,
  parameter integer HAS_SIGN     = 1,
  parameter integer WB_PORTS     = 4,
  parameter integer CTX_CHECKED  = 0,
  parameter integer HOST_WSEL    = 0
) (
  input  wire                     clk_i,
  input  wire                     rst_i,
  // the host port
  input  wire                     host_we_i,
  input  wire [11:0]              host_addr_i,
  input  wire [31:0]              host_wdata_i,
  input  wire [7:0]               host_wsel_i,    // HOST_WSEL = 1: fp3_host_dec of host_addr_i
  output wire [31:0]              host_rdata_o,
  // program load and run control (fp3_scheduler)
  output wire                     imem_we_o,
  output wire [AW-1:0]            imem_waddr_o,
  output wire [63:0]              imem_wdata_o,
  output wire                     start_o,
  output wire                     clear_o,
  output wire [31:0]              steps_o,
  output wire                     steps_zero_o,
  output wire                     steps_one_o,
  output wire [31:0]              steps_last2_o,
  output wire                     contexts_bad_o,
  output wire [NUM_CONTEXTS-1:0]  contexts_run_o,
  output wire [CW-1:0]            sel_ctx_o,
  // status and counters (fp3_scheduler)
  input  wire                     running_i,
  input  wire                     done_i,
  input  wire                     any_error_i,
  input  wire [3:0]               error_i,
  input  wire [31:0]              fault_pc_i,
  input  wire [31:0]              steps_done_i,
  input  wire [63:0]              cycles_i,
  input  wire [63:0]              issued_i,
  input  wire [63:0]              stalls_i,
  // the lanes' register window and sticky flags (fp3_simd)
  output wire [NUM_LANES-1:0]     reg_we_o,
  output wire [CW+IW-1:0]         reg_idx_o,
  input  wire [32*NUM_LANES-1:0]  reg_rdata_i,
  output wire                     flags_clr_o,
  output wire [CW-1:0]            flags_ctx_o,
  input  wire [5*NUM_LANES-1:0]   flags_i
);
`include "fp3_isa.vh"

  localparam integer NL   = NUM_LANES;
  localparam integer LW   = (NUM_LANES <= 2) ? 1 : $clog2(NUM_LANES);   // LANE's width
  localparam integer READ = READ_STAGES;
  localparam integer BC   = HOST_STAGES;
  localparam [0:0]   WB1  = WB_PORTS == 1;

  // ---- host port decode ----------------------------------------------------
  // The register or window host_addr_i names (hsel: reads, and writes
  // with HOST_WSEL = 0), and the one a write takes (wsel): fp3_host_dec's
  // one-hot {LANE, program high word, program low word, register window,
  // CTX, CONTEXTS, STEPS, CTRL}.
  wire [7:0]  hsel, wsel;
  wire        hsel_imem_ok;   // (hsel[6] has it for the writes)
  fp3_host_dec #(.NUM_REGS(NUM_REGS), .IW(IW), .IMEM_DEPTH(IMEM_DEPTH), .AW(AW)) u_host_dec (
    .addr_i    (host_addr_i),
    .wsel_o    (hsel),
    .imem_ok_o (hsel_imem_ok)
  );
  generate
    if (HOST_WSEL != 0) begin : g_wsel_in
      assign wsel = host_wsel_i;
      wire unused_hsel = &{1'b0, hsel[7:5], hsel[3:0], hsel_imem_ok};   // (reads use hsel[4])
    end else begin : g_wsel_here
      assign wsel = hsel;
      wire unused_wsel = &{1'b0, host_wsel_i, hsel_imem_ok};
    end
  endgenerate
  wire [AW-1:0] imem_idx = host_addr_i[AW:1];   // (hsel checks its range)

  reg  [31:0] steps_q;
  reg  [31:0] contexts_q;
  reg  [CW-1:0] ctx_q;     // context the host sees
  reg  [LW-1:0] lane_q;    // lane the host sees
  reg  [31:0] imem_lo_q;   // low half of an instruction being written

  wire host_idle   = !running_i;
  // A write to CTX taken (ctx_q and its copies, below)
  wire ctx_we      = host_we_i && host_idle && wsel[3] &&
                     (CTX_CHECKED != 0 || host_wdata_i < NUM_CONTEXTS);
  // ... and to LANE
  wire lane_we     = host_we_i && host_idle && wsel[7] &&
                     (CTX_CHECKED != 0 || host_wdata_i < NUM_LANES);
  wire wr_ctrl     = host_we_i && wsel[0];
  wire start       = wr_ctrl && host_wdata_i[0];
  wire clear       = wr_ctrl && host_wdata_i[1];
  wire host_reg_we = host_we_i && host_idle && wsel[4];
  wire imem_we     = host_we_i && host_idle && wsel[6];
  // the instruction word a write of its high half completes
  wire [63:0] imem_wdata = {host_wdata_i, imem_lo_q};

  // What a START needs of STEPS and CONTEXTS, decided as the host writes
  // them (the scheduler's START then compares nothing 32 bits wide): STEPS
  // is 0, is 1, STEPS - 2; CONTEXTS is outside 1..NUM_CONTEXTS; the
  // contexts it starts (k < CONTEXTS), one bit each.
  reg                    steps_zero_q, steps_one_q, contexts_bad_q;
  reg  [31:0]            steps_last2_q;
  reg  [NUM_CONTEXTS-1:0] contexts_run_q;
  integer k;
  always @(posedge clk_i) begin
    if (rst_i) begin
      steps_q        <= 32'd0;
      steps_zero_q   <= 1'b1;
      steps_one_q    <= 1'b0;
      steps_last2_q  <= 32'hffff_fffe;
      contexts_q     <= 32'd1;
      contexts_bad_q <= 1'b0;
      contexts_run_q <= {{(NUM_CONTEXTS-1){1'b0}}, 1'b1};
      ctx_q          <= {CW{1'b0}};
      lane_q         <= {LW{1'b0}};
    end else if (host_we_i && host_idle) begin
      if (wsel[1]) begin
        steps_q       <= host_wdata_i;
        steps_zero_q  <= host_wdata_i == 32'd0;
        steps_one_q   <= host_wdata_i == 32'd1;
        steps_last2_q <= host_wdata_i - 32'd2;
      end
      if (wsel[2]) begin
        contexts_q     <= host_wdata_i;
        contexts_bad_q <= host_wdata_i == 32'd0 || host_wdata_i > NUM_CONTEXTS;
        for (k = 0; k < NUM_CONTEXTS; k = k + 1) contexts_run_q[k] <= k < host_wdata_i;
      end
      if (ctx_we)                     ctx_q      <= host_wdata_i[CW-1:0];
      if (lane_we)                    lane_q     <= host_wdata_i[LW-1:0];
    end
    if (host_we_i && wsel[5]) imem_lo_q <= host_wdata_i;
  end
  // CTX's copies for the selected context's words, kept, each placed
  // beside its multiplexers: the scheduler's (STATUS's error, FAULT_PC,
  // STEPS_DONE: ctx_sch) and the flags' (FLAGS: ctx_flg).  ctx_q, which
  // also indexes the register file's host port, across the die to the
  // flags' multiplexer is otherwise a critical path of the placement.
  wire [CW-1:0] ctx_sch, ctx_flg;
  fp3_keep #(.W(CW)) u_ctx_sch (
    .clk_i (clk_i),
    .d_i   (rst_i ? {CW{1'b0}} : ctx_we ? host_wdata_i[CW-1:0] : ctx_sch),
    .q_o   (ctx_sch)
  );
  fp3_keep #(.W(CW)) u_ctx_flg (
    .clk_i (clk_i),
    .d_i   (rst_i ? {CW{1'b0}} : ctx_we ? host_wdata_i[CW-1:0] : ctx_flg),
    .q_o   (ctx_flg)
  );

  assign imem_we_o      = imem_we;
  assign imem_waddr_o   = imem_idx;
  assign imem_wdata_o   = imem_wdata;
  assign start_o        = start;
  assign clear_o        = clear;
  assign steps_o        = steps_q;
  assign steps_zero_o   = steps_zero_q;
  assign steps_one_o    = steps_one_q;
  assign steps_last2_o  = steps_last2_q;
  assign contexts_bad_o = contexts_bad_q;
  assign contexts_run_o = contexts_run_q;
  assign sel_ctx_o      = ctx_sch;
  assign flags_ctx_o    = ctx_flg;

  // ---- the register window: the lane LANE names ----------------------------
  assign reg_idx_o = {ctx_q, host_addr_i[IW-1:0]};
  genvar ln;
  generate
    for (ln = 0; ln < NL; ln = ln + 1) begin : g_reg_we
      assign reg_we_o[ln] = host_reg_we && lane_q == ln[LW-1:0];
    end
  endgenerate

  // ---- the sticky flags' clear ---------------------------------------------
  // The run's first cycle, a cycle after its START (as the scheduler clears
  // its counters), in which nothing has issued yet: so the host port's
  // decode does not reach the flags.
  reg fclr_q;
  always @(posedge clk_i) fclr_q <= start && host_idle;
  assign flags_clr_o = fclr_q;

  // ---- host read mux (registered) ------------------------------------------
  // The words of the four addresses host_addr_i[11:2] names (hr_four),
  // then the one host_addr_i[1:0] names.  With READ >= 2 (FMAX_PIPE) the
  // four words are registered between the two halves (HSPLIT), sampled in
  // the cycle of the address as before, and the read takes READ cycles
  // still.  The words of context CTX (STATUS, STEPS_DONE, FAULT_PC,
  // FLAGS) are then registered in every cycle instead, as selected, and
  // taken in the second half (so the context select does not reach the
  // address's multiplexer): the same cycle's values.
  localparam integer HSPLIT = (READ >= 2) ? 1 : 0;
  // The selected context's flags, of lane LANE (flags_sel).  With HSPLIT
  // FLAGS takes its own path: each lane's flags of context ctx_flg
  // registered beside that lane in every cycle (fsel_q, 5 flip-flops a
  // lane), and the lane multiplexer after those registers, in the second
  // half, by a copy of LANE of its own (lane_flg, kept).  So the context
  // multiplexers and the staged cycle's compares end in their lane, and
  // only a registered 5-bit word a lane crosses the die to the
  // multiplexer; the read returns the address cycle's flags as the other
  // words of context CTX do.
  wire [5*NL-1:0] flags_src;   // flags_i, or (HSPLIT) flags_i of the cycle before
  wire [4:0]      flags_sel;
  generate
    if (HSPLIT != 0) begin : g_flags_split
      reg [5*NL-1:0] fsel_q;
      always @(posedge clk_i) fsel_q <= flags_i;
      assign flags_src = fsel_q;
    end else begin : g_flags_now
      assign flags_src = flags_i;
    end
    if (NL == 1) begin : g_flags_one
      assign flags_sel = flags_src;
    end else begin : g_flags_lane
      wire [LW-1:0] lane_fl;   // the lane multiplexer's select
      if (HSPLIT != 0) begin : g_lane_flg
        fp3_keep #(.W(LW)) u_lane_flg (
          .clk_i (clk_i),
          .d_i   (rst_i ? {LW{1'b0}} : lane_we ? host_wdata_i[LW-1:0] : lane_fl),
          .q_o   (lane_fl)
        );
      end else begin : g_lane_q
        assign lane_fl = lane_q;
      end
      assign flags_sel = flags_src[5*lane_fl +: 5];
    end
  endgenerate
  wire [31:0] w_status = {20'd0, error_i, 5'd0, any_error_i, done_i, running_i};
  wire [31:0] w_flags  = {27'd0, flags_sel};
  wire        in_four  = HSPLIT == 0;   // the context's words are in hr_four
  // The scalar registers are words 0x000 .. 0x01F of the map (HR_INFO2,
  // the last, is checked below): hr_four is chosen by host_addr_i[4:2]
  // only, and whether the address is among those words at all (scal) is
  // applied after the choice (with HSPLIT, registered beside it).  So no
  // compare of the whole address clears the four words' registers (as a
  // synchronous reset from the address decode it was a critical path).
  wire        scal = host_addr_i[11:5] == 7'd0;
  reg [127:0] hr_four;
  integer hk;
  always @(*) begin
    hr_four = 128'd0;
    for (hk = 0; hk < 4; hk = hk + 1) begin
      case ({host_addr_i[4:2], hk[1:0]})
        HR_STATUS[4:0]:     hr_four[32*hk +: 32] = in_four ? w_status : 32'd0;
        HR_STEPS[4:0]:      hr_four[32*hk +: 32] = steps_q;
        HR_STEPS_DONE[4:0]: hr_four[32*hk +: 32] = in_four ? steps_done_i : 32'd0;
        HR_FAULT_PC[4:0]:   hr_four[32*hk +: 32] = in_four ? fault_pc_i : 32'd0;
        HR_FLAGS[4:0]:      hr_four[32*hk +: 32] = in_four ? w_flags : 32'd0;
        HR_CYCLES_LO[4:0]:  hr_four[32*hk +: 32] = cycles_i[31:0];
        HR_CYCLES_HI[4:0]:  hr_four[32*hk +: 32] = cycles_i[63:32];
        HR_ISSUED_LO[4:0]:  hr_four[32*hk +: 32] = issued_i[31:0];
        HR_ISSUED_HI[4:0]:  hr_four[32*hk +: 32] = issued_i[63:32];
        HR_STALLS_LO[4:0]:  hr_four[32*hk +: 32] = stalls_i[31:0];
        HR_STALLS_HI[4:0]:  hr_four[32*hk +: 32] = stalls_i[63:32];
        HR_INFO0[4:0]:      hr_four[32*hk +: 32] = {IMEM_DEPTH[15:0], NUM_REGS[15:0]};
        HR_INFO1[4:0]:      hr_four[32*hk +: 32] = {5'd0, DIV_LATENCY[7:0], FMAX_PIPE[0], FTZ[0],
                                                    ROUND[0], MUL_LATENCY[7:0], ADD_LATENCY[7:0]};
        HR_ID[4:0]:         hr_four[32*hk +: 32] = ID_VALUE;
        HR_CTX[4:0]:        hr_four[32*hk +: 32] = {{(32-CW){1'b0}}, ctx_q};
        HR_CONTEXTS[4:0]:   hr_four[32*hk +: 32] = contexts_q;
        HR_INFO2[4:0]:      hr_four[32*hk +: 32] = {NUM_LANES[7:0], 1'b0, WB1, HAS_SIGN[0],
                                                    HAS_SQRT[0], HAS_DIV[0], HAS_MUL[0],
                                                    HAS_SUB[0], HAS_ADD[0], NUM_CONTEXTS[15:0]};
        HR_LANE[4:0]:       hr_four[32*hk +: 32] = {{(32-LW){1'b0}}, lane_q};
        default:            hr_four[32*hk +: 32] = 32'd0;
      endcase
    end
  end
  generate
    if (HR_INFO2 > 12'h01F || HR_LANE > 12'h01F) begin : g_bad_map
      // Elaboration error on purpose: the scalar map outgrew host_addr_i[4:0].
      fp3_host_error_scalar_registers_must_be_words_0_to_31 u_error ();
    end
  endgenerate
  wire         hr_reg = hsel[4] && host_idle;   // a register of the window
  wire [31:0]  rdata_d;    // the word host_addr_i named (READ - HSPLIT cycles to go)
  wire         hr_reg_w;   // ... it is the register file's
  generate
    if (HSPLIT != 0) begin : g_host_split
      reg [127:0] four_q;
      reg [1:0]   lo_q;
      reg         scal_q;
      reg         reg_q;
      reg [31:0]  st_q, sd_q, fpc_q;   // context CTX's words (FLAGS: w_flags, from fsel_q)
      reg [3:0]   ctxw_q;  // one-hot: host_addr_i named one of them (STATUS .. FLAGS)
      always @(posedge clk_i) begin
        four_q   <= hr_four;
        lo_q     <= host_addr_i[1:0];
        scal_q   <= scal;
        reg_q    <= hr_reg && !rst_i;
        st_q     <= w_status;
        sd_q     <= steps_done_i;
        fpc_q    <= fault_pc_i;
        ctxw_q   <= {host_addr_i == HR_FLAGS, host_addr_i == HR_FAULT_PC,
                     host_addr_i == HR_STEPS_DONE, host_addr_i == HR_STATUS};
      end
      assign rdata_d = ({32{scal_q}} & four_q[32*lo_q +: 32]) | ({32{ctxw_q[0]}} & st_q) |
                       ({32{ctxw_q[1]}} & sd_q) | ({32{ctxw_q[2]}} & fpc_q) |
                       ({32{ctxw_q[3]}} & w_flags);
      assign hr_reg_w = reg_q;
    end else begin : g_host_one
      assign rdata_d  = {32{scal}} & hr_four[32*host_addr_i[1:0] +: 32];
      assign hr_reg_w = hr_reg;
    end
  endgenerate
  // A register of the window comes straight from the register file's read
  // port A, which answers READ (+ HOST_STAGES) cycles after the address;
  // the other registers are delayed to match.
  wire [31:0] rdata_q;
  wire        reg_read_q;
  fp_pipe #(.WIDTH(32), .DEPTH(READ - HSPLIT + BC)) u_host_read (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (hr_reg_w),
    .data_i  (rdata_d),
    .valid_o (reg_read_q),
    .data_o  (rdata_q)
  );
  wire [31:0] ra_data_sel = reg_rdata_i[32*lane_q +: 32];   // lane LANE's port A
  assign host_rdata_o = reg_read_q ? ra_data_sel : rdata_q;

  // Host address bits that select windows but are not register indices.
  wire unused_addr = &{1'b0, host_addr_i};
endmodule
`default_nettype wire
