// fp3_uartbone -- a UARTBone bridge: frames from a serial line become
// AXI4-Lite transfers on fp3_axil's port, read data go back on the line.
//
// Protocol: LiteX's UART bridge (litex/soc/cores/uart.py Stream2Wishbone;
// its host side litex/tools/remote/comm_uart.py), so that litex_server,
// litex_cli and RemoteClient drive FP3 as they drive a LiteX SoC.  A
// frame is
//     cmd, len, addr[4], data[4 * len]      (data only in a write)
//   cmd  0x01 write, address incrementing   0x02 read, incrementing
//        0x03 write, address fixed          0x04 read, fixed
//   len  words, 1 .. 255 (0: the frame ends after its address)
//   addr a 32-bit word address, big-endian; each data word big-endian.
// A read answers exactly 4 * len bytes, a write answers nothing.  Another
// first byte is not a command and is skipped.  Word address N is host
// register N of fp3_axil (byte address 4N on AXI: FP3's register map,
// sw/isa/fp3_isa.h FP3_HOSTREGS); word addresses 0 .. 2^(ADDR_WIDTH-2)-1
// go to the bus.
//
// Bridge status, word address BRIDGE_STATUS (0x1000, just above FP3's
// 12-bit map): read-only, and reading it clears it (a read-to-clear
// register: the host reads it after the writes whose outcome matters,
// since a write answers nothing).  Sticky bits, set since the last read:
//   bit 0  BUS_ERROR   a transfer answered SLVERR or DECERR (fp3_axil: a
//                      write to a read-only register, or to the register or
//                      program windows while a run is in progress, ...),
//                      or a read or write of an address neither on the bus
//                      nor BRIDGE_STATUS (then nothing is done)
//   bit 1  DROPPED     a frame was dropped: no byte came for TIMEOUT
//                      cycles in the middle of it
//   bit 2  FRAMING     a character's stop bit was low (it was skipped)
//   bit 3  OVERRUN     a character came while the bridge was still busy
//                      with the bus or sending read data (it was lost)
// A bit whose cause comes in the very cycle the status is read is kept
// for the next read.
// A read that ends in a bus error returns ERROR_DATA (0xBADC0DE5) instead
// of the slave's data, and sets BUS_ERROR.  The fault output is high
// while any bit is set (the board's fault LED).
//
// Timing: the bridge takes a byte whenever it waits for one (command,
// length, address, write data), so frames may follow each other without
// a gap.  It performs each write as soon as its fourth byte is in; the
// bus must answer within the next character time (10 * CLKS_PER_BIT of
// the UART; fp3_axil: a few cycles), else the next byte is lost
// (OVERRUN).  A read's words are fetched one at a time, each before it is
// sent.  TIMEOUT bounds the wait for the next byte of an unfinished frame
// (LiteX: 100 ms), so that a host that died mid-frame leaves the bridge
// ready for the next frame.
//
// Parameters
//   ADDR_WIDTH  AXI byte address bits (fp3_axil's, >= 3)
//   TIMEOUT     cycles without a byte after which an unfinished frame is
//               dropped, >= 2
// Ports
//   clk_i, rst_i        clock; synchronous reset, active high
//   rx_data_i, rx_valid_i  received characters (fp3_uart_rx)
//   rx_ferr_i           a character with a low stop bit (fp3_uart_rx)
//   tx_data_o, tx_valid_o, tx_ready_i  characters to send (fp3_uart_tx)
//   m_axil_*            AXI4-Lite master; WSTRB all ones, PROT 0
//   fault_o             some bridge status bit is set
//   busy_o              a frame is in progress (the activity LED)
`default_nettype none
module fp3_uartbone #(
  parameter integer ADDR_WIDTH = 14,
  parameter integer TIMEOUT    = 10_000_000
) (
  input  wire                  clk_i,
  input  wire                  rst_i,
  // the serial side
  input  wire [7:0]            rx_data_i,
  input  wire                  rx_valid_i,
  input  wire                  rx_ferr_i,
  output wire [7:0]            tx_data_o,
  output wire                  tx_valid_o,
  input  wire                  tx_ready_i,
  // AXI4-Lite master
  output wire [ADDR_WIDTH-1:0] m_axil_awaddr_o,
  output wire [2:0]            m_axil_awprot_o,
  output wire                  m_axil_awvalid_o,
  input  wire                  m_axil_awready_i,
  output wire [31:0]           m_axil_wdata_o,
  output wire [3:0]            m_axil_wstrb_o,
  output wire                  m_axil_wvalid_o,
  input  wire                  m_axil_wready_i,
  input  wire [1:0]            m_axil_bresp_i,
  input  wire                  m_axil_bvalid_i,
  output wire                  m_axil_bready_o,
  output wire [ADDR_WIDTH-1:0] m_axil_araddr_o,
  output wire [2:0]            m_axil_arprot_o,
  output wire                  m_axil_arvalid_o,
  input  wire                  m_axil_arready_i,
  input  wire [31:0]           m_axil_rdata_i,
  input  wire [1:0]            m_axil_rresp_i,
  input  wire                  m_axil_rvalid_i,
  output wire                  m_axil_rready_o,
  // status
  output wire                  fault_o,
  output wire                  busy_o
);
  // commands (Stream2Wishbone)
  localparam [7:0] CMD_WRITE_INCR = 8'h01;
  localparam [7:0] CMD_READ_INCR  = 8'h02;
  localparam [7:0] CMD_WRITE_FIX  = 8'h03;
  localparam [7:0] CMD_READ_FIX   = 8'h04;
  localparam [31:0] BRIDGE_STATUS = 32'h0000_1000;
  localparam [31:0] ERROR_DATA    = 32'hBADC_0DE5;
  localparam [1:0]  RESP_OKAY     = 2'b00;
  localparam integer WA_BITS = ADDR_WIDTH - 2;        // word address bits on the bus
  localparam integer TW      = $clog2(TIMEOUT + 1);
`ifdef FP3_MUTANT_UARTBONE_TIMEOUT
  localparam [TW-1:0] TIMEOUT_LAST = TIMEOUT[TW-1:0] - 2'd2;   // broken: a cycle early
