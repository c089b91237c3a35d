// fp_recur_out.v -- the last two datapath steps of the digit-recurrence
// cores fp_div and fp_sqrt: the rounding increment (fp_round), flags,
// overflow, flush to zero and the special result (fp_round_pack), with
// the core's register places between and after them.
//
// Both cores end the same way once their recurrence has produced a
// normalised significand with guard, round and sticky bits: round, then
// either the rounded result or the special one decided at unpack (NaN,
// infinity, zero), with its flags.  The divide-by-zero flag rides along
// (fp_sqrt ties it to 0).
//
// Parameters:
//   ROUND      0: round to nearest, ties to even; 1: round toward zero
//   FTZ        1: a tiny result is flushed to a zero of its sign, with
//              underflow and inexact (fp_round_pack)
//   MID_DEPTH  pipeline registers between the rounding increment and the
//              pack (the core's register place after its rounding step:
//              0 or 1)
//   OUT_DEPTH  registers after the pack: the output register and any
//              output delay stages, >= 1
//
// Ports:
//   clk_i      clock, rising edge
//   rst_i      synchronous reset, active high; clears the valid bits only
//   valid_i    the inputs hold an operation this cycle
//   exp_i      biased exponent of the exact result, >= 1 (fp_round exp_i)
//   mant_i     24-bit significand, hidden bit included (fp_round mant_i)
//   guard_i, round_i, sticky_i  the bits below mant_i (fp_round)
//   sign_i     sign of the result
//   spec_i     the operation has the special result spec_y_i (no rounding)
//   spec_y_i   that result (binary32)
//   spec_nv_i  with spec_i: raise invalid
//   spec_dz_i  with spec_i: raise divide by zero (infinite, flags bit 3)
//   valid_o    valid_i delayed by MID_DEPTH + OUT_DEPTH rising edges
//   y_o        binary32 result
//   flags_o    {invalid, infinite, overflow, underflow, inexact}, the
//              Berkeley SoftFloat bit order (bit 0 inexact)
//
// Timing: what is on the inputs in cycle t is on the outputs in cycle
// t + MID_DEPTH + OUT_DEPTH; initiation interval 1.
//
// Cost: fp_round's 31-bit increment and fp_round_pack's multiplexers;
// 73 flip-flops at the place after rounding, 38 per output stage.
//
// Standards (IEEE 754-2019): §4.3 rounding, §7.3 division by zero, §7.4
// overflow, §7.5 underflow with tininess after rounding (fp_round,
// fp_round_pack).
`default_nettype none

module fp_recur_out #(
  parameter integer ROUND     = 0, // 0 RNE, 1 RTZ
  parameter integer FTZ       = 0, // 1: flush tiny results to zero
  parameter integer MID_DEPTH = 0, // registers between round and pack
  parameter integer OUT_DEPTH = 1  // output register and delay stages, >= 1
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        valid_i,
  input  wire [9:0]  exp_i,
  input  wire [23:0] mant_i,
  input  wire        guard_i,
  input  wire        round_i,
  input  wire        sticky_i,
  input  wire        sign_i,
  input  wire        spec_i,
  input  wire [31:0] spec_y_i,
  input  wire        spec_nv_i,
  input  wire        spec_dz_i,
  output wire        valid_o,
  output wire [31:0] y_o,
  output wire [4:0]  flags_o
);

  generate
    if (OUT_DEPTH < 1) begin : g_bad_depth
      // Elaboration error on purpose: the output register is required.
      fp_recur_out_error_OUT_DEPTH_must_be_at_least_1 u_error ();
    end
  endgenerate

  // Rounding increment.
  wire [30:0] r_pack;
  wire        r_overflow, r_inexact, r_tiny;
  fp_round #(.ROUND(ROUND)) u_round (
    .exp_i     (exp_i),
    .mant_i    (mant_i),
    .guard_i   (guard_i),
    .round_i   (round_i),
    .sticky_i  (sticky_i),
    .pack_o    (r_pack),
    .overflow_o(r_overflow),
    .inexact_o (r_inexact),
    .tiny_o    (r_tiny)
  );

  localparam integer WR = 1 + 32 + 1 + 1 + 1 + 31 + 3;
  wire          s_valid;
  wire [WR-1:0] s_data;
  fp_pipe #(.WIDTH(WR), .DEPTH(MID_DEPTH)) u_pipe_round (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({spec_i, spec_y_i, spec_nv_i, spec_dz_i, sign_i, r_pack, r_overflow,
               r_inexact, r_tiny}),
    .valid_o (s_valid),
    .data_o  (s_data)
  );

  // Overflow, flush, flags, special result.
  wire        p_spec, p_nv, p_dz, p_sign;
  wire [31:0] p_spec_y;
  wire [30:0] p_pack;
  wire        p_overflow, p_inexact, p_tiny;
  assign {p_spec, p_spec_y, p_nv, p_dz, p_sign, p_pack, p_overflow, p_inexact,
          p_tiny} = s_data;

  wire [31:0] p_y;
  wire [4:0]  p_flags;
  fp_round_pack #(.ROUND(ROUND), .FTZ(FTZ)) u_pack (
    .sign_i    (p_sign),
    .pack_i    (p_pack),
    .overflow_i(p_overflow),
    .inexact_i (p_inexact),
    .tiny_i    (p_tiny),
    .spec_i    (p_spec),
    .spec_y_i  (p_spec_y),
    .spec_nv_i (p_nv),
    .y_o       (p_y),
    .flags_o   (p_flags)
  );
  // The divide-by-zero flag (bit 3) beside fp_round_pack's: only with a
  // special result, whose other flags are 0.
  wire [4:0] p_flags_dz = p_flags | {1'b0, p_dz & p_spec, 3'b000};

  fp_pipe #(.WIDTH(32 + 5), .DEPTH(OUT_DEPTH)) u_pipe_out (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (s_valid),
    .data_i  ({p_y, p_flags_dz}),
    .valid_o (valid_o),
    .data_o  ({y_o, flags_o})
  );

endmodule

`default_nettype wire
