// fp3_uart_tx -- UART transmitter: 8 data bits, no parity, one stop bit
// (8N1), least significant bit first, line idle high.
//
// A character is taken when valid_i and ready_o are both high (a
// valid/ready handshake, as an AXI4-Stream sink); it leaves as a start
// bit, the eight data bits and a stop bit, each CLKS_PER_BIT cycles long.
// ready_o is high once the stop bit has lasted its bit time, so
// back-to-back characters are 10 bit times apart.  tx_o is a register.
//
// Parameters
//   CLKS_PER_BIT  clock cycles per bit, >= 2 (clock / baud rate, rounded)
// Ports
//   clk_i, rst_i  clock; synchronous reset, active high (line idle)
//   data_i        the character to send, taken with valid_i && ready_o
//   valid_i       a character is offered
//   ready_o       the transmitter takes a character this cycle
//   tx_o          the serial line
`default_nettype none
module fp3_uart_tx #(
  parameter integer CLKS_PER_BIT = 33
) (
  input  wire       clk_i,
  input  wire       rst_i,
  input  wire [7:0] data_i,
  input  wire       valid_i,
  output wire       ready_o,
  output wire       tx_o
);
  localparam integer CW   = $clog2(CLKS_PER_BIT + 1);
  localparam [CW-1:0] FULL = CLKS_PER_BIT[CW-1:0] - 1'b1;

  reg [9:0]    shift_q, shift_d;   // {stop, data, start}: shift_q[0] is on the line
  reg [3:0]    left_q,  left_d;    // bits still on their way (incl. the current); 0: idle
  reg [CW-1:0] timer_q, timer_d;   // cycles left of the current bit
  reg          tx_q,    tx_d;

  wire take = valid_i && left_q == 4'd0;

  always @(*) begin
    shift_d = shift_q;
    left_d  = left_q;
    timer_d = timer_q;
    tx_d    = tx_q;
    if (take) begin
      shift_d = {1'b1, data_i, 1'b0};
      tx_d    = 1'b0;                    // the start bit
      left_d  = 4'd10;
      timer_d = FULL;
    end else if (left_q != 4'd0) begin
      if (timer_q == {CW{1'b0}}) begin
        left_d = left_q - 4'd1;
        if (left_q != 4'd1) begin        // the next bit (the last is the stop bit)
          shift_d = {1'b1, shift_q[9:1]};
          tx_d    = shift_q[1];
          timer_d = FULL;
        end
      end else begin
        timer_d = timer_q - 1'b1;
      end
    end
  end

  always @(posedge clk_i) begin
    if (rst_i) begin
      left_q <= 4'd0;
      tx_q   <= 1'b1;
    end else begin
      left_q <= left_d;
      tx_q   <= tx_d;
    end
    shift_q <= shift_d;
    timer_q <= timer_d;
  end

  assign ready_o = left_q == 4'd0;
  assign tx_o    = tx_q;
endmodule
`default_nettype wire
