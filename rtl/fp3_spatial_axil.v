// fp3_spatial_axil -- AXI4-Lite slave of a spatial chip: the register map
// of sw/isa/fp3_spatial_regs.h (the one source; tests/test_spatial.sh
// reads every register through it) over the host port and the run inputs
// of fp3_spatial_frame.
//
// Byte address = word address x 4; 24 address bits decoded (bits [1:0]
// are not).  Data are 32 bits wide.
//
// Channels, as fp3_axil's: AW and W are accepted independently, in either
// order, into a one-entry holding register each; the write is decided
// once both are held and the B channel is free (or being emptied this
// cycle), and performed in the next cycle.  AR is held likewise, decided
// and performed a cycle later; the read's word is captured RD_CYCLES = 6
// cycles after it is performed (the host port's register, the frame's
// two-cycle memory read and its three read stages) and held on R until
// RREADY.  B and R stay valid, with stable payload, until accepted.  Each
// channel takes a new transfer every second cycle (reads every eighth:
// one read in flight).  When N is not a power of
// two, an access to a window waits clog2(M + 1) + 1 cycles for its object
// or entry number's division by N (fp3_spatial_divn; none for the next
// word of the same object), and a write to the awake list or COUNT as
// long for its word's.  A write and a read that are both ready in one
// cycle take turns (round robin).  All outputs are registered; no READY
// depends combinationally on a VALID.  The side band (running_o, done_o)
// follows STATUS a cycle later.
//
// Addresses are decoded as they are captured (fp3_spatial_dec; the
// awake entry's object number as the W word is), so that the checks at
// the access are a few flip-flops, compares of the held offset and
// RUNNING.
//
// Responses: OKAY, or SLVERR (2'b10) with no effect and RDATA 0 for
//   - a write to a read-only or unmapped address; a read of CTRL or of an
//     unmapped address;
//   - a write whose WSTRB is not 4'b1111;
//   - while a run is in progress: a write to STEPS or COUNT, and any
//     access to a window;
//   - a write to COUNT of a value above MAXOBJ;
//   - a window address whose object or entry number is >= MAXOBJ, or
//     whose word is at or beyond the object's words within its stride;
//   - a write to the awake list of a value other than 0xFFFFFFFF (the empty
//     slot) that is >= MAXOBJ or of another bank than the entry's.
// CTRL is always writable; START while running is ignored (the feeder's).
//
// Parameters
//   PIPELINES, INPUTS, CARRIED, LATENCY  the chip's N, words per object,
//              the step module's LATENCY (INFO, LATENCY)
//   MAXOBJ     M, a multiple of N, M x stride <= 2^20 in either window
//   RW, RB, BW  the frame's widths (fp3_spatial_frame)
//   SLOG, ILOG log2 of the windows' object strides
//   HASH       the step module's hash, low 32 bits (HASH)
// Reset: rst_i, synchronous, active high (invert ARESETn outside); STEPS
// and COUNT reset to 0.
`default_nettype none
module fp3_spatial_axil #(
  parameter integer PIPELINES = 1,
  parameter integer INPUTS    = 1,
  parameter integer CARRIED   = 1,
  parameter integer LATENCY   = 1,
  parameter integer MAXOBJ    = 2,
  parameter integer RW        = 1,
  parameter integer RB        = 2,
  parameter integer BW        = 1,
  parameter integer SLOG      = 0,
  parameter integer ILOG      = 0,
  parameter [31:0]  HASH      = 32'd0
) (
  input  wire          clk_i,
  input  wire          rst_i,
  // write address channel
  input  wire [23:0]   s_axil_awaddr_i,
  input  wire [2:0]    s_axil_awprot_i,
  input  wire          s_axil_awvalid_i,
  output wire          s_axil_awready_o,
  // write data channel
  input  wire [31:0]   s_axil_wdata_i,
  input  wire [3:0]    s_axil_wstrb_i,
  input  wire          s_axil_wvalid_i,
  output wire          s_axil_wready_o,
  // write response channel
  output wire [1:0]    s_axil_bresp_o,
  output wire          s_axil_bvalid_o,
  input  wire          s_axil_bready_i,
  // read address channel
  input  wire [23:0]   s_axil_araddr_i,
  input  wire [2:0]    s_axil_arprot_i,
  input  wire          s_axil_arvalid_i,
  output wire          s_axil_arready_o,
  // read data channel
  output wire [31:0]   s_axil_rdata_o,
  output wire [1:0]    s_axil_rresp_o,
  output wire          s_axil_rvalid_o,
  input  wire          s_axil_rready_i,
  // side band: a run is in progress / the last run has ended (interrupt)
  output wire          running_o,
  output wire          done_o,
  // the frame's host port (fp3_spatial_frame)
  output wire          host_we_o,
  output wire          host_re_o,
  output wire [1:0]    host_sel_o,
  output wire [BW-1:0] host_bank_o,
  output wire [RW-1:0] host_row_o,
  output wire [7:0]    host_word_o,
  output wire [31:0]   host_wdata_o,
  input  wire [31:0]   host_rdata_i,
  // the frame's run
  output wire          start_o,
  output wire [31:0]   steps_o,
  output wire [RB-1:0] rounds_o,
  output wire [BW:0]   tail_o,
  input  wire          running_i,
  input  wire          done_i,
  input  wire [63:0]   cycles_i,
  input  wire [4:0]    flags_i
);
  localparam [1:0]  RESP_OKAY   = 2'b00;
  localparam [1:0]  RESP_SLVERR = 2'b10;
  localparam [3:0]  STRB_ALL    = 4'b1111;
  localparam [1:0]  SEL_SCALAR  = 2'd0;
  localparam [1:0]  SEL_AWAKE   = 2'd1;
  localparam integer RD_CYCLES  = 6;
  // the scalar registers (fp3_spatial_regs.h FP3S_REGS)
  localparam [19:0] R_ID = 20'h000, R_HASH = 20'h001, R_INFO = 20'h002, R_LATENCY = 20'h003,
                    R_MAXOBJ = 20'h004, R_STRIDES = 20'h005, R_CTRL = 20'h008,
                    R_STATUS = 20'h009, R_STEPS = 20'h00A, R_COUNT = 20'h00B,
                    R_CYCLES_LO = 20'h00C, R_CYCLES_HI = 20'h00D, R_FLAGS = 20'h00E;
  localparam [31:0] ID_VALUE = 32'h46503353;
  localparam [31:0] INFO_VALUE = {8'd0, CARRIED[7:0], INPUTS[7:0], PIPELINES[7:0]};
  localparam [31:0] STRIDES_VALUE = {16'd0, ILOG[7:0], SLOG[7:0]};
  // bits of the numbers the slave divides by N: objects, entries, COUNT <= M
  localparam integer DW = $clog2(MAXOBJ + 1) < 2 ? 2 : $clog2(MAXOBJ + 1);
  localparam [31:0] M32 = MAXOBJ;
  localparam [BW:0] N_T = PIPELINES[BW:0];

  // ---- state -------------------------------------------------------------------
  reg          aw_valid_q, w_valid_q, b_valid_q, ar_valid_q, r_valid_q, prio_q;
  reg [31:0]   w_data_q, r_data_q;
  reg          w_all_q;
  reg [1:0]    b_resp_q, r_resp_q;
  reg [RD_CYCLES-1:0] rd_pend_q;
  reg          rd_err_q;
  reg [31:0]   steps_q;
  reg [31:0]   count_q;
  reg [RB-1:0] rounds_q;
  reg [BW:0]   tail_q;    // entries of the last round, COUNT - (R - 1) N

  // ---- write address: captured with its decode -------------------------------
  wire          aw_take = s_axil_awvalid_i && !aw_valid_q;
  wire [1:0]    wa_sel_q;
  wire [19:0]   wa_off_q;
  wire          wa_ok_q;
  wire [BW-1:0] wa_bank_q;
  wire [RW-1:0] wa_row_q;
  wire [7:0]    wa_word_q;
  wire          wa_ready;
  fp3_spatial_dec #(.PIPELINES(PIPELINES), .MAXOBJ(MAXOBJ), .CARRIED(CARRIED),
                    .INPUTS(INPUTS), .SLOG(SLOG), .ILOG(ILOG), .RW(RW), .BW(BW),
                    .DW(DW)) u_aw_dec (
    .clk_i (clk_i), .rst_i (rst_i), .take_i (aw_take), .addr_i (s_axil_awaddr_i[23:2]),
    .sel_o (wa_sel_q), .off_o (wa_off_q), .ok_o (wa_ok_q), .bank_o (wa_bank_q),
    .row_o (wa_row_q), .word_o (wa_word_q), .ready_o (wa_ready)
  );
  wire wa_scalar = wa_sel_q == SEL_SCALAR;
  wire wa_ctrl   = wa_scalar && wa_off_q == R_CTRL;
  wire wa_steps  = wa_scalar && wa_off_q == R_STEPS;
  wire wa_count  = wa_scalar && wa_off_q == R_COUNT;

  // ---- write data: captured with the awake entry's and COUNT's decode ----------
  // (the value's row and bank, v / N and v mod N, as an awake entry's
  // object; for COUNT, the rounds ceil(v / N) = v / N + (v mod N != 0))
  wire          w_take = s_axil_wvalid_i && !w_valid_q;
  reg           wd_none_q, wd_obj_ok_q, wd_count_ok_q;
  wire [DW-1:0] wd_row;
  wire [BW-1:0] wd_bank;
  wire          wd_ready;
  fp3_spatial_divn #(.N(PIPELINES), .W(DW), .NB(BW)) u_wd_div (
    .clk_i (clk_i), .rst_i (rst_i), .start_i (w_take), .x_i (s_axil_wdata_i[DW-1:0]),
    .ready_o (wd_ready), .q_o (wd_row), .r_o (wd_bank)
  );
  always @(posedge clk_i) begin
    if (w_take) begin
      wd_none_q     <= s_axil_wdata_i == 32'hFFFFFFFF;
      wd_obj_ok_q   <= s_axil_wdata_i < M32;
      wd_count_ok_q <= s_axil_wdata_i <= M32;
    end
  end
  wire [RB-1:0] wd_rounds = wd_row[RB-1:0] + {{(RB-1){1'b0}}, wd_bank != {BW{1'b0}}};

  // ---- read address: captured with its decode ----------------------------------
  wire          ar_take = s_axil_arvalid_i && !ar_valid_q;
  wire [1:0]    ra_sel_q;
  wire [19:0]   ra_reg_q;   // a scalar register's address
  wire          ra_ok_q;
  wire [BW-1:0] ra_bank_q;
  wire [RW-1:0] ra_row_q;
  wire [7:0]    ra_word_q;
  wire          ra_ready;
  fp3_spatial_dec #(.PIPELINES(PIPELINES), .MAXOBJ(MAXOBJ), .CARRIED(CARRIED),
                    .INPUTS(INPUTS), .SLOG(SLOG), .ILOG(ILOG), .RW(RW), .BW(BW),
                    .DW(DW)) u_ar_dec (
    .clk_i (clk_i), .rst_i (rst_i), .take_i (ar_take), .addr_i (s_axil_araddr_i[23:2]),
    .sel_o (ra_sel_q), .off_o (ra_reg_q), .ok_o (ra_ok_q), .bank_o (ra_bank_q),
    .row_o (ra_row_q), .word_o (ra_word_q), .ready_o (ra_ready)
  );

  // ---- checks ------------------------------------------------------------------
  // A run is in progress, or its START is on its way to the frame (a CTRL
  // write performed in the cycle before): an access performed now would
  // reach the frame after the run has begun.
  reg  start_q;
  wire busy = running_i || start_q;
  wire wa_win = wa_sel_q != SEL_SCALAR;
  wire awake_ok = wd_none_q || (wd_obj_ok_q && wd_bank == wa_bank_q);
  // a write's checks: CTRL always; the others only while no run is in
  // progress (busy, applied at the access)
  wire wr_ok_ctrl = w_all_q && wa_ctrl;
  wire wr_ok_idle = w_all_q &&
                    (wa_steps || (wa_count && wd_count_ok_q) ||
                     (wa_win && wa_ok_q && (wa_sel_q != SEL_AWAKE || awake_ok)));
  wire ra_win = ra_sel_q != SEL_SCALAR;
  reg  sc_readable;
  reg [31:0] sc_value;
  always @(*) begin
    sc_readable = ra_sel_q == SEL_SCALAR;
    case (ra_reg_q)
      R_ID:        sc_value = ID_VALUE;
      R_HASH:      sc_value = HASH;
      R_INFO:      sc_value = INFO_VALUE;
      R_LATENCY:   sc_value = LATENCY;
      R_MAXOBJ:    sc_value = MAXOBJ;
      R_STRIDES:   sc_value = STRIDES_VALUE;
      R_STATUS:    sc_value = {30'd0, done_i, running_i};
      R_STEPS:     sc_value = steps_q;
      R_COUNT:     sc_value = count_q;
      R_CYCLES_LO: sc_value = cycles_i[31:0];
      R_CYCLES_HI: sc_value = cycles_i[63:32];
      R_FLAGS:     sc_value = {27'd0, flags_i};
      default: begin
        sc_value    = 32'd0;
        sc_readable = 1'b0;
      end
    endcase
  end
  wire rd_ok = ra_win ? (ra_ok_q && !busy) : sc_readable;

  // ---- arbitration: decided in one cycle, performed in the next -----------
  // (a window's address waits for its division, and so does the word of
  // an awake entry or COUNT; the scalar registers and the other words
  // need none).  The decision leaves registers (do_write_q, do_read_q):
  // from a divider's ready flag through both candidates and the
  // round-robin choice to the enables of the registers a write sets was
  // a placed chip's critical path.  The access is performed from them a
  // cycle later, with the held address and data, which no new transfer
  // can replace before the end of that cycle (AW, W and AR are taken
  // again only once their holding register is empty, from the decision
  // on).  RUNNING (busy) is checked at the access.  Cost: a cycle more
  // per write response and per read.
  reg  do_write_q, do_read_q;   // the access decided in the cycle before
  wire wa_divided = wa_ready || !wa_win;
  wire wd_divided = wd_ready || !(wa_sel_q == SEL_AWAKE || wa_count);
  wire wr_cand   = aw_valid_q && w_valid_q && wa_divided && wd_divided &&
                   (!b_valid_q || s_axil_bready_i);
  wire rd_cand   = ar_valid_q && (ra_ready || !ra_win) && rd_pend_q == {RD_CYCLES{1'b0}} &&
                   (!r_valid_q || s_axil_rready_i);
  wire dec_write = wr_cand && (!rd_cand || !prio_q);
  wire dec_read  = rd_cand && (!wr_cand || prio_q);
  // what the decided write may do, but for busy (its inputs hold from the
  // decision to the access)
  reg  wk_ctrl_q, wk_steps_q, wk_count_q, wk_win_q, wk_ok_ctrl_q, wk_ok_idle_q;
  always @(posedge clk_i) begin
    do_write_q <= !rst_i && dec_write;
    do_read_q  <= !rst_i && dec_read;
    if (dec_write) begin
      wk_ctrl_q    <= wa_ctrl;
      wk_steps_q   <= wa_steps;
      wk_count_q   <= wa_count;
      wk_win_q     <= wa_win;
      wk_ok_ctrl_q <= wr_ok_ctrl;
      wk_ok_idle_q <= wr_ok_idle;
    end
  end
  wire do_write  = do_write_q;
  wire do_read   = do_read_q;
  wire wr_ok     = wk_ok_ctrl_q || (!busy && wk_ok_idle_q);
  wire wr_now    = do_write && wr_ok;
  wire rd_arrive = rd_pend_q[RD_CYCLES-1];

  // a read's word: a scalar's at the read, a window's from the frame (an
  // awake entry as its object's number: the frame converts it in its last
  // read stage, so no adder lies between its read-data register and
  // r_data_q)
  reg [31:0]   rd_sc_q;
  reg          rd_win_q;
  always @(posedge clk_i) begin
    if (do_read) begin
      rd_sc_q    <= sc_value;
      rd_win_q   <= ra_win;
    end
  end
  wire [31:0] rd_word = !rd_win_q ? rd_sc_q : host_rdata_i;

  always @(posedge clk_i) begin
    if (rst_i) begin
      aw_valid_q <= 1'b0;
      w_valid_q  <= 1'b0;
      b_valid_q  <= 1'b0;
      ar_valid_q <= 1'b0;
      r_valid_q  <= 1'b0;
      rd_pend_q  <= {RD_CYCLES{1'b0}};
      prio_q     <= 1'b0;
      steps_q    <= 32'd0;
      count_q    <= 32'd0;
      rounds_q   <= {RB{1'b0}};
      tail_q     <= {(BW+1){1'b0}};
    end else begin
      prio_q    <= (wr_cand && rd_cand) ? !prio_q : prio_q;
      rd_pend_q <= {rd_pend_q[RD_CYCLES-2:0], do_read};
      // write: hold AW and W, then perform and respond
      if (aw_take) aw_valid_q <= 1'b1;
      if (w_take) w_valid_q <= 1'b1;
      if (s_axil_bready_i) b_valid_q <= 1'b0;
      if (dec_write) begin
        aw_valid_q <= 1'b0;
        w_valid_q  <= 1'b0;
      end
      if (do_write) b_valid_q <= 1'b1;
      if (wr_now && wk_steps_q) steps_q <= w_data_q;
      if (wr_now && wk_count_q) begin
        count_q  <= w_data_q;
        rounds_q <= wd_rounds;
        tail_q   <= wd_bank == {BW{1'b0}} ? N_T : {1'b0, wd_bank};
      end
      // read: hold AR, perform, capture the word
      if (ar_take) ar_valid_q <= 1'b1;
      if (dec_read) ar_valid_q <= 1'b0;
      if (s_axil_rready_i) r_valid_q <= 1'b0;
      if (rd_arrive) r_valid_q <= 1'b1;
    end
    if (w_take) begin
      w_data_q <= s_axil_wdata_i;
      w_all_q  <= s_axil_wstrb_i == STRB_ALL;
    end
    if (do_write) b_resp_q <= wr_ok ? RESP_OKAY : RESP_SLVERR;
    if (do_read) rd_err_q <= !rd_ok;
    if (rd_arrive) begin
      r_data_q <= rd_err_q ? 32'd0 : rd_word;
      r_resp_q <= rd_err_q ? RESP_SLVERR : RESP_OKAY;
    end
  end

  // ---- the frame -----------------------------------------------------------------
  // The host port leaves registers: the arbitration's decision and the
  // frame's memories are far apart on a full chip, and a path from one
  // through the other was the chip's critical path.  A window access
  // reaches the frame a cycle after it is performed, reads and writes
  // alike, so they stay in order; START leaves a register too (the
  // frame's feeder and its flags' clear are far from the slave: the path
  // from the arbitration through START to them was a placed chip's
  // critical path) and reaches the frame a cycle after CTRL is written,
  // at least a cycle after the last window write lands (one write every
  // second cycle).
  wire [31:0] host_wdata = wa_sel_q == SEL_AWAKE
                         ? {wd_none_q, {(31 - RW){1'b0}}, wd_row[RW-1:0]} : w_data_q;
  reg          host_we_q, host_re_q;
  reg [1:0]    host_sel_q;
  reg [BW-1:0] host_bank_q;
  reg [RW-1:0] host_row_q;
  reg [7:0]    host_word_q;
  reg [31:0]   host_wdata_q;
  always @(posedge clk_i) begin
    start_q      <= !rst_i && wr_now && wk_ctrl_q && w_data_q[0];
    host_we_q    <= !rst_i && wr_now && wk_win_q;
    host_re_q    <= !rst_i && do_read && rd_ok && ra_win;
    host_sel_q   <= do_write ? wa_sel_q  : ra_sel_q;
    host_bank_q  <= do_write ? wa_bank_q : ra_bank_q;
    host_row_q   <= do_write ? wa_row_q  : ra_row_q;
    host_word_q  <= do_write ? wa_word_q : ra_word_q;
    host_wdata_q <= host_wdata;
  end
  assign host_we_o    = host_we_q;
  assign host_re_o    = host_re_q;
  assign host_sel_o   = host_sel_q;
  assign host_bank_o  = host_bank_q;
  assign host_row_o   = host_row_q;
  assign host_word_o  = host_word_q;
  assign host_wdata_o = host_wdata_q;
  assign start_o      = start_q;
  assign steps_o      = steps_q;
  assign rounds_o     = rounds_q;
  assign tail_o       = tail_q;

  // ---- outputs -------------------------------------------------------------------
  reg running_q, done_q;
  always @(posedge clk_i) begin
    running_q <= !rst_i && running_i;
    done_q    <= !rst_i && done_i;
  end
  assign s_axil_awready_o = !aw_valid_q;
  assign s_axil_wready_o  = !w_valid_q;
  assign s_axil_bvalid_o  = b_valid_q;
  assign s_axil_bresp_o   = b_resp_q;
  assign s_axil_arready_o = !ar_valid_q;
  assign s_axil_rvalid_o  = r_valid_q;
  assign s_axil_rdata_o   = r_data_q;
  assign s_axil_rresp_o   = r_resp_q;
  assign running_o        = running_q;
  assign done_o           = done_q;

  // Not decoded: protection bits and the byte offset.  The entry's row
  // and bank fields above RW, BW bits are zero for a number below MAXOBJ.
  wire unused = &{1'b0, s_axil_awprot_i, s_axil_arprot_i, s_axil_awaddr_i[1:0],
                  s_axil_araddr_i[1:0], wd_row};
endmodule
`default_nettype wire
