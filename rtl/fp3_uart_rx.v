// fp3_uart_rx -- UART receiver: 8 data bits, no parity, one stop bit
// (8N1), least significant bit first, line idle high.
//
// The line passes a two-flop synchronizer (it comes from another clock
// domain: the USB-serial chip's).  A falling edge starts a character; the
// start bit is checked low again half a bit later (a shorter glitch is
// ignored), and from there each data bit and the stop bit are sampled
// CLKS_PER_BIT cycles apart, in the middle of each bit.  A character
// whose stop bit is low is not delivered: frame_err_o pulses instead
// (a break, or a baud rate mismatch).
//
// Tolerance: sampling starts within one cycle (plus the synchronizer's
// two) of the real falling edge, so with the mid-bit point at
// CLKS_PER_BIT/2 the stop bit's sample stays inside the stop bit while
// the two ends' bit times differ by less than about
// (0.5 - 1/CLKS_PER_BIT) / 9.5 (4.9 % at 33 clocks a bit, the ULX3S
// build; docs/board.md "Clock and baud rate").
//
// Parameters
//   CLKS_PER_BIT  clock cycles per bit, >= 4 (clock / baud rate, rounded)
// Ports
//   clk_i, rst_i  clock; synchronous reset, active high
//   rx_i          the serial line (asynchronous)
//   data_o        the character received, valid with valid_o
//   valid_o       one-cycle pulse: data_o holds a new character
//   frame_err_o   one-cycle pulse: a character ended with a low stop bit
`default_nettype none
module fp3_uart_rx #(
  parameter integer CLKS_PER_BIT = 33
) (
  input  wire       clk_i,
  input  wire       rst_i,
  input  wire       rx_i,
  output wire [7:0] data_o,
  output wire       valid_o,
  output wire       frame_err_o
);
  localparam integer CW   = $clog2(CLKS_PER_BIT + 1);
  localparam [CW-1:0] FULL = CLKS_PER_BIT[CW-1:0] - 1'b1;        // a whole bit
  localparam [CW-1:0] HALF = CLKS_PER_BIT[CW:1] - 1'b1;          // to mid-bit
  localparam [1:0] S_IDLE = 2'd0, S_START = 2'd1, S_DATA = 2'd2, S_STOP = 2'd3;

  // two-flop synchronizer, reset to the idle level
  reg [1:0] sync_q;
  always @(posedge clk_i) begin
    if (rst_i) sync_q <= 2'b11;
    else       sync_q <= {sync_q[0], rx_i};
  end
  wire rx = sync_q[1];

  reg [1:0]    state_q, state_d;
  reg [CW-1:0] timer_q, timer_d;   // cycles to the next sample
  reg [2:0]    bit_q,   bit_d;     // data bit being received
  reg [7:0]    shift_q, shift_d;
  reg          valid_q, valid_d;
  reg          ferr_q,  ferr_d;

  always @(*) begin
    state_d = state_q;
    timer_d = timer_q;
    bit_d   = bit_q;
    shift_d = shift_q;
    valid_d = 1'b0;
    ferr_d  = 1'b0;
    if (timer_q != {CW{1'b0}}) timer_d = timer_q - 1'b1;
    case (state_q)
      S_IDLE:
        if (!rx) begin
          state_d = S_START;
          timer_d = HALF;
        end
      S_START:
        if (timer_q == {CW{1'b0}}) begin
          if (rx) state_d = S_IDLE;          // a glitch, not a start bit
          else begin
            state_d = S_DATA;
            timer_d = FULL;
            bit_d   = 3'd0;
          end
        end
      S_DATA:
        if (timer_q == {CW{1'b0}}) begin
          shift_d = {rx, shift_q[7:1]};
          timer_d = FULL;
          bit_d   = bit_q + 3'd1;
          if (bit_q == 3'd7) state_d = S_STOP;
        end
      default: // S_STOP
        if (timer_q == {CW{1'b0}}) begin
          state_d = S_IDLE;
          valid_d = rx;
          ferr_d  = !rx;
        end
    endcase
  end

  always @(posedge clk_i) begin
    if (rst_i) begin
      state_q <= S_IDLE;
      valid_q <= 1'b0;
      ferr_q  <= 1'b0;
    end else begin
      state_q <= state_d;
      valid_q <= valid_d;
      ferr_q  <= ferr_d;
    end
    timer_q <= timer_d;
    bit_q   <= bit_d;
    shift_q <= shift_d;
  end

  assign data_o      = shift_q;
  assign valid_o     = valid_q;
  assign frame_err_o = ferr_q;
endmodule
`default_nettype wire
