// fp3_wb_tag -- the write-back tag line of one unit: the destination index
// of each operation, from its issue to its write-back, announced AHEAD
// cycles before the write-back for the scoreboard.
//
// An operation issued in cycle t (the cycle its operands' addresses go to
// the register file) is written back in cycle W = t + ISSUE_TO_WB.  The
// line delivers its index twice: on ahead_*_o in cycle W - AHEAD, when the
// scheduler may already count the register as free (its consumer, issued
// in cycle W - READ_STAGES + 1 at the earliest, reads it from the
// register file's bypass; fp3_top "Pipeline"), and
// on wb_*_o in cycle W, with the result, as the register file's write
// index and the trace.  The announcement is also shown a cycle before it
// is made, on early_*_o in cycle W - AHEAD - 1, so that the scheduler can
// compare it with its queued instructions' registers a cycle ahead and
// keep the outcome in a register.  And, for registers that copy the
// announcement beside groups of its loads (fp3_sched_queue's per-context
// copies) or that look further ahead (its issue loop's registered stages),
// one, two and three cycles before that, on pre_*_o, pre2_*_o and
// pre3_*_o: taps of the line, as far back as it reaches; the pick (the
// issue a cycle ahead) is the earliest, and a tap the line is too short
// for shows the pick, later than its name (the scheduler's ready step is
// then as much later for this unit's consumers, never early).
//
// Parameters
//   XW           index width ({context, register})
//   ISSUE_TO_WB  cycles from issue to write-back (read stages + unit
//                latency), >= AHEAD + 1
//   AHEAD        cycles the announcement precedes the write-back, >= 1
// Ports
//   valid_i, idx_i  an operation for this unit issues this cycle
//   pvalid_i, pidx_i  the operation picked: valid_i, idx_i of the next
//                   cycle (the issue a cycle ahead); the taps that reach
//                   past the line's start (issue) show it
//   pre_valid_o, pre_idx_o  ... will be written back in AHEAD + 2 cycles
//                   (the line's stage in front of early_*_o; the pick if
//                   ISSUE_TO_WB = AHEAD + 1)
//   pre2_valid_o, pre2_idx_o  ... in AHEAD + 3 cycles (ISSUE_TO_WB >=
//                   AHEAD + 2; else as pre_*_o)
//   pre3_valid_o, pre3_idx_o  ... in AHEAD + 4 cycles (ISSUE_TO_WB >=
//                   AHEAD + 3; else as pre2_*_o)
//   early_valid_o, early_idx_o  ... will be written back in AHEAD + 1
//                   cycles (with ISSUE_TO_WB = AHEAD + 1, valid_i, idx_i)
//   ahead_valid_o, ahead_idx_o  ... will be written back in AHEAD cycles
//   next2_valid_o, next2_idx_o  ... is written back in 2 cycles (the
//                               register file's read stages compare it
//                               with their index: fp3_regfile nx2*_i)
//   wb_valid_o, wb_idx_o        ... is written back this cycle
`default_nettype none
module fp3_wb_tag #(
  parameter integer XW          = 5,
  parameter integer ISSUE_TO_WB = 2,
  parameter integer AHEAD       = 1
) (
  input  wire          clk_i,
  input  wire          rst_i,
  input  wire          valid_i,
  input  wire [XW-1:0] idx_i,
  input  wire          pvalid_i,
  input  wire [XW-1:0] pidx_i,
  output wire          pre_valid_o,
  output wire [XW-1:0] pre_idx_o,
  output wire          pre2_valid_o,
  output wire [XW-1:0] pre2_idx_o,
  output wire          pre3_valid_o,
  output wire [XW-1:0] pre3_idx_o,
  output wire          early_valid_o,
  output wire [XW-1:0] early_idx_o,
  output wire          ahead_valid_o,
  output wire [XW-1:0] ahead_idx_o,
  output wire          next2_valid_o,
  output wire [XW-1:0] next2_idx_o,
  output wire          wb_valid_o,
  output wire [XW-1:0] wb_idx_o
);
  // The line from the issue to the announcement shown early: stage j
  // (0 .. D) holds the operation issued j cycles ago; stage D is early_*_o.
  // A tap k cycles before early_*_o is stage D - k, or the pick for
  // k = D + 1; taps the line does not reach take the pick (the earliest
  // the line knows of the operation).
  localparam integer D = ISSUE_TO_WB - AHEAD - 1;
  wire [D:0]          line_v;
  wire [(D+1)*XW-1:0] line_i;
  assign line_v[0]       = valid_i;
  assign line_i[0 +: XW] = idx_i;
  genvar j;
  generate
    if (D < 0) begin : g_bad_line
      // Elaboration error on purpose: ISSUE_TO_WB must exceed AHEAD.
      fp3_wb_tag_error_ISSUE_TO_WB_must_exceed_AHEAD u_error ();
    end
    for (j = 1; j <= D; j = j + 1) begin : g_line
      fp_pipe #(.WIDTH(XW), .DEPTH(1)) u_stage (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (line_v[j-1]),
        .data_i  (line_i[(j-1)*XW +: XW]),
        .valid_o (line_v[j]),
        .data_o  (line_i[j*XW +: XW])
      );
    end
  endgenerate
  assign early_valid_o = line_v[D];
  assign early_idx_o   = line_i[D*XW +: XW];
  // The taps: k = 1 (pre_*_o), 2 (pre2_*_o), 3 (pre3_*_o).
  wire [3:1]      tap_v;
  wire [3*XW-1:0] tap_i;              // tap k in [(k-1)*XW +: XW]
  generate
    for (j = 1; j <= 3; j = j + 1) begin : g_tap
      if (j <= D) begin : g_stage
        assign tap_v[j]              = line_v[D-j];
        assign tap_i[(j-1)*XW +: XW] = line_i[(D-j)*XW +: XW];
      end else begin : g_pick
        assign tap_v[j]              = pvalid_i;
        assign tap_i[(j-1)*XW +: XW] = pidx_i;
      end
    end
    if (D >= 3) begin : g_no_pick
      wire unused_pick = &{1'b0, pvalid_i, pidx_i};  // (the line has every tap)
    end
  endgenerate
  assign {pre3_valid_o, pre2_valid_o, pre_valid_o} = tap_v;
  assign {pre3_idx_o, pre2_idx_o, pre_idx_o}       = tap_i;
`ifdef FP3_MUTANT_ANNOUNCE_EARLY
  // A broken line for formal/sched.sby's mutant: one stage short, so the
  // announcement (and the write-back index behind it) comes a cycle
  // early: the busy flag clears, and a consumer may issue, a cycle before
  // the operand's value exists.
  assign ahead_valid_o = early_valid_o;
  assign ahead_idx_o   = early_idx_o;
