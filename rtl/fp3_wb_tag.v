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
// keep the outcome in a register.  And a cycle before that, on pre_*_o
// (early_* of the next cycle), for registers that copy the announcement
// beside groups of its loads (fp3_scheduler's per-context copies).
//
// Parameters
//   XW           index width ({context, register})
//   ISSUE_TO_WB  cycles from issue to write-back (read stages + unit
//                latency), >= AHEAD + 1
//   AHEAD        cycles the announcement precedes the write-back, >= 1
// Ports
//   valid_i, idx_i  an operation for this unit issues this cycle
//   pvalid_i, pidx_i  the operation picked: valid_i, idx_i of the next
//                   cycle (the issue a cycle ahead); used only with
//                   ISSUE_TO_WB = AHEAD + 1, where it is pre_*_o
//   pre_valid_o, pre_idx_o  ... will be written back in AHEAD + 2 cycles
//                   (the line's stage in front of early_*_o; with
//                   ISSUE_TO_WB = AHEAD + 2, valid_i, idx_i; with AHEAD + 1,
//                   pvalid_i, pidx_i)
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
  output wire          early_valid_o,
  output wire [XW-1:0] early_idx_o,
  output wire          ahead_valid_o,
  output wire [XW-1:0] ahead_idx_o,
  output wire          next2_valid_o,
  output wire [XW-1:0] next2_idx_o,
  output wire          wb_valid_o,
  output wire [XW-1:0] wb_idx_o
);
  generate
    if (ISSUE_TO_WB == AHEAD + 1) begin : g_early_input
      // The announcement is the issue itself: a cycle before, the pick.
      assign pre_valid_o   = pvalid_i;
      assign pre_idx_o     = pidx_i;
      assign early_valid_o = valid_i;
      assign early_idx_o   = idx_i;
    end else begin : g_early_line
      fp_pipe #(.WIDTH(XW), .DEPTH(ISSUE_TO_WB - AHEAD - 2)) u_to_pre (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (valid_i),
        .data_i  (idx_i),
        .valid_o (pre_valid_o),
        .data_o  (pre_idx_o)
      );
      fp_pipe #(.WIDTH(XW), .DEPTH(1)) u_to_early (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (pre_valid_o),
        .data_i  (pre_idx_o),
        .valid_o (early_valid_o),
        .data_o  (early_idx_o)
      );
      wire unused_pick = &{1'b0, pvalid_i, pidx_i};  // (the line has the stage)
    end
  endgenerate
  fp_pipe #(.WIDTH(XW), .DEPTH(1)) u_to_ahead (
    .clk_i   (clk_i),
    .rst_i   (rst_i),
    .valid_i (early_valid_o),
    .data_i  (early_idx_o),
    .valid_o (ahead_valid_o),
    .data_o  (ahead_idx_o)
  );
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
