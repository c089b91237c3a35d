// fp3_axil_check -- AXI4-Lite slave protocol property set (formal only).
//
// Written from the AMBA AXI and ACE Protocol Specification (ARM IHI 0022,
// issue E and later): A3.1.2 (reset), A3.2.1 (handshake: once VALID is
// asserted it stays asserted until the handshake, and the information it
// carries stays stable), A3.3 (relationships between the channels: a
// write response follows both the write address and the last write data
// transfer, read data follow the read address) and B1.1 (AXI4-Lite: every
// transaction is one transfer, no IDs, all accesses the full data width
// or strobed).  The checker sits beside a slave and sees its ports only:
//
//   assumed of the master (the slave's inputs):
//     M1  AWVALID, WVALID, ARVALID low while reset is asserted (A3.1.2);
//     M2  a VALID that is not yet accepted stays high in the next cycle,
//         with the same address / data / strobes / protection (A3.2.1);
//   asserted of the slave (its outputs):
//     S1  BVALID and RVALID low in the cycle after a reset cycle (A3.1.2);
//     S2  a BVALID / RVALID that is not yet accepted stays high in the next
//         cycle, with the same BRESP / RDATA, RRESP (A3.2.1);
//     S3  no write response without an outstanding write address and an
//         outstanding write data transfer; no read data without an
//         outstanding read address (A3.3: one response per request, none
//         without one);
//     S4  at most MAX_OUT transactions outstanding on each of AW, W and AR
//         (counted from the handshakes: accepted, response not yet
//         accepted), so the counts below never wrap;
//     S5  (LIVE = 1 only) with a master that always holds BREADY and
//         RREADY, every complete outstanding write is answered within
//         MAX_WAIT cycles, and every outstanding read likewise: a slave
//         that never answers would satisfy S1-S4 (a bounded response
//         property; LIVE = 1 also assumes the two READYs high, which is why
//         it is a task of its own).
//
// The counts f_aw_out_o, f_w_out_o, f_ar_out_o (accepted minus answered)
// are outputs so that the slave can tie them to its own state: the
// invariants that let k-induction close (fp3_axil's FORMAL block).
//
// Parameters
//   ADDR_WIDTH  address bits of AWADDR / ARADDR
//   MAX_OUT     bound of S4 (transactions outstanding per channel)
//   CW          width of the counts, enough for MAX_OUT + 1
//   LIVE        1: assume BREADY and RREADY always high, check S5
//   MAX_WAIT    bound of S5, in cycles
//   B_GAP, R_GAP  the slave's shortest distance between two write (read)
//               responses, 1..8 cycles: the back-to-back covers
// Reset: rst_i, synchronous, active high.  `initial assume (rst_i)`: every
// trace starts in reset.
`default_nettype none
module fp3_axil_check #(
  parameter integer ADDR_WIDTH = 14,
  parameter integer MAX_OUT    = 2,
  parameter integer CW         = 4,
  parameter integer LIVE       = 0,
  parameter integer MAX_WAIT   = 8,
  parameter integer B_GAP      = 2,
  parameter integer R_GAP      = 2
) (
  input  wire                  clk_i,
  input  wire                  rst_i,
  input  wire [ADDR_WIDTH-1:0] awaddr,
  input  wire [2:0]            awprot,
  input  wire                  awvalid,
  input  wire                  awready,
  input  wire [31:0]           wdata,
  input  wire [3:0]            wstrb,
  input  wire                  wvalid,
  input  wire                  wready,
  input  wire [1:0]            bresp,
  input  wire                  bvalid,
  input  wire                  bready,
  input  wire [ADDR_WIDTH-1:0] araddr,
  input  wire [2:0]            arprot,
  input  wire                  arvalid,
  input  wire                  arready,
  input  wire [31:0]           rdata,
  input  wire [1:0]            rresp,
  input  wire                  rvalid,
  input  wire                  rready,
  output reg  [CW-1:0]         f_aw_out_o,
  output reg  [CW-1:0]         f_w_out_o,
  output reg  [CW-1:0]         f_ar_out_o
);
  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;
  initial assume (rst_i);

  wire aw_hs = awvalid && awready;
  wire w_hs  = wvalid && wready;
  wire b_hs  = bvalid && bready;
  wire ar_hs = arvalid && arready;
  wire r_hs  = rvalid && rready;

  // ---- M1, M2: the master -------------------------------------------------
  always @(*) if (rst_i) assume (!awvalid && !wvalid && !arvalid);
  always @(posedge clk_i) begin
    if (f_past_valid && !$past(rst_i) && !rst_i) begin
      if ($past(awvalid && !awready))
        assume (awvalid && $stable(awaddr) && $stable(awprot));
      if ($past(wvalid && !wready))
        assume (wvalid && $stable(wdata) && $stable(wstrb));
      if ($past(arvalid && !arready))
        assume (arvalid && $stable(araddr) && $stable(arprot));
    end
  end

  // ---- the counts of outstanding transactions -------------------------------
  always @(posedge clk_i) begin
    if (rst_i) begin
      f_aw_out_o <= {CW{1'b0}};
      f_w_out_o  <= {CW{1'b0}};
      f_ar_out_o <= {CW{1'b0}};
    end else begin
      f_aw_out_o <= f_aw_out_o + {{(CW-1){1'b0}}, aw_hs} - {{(CW-1){1'b0}}, b_hs};
      f_w_out_o  <= f_w_out_o  + {{(CW-1){1'b0}}, w_hs}  - {{(CW-1){1'b0}}, b_hs};
      f_ar_out_o <= f_ar_out_o + {{(CW-1){1'b0}}, ar_hs} - {{(CW-1){1'b0}}, r_hs};
    end
  end

  // ---- S1, S2: the slave's handshakes -----------------------------------------
  always @(posedge clk_i) begin
    if (f_past_valid && $past(rst_i)) begin
      s1_b_low: assert (!bvalid);
      s1_r_low: assert (!rvalid);
    end
    if (f_past_valid && !$past(rst_i) && !rst_i) begin
      if ($past(bvalid && !bready)) begin
        s2_b_held:   assert (bvalid);
        s2_b_stable: assert ($stable(bresp));
      end
      if ($past(rvalid && !rready)) begin
        s2_r_held:   assert (rvalid);
        s2_r_stable: assert ($stable(rdata) && $stable(rresp));
      end
    end
  end

  // ---- S3, S4: one response per request, a bounded number outstanding ---------
  always @(*) begin
    if (!rst_i) begin
      if (bvalid) s3_b_after_req: assert (f_aw_out_o != 0 && f_w_out_o != 0);
      if (rvalid) s3_r_after_req: assert (f_ar_out_o != 0);
      s4_aw_bound: assert (f_aw_out_o <= MAX_OUT);
      s4_w_bound:  assert (f_w_out_o  <= MAX_OUT);
      s4_ar_bound: assert (f_ar_out_o <= MAX_OUT);
    end
  end

  // ---- S5: bounded response time (LIVE) ------------------------------------------
  // f_bwait: cycles a complete write (address and data accepted) has waited
  // without a write response handshake; f_rwait likewise for a read.
  reg [7:0] f_bwait, f_rwait;
  always @(posedge clk_i) begin
    if (rst_i || b_hs || f_aw_out_o == 0 || f_w_out_o == 0) f_bwait <= 8'd0;
    else if (f_bwait != 8'hff) f_bwait <= f_bwait + 8'd1;
    if (rst_i || r_hs || f_ar_out_o == 0) f_rwait <= 8'd0;
    else if (f_rwait != 8'hff) f_rwait <= f_rwait + 8'd1;
  end
  generate
    if (LIVE != 0) begin : g_live
      always @(*) assume (bready && rready);
      always @(*) if (!rst_i) begin
        s5_b_in_time: assert (f_bwait <= MAX_WAIT);
        s5_r_in_time: assert (f_rwait <= MAX_WAIT);
      end
    end
  endgenerate

  // ---- covers: the properties are not vacuous ----------------------------------------
  // Responses back to back at the slave's rate (a write response B_GAP
  // cycles after the last one, a read's R_GAP after), both responses
  // pending at once, a stalled response with the outstanding bound
  // reached, each response code the slave gives.
  reg [7:0] f_b_hist, f_r_hist;   // bit k: a handshake k + 1 cycles ago
  always @(posedge clk_i) begin
    f_b_hist <= rst_i ? 8'd0 : {f_b_hist[6:0], b_hs};
    f_r_hist <= rst_i ? 8'd0 : {f_r_hist[6:0], r_hs};
  end
  always @(*) begin
    if (!rst_i && LIVE == 0) begin
      c_write_back_to_back: cover (b_hs && f_b_hist[B_GAP-1]);
      c_read_back_to_back:  cover (r_hs && f_r_hist[R_GAP-1]);
      c_write_slverr:       cover (b_hs && bresp == 2'b10);
      c_write_okay:         cover (b_hs && bresp == 2'b00);
      c_read_slverr:        cover (r_hs && rresp == 2'b10);
      c_read_okay:          cover (r_hs && rresp == 2'b00);
      c_both_outstanding:   cover (bvalid && rvalid);
      c_b_stalled:          cover (bvalid && !bready && f_aw_out_o == MAX_OUT);
      c_r_stalled:          cover (rvalid && !rready && f_ar_out_o == MAX_OUT);
    end
  end
endmodule
`default_nettype wire
