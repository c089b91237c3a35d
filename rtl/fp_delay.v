// fp_delay.v -- a long delay line in RAM: a data word delayed by exactly
// DEPTH cycles, as a circular buffer written every cycle and read with a
// registered read.  The spatial back end (sw/compiler/spatial.h) uses it
// for the delay lines that balance a pipeline's paths when they are longer
// than a few stages; shorter ones are rtl/fp_pipe.v flip-flops.
//
// Why: a flip-flop delay costs WIDTH flip-flops per stage (a 180-stage
// line of one binary32 value: 5,760 flip-flops), while a RAM holds the
// same words in LUT RAM (ECP5 TRELLIS_DPR16X4: 16 words x 4 bits in one
// cell) or in one block RAM (ECP5 DP16KD: 512 x 36).  The measured costs
// and the rule that chooses the form are in spatial.h and docs/spatial.md.
//
// Parameters:
//   WIDTH  data bits (>= 1)
//   DEPTH  the delay, cycles: STYLE 1 >= 2, STYLE 2 >= 3
//   STYLE  1: LUT RAM (ram_style "distributed"): the read address is a
//             register, the RAM's asynchronous read is registered (1
//             read stage);
//          2: block RAM (ram_style "block"): the read address and word
//             registered in the block, then one fabric register (2 read
//             stages).  In ECP5 synthesis (FP3_ECP5_EBR, set by
//             scripts/synth.sh) and up to 512 words: the block's own
//             output register instead of the fabric one (fp3_ram
//             READ_STAGES 2, a PDPW16KD with REGMODE "OUTREG"), the same
//             2 read stages.  Why: without it the word leaves the block
//             5.61 ns after the clock in nextpnr's model, and the placer
//             does not keep the fabric register beside the block: on the
//             literal ship's chip that route (3.39 ns) made the 9.0 ns
//             critical path; with it the word leaves a register 0.97 ns
//             after the clock.  tests/test_delay_ebr.sh checks that the
//             synthesized form delays as the RTL does.
//
// Ports:
//   clk_i   clock, rising edge
//   data_i  the word entering the line (written every cycle)
//   data_o  data_i of DEPTH cycles before (don't-care for the first DEPTH
//           cycles after configuration)
//
// How: the write address wa_q counts up by one every cycle, modulo N (a
// power of two, the RAM's words).  A word written in cycle t must be read
// in cycle t + DEPTH - R (R read stages) to leave in cycle t + DEPTH, so
// the read address is wa_q - (DEPTH - R); it is a register loaded with
// the next cycle's value, wa_q + 1 - (DEPTH - R), so it follows wa_q from
// any initial value.  The word read was written DEPTH - R >= 1 cycles
// earlier (never in the read's own cycle: no read-during-write case) and
// is overwritten N cycles after its write, after its read when
// N >= DEPTH - R + 1.  No reset: the line holds data, not control (the
// pipeline's valid bit travels in fp_pipe).
`default_nettype none

module fp_delay #(
  parameter integer WIDTH = 32, // data bits
  parameter integer DEPTH = 16, // delay, cycles
  parameter integer STYLE = 1   // 1 LUT RAM, 2 block RAM
) (
  input  wire             clk_i,
  input  wire [WIDTH-1:0] data_i,
  output wire [WIDTH-1:0] data_o
);

  localparam integer R    = STYLE == 2 ? 2 : 1;  // read stages
  localparam integer GAP  = DEPTH - R;           // write-to-read cycles
  localparam integer AW   = clog2(GAP + 1);      // N = 2^AW >= GAP + 1
  localparam integer N    = 1 << AW;
  // wa_q + 1 - GAP, modulo N
  localparam integer STEP_I = (N + 1 - GAP) % N;
  localparam [AW-1:0] STEP = STEP_I[AW-1:0];

  function integer clog2(input integer v);
    integer k;
    begin
      clog2 = 1;
      for (k = 2; k < v; k = k * 2) clog2 = clog2 + 1;
    end
  endfunction

  generate
    if (STYLE != 1 && STYLE != 2) begin : g_bad_style
      // Elaboration error on purpose: STYLE must be 1 or 2.
      fp_delay_error_STYLE_must_be_1_or_2 u_error ();
    end else if (GAP < 1) begin : g_bad_depth
      // Elaboration error on purpose: DEPTH too short for the read stages.
      fp_delay_error_DEPTH_too_short u_error ();
    end else begin : g_ram
      reg [AW-1:0]    wa_q = {AW{1'b0}};
      reg [AW-1:0]    ra_q = {AW{1'b0}};
      reg [WIDTH-1:0] rd_q;

      always @(posedge clk_i) begin
        wa_q <= wa_q + 1'b1;
        ra_q <= wa_q + STEP;
      end

      if (STYLE == 1) begin : g_lut
        (* ram_style = "distributed", no_rw_check *) reg [WIDTH-1:0] mem [0:N-1];
        always @(posedge clk_i) begin
          mem[wa_q] <= data_i;
          rd_q      <= mem[ra_q];
        end
        assign data_o = rd_q;
`ifdef FP3_ECP5_EBR
      end else if (N <= 512) begin : g_block
        // ECP5 synthesis only (no simulator sees this form): the read
        // address goes to the block unregistered (fp3_ram registers it
        // inside), wa_q - GAP modulo N, the address ra_q holds a cycle
        // later in the form below; the block's output register is the
        // second read stage.  A word is read GAP >= 1 cycles after its
        // write and rewritten N >= GAP + 1 cycles after it, never at the
        // read's own edge (the case the block gives no promise for).
        localparam integer BACK_I = N - GAP;
        localparam [AW-1:0] BACK = BACK_I[AW-1:0];
        fp3_ram #(.DEPTH(N), .AW(AW), .WIDTH(WIDTH), .READ_STAGES(2)) u_ebr (
          .clk_i(clk_i), .we_i(1'b1), .waddr_i(wa_q), .wdata_i(data_i),
          .raddr_i(wa_q + BACK), .rdata_o(data_o));
`endif
      end else begin : g_block
        (* ram_style = "block", no_rw_check *) reg [WIDTH-1:0] mem [0:N-1];
        reg [WIDTH-1:0] out_q;
        always @(posedge clk_i) begin
          mem[wa_q] <= data_i;
          rd_q      <= mem[ra_q];
          out_q     <= rd_q;
        end
        assign data_o = out_q;
      end
    end
  endgenerate

endmodule

`default_nettype wire
