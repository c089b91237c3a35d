// fp3_board -- what every FPGA board carries of FP3, whatever its pins and
// clock: the processor behind its AXI4-Lite port (fp3_axil, by default the
// build for clock rate of docs/fpga.md), a UARTBone bridge from a serial
// line to that port (fp3_uart_rx, fp3_uart_tx, fp3_uartbone), the reset
// and the status LEDs.  A board's own top (boards/NAME/) makes the clock
// (its PLL), names the pins and instantiates this.
//
// Reset: held while the clock is not locked (locked_i low) or the reset
// button is pressed (rst_btn_i high), both asynchronous to clk_i and
// taken through a two-flop synchronizer, and for 2^RESET_BITS cycles
// after both are released, so that every register starts from a clock
// that is running and stable.
//
// LEDs (led_o, on when high):
//   0  running    a run is in progress (fp3_axil running_o)
//   1  done       the last run has ended (fp3_axil done_o; CTRL CLEAR
//                 clears it)
//   2  fault      a bridge status bit is set (fp3_uartbone: bus error,
//                 dropped frame, framing error, overrun) until the host
//                 reads BRIDGE_STATUS
//   3  heartbeat  toggles every 2^HEARTBEAT_BIT cycles: the clock runs
//                 and the design is out of reset
//   4  link       a UARTBone frame is in progress
//   5, 6          off
//   7  reset      the design is held in reset
//
// Parameters
//   CLKS_PER_BIT  clock cycles per UART bit (clock / baud rate, rounded)
//   TIMEOUT       cycles after which the bridge drops an unfinished frame
//   HEARTBEAT_BIT the heartbeat's counter bit (26: 0.67 s a toggle at 100 MHz)
//   RESET_BITS    the reset lasts 2^RESET_BITS cycles after lock
//   NUM_CONTEXTS .. WB_PORTS  fp3_axil's (see there); the defaults are
//                 the build for clock rate without the div/sqrt unit
// Ports
//   clk_i         the system clock (the board's PLL output)
//   locked_i      the clock is stable (the PLL's lock; tie high without one)
//   rst_btn_i     reset button, active high (the board top inverts an
//                 active-low button)
//   uart_rx_i     serial data from the host (the USB-serial chip's TXD)
//   uart_tx_o     serial data to the host (its RXD)
//   led_o         the LEDs above
`default_nettype none
module fp3_board #(
  parameter integer CLKS_PER_BIT  = 33,
  parameter integer TIMEOUT       = 10_000_000,
  parameter integer HEARTBEAT_BIT = 26,
  parameter integer RESET_BITS    = 4,
  parameter integer NUM_CONTEXTS  = 8,
  parameter integer NUM_LANES     = 1,
  parameter integer NUM_REGS      = 32,
  parameter integer IMEM_DEPTH    = 256,
  parameter integer ADD_LATENCY   = 9,
  parameter integer MUL_LATENCY   = 10,
  parameter integer MUL_FEED      = 0,
  parameter integer ROUND         = 0,
  parameter integer FTZ           = 0,
  parameter integer HAS_DIV       = 0,
  parameter integer HAS_SQRT      = 0,
  parameter integer DIV_LATENCY   = 8,
  parameter integer FMAX_PIPE     = 1,
  parameter integer WB_PORTS      = 4
) (
  input  wire       clk_i,
  input  wire       locked_i,
  input  wire       rst_btn_i,
  input  wire       uart_rx_i,
  output wire       uart_tx_o,
  output wire [7:0] led_o
);
  localparam integer ADDR_WIDTH = 14;

  // ---- reset ----------------------------------------------------------------
  reg [1:0]          rst_sync_q;     // synchronizer of "hold in reset"
  reg [RESET_BITS:0] rst_cnt_q;      // counts up to the release (its MSB)
  always @(posedge clk_i) begin
    rst_sync_q <= {rst_sync_q[0], !locked_i || rst_btn_i};
    if (rst_sync_q[1]) rst_cnt_q <= {(RESET_BITS + 1){1'b0}};
    else if (!rst_cnt_q[RESET_BITS]) rst_cnt_q <= rst_cnt_q + 1'b1;
  end
  // (initial values: an FPGA's flip-flops start from them; the design
  // starts in reset until the counter has run)
  initial rst_sync_q = 2'b11;
  initial rst_cnt_q  = {(RESET_BITS + 1){1'b0}};
  wire rst = !rst_cnt_q[RESET_BITS];

  // ---- the serial line and the bridge -----------------------------------------
  wire [7:0] rx_data, tx_data;
  wire       rx_valid, rx_ferr, tx_valid, tx_ready;
  fp3_uart_rx #(.CLKS_PER_BIT(CLKS_PER_BIT)) u_rx (
    .clk_i       (clk_i),
    .rst_i       (rst),
    .rx_i        (uart_rx_i),
    .data_o      (rx_data),
    .valid_o     (rx_valid),
    .frame_err_o (rx_ferr)
  );
  fp3_uart_tx #(.CLKS_PER_BIT(CLKS_PER_BIT)) u_tx (
    .clk_i   (clk_i),
    .rst_i   (rst),
    .data_i  (tx_data),
    .valid_i (tx_valid),
    .ready_o (tx_ready),
    .tx_o    (uart_tx_o)
  );

  wire [ADDR_WIDTH-1:0] awaddr, araddr;
  wire [2:0]  awprot, arprot;
  wire        awvalid, awready, wvalid, wready, bvalid, bready;
  wire        arvalid, arready, rvalid, rready;
  wire [31:0] wdata, rdata;
  wire [3:0]  wstrb;
  wire [1:0]  bresp, rresp;
  wire        fault, busy, running, done;
  fp3_uartbone #(.ADDR_WIDTH(ADDR_WIDTH), .TIMEOUT(TIMEOUT)) u_bridge (
    .clk_i            (clk_i),
    .rst_i            (rst),
    .rx_data_i        (rx_data),
    .rx_valid_i       (rx_valid),
    .rx_ferr_i        (rx_ferr),
    .tx_data_o        (tx_data),
    .tx_valid_o       (tx_valid),
    .tx_ready_i       (tx_ready),
    .m_axil_awaddr_o  (awaddr),
    .m_axil_awprot_o  (awprot),
    .m_axil_awvalid_o (awvalid),
    .m_axil_awready_i (awready),
    .m_axil_wdata_o   (wdata),
    .m_axil_wstrb_o   (wstrb),
    .m_axil_wvalid_o  (wvalid),
    .m_axil_wready_i  (wready),
    .m_axil_bresp_i   (bresp),
    .m_axil_bvalid_i  (bvalid),
    .m_axil_bready_o  (bready),
    .m_axil_araddr_o  (araddr),
    .m_axil_arprot_o  (arprot),
    .m_axil_arvalid_o (arvalid),
    .m_axil_arready_i (arready),
    .m_axil_rdata_i   (rdata),
    .m_axil_rresp_i   (rresp),
    .m_axil_rvalid_i  (rvalid),
    .m_axil_rready_o  (rready),
    .fault_o          (fault),
    .busy_o           (busy)
  );

  // ---- the processor ------------------------------------------------------------
  fp3_axil #(
    .ADDR_WIDTH   (ADDR_WIDTH),
    .NUM_CONTEXTS (NUM_CONTEXTS),
    .NUM_LANES    (NUM_LANES),
    .NUM_REGS     (NUM_REGS),
    .IMEM_DEPTH   (IMEM_DEPTH),
    .ADD_LATENCY  (ADD_LATENCY),
    .MUL_LATENCY  (MUL_LATENCY),
    .MUL_FEED     (MUL_FEED),
    .ROUND        (ROUND),
    .FTZ          (FTZ),
    .HAS_DIV      (HAS_DIV),
    .HAS_SQRT     (HAS_SQRT),
    .DIV_LATENCY  (DIV_LATENCY),
    .FMAX_PIPE    (FMAX_PIPE),
    .WB_PORTS     (WB_PORTS)
  ) u_fp3 (
    .clk_i            (clk_i),
    .rst_i            (rst),
    .s_axil_awaddr_i  (awaddr),
    .s_axil_awprot_i  (awprot),
    .s_axil_awvalid_i (awvalid),
    .s_axil_awready_o (awready),
    .s_axil_wdata_i   (wdata),
    .s_axil_wstrb_i   (wstrb),
    .s_axil_wvalid_i  (wvalid),
    .s_axil_wready_o  (wready),
    .s_axil_bresp_o   (bresp),
    .s_axil_bvalid_o  (bvalid),
    .s_axil_bready_i  (bready),
    .s_axil_araddr_i  (araddr),
    .s_axil_arprot_i  (arprot),
    .s_axil_arvalid_i (arvalid),
    .s_axil_arready_o (arready),
    .s_axil_rdata_o   (rdata),
    .s_axil_rresp_o   (rresp),
    .s_axil_rvalid_o  (rvalid),
    .s_axil_rready_i  (rready),
    .running_o        (running),
    .done_o           (done)
  );

  // ---- LEDs -----------------------------------------------------------------------
  reg [HEARTBEAT_BIT:0] beat_q;
  always @(posedge clk_i) begin
    if (rst) beat_q <= {(HEARTBEAT_BIT + 1){1'b0}};
    else     beat_q <= beat_q + 1'b1;
  end
  reg [7:0] led_q;
  always @(posedge clk_i)
    led_q <= {rst, 2'b00, busy, beat_q[HEARTBEAT_BIT], fault, done, running};
  assign led_o = led_q;
endmodule
`default_nettype wire