`else
  fp_pipe #(.WIDTH(XW), .DEPTH(1)) u_to_ahead (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (early_valid_o),
    .data_i  (early_idx_o),
    .valid_o (ahead_valid_o),
    .data_o  (ahead_idx_o)
  );
`endif
  // Two cycles before the write-back: the announcement a cycle early
  // (AHEAD = 1), or a stage of the line after the announcement.
  wire          next_valid;
  wire [XW-1:0] next_idx;
  generate
    if (AHEAD == 1) begin : g_next2_early
      assign next2_valid_o = early_valid_o;
      assign next2_idx_o   = early_idx_o;
      assign next_valid    = ahead_valid_o;
      assign next_idx      = ahead_idx_o;
    end else begin : g_next2_line
      fp_pipe #(.WIDTH(XW), .DEPTH(AHEAD - 2)) u_to_next2 (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (ahead_valid_o),
        .data_i  (ahead_idx_o),
        .valid_o (next2_valid_o),
        .data_o  (next2_idx_o)
      );
      fp_pipe #(.WIDTH(XW), .DEPTH(1)) u_to_next (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (next2_valid_o),
        .data_i  (next2_idx_o),
        .valid_o (next_valid),
        .data_o  (next_idx)
      );
    end
  endgenerate
  fp_pipe #(.WIDTH(XW), .DEPTH(1)) u_to_wb (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (next_valid),
    .data_i  (next_idx),
    .valid_o (wb_valid_o),
    .data_o  (wb_idx_o)
  );
endmodule
`default_nettype wire