`else
  localparam [TW-1:0] TIMEOUT_LAST = TIMEOUT[TW-1:0] - 1'b1;
`endif

  localparam [2:0] S_CMD   = 3'd0,  // waiting for a command byte
                   S_LEN   = 3'd1,  // ... for the length
                   S_ADDR  = 3'd2,  // ... for the 4 address bytes
                   S_WDATA = 3'd3,  // ... for the 4 bytes of a write's word
                   S_WBUS  = 3'd4,  // a write on the bus
                   S_RBUS  = 3'd5,  // a read on the bus
                   S_RSEND = 3'd6;  // sending a read's word

  reg [2:0]    state_q,  state_d;
  reg          write_q,  write_d;   // the frame writes
  reg          incr_q,   incr_d;    // the frame's address increments
  reg [7:0]    left_q,   left_d;    // words still to transfer (this one incl.)
  reg [31:0]   addr_q,   addr_d;    // word address of this word
  reg [31:0]   data_q,   data_d;    // the word being received or sent
  reg [1:0]    nbyte_q,  nbyte_d;   // bytes of addr / data so far (mod 4)
  reg [TW-1:0] idle_q,   idle_d;    // cycles since the last byte, mid-frame
  reg          aw_q,     aw_d;      // AWVALID
  reg          w_q,      w_d;       // WVALID
  reg          ar_q,     ar_d;      // ARVALID
  reg          issued_q, issued_d;  // this word's transfer was started
  reg [3:0]    status_q, status_d;  // {OVERRUN, FRAMING, DROPPED, BUS_ERROR}

  wire on_bus    = addr_q[31:WA_BITS] == {(32 - WA_BITS){1'b0}};
  wire is_status = addr_q == BRIDGE_STATUS;
  wire last_word = left_q == 8'd1;
  wire [31:0] addr_next = incr_q ? addr_q + 32'd1 : addr_q;
  wire waiting_byte = state_q == S_CMD || state_q == S_LEN || state_q == S_ADDR ||
                      state_q == S_WDATA;

  always @(*) begin
    state_d  = state_q;
    write_d  = write_q;
    incr_d   = incr_q;
    left_d   = left_q;
    addr_d   = addr_q;
    data_d   = data_q;
    nbyte_d  = nbyte_q;
    idle_d   = idle_q;
    aw_d     = aw_q && !m_axil_awready_i;
`ifdef FP3_MUTANT_UARTBONE_WVALID
    w_d      = w_q && !m_axil_awready_i;   // broken: WVALID follows the address's handshake
`else
    w_d      = w_q && !m_axil_wready_i;
`endif
    ar_d     = ar_q && !m_axil_arready_i;
    issued_d = issued_q;
    status_d = status_q;
    if (rx_ferr_i) status_d[2] = 1'b1;
    if (rx_valid_i && !waiting_byte) status_d[3] = 1'b1;

    // an unfinished frame: count the cycles without a byte, drop it after TIMEOUT
    if (state_q == S_LEN || state_q == S_ADDR || state_q == S_WDATA) begin
      if (rx_valid_i) idle_d = {TW{1'b0}};
      else if (idle_q == TIMEOUT_LAST) begin
        state_d     = S_CMD;
        status_d[1] = 1'b1;
      end else idle_d = idle_q + 1'b1;
    end else begin
      idle_d = {TW{1'b0}};
    end

    case (state_q)
      S_CMD:
        if (rx_valid_i) begin
          write_d = rx_data_i == CMD_WRITE_INCR || rx_data_i == CMD_WRITE_FIX;
          incr_d  = rx_data_i == CMD_WRITE_INCR || rx_data_i == CMD_READ_INCR;
          if (rx_data_i == CMD_WRITE_INCR || rx_data_i == CMD_READ_INCR ||
              rx_data_i == CMD_WRITE_FIX || rx_data_i == CMD_READ_FIX)
            state_d = S_LEN;
        end
      S_LEN:
        if (rx_valid_i) begin
          left_d  = rx_data_i;
          nbyte_d = 2'd0;
          state_d = S_ADDR;
        end
      S_ADDR:
        if (rx_valid_i) begin
          addr_d  = {addr_q[23:0], rx_data_i};
          nbyte_d = nbyte_q + 2'd1;
          if (nbyte_q == 2'd3) begin
            issued_d = 1'b0;
            if (left_q == 8'd0) state_d = S_CMD;
            else state_d = write_q ? S_WDATA : S_RBUS;
          end
        end
      S_WDATA:
        if (rx_valid_i) begin
          data_d  = {data_q[23:0], rx_data_i};
          nbyte_d = nbyte_q + 2'd1;
          if (nbyte_q == 2'd3) state_d = S_WBUS;
        end
      S_WBUS: begin
        // start the write (on the bus), or refuse it (anywhere else)
        if (!issued_q) begin
          issued_d = 1'b1;
          if (on_bus) begin
            aw_d = 1'b1;
            w_d  = 1'b1;
          end
        end
        if (issued_q && (!on_bus || (m_axil_bvalid_i && !aw_q && !w_q))) begin
          if (!on_bus || m_axil_bresp_i != RESP_OKAY) status_d[0] = 1'b1;
          issued_d = 1'b0;
          left_d   = left_q - 8'd1;
          addr_d   = addr_next;
          state_d  = last_word ? S_CMD : S_WDATA;
        end
      end
      S_RBUS: begin
        if (!issued_q) begin
          issued_d = 1'b1;
          if (on_bus) ar_d = 1'b1;
        end
        if (issued_q && !on_bus) begin
          // the bridge's own status register, or no register at all
          if (is_status) begin
            data_d   = {28'd0, status_q};
            status_d = 4'd0;
            // set in this cycle: kept for the next read
            if (rx_ferr_i) status_d[2] = 1'b1;
            if (rx_valid_i) status_d[3] = 1'b1;
          end else begin
            data_d      = ERROR_DATA;
            status_d[0] = 1'b1;
          end
          nbyte_d = 2'd0;
          state_d = S_RSEND;
        end else if (issued_q && m_axil_rvalid_i && !ar_q) begin
          if (m_axil_rresp_i != RESP_OKAY) begin
            data_d      = ERROR_DATA;
            status_d[0] = 1'b1;
          end else begin
            data_d = m_axil_rdata_i;
          end
          nbyte_d = 2'd0;
          state_d = S_RSEND;
        end
      end
      default: // S_RSEND: the word, most significant byte first
        if (tx_ready_i) begin
          data_d  = {data_q[23:0], 8'h00};
          nbyte_d = nbyte_q + 2'd1;
          if (nbyte_q == 2'd3) begin
            issued_d = 1'b0;
            left_d   = left_q - 8'd1;
            addr_d   = addr_next;
`ifdef FP3_MUTANT_UARTBONE_LEN
            state_d  = left_q <= 8'd2 ? S_CMD : S_RBUS;   // broken: a word short
`else
            state_d  = last_word ? S_CMD : S_RBUS;
`endif
          end
        end
    endcase
  end

  always @(posedge clk_i) begin
    if (rst_i) begin
      state_q  <= S_CMD;
      aw_q     <= 1'b0;
      w_q      <= 1'b0;
      ar_q     <= 1'b0;
      issued_q <= 1'b0;
      status_q <= 4'd0;
      idle_q   <= {TW{1'b0}};
    end else begin
      state_q  <= state_d;
      aw_q     <= aw_d;
      w_q      <= w_d;
      ar_q     <= ar_d;
      issued_q <= issued_d;
      status_q <= status_d;
      idle_q   <= idle_d;
    end
    write_q <= write_d;
    incr_q  <= incr_d;
    left_q  <= left_d;
    addr_q  <= addr_d;
    data_q  <= data_d;
    nbyte_q <= nbyte_d;
  end

  assign m_axil_awaddr_o  = {addr_q[WA_BITS-1:0], 2'b00};
  assign m_axil_awprot_o  = 3'b000;
  assign m_axil_awvalid_o = aw_q;
  assign m_axil_wdata_o   = data_q;
  assign m_axil_wstrb_o   = 4'b1111;
  assign m_axil_wvalid_o  = w_q;
  assign m_axil_bready_o  = 1'b1;
  assign m_axil_araddr_o  = {addr_q[WA_BITS-1:0], 2'b00};
  assign m_axil_arprot_o  = 3'b000;
  assign m_axil_arvalid_o = ar_q;
  assign m_axil_rready_o  = 1'b1;
  assign tx_data_o        = data_q[31:24];
  assign tx_valid_o       = state_q == S_RSEND;
  assign fault_o          = status_q != 4'd0;
  assign busy_o           = state_q != S_CMD;

`ifdef FORMAL
  // Properties (formal/uartbone.sby proves them by k-induction with a
  // small TIMEOUT and ADDR_WIDTH; the frame length is any of 0 .. 255).
  // Assumed of the environment: every trace starts with a reset; the
  // AXI4-Lite slave answers a write only after it accepted both its
  // address and its data, and a read only after its address (AMBA AXI,
  // ARM IHI 0022, A3.3); bytes, framing errors and TREADY arrive in any
  // pattern (faster than a UART could: OVERRUN covers it).  Asserted:
  //   the master's handshakes (A3.1.2, A3.2.1): no VALID in the cycle after
  //     a reset; a VALID not yet accepted stays high with its address,
  //     data and strobes; likewise the characters to send (tx_valid_o);
  //   one transaction at a time: at most one write or read outstanding,
  //     never both, counted from the handshakes;
  //   a frame's words go to host registers addr, addr + 1, ... (addr for
  //     the fixed commands), each write's data are its four bytes;
  //   a read answers exactly 4 * len bytes, sent only in a read frame;
  //   an unfinished frame is dropped after exactly TIMEOUT cycles without
  //     a byte (DROPPED set), never earlier;
  //   the status bits: each set by its cause and by nothing else, kept
  //     until the bridge's status register is read, which answers them
  //     and clears them (a cause of that very cycle is kept for the next
  //     read); a bus error's read answers ERROR_DATA.
  // FP3_MUTANT_UARTBONE_* are deliberately broken copies for the mutation
  // test (tests/test_formal_mutant.sh): _LEN ends a read frame a word
  // short, _TIMEOUT drops a frame a cycle early, _WVALID lets WVALID fall
  // with AWREADY instead of WREADY.
  reg f_past_valid = 1'b0, f_rst_q = 1'b1;
  always @(posedge clk_i) begin
    f_past_valid <= 1'b1;
    f_rst_q      <= rst_i;
  end
  always @(*) if (!f_past_valid) assume (rst_i);
  wire f_run = f_past_valid && !f_rst_q && !rst_i;   // this cycle and the last out of reset

  // ---- the bus: handshakes and the outstanding counts ---------------------
  wire f_aw_hs = m_axil_awvalid_o && m_axil_awready_i;
  wire f_w_hs  = m_axil_wvalid_o && m_axil_wready_i;
  wire f_b_hs  = m_axil_bvalid_i && m_axil_bready_o;
  wire f_ar_hs = m_axil_arvalid_o && m_axil_arready_i;
  wire f_r_hs  = m_axil_rvalid_i && m_axil_rready_o;
  wire f_tx_hs = tx_valid_o && tx_ready_i;
  reg [1:0] f_aw_out, f_w_out, f_ar_out;     // accepted, not yet answered
  always @(posedge clk_i) begin
    if (rst_i) begin
      f_aw_out <= 2'd0;
      f_w_out  <= 2'd0;
      f_ar_out <= 2'd0;
    end else begin
      f_aw_out <= f_aw_out + {1'b0, f_aw_hs} - {1'b0, f_b_hs};
      f_w_out  <= f_w_out  + {1'b0, f_w_hs}  - {1'b0, f_b_hs};
      f_ar_out <= f_ar_out + {1'b0, f_ar_hs} - {1'b0, f_r_hs};
    end
  end
  always @(*) begin
    if (m_axil_bvalid_i) assume (!rst_i && f_aw_out != 2'd0 && f_w_out != 2'd0);
    if (m_axil_rvalid_i) assume (!rst_i && f_ar_out != 2'd0);
  end
  wire f_wr_open = m_axil_awvalid_o || m_axil_wvalid_o || f_aw_out != 2'd0 || f_w_out != 2'd0;
  wire f_rd_open = m_axil_arvalid_o || f_ar_out != 2'd0;

  // ---- the frame as the line carried it ------------------------------------
  // f_len, f_base, f_cmd: the frame's length, address and command bytes;
  // f_word: the last four bytes received; f_sent: bytes sent since the
  // frame's address; f_wait: cycles mid-frame without a byte.
  reg [7:0]  f_len, f_cmd;
  reg [31:0] f_base, f_word;
  reg [9:0]  f_sent;
  reg [TW:0] f_wait;
  wire f_mid  = state_q == S_LEN || state_q == S_ADDR || state_q == S_WDATA;
  wire f_data = state_q == S_WDATA || state_q == S_WBUS || state_q == S_RBUS ||
                state_q == S_RSEND;
  wire f_incr = f_cmd == CMD_WRITE_INCR || f_cmd == CMD_READ_INCR;
  wire [7:0] f_done = f_len - left_q;                      // words done
  wire [31:0] f_addr = f_base + (f_incr ? {24'd0, f_done} : 32'd0);  // this word's
  // the bytes of a word received so far (the low nbyte_q of 4)
  wire [31:0] f_got = nbyte_q == 2'd0 ? 32'h0000_0000 : nbyte_q == 2'd1 ? 32'h0000_00ff :
                      nbyte_q == 2'd2 ? 32'h0000_ffff : 32'h00ff_ffff;
  wire f_status_read = state_q == S_RBUS && issued_q && is_status;
  always @(posedge clk_i) begin
    if (state_q == S_CMD && rx_valid_i) f_cmd <= rx_data_i;
    if (state_q == S_LEN && rx_valid_i) f_len <= rx_data_i;
    if (state_q == S_ADDR && rx_valid_i) f_base <= {f_base[23:0], rx_data_i};
    if (rx_valid_i && waiting_byte) f_word <= {f_word[23:0], rx_data_i};
    if (state_q == S_ADDR) f_sent <= 10'd0;
    else if (f_tx_hs) f_sent <= f_sent + 10'd1;
    if (rst_i || !f_mid || rx_valid_i) f_wait <= {(TW+1){1'b0}};
    else f_wait <= f_wait + 1'b1;
  end

  always @(posedge clk_i) begin
    if (f_past_valid && $past(rst_i)) begin
      m_reset_aw: assert (!m_axil_awvalid_o);
      m_reset_w:  assert (!m_axil_wvalid_o);
      m_reset_ar: assert (!m_axil_arvalid_o);
    end
    if (f_run) begin
      // the master's handshakes
      if ($past(m_axil_awvalid_o && !m_axil_awready_i))
        m_aw_held: assert (m_axil_awvalid_o && $stable(m_axil_awaddr_o) && $stable(m_axil_awprot_o));
      if ($past(m_axil_wvalid_o && !m_axil_wready_i))
        m_w_held: assert (m_axil_wvalid_o && $stable(m_axil_wdata_o) && $stable(m_axil_wstrb_o));
      if ($past(m_axil_arvalid_o && !m_axil_arready_i))
        m_ar_held: assert (m_axil_arvalid_o && $stable(m_axil_araddr_o) && $stable(m_axil_arprot_o));
      if ($past(tx_valid_o && !tx_ready_i))
        tx_held: assert (tx_valid_o && $stable(tx_data_o));
      // a read frame ends after exactly 4 * len bytes
      if ($past(state_q == S_RSEND) && state_q == S_CMD)
        rd_len_exact: assert (f_sent == {f_len, 2'b00});
      // the timeout: dropped after TIMEOUT cycles without a byte, not before
      if ($past(f_mid && !rx_valid_i))
        if ($past(f_wait) == TIMEOUT - 1) begin
          drop_at_timeout: assert (state_q == S_CMD && status_q[1]);
        end else begin
          drop_not_early: assert (state_q == $past(state_q));
        end
      // the status bits: their causes, kept until read
      if ($past(f_b_hs && m_axil_bresp_i != RESP_OKAY) || $past(f_r_hs && m_axil_rresp_i != RESP_OKAY))
        st_bus_error: assert (status_q[0]);
      if ($past(rx_ferr_i)) st_framing: assert (status_q[2]);
      if ($past(rx_valid_i && !waiting_byte)) st_overrun: assert (status_q[3]);
      if (!$past(f_status_read))
        st_sticky: assert ((status_q & $past(status_q)) == $past(status_q));
      if ($rose(status_q[1]))
        st_dropped_cause: assert ($past(f_mid && !rx_valid_i && f_wait == TIMEOUT - 1));
      if ($rose(status_q[2])) st_framing_cause: assert ($past(rx_ferr_i));
      if ($rose(status_q[3])) st_overrun_cause: assert ($past(rx_valid_i && !waiting_byte));
      if ($rose(status_q[0]))
        st_bus_error_cause: assert ($past(f_b_hs && m_axil_bresp_i != RESP_OKAY) ||
                                    $past(f_r_hs && m_axil_rresp_i != RESP_OKAY) ||
                                    $past(issued_q && !on_bus &&
                                          (state_q == S_WBUS || (state_q == S_RBUS && !is_status))));
      if ($past(f_status_read)) begin
        st_read_value: assert (data_q == {28'd0, $past(status_q)});
        st_read_clears: assert (status_q == {$past(rx_valid_i), $past(rx_ferr_i), 2'b00});
      end
      if ($past(f_r_hs))
        rd_data: assert (data_q == ($past(m_axil_rresp_i) == RESP_OKAY ? $past(m_axil_rdata_i) : ERROR_DATA));
    end
  end

  always @(*) begin
    if (f_past_valid && !rst_i) begin
      one_outstanding: assert (!(f_wr_open && f_rd_open) && f_aw_out <= 2'd1 &&
                               f_w_out <= 2'd1 && f_ar_out <= 2'd1);
      // each word on the bus: register base + index (base alone when fixed)
      if (m_axil_awvalid_o)
        wr_addr: assert (m_axil_awaddr_o == {f_addr[WA_BITS-1:0], 2'b00});
      if (m_axil_wvalid_o) wr_data: assert (m_axil_wdata_o == f_word && m_axil_wstrb_o == 4'hf);
      if (m_axil_arvalid_o)
        rd_addr: assert (m_axil_araddr_o == {f_addr[WA_BITS-1:0], 2'b00});
      rd_len_bound: assert (f_sent <= {f_len, 2'b00} || state_q != S_RSEND);
      // the invariants that make k-induction close
      inv_state: assert (state_q <= S_RSEND);
      if (state_q == S_WDATA) inv_not_issued: assert (!issued_q);
      inv_valid_state: assert (!(m_axil_awvalid_o || m_axil_wvalid_o || f_aw_out != 2'd0 || f_w_out != 2'd0) ||
                               (state_q == S_WBUS && issued_q && on_bus));
      if (state_q == S_WBUS && issued_q && on_bus)
        wr_aw_w_once: assert ({1'b0, aw_q} + f_aw_out == 2'd1 && {1'b0, w_q} + f_w_out == 2'd1);
      inv_rd_state: assert (!f_rd_open || (state_q == S_RBUS && issued_q && on_bus));
      if (state_q == S_RBUS && issued_q && on_bus) rd_ar_once: assert ({1'b0, ar_q} + f_ar_out == 2'd1);
      if (f_mid) inv_wait: assert (f_wait == {1'b0, idle_q} && idle_q <= TIMEOUT_LAST);
      if (state_q == S_ADDR) inv_addr_left: assert (left_q == f_len);
      if (state_q == S_WDATA || state_q == S_WBUS) inv_write: assert (write_q && f_cmd[0]);
      if (state_q == S_RBUS || state_q == S_RSEND) inv_read: assert (!write_q && !f_cmd[0]);
      if (state_q != S_CMD) inv_cmd_flags: assert (incr_q == f_incr && write_q == f_cmd[0]);
      if (state_q != S_CMD) inv_cmd: assert (f_cmd >= 8'd1 && f_cmd <= 8'd4);
      if (f_data) begin
        inv_left: assert (left_q != 8'd0 && left_q <= f_len);
        inv_addr: assert (addr_q == f_addr);
      end
      if (state_q == S_WDATA) inv_wdata: assert ((data_q & f_got) == (f_word & f_got));
      if (state_q == S_ADDR) inv_abytes: assert ((addr_q & f_got) == (f_base & f_got));
      if (state_q == S_WBUS || state_q == S_RBUS) inv_nbyte: assert (nbyte_q == 2'd0);
      if (state_q == S_WBUS) inv_wword: assert (data_q == f_word);
      if (state_q == S_RBUS) inv_rd_sent: assert (f_sent == {f_done, 2'b00});
      if (state_q == S_RSEND) inv_rs_sent: assert (f_sent == {f_done, 2'b00} + {8'd0, nbyte_q});
    end
  end

  // ---- covers: the properties are not vacuous ----------------------------------
  always @(posedge clk_i) begin
    if (f_run) begin
      c_read2_done: cover ($past(state_q == S_RSEND) && state_q == S_CMD && f_len == 8'd2 && f_incr);
      c_write2_done: cover ($past(state_q == S_WBUS) && state_q == S_CMD && f_len == 8'd2 && f_incr);
      c_dropped: cover ($rose(status_q[1]) && $past(state_q == S_WDATA));
      c_bus_error_read: cover ($past(f_r_hs && m_axil_rresp_i != RESP_OKAY) && state_q == S_RSEND);
      c_status_read: cover ($past(f_status_read) && data_q[1]);
    end
  end
`endif
endmodule
`default_nettype wire
