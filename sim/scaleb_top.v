// scaleb_top.v -- Verilator test top of rtl/fp_scaleb.v: sixteen
// instances side by side on one operand pair, every rounding and FTZ
// configuration (index k = 2 * FTZ + ROUND) at LATENCY 1, 2, 3 and 4
// (instance j at LATENCY j / 4 + 1: every register place), driven by
// sim/scaleb_tb.cpp.
//
// Ports: clk_i, rst_i, valid_i, a_i, b_i as fp_scaleb's; instance j's
// valid_o, y_o and flags_o at bit j, [32j +: 32] and [5j +: 5].
`default_nettype none

module scaleb_top (
  input  wire         clk_i,
  input  wire         rst_i,
  input  wire         valid_i,
  input  wire [31:0]  a_i,
  input  wire [31:0]  b_i,
  output wire [15:0]  valid_o,
  output wire [511:0] y_o,
  output wire [79:0]  flags_o
);
  genvar j;
  generate
    for (j = 0; j < 16; j = j + 1) begin : g_core
      fp_scaleb #(.LATENCY(j / 4 + 1), .ROUND(j % 2), .FTZ((j / 2) % 2)) u_scaleb (
        .clk_i(clk_i), .rst_i(rst_i), .valid_i(valid_i), .a_i(a_i), .b_i(b_i),
        .valid_o(valid_o[j]), .y_o(y_o[32 * j +: 32]), .flags_o(flags_o[5 * j +: 5])
      );
    end
  endgenerate
endmodule

`default_nettype wire
