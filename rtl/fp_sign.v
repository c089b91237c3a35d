// fp_sign.v -- the exact binary32 sign and compare operations abs, neg,
// min and max, for the processor's move path.
//
// Bit for bit equal to sw/ref/fpref.h fpref_abs, fpref_neg, fpref_min and
// fpref_max.  Nothing is rounded, and FTZ does not apply: a subnormal
// operand is compared by its value and returned as it is (the result is
// always an operand's bit pattern, a quieted NaN, or abs/neg of a).
//
//   op_i = 0  abs: a with bit 31 cleared          (IEEE 754-2019 §5.5.1)
//   op_i = 1  neg: a with bit 31 flipped          (§5.5.1)
//             both also for a NaN, and quiet: never a flag
//   op_i = 2  min: IEEE 754-2019 §9.6 minimum
//   op_i = 3  max: IEEE 754-2019 §9.6 maximum
//             a NaN operand gives a NaN: a quieted if a is NaN, else b
//             quieted (the rule of the arithmetic cores, §6.2); invalid
//             only when an operand is a signalling NaN; -0 < +0; among
//             equal operands (the same bit pattern) either
//
// Comparison: for numbers of different signs the negative one is the
// smaller (-0 included); for two positive ones the smaller magnitude
// field, for two negative ones the larger: one 31-bit magnitude compare
// and a sign test.
//
// Parameters:
//   LATENCY  register stages from the operands to the result, >= 1
//            (the move path: 1, or 1 + the pick stages of FMAX_PIPE)
//
// Ports:
//   clk_i, rst_i  clock (rising edge), synchronous reset of the valid bits
//   valid_i       an operation is presented this cycle
//   op_i          the operation (above)
//   a_i, b_i      operands (binary32 bit patterns; b_i unused by abs, neg)
//   valid_o       a result is presented this cycle (LATENCY after valid_i)
//   y_o           result
//   flags_o       {invalid, 0, 0, 0, 0}, the SoftFloat bit order
//
// Cost: a 31-bit comparator, two NaN tests and a 32-bit four-way
// multiplexer (about 60 LUT4s), plus the registers: with LATENCY >= 2 the
// first holds the operands (66 bits and the valid bit), with LATENCY >= 3
// the second the operands and the compare's results, the others the
// result and flags.
`default_nettype none

module fp_sign #(
  parameter integer LATENCY = 1 // register stages, >= 1
) (
  input  wire        clk_i,
  input  wire        rst_i,
  input  wire        valid_i,
  input  wire [1:0]  op_i,
  input  wire [31:0] a_i,
  input  wire [31:0] b_i,
  output wire        valid_o,
  output wire [31:0] y_o,
  output wire [4:0]  flags_o
);

  localparam [1:0]  OP_ABS    = 2'd0;
  localparam [1:0]  OP_NEG    = 2'd1;
  localparam [1:0]  OP_MIN    = 2'd2;
  localparam [31:0] QUIET_BIT = 32'h0040_0000;
  localparam [4:0]  FLAG_NV   = 5'b10000;

  generate
    if (LATENCY < 1) begin : g_bad_latency
      // Elaboration error on purpose: LATENCY must be at least 1.
      fp_sign_error_LATENCY_must_be_at_least_1 u_error ();
    end
  endgenerate

  // With LATENCY >= 2 the first register stage holds the operands, in
  // front of the compare: the operands arrive from the register file's
  // last read stage through the immediate multiplexer, and the 31-bit
  // compare's carry chain and the result multiplexer behind them in the
  // same cycle made this the build for clock rate's critical path (about
  // 100 MHz on the LFE5U-85F-6).  Costs 29 flip-flops more (the
  // operands are 66 bits, the result and flags 37), no cycle.
  localparam integer IN_REG = (LATENCY >= 2) ? 1 : 0;
  wire        v;
  wire [1:0]  op;
  wire [31:0] a, b;
  fp_pipe #(.WIDTH(2 + 32 + 32), .DEPTH(IN_REG)) u_pipe_in (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (valid_i),
    .data_i  ({op_i, a_i, b_i}),
    .valid_o (v),
    .data_o  ({op, a, b})
  );

  wire a_nan_d  = (a[30:23] == 8'hFF) & (|a[22:0]);
  wire b_nan_d  = (b[30:23] == 8'hFF) & (|b[22:0]);
  wire any_snan_d = a_nan_d & ~a[22] | b_nan_d & ~b[22];

  // a < b in the order of §9.6 (meaningless when either is a NaN).
  wire mag_lt = a[30:0] < b[30:0];
  wire mag_gt = a[30:0] > b[30:0];
  wire a_lt_b_d = (a[31] != b[31]) ? a[31]
                : (a[31] ? mag_gt : mag_lt);

  // With LATENCY >= 3 a second register stage holds the compare's and
  // the NaN tests' results, so that the carry chain and the result
  // multiplexer are in different cycles (the compare alone after the
  // operand register still limited the build for clock rate to about
  // 126 MHz).  Costs 70 flip-flops, no cycle.
  localparam integer MID_REG = (LATENCY >= 3) ? 1 : 0;
  wire        vm;
  wire [1:0]  opm;
  wire [31:0] am, bm;
  wire        a_nan, b_nan, any_snan, a_lt_b;
  fp_pipe #(.WIDTH(2 + 32 + 32 + 4), .DEPTH(MID_REG)) u_pipe_mid (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (v),
    .data_i  ({op, a, b, a_nan_d, b_nan_d, any_snan_d, a_lt_b_d}),
    .valid_o (vm),
    .data_o  ({opm, am, bm, a_nan, b_nan, any_snan, a_lt_b})
  );

  reg  [31:0] y;
  reg  [4:0]  flags;
  always @* begin
    flags = 5'd0;
    case (opm)
      OP_ABS: y = {1'b0, am[30:0]};
      OP_NEG: y = {~am[31], am[30:0]};
      default: begin
        if (a_nan | b_nan) begin
          y     = (a_nan ? am : bm) | QUIET_BIT;
          flags = any_snan ? FLAG_NV : 5'd0;
        end else begin
          // min: a if a < b, else b; max: a unless a < b.
          y = ((opm == OP_MIN) == a_lt_b) ? am : bm;
        end
      end
    endcase
  end

  fp_pipe #(.WIDTH(32 + 5), .DEPTH(LATENCY - IN_REG - MID_REG)) u_pipe_out (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (vm),
    .data_i  ({y, flags}),
    .valid_o (valid_o),
    .data_o  ({y_o, flags_o})
  );

endmodule

`default_nettype wire
