// fp3_axil -- AXI4-Lite slave wrapper of the FP3 processor (fp3_top).
//
// Register map: the host-port map of sw/isa/fp3_isa.h (FP3_HOSTREGS, HR_* in
// the generated rtl/fp3_isa.vh) at byte address = word address x 4.  Data
// is 32 bits wide; address bits [1:0] and bits above 13 are not decoded
// (an interconnect decodes the base address).
//
// Channels: AW and W are accepted independently, in either order, into a
// one-entry holding register each; the write reaches the host port once
// both are held and the B channel is free (or being emptied this cycle).
// AR is held likewise; the read address goes to the host port for one
// cycle, the core's registered read data is captured one cycle later (five
// with FMAX_PIPE: a register in front of the host port, four read cycles;
// one more with lanes: fp3_top "Host port") and held on R until RREADY.
// B and R stay valid, with stable payload, until accepted.  Each channel
// takes a new transfer every second cycle (reads every sixth with
// FMAX_PIPE, one cycle more with lanes).  The
// host port has one address, so a write and a read that are both ready in
// the same cycle take turns (round robin).  All outputs are registered;
// no READY depends combinationally on a VALID.  The side band (running_o,
// done_o) is fp3_top's, registered once more: it follows STATUS a cycle
// later, and its output flip-flops are not the run state's, which fans
// out through the core.
//
// Responses: OKAY (2'b00) for an access the core performs, SLVERR (2'b10)
// with no effect on the core for
//   - a write to an unmapped or read-only address (STATUS .. ID, INFO2, a
//     register or instruction index beyond NUM_REGS / IMEM_DEPTH);
//   - a write to STEPS, CONTEXTS, CTX, LANE, the register window or the
//     program window while a run is in progress (the core ignores those),
//     a write of a context number >= NUM_CONTEXTS to CTX and one of a lane
//     number >= NUM_LANES to LANE (ignored too);
//   - a write whose WSTRB is not 4'b1111 (the host port has no byte lanes);
//   - a read of an unmapped address, of the write-only CTRL register or of
//     the program window (the core has no read path there); RDATA is 0.
// CTRL is always writable (START while running is ignored by the core).
// The access of each address follows the table in sw/isa/fp3_isa.h (R, W,
// RW); fp3_isa.vh carries only the addresses, so the list of readable
// and writable scalar registers is spelled out below (reg_readable,
// wr_ok) and test_axil checks every one.
//
// Parameters
//   ADDR_WIDTH   AXI address bits, at least 14 (12-bit word address x 4)
//   NUM_CONTEXTS contexts of fp3_top, 1..64
//   NUM_LANES    lanes per context of fp3_top, 1..64
//   NUM_REGS     registers per context of fp3_top, 2..256
//   IMEM_DEPTH   instruction memory entries of fp3_top, 2..1024
//   ADD_LATENCY  add/sub core latency in cycles
//   MUL_LATENCY  mul core latency in cycles
//   MUL_FEED     1: a fabric register in front of the multipliers' DSP
//                blocks (fp3_top)
//   ROUND        0 round to nearest even, 1 round toward zero
//   FTZ          0 IEEE subnormals, 1 flush subnormals to zero
//   HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV, HAS_SQRT, HAS_SIGN, DIV_LATENCY
//                units built (see fp3_top)
//   FMAX_PIPE    pipeline for clock rate (see fp3_top); 1: the host port's
//                inputs are registered, a read's data are captured three
//                cycles after its address
//   WB_PORTS     write-back ports of the register file, 4 or 1 (see fp3_top)
// Reset: rst_i, synchronous, active high (invert ARESETn outside).
`default_nettype none
module fp3_axil #(
  parameter integer ADDR_WIDTH   = 14,
  parameter integer NUM_CONTEXTS = 8,
  parameter integer NUM_LANES    = 1,
  parameter integer NUM_REGS     = 32,
  parameter integer IMEM_DEPTH   = 256,
  parameter integer ADD_LATENCY  = 4,
  parameter integer MUL_LATENCY  = 3,
  parameter integer MUL_FEED     = 0,
  parameter integer ROUND        = 0,
  parameter integer FTZ          = 0,
  parameter integer HAS_ADD      = 1,
  parameter integer HAS_SUB      = 1,
  parameter integer HAS_MUL      = 1,
  parameter integer HAS_DIV      = 1,
  parameter integer HAS_SQRT     = 1,
  parameter integer HAS_SIGN     = 1,
  parameter integer DIV_LATENCY  = 8,
  parameter integer FMAX_PIPE    = 0,
  parameter integer WB_PORTS     = 4
) (
  input  wire                  clk_i,
  input  wire                  rst_i,
  // write address channel
  input  wire [ADDR_WIDTH-1:0] s_axil_awaddr_i,
  input  wire [2:0]            s_axil_awprot_i,
  input  wire                  s_axil_awvalid_i,
  output wire                  s_axil_awready_o,
  // write data channel
  input  wire [31:0]           s_axil_wdata_i,
  input  wire [3:0]            s_axil_wstrb_i,
  input  wire                  s_axil_wvalid_i,
  output wire                  s_axil_wready_o,
  // write response channel
  output wire [1:0]            s_axil_bresp_o,
  output wire                  s_axil_bvalid_o,
  input  wire                  s_axil_bready_i,
  // read address channel
  input  wire [ADDR_WIDTH-1:0] s_axil_araddr_i,
  input  wire [2:0]            s_axil_arprot_i,
  input  wire                  s_axil_arvalid_i,
  output wire                  s_axil_arready_o,
  // read data channel
  output wire [31:0]           s_axil_rdata_o,
  output wire [1:0]            s_axil_rresp_o,
  output wire                  s_axil_rvalid_o,
  input  wire                  s_axil_rready_i,
  // side band: a run is in progress / the last run has ended (interrupt)
  output wire                  running_o,
  output wire                  done_o
);
`include "fp3_isa.vh"

  localparam [1:0] RESP_OKAY   = 2'b00;
  localparam [1:0] RESP_SLVERR = 2'b10;
  localparam [3:0] STRB_ALL    = 4'b1111;
  localparam integer WA_LSB    = 2;   // byte address -> word address
  localparam integer WA_BITS   = 12;  // host-port word address width
  localparam integer IW = (NUM_REGS <= 2) ? 1 : $clog2(NUM_REGS);      // as fp3_top's
  localparam integer AW = (IMEM_DEPTH <= 2) ? 1 : $clog2(IMEM_DEPTH);

  // ---- state ---------------------------------------------------------------
  reg                aw_valid_q, aw_valid_d;
  reg  [WA_BITS-1:0] aw_addr_q,  aw_addr_d;
  reg                w_valid_q,  w_valid_d;
  reg  [31:0]        w_data_q,   w_data_d;
  reg                w_all_q,    w_all_d;     // all four byte strobes
  reg                b_valid_q,  b_valid_d;
  reg  [1:0]         b_resp_q,   b_resp_d;
  reg                ar_valid_q, ar_valid_d;
  reg  [WA_BITS-1:0] ar_addr_q,  ar_addr_d;
  // The host port's read data arrive RD_CYCLES after the address: 1, or 5
  // with FMAX_PIPE (its input register and the core's four read cycles),
  // and one more with lanes (fp3_top "Host port").
  localparam integer RD_CYCLES = (FMAX_PIPE != 0 ? 5 : 1) + (NUM_LANES > 1 ? 1 : 0);
  reg  [RD_CYCLES-1:0] rd_pend_q, rd_pend_d;  // a host-port read 1 .. RD_CYCLES cycles ago
  reg                rd_err_q,   rd_err_d;    // ... for an address answered SLVERR
  reg                r_valid_q,  r_valid_d;
  reg  [31:0]        r_data_q,   r_data_d;
  reg  [1:0]         r_resp_q,   r_resp_d;
  reg                prio_q,     prio_d;      // 1: a read wins the next tie

  wire        running;
  wire        done;
  // The side band's own registers (see the header).
  reg         running_q, done_q;
  always @(posedge clk_i) begin
    running_q <= !rst_i && running;
    done_q    <= !rst_i && done;
  end
  wire [31:0] host_rdata;

  // ---- address decode --------------------------------------------------------
  // The register window (REG_BASE + r, r < NUM_REGS) and the program window
  // (IMEM_BASE + 2i (+1), i < IMEM_DEPTH; bit 0 the half of the word) are
  // fp3_host_dec's, as fp3_top decodes them (wsel_o[4]; imem_ok_o).

  // Scalar registers the host may read (access R or RW in the table); a
  // register of the window: reg_win, fp3_host_dec's wsel_o[4] of a.
  function reg_readable;
    input [WA_BITS-1:0] a;
    input               reg_win;
    begin
      case (a)
        HR_STATUS, HR_STEPS, HR_STEPS_DONE, HR_FAULT_PC, HR_FLAGS,
        HR_CYCLES_LO, HR_CYCLES_HI, HR_ISSUED_LO, HR_ISSUED_HI,
        HR_STALLS_LO, HR_STALLS_HI, HR_INFO0, HR_INFO1, HR_ID,
        HR_CTX, HR_CONTEXTS, HR_INFO2, HR_LANE: reg_readable = 1'b1;
        default:                       reg_readable = reg_win;
      endcase
    end
  endfunction

  // A write the core performs now (access W or RW; all but CTRL only
  // while stopped).  Its address and data are decoded as they are
  // captured, from the bus (aw_take, w_take: the decode is held with the
  // word), so that the check is a few flip-flops and RUNNING, not
  // compares in front of the host port, and the compares do not follow
  // the holding multiplexer.
  wire               aw_take = s_axil_awvalid_i && !aw_valid_q;
  wire [WA_BITS-1:0] aw_in   = s_axil_awaddr_i[WA_LSB +: WA_BITS];
  wire               w_take  = s_axil_wvalid_i && !w_valid_q;
  // The register or window the address names (fp3_host_dec), decoded
  // once, as it is captured: for these checks and, held with the word,
  // for the core's write (fp3_top HOST_WSEL).
  wire [7:0] aw_wsel;
  wire       aw_imem_ok;   // its program index is below IMEM_DEPTH
  fp3_host_dec #(.NUM_REGS(NUM_REGS), .IW(IW), .IMEM_DEPTH(IMEM_DEPTH), .AW(AW)) u_aw_dec (
    .addr_i    (aw_in),
    .wsel_o    (aw_wsel),
    .imem_ok_o (aw_imem_ok)
  );
  reg [7:0] wa_wsel_q;  // aw_wsel of the held address: bit 0 CTRL, 3 CTX, 7 LANE
  reg wa_stop_q;    // ... a register written only while stopped (not CTX, LANE)
  reg wd_ctx_q;     // the data name a context (for CTX)
  reg wd_lane_q;    // the data name a lane (for LANE)
  wire wr_ok = w_all_q &&
               (wa_wsel_q[0] || (!running && (wa_stop_q || (wa_wsel_q[3] && wd_ctx_q) ||
                                              (wa_wsel_q[7] && wd_lane_q))));
  wire [7:0] ar_wsel;      // the read's address, decoded (its register window)
  wire       ar_imem_ok;
  fp3_host_dec #(.NUM_REGS(NUM_REGS), .IW(IW), .IMEM_DEPTH(IMEM_DEPTH), .AW(AW)) u_ar_dec (
    .addr_i    (ar_addr_q),
    .wsel_o    (ar_wsel),
    .imem_ok_o (ar_imem_ok)
  );
  wire unused_ar_dec = &{1'b0, ar_wsel[7:5], ar_wsel[3:0], ar_imem_ok};
  wire rd_ok = reg_readable(ar_addr_q, ar_wsel[4]);

  // ---- host-port arbitration -----------------------------------------------
  wire wr_cand  = aw_valid_q && w_valid_q && (!b_valid_q || s_axil_bready_i);
  wire rd_arrive = rd_pend_q[RD_CYCLES-1];
  wire rd_cand  = ar_valid_q && rd_pend_q == {RD_CYCLES{1'b0}} &&
                  (!r_valid_q || s_axil_rready_i);
  wire do_write = wr_cand && (!rd_cand || !prio_q);
  wire do_read  = rd_cand && (!wr_cand || prio_q);

  wire               host_we_c   = do_write && wr_ok;
  wire [WA_BITS-1:0] host_addr_c = do_write ? aw_addr_q : ar_addr_q;

  // FMAX_PIPE: the host port's inputs are registered, the write's decode
  // with them (the address decode and the write checks above do not reach
  // into the core's start logic or its host registers' enables).
  wire               host_we;
  wire [WA_BITS-1:0] host_addr;
  wire [31:0]        host_wdata;
  wire [7:0]         host_wsel;
  fp_pipe #(.WIDTH(WA_BITS + 32 + 8), .DEPTH(FMAX_PIPE != 0 ? 1 : 0)) u_host_in (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (host_we_c),
    .data_i  ({host_addr_c, w_data_q, wa_wsel_q}),   // (wa_wsel_q: used only with a write)
    .valid_o (host_we),
    .data_o  ({host_addr, host_wdata, host_wsel})
  );

  // ---- next state --------------------------------------------------------------
  always @(*) begin
    aw_valid_d = aw_valid_q;
    aw_addr_d  = aw_addr_q;
    w_valid_d  = w_valid_q;
    w_data_d   = w_data_q;
    w_all_d    = w_all_q;
    b_valid_d  = b_valid_q;
    b_resp_d   = b_resp_q;
    ar_valid_d = ar_valid_q;
    ar_addr_d  = ar_addr_q;
    rd_pend_d  = (rd_pend_q << 1) | {{(RD_CYCLES-1){1'b0}}, do_read};
    rd_err_d   = rd_err_q;
    r_valid_d  = r_valid_q;
    r_data_d   = r_data_q;
    r_resp_d   = r_resp_q;
    prio_d     = (wr_cand && rd_cand) ? !prio_q : prio_q;

    // write: hold AW and W, then perform and respond
    if (aw_take) begin
      aw_valid_d = 1'b1;
      aw_addr_d  = aw_in;
    end
    if (w_take) begin
      w_valid_d = 1'b1;
      w_data_d  = s_axil_wdata_i;
      w_all_d   = s_axil_wstrb_i == STRB_ALL;
    end
    if (s_axil_bready_i) b_valid_d = 1'b0;
    if (do_write) begin
      aw_valid_d = 1'b0;
      w_valid_d  = 1'b0;
      b_valid_d  = 1'b1;
      b_resp_d   = wr_ok ? RESP_OKAY : RESP_SLVERR;
    end

    // read: hold AR, address the host port, capture its registered data
    if (s_axil_arvalid_i && !ar_valid_q) begin
      ar_valid_d = 1'b1;
      ar_addr_d  = s_axil_araddr_i[WA_LSB +: WA_BITS];
    end
    if (do_read) begin
      ar_valid_d = 1'b0;
      rd_err_d   = !rd_ok;
    end
    if (s_axil_rready_i) r_valid_d = 1'b0;
    if (rd_arrive) begin
      r_valid_d = 1'b1;
      r_data_d  = rd_err_q ? 32'd0 : host_rdata;
      r_resp_d  = rd_err_q ? RESP_SLVERR : RESP_OKAY;
    end
  end

  always @(posedge clk_i) begin
    if (rst_i) begin
      aw_valid_q <= 1'b0;
      w_valid_q  <= 1'b0;
      b_valid_q  <= 1'b0;
      ar_valid_q <= 1'b0;
      rd_pend_q  <= {RD_CYCLES{1'b0}};
      r_valid_q  <= 1'b0;
      prio_q     <= 1'b0;
    end else begin
      aw_valid_q <= aw_valid_d;
      w_valid_q  <= w_valid_d;
      b_valid_q  <= b_valid_d;
      ar_valid_q <= ar_valid_d;
      rd_pend_q  <= rd_pend_d;
      r_valid_q  <= r_valid_d;
      prio_q     <= prio_d;
    end
    aw_addr_q <= aw_addr_d;
    w_data_q  <= w_data_d;
    w_all_q   <= w_all_d;
    if (aw_take) begin
      wa_wsel_q <= aw_wsel;
      // (the program window's low words too: an index beyond IMEM_DEPTH
      // is refused, which aw_wsel[5] does not check)
      wa_stop_q <= aw_wsel[1] || aw_wsel[2] || aw_wsel[4] || aw_wsel[6] ||
                   (aw_wsel[5] && aw_imem_ok);
    end
    if (w_take) wd_ctx_q  <= s_axil_wdata_i < NUM_CONTEXTS;
    if (w_take) wd_lane_q <= s_axil_wdata_i < NUM_LANES;
    b_resp_q  <= b_resp_d;
    ar_addr_q <= ar_addr_d;
    rd_err_q  <= rd_err_d;
    r_data_q  <= r_data_d;
    r_resp_q  <= r_resp_d;
  end

  // ---- the processor -----------------------------------------------------------
  wire       tr_issue, tr_endi, tr_add_valid, tr_mul_valid, tr_mov_valid, tr_div_valid;
  wire [2:0] tr_issue_unit;
  wire [5:0] tr_issue_ctx, tr_add_ctx, tr_mul_ctx, tr_mov_ctx, tr_div_ctx;
  wire [7:0] tr_add_reg, tr_mul_reg, tr_mov_reg, tr_div_reg;
  wire [32*NUM_LANES-1:0] tr_add_data, tr_mul_data, tr_mov_data, tr_div_data;

  fp3_top #(
    .NUM_CONTEXTS (NUM_CONTEXTS),
    .NUM_LANES    (NUM_LANES),
    .NUM_REGS     (NUM_REGS),
    .IMEM_DEPTH   (IMEM_DEPTH),
    .ADD_LATENCY  (ADD_LATENCY),
    .MUL_LATENCY  (MUL_LATENCY),
    .MUL_FEED     (MUL_FEED),
    .ROUND        (ROUND),
    .FTZ          (FTZ),
    .HAS_ADD      (HAS_ADD),
    .HAS_SUB      (HAS_SUB),
    .HAS_MUL      (HAS_MUL),
    .HAS_DIV      (HAS_DIV),
    .HAS_SQRT     (HAS_SQRT),
    .HAS_SIGN     (HAS_SIGN),
    .DIV_LATENCY  (DIV_LATENCY),
    .FMAX_PIPE    (FMAX_PIPE),
    .WB_PORTS     (WB_PORTS),
    .CTX_CHECKED  (1),              // wr_ok: wd_ctx_q, wd_lane_q
    .HOST_WSEL    (1)               // host_wsel
  ) u_fp3 (
    .clk_i           (clk_i),
    .rst_i           (rst_i),
    .host_we_i       (host_we),
    .host_addr_i     (host_addr),
    .host_wdata_i    (host_wdata),
    .host_wsel_i     (host_wsel),
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

  // ---- outputs -------------------------------------------------------------------
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

  // Not decoded: protection bits, byte offsets and address bits above the
  // map (see the header), and the trace port, which a bus cannot carry.
  wire unused = &{1'b0, s_axil_awprot_i, s_axil_arprot_i, s_axil_awaddr_i,
                  s_axil_araddr_i, tr_issue, tr_issue_unit, tr_endi,
                  tr_issue_ctx, tr_add_ctx, tr_mul_ctx, tr_mov_ctx,
                  tr_add_valid, tr_add_reg, tr_add_data, tr_mul_valid,
                  tr_mul_reg, tr_mul_data, tr_mov_valid, tr_mov_reg,
                  tr_mov_data, tr_div_valid, tr_div_ctx, tr_div_reg, tr_div_data};

`ifdef FORMAL
  // The AXI4-Lite slave property set (formal/fp3_axil_check.v, from the
  // AMBA specification) on this wrapper's ports, and the invariants that
  // tie its counts of outstanding transactions to the holding registers,
  // so that k-induction closes: a write is outstanding while its address
  // (its data) is held or its response waits; a read while its address is
  // held, its data are on the way from the host port (at most one: a read
  // goes to the port only with rd_pend_q clear) or its response waits.
  // formal/axil.sby cuts the processor out (its outputs free), so the
  // proof holds whatever the core answers.  F_LIVE, F_MAX_WAIT: the
  // checker's LIVE task (formal/axil.sby).
`ifdef FP3_F_LIVE
  localparam integer F_LIVE     = 1;
`else
  localparam integer F_LIVE     = 0;
`endif
  localparam integer F_MAX_WAIT = FMAX_PIPE != 0 ? 10 : 6;
  wire [3:0] f_aw_out, f_w_out, f_ar_out;
  fp3_axil_check #(
    .ADDR_WIDTH (ADDR_WIDTH),
    .MAX_OUT    (2),
    .CW         (4),
    .LIVE       (F_LIVE),
    .MAX_WAIT   (F_MAX_WAIT),
    .B_GAP      (2),
    .R_GAP      (RD_CYCLES + 1)
  ) u_check (
    .clk_i (clk_i), .rst_i (rst_i),
    .awaddr (s_axil_awaddr_i), .awprot (s_axil_awprot_i),
    .awvalid (s_axil_awvalid_i), .awready (s_axil_awready_o),
    .wdata (s_axil_wdata_i), .wstrb (s_axil_wstrb_i),
    .wvalid (s_axil_wvalid_i), .wready (s_axil_wready_o),
    .bresp (s_axil_bresp_o), .bvalid (s_axil_bvalid_o), .bready (s_axil_bready_i),
    .araddr (s_axil_araddr_i), .arprot (s_axil_arprot_i),
    .arvalid (s_axil_arvalid_i), .arready (s_axil_arready_o),
    .rdata (s_axil_rdata_o), .rresp (s_axil_rresp_o),
    .rvalid (s_axil_rvalid_o), .rready (s_axil_rready_i),
    .f_aw_out_o (f_aw_out), .f_w_out_o (f_w_out), .f_ar_out_o (f_ar_out)
  );
  wire f_rd_pending = rd_pend_q != {RD_CYCLES{1'b0}};
  always @(*) begin
    if (!rst_i) begin
      assert (f_aw_out == {3'd0, aw_valid_q} + {3'd0, b_valid_q});
      assert (f_w_out  == {3'd0, w_valid_q}  + {3'd0, b_valid_q});
      assert (f_ar_out == {3'd0, ar_valid_q} + {3'd0, f_rd_pending} + {3'd0, r_valid_q});
      assert ($onehot0(rd_pend_q));
      assert (!(f_rd_pending && r_valid_q));
    end
  end
`endif
endmodule
`default_nettype wire
