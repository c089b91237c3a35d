// fp3_spatial_feeder -- the run sequencer of a spatial frame: a run of K
// steps over R rounds of the awake list, one round a cycle.
//
// A step presents rounds 0 .. R-1 in its first R cycles and lasts
// P = max(R, PERIOD) cycles: an object's next step may read it only
// after its last one is written back, PERIOD cycles after its round
// (the frame's PERIOD: the awake-list and object reads, 2 cycles, and the
// pipeline's latency L), so with fewer rounds than that a step ends in
// P - R bubbles.  After the last step's last round the feeder waits DRAIN
// cycles (the frame's: the last round's write-back) and the run is done.
// A run therefore takes
//     CYCLES = (K - 1) * max(R, PERIOD) + R + DRAIN
// cycles from the cycle after START to the cycle DONE rises, counted in
// cycles_o; a START with K = 0 or R = 0 is done at once, 0 cycles.
//
// Parameters
//   RB      round number bits (R < 2^RB)
//   PERIOD  the fewest cycles between an object's rounds in two steps, >= 1
//   DRAIN   cycles from the last round to DONE, >= 1
// Ports
//   start_i          begin a run (ignored while running): steps_i = K and
//                    rounds_i = R are sampled at this edge
//   feed_o, round_o  present round round_o of the awake list this cycle
//   last_o           ... the step's last round
//   running_o        a run is in progress (registered)
//   done_o           the last run has ended (registered; cleared by start)
//   cycles_o         cycles of the current or last run (64 bits)
// Reset: rst_i, synchronous, active high: stopped, not done, cycles 0.
`default_nettype none
module fp3_spatial_feeder #(
  parameter integer RB     = 8,
  parameter integer PERIOD = 3,
  parameter integer DRAIN  = 3
) (
  input  wire          clk_i,
  input  wire          rst_i,
  input  wire          start_i,
  input  wire [31:0]   steps_i,
  input  wire [RB-1:0] rounds_i,
  output wire          feed_o,
  output wire [RB-1:0] round_o,
  output wire          last_o,
  output wire          running_o,
  output wire          done_o,
  output wire [63:0]   cycles_o
);
  // The step's cycle counter counts to max(R, PERIOD) - 1.
  localparam integer PB = $clog2(PERIOD + 1);
  localparam integer TW = (RB > PB ? RB : PB) + 1;
  localparam integer DB = $clog2(DRAIN + 1);
  localparam [TW-1:0] PERIOD_T = PERIOD[TW-1:0];
  localparam [DB-1:0] DRAIN_D  = DRAIN[DB-1:0];

  reg          running_q, done_q, drain_q;
  reg [31:0]   left_q;    // steps left, the current one included
  reg [TW-1:0] t_q;       // cycle of the current step
  reg [TW-1:0] last_q;    // the step's last cycle, max(R, PERIOD) - 1
  reg [TW-1:0] rlast_q;   // its last round's cycle, R - 1
  reg [DB-1:0] dcnt_q;    // drain cycles left
  reg [63:0]   cycles_q;

  wire [TW-1:0] rounds_t = {{(TW-RB){1'b0}}, rounds_i};

  always @(posedge clk_i) begin
    if (rst_i) begin
      running_q <= 1'b0;
      done_q    <= 1'b0;
      drain_q   <= 1'b0;
      cycles_q  <= 64'd0;
    end else if (!running_q) begin
      if (start_i) begin
        done_q   <= 1'b0;
        cycles_q <= 64'd0;
        if (steps_i == 32'd0 || rounds_i == {RB{1'b0}}) begin
          done_q <= 1'b1;
        end else begin
          running_q <= 1'b1;
          drain_q   <= 1'b0;
          left_q    <= steps_i;
          t_q       <= {TW{1'b0}};
          rlast_q   <= rounds_t - 1'b1;
          last_q    <= (rounds_t > PERIOD_T ? rounds_t : PERIOD_T) - 1'b1;
        end
      end
    end else begin
      cycles_q <= cycles_q + 64'd1;
      if (drain_q) begin
        if (dcnt_q == {{(DB-1){1'b0}}, 1'b1}) begin
          running_q <= 1'b0;
          done_q    <= 1'b1;
        end
        dcnt_q <= dcnt_q - 1'b1;
      end else if (left_q == 32'd1 && t_q == rlast_q) begin
        drain_q <= 1'b1;   // the last step's last round: wait for it
        dcnt_q  <= DRAIN_D;
      end else if (t_q == last_q) begin
        t_q    <= {TW{1'b0}};
        left_q <= left_q - 32'd1;
      end else begin
        t_q <= t_q + 1'b1;
      end
    end
  end

  assign feed_o    = running_q && !drain_q && t_q <= rlast_q;
  assign round_o   = t_q[RB-1:0];
  assign last_o    = t_q == rlast_q;
  assign running_o = running_q;
  assign done_o    = done_q;
  assign cycles_o  = cycles_q;
endmodule
`default_nettype wire
