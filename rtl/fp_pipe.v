// fp_pipe.v -- delay line of DEPTH pipeline registers for a valid bit and a
// data word, used to place the stage boundaries of the FP cores.
//
// Parameters:
//   WIDTH  data bits carried alongside the valid bit (>= 1)
//   DEPTH  register stages (>= 0); 0 is a plain wire (no clock, no reset)
//   HOLD   0: the data registers load every cycle (the default);
//          1: each loads only with the valid bit entering its stage, and
//          holds its word across bubbles; its registers carry Yosys's
//          keep attribute.  Two lines with the same inputs are then not
//          merged into one set by synthesis, even when their valid bits
//          are the same net (the FP cores' operand registers: each core
//          keeps its own, placed beside it).
//
// Ports:
//   clk_i    clock, rising edge
//   rst_i    synchronous reset, active high: clears the valid bits only
//   valid_i  valid bit entering the line
//   data_i   data entering the line
//   valid_o  valid_i delayed by DEPTH rising edges (reset to 0)
//   data_o   data_i delayed by DEPTH rising edges (not reset)
//
// Timing: what is on the inputs in cycle t is on the outputs in cycle
// t + DEPTH.  With HOLD = 0 data registers load every cycle (no enable): a
// bubble carries don't-care data with valid 0.
`default_nettype none

module fp_pipe #(
  parameter integer WIDTH = 1, // data bits
  parameter integer DEPTH = 1, // register stages, 0 = wire
  parameter integer HOLD  = 0  // 1: data loads only with its valid bit
) (
  input  wire             clk_i,
  input  wire             rst_i,
  input  wire             valid_i,
  input  wire [WIDTH-1:0] data_i,
  output wire             valid_o,
  output wire [WIDTH-1:0] data_o
);

  generate
    if (DEPTH < 0) begin : g_bad_depth
      // Elaboration error on purpose: DEPTH must not be negative.
      fp_pipe_error_DEPTH_must_be_at_least_0 u_error ();
    end else if (DEPTH == 0) begin : g_wire
      assign valid_o = valid_i;
      assign data_o  = data_i;
      // Clock and reset are not needed by a wire.
      wire unused_clk_rst = &{1'b0, clk_i, rst_i, 1'b0};
    end else begin : g_regs
      // Stage k occupies bits [k*WIDTH +: WIDTH] of data_q and bit k of
      // valid_q; stage 0 is loaded from the inputs, the last drives the
      // outputs.
      reg [DEPTH-1:0]       valid_q;
      reg [WIDTH*DEPTH-1:0] data_q;
      wire [DEPTH-1:0]       valid_d;
      wire [WIDTH*DEPTH-1:0] data_d;

      if (DEPTH == 1) begin : g_one
        assign valid_d = valid_i;
        assign data_d  = data_i;
      end else begin : g_many
        assign valid_d = {valid_q[DEPTH-2:0], valid_i};
        assign data_d  = {data_q[WIDTH*(DEPTH-1)-1:0], data_i};
      end

      always @(posedge clk_i) begin
        if (rst_i) begin
          valid_q <= {DEPTH{1'b0}};
        end else begin
          valid_q <= valid_d;
        end
      end

      genvar k;
      for (k = 0; k < DEPTH; k = k + 1) begin : g_stage
        // keep (HOLD = 1): Yosys's opt_merge would otherwise still merge
        // two such lines whose valid bits are the same net (the spatial
        // datapath's cores, whose valid_i is a constant 1).  A register
        // with a constant input is still removed.  (An attribute, not a
        // generate branch: HOLD = 0 lines keep their names, and so their
        // netlist.)
        (* keep = HOLD *)
        always @(posedge clk_i) begin
          if (HOLD == 0 || valid_d[k]) data_q[k*WIDTH +: WIDTH] <= data_d[k*WIDTH +: WIDTH];
        end
      end

      assign valid_o = valid_q[DEPTH-1];
      assign data_o  = data_q[WIDTH*DEPTH-1 -: WIDTH];
    end
  endgenerate

endmodule

`default_nettype wire
