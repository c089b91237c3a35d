// fp_round_pack.v -- second half of rounding a binary32 result
// (combinational), shared by fp_add and fp_mul: overflow, flush to zero,
// the exception flags, and the core's special result (NaN, infinity,
// zero) in place of the rounded one.  Takes the outputs of fp_round.
//
// Parameters:
//   ROUND  0: round to nearest, ties to even (RNE); 1: toward zero (RTZ)
//   FTZ    1: a tiny result is flushed to a zero of the same sign
//
// Ports:
//   sign_i     sign of the result
//   pack_i     fp_round pack_o: {exponent, fraction} fields
//   overflow_i fp_round overflow_o
//   inexact_i  fp_round inexact_o
//   tiny_i     fp_round tiny_o
//   spec_i     the operation has a special result: spec_y_i, no rounding
//   spec_y_i   that result
//   spec_nv_i  with spec_i: raise invalid (else no flag)
//   y_o        binary32 result
//   flags_o    {invalid, infinite (0), overflow, underflow, inexact}
//
// Standards: IEEE 754-2008 §7.4 overflow (RNE: infinity, RTZ: largest
// finite, both with inexact), §7.5 underflow: raised when tiny and
// inexact.  FTZ (not IEEE, matches x86 MXCSR.FTZ): a tiny nonzero result
// becomes +-0 with underflow and inexact.
`default_nettype none

module fp_round_pack #(
  parameter integer ROUND = 0, // 0 RNE, 1 RTZ
  parameter integer FTZ   = 0  // 1: flush tiny results to zero
) (
  input  wire        sign_i,
  input  wire [30:0] pack_i,
  input  wire        overflow_i,
  input  wire        inexact_i,
  input  wire        tiny_i,
  input  wire        spec_i,
  input  wire [31:0] spec_y_i,
  input  wire        spec_nv_i,
  output reg  [31:0] y_o,
  output reg  [4:0]  flags_o
);

  localparam integer ROUND_RNE = 0;
  localparam [30:0]  MAG_INF   = 31'h7F80_0000;
  localparam [30:0]  MAG_MAX   = 31'h7F7F_FFFF;
  localparam [4:0]   FLAG_NX   = 5'b00001;
  localparam [4:0]   FLAG_UF   = 5'b00010;
  localparam [4:0]   FLAG_OF   = 5'b00100;
  localparam [4:0]   FLAG_NV   = 5'b10000;

  always @* begin
    if (spec_i) begin
      y_o     = spec_y_i;
      flags_o = spec_nv_i ? FLAG_NV : 5'd0;
    end else if (overflow_i) begin
      y_o     = {sign_i, (ROUND == ROUND_RNE) ? MAG_INF : MAG_MAX};
      flags_o = FLAG_OF | FLAG_NX;
    end else if ((FTZ != 0) && tiny_i) begin
      y_o     = {sign_i, 31'd0};
      flags_o = FLAG_UF | FLAG_NX;
    end else begin
      y_o     = {sign_i, pack_i[30:0]};
      flags_o = (inexact_i ? FLAG_NX : 5'd0) | ((tiny_i & inexact_i) ? FLAG_UF : 5'd0);
    end
  end

endmodule

`default_nettype wire
