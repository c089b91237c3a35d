// fp3_spatial_frame -- the fixed frame around N step pipelines of a
// spatial chip (docs/spatial.md "The frame"): the objects' memory, the
// feeder that streams the awake list into the pipelines, the write-back
// of their results, and a run of K steps; the host reaches the memory
// through a simple port while no run is in progress
// (rtl/fp3_spatial_axil.v drives it; sw/isa/fp3_spatial_regs.h the map).
//
// Memory: M = N * ROWS objects in N banks; object o is row o / N of bank
// o mod N, and pipeline p reads and writes only bank p.  A bank holds
//   - the awake list's entries p, N + p, 2N + p, ... (entry i at row
//     i / N), each the row of an object of this bank or empty (bit RW);
//   - the objects' carried values, CARRIED words a row (fp3_spatial_mem);
//   - the objects' inputs, INPUTS words a row.
// Every memory is block RAM (fp3_spatial_mem) with one read and one write
// a cycle, so each pipeline reads one object and writes one back every
// cycle, with no port shared between banks.  Every read takes two cycles
// and its word leaves a register (the block's output register): a block
// RAM's read without it (5.83 ns clock-to-output on the ECP5) followed by
// the row multiplexer and the next memory's address would be the chip's
// critical path, slower than any pipeline's core.
//
// The feed, for round r of a step (fp3_spatial_feeder), pipeline p:
//   cycle t      every bank's awake list is read at row r;
//   cycle t + 2  its entry (if not empty) addresses the object's row in
//                the carried and the input memory;
//   cycle t + 4  the object enters pipeline p (valid, in_i, y_i); its row
//                has entered a delay line of LATENCY + 2 stages at t + 2;
//   cycle t + 4 + LATENCY  the pipeline's valid_o and y_o, and the row from
//                the line: the new carried values are written at the edge
//                that ends this cycle.
// The object's next step addresses its row no earlier than cycle
// t + LATENCY + 5 (a read has the writes of the cycles before its own),
// i.e. its round comes LATENCY + 3 cycles after this one: the feeder's
// PERIOD is LATENCY + 3 and its DRAIN LATENCY + 4, and a run of K steps
// over R rounds takes (K - 1) * max(R, LATENCY + 3) + R + LATENCY + 4
// cycles.
//
// Parameters
//   PIPELINES  N, 1 .. 255
//   INPUTS     input words per object (the step module's in_i), >= 1
//   CARRIED    carried words per object (its y_i, y_o), >= 1
//   ROWS       objects per bank, M / N, >= 2
//   RW         row address bits, clog2(ROWS) (at least 1)
//   RB         round bits, clog2(ROWS + 1)
//   LATENCY    the step module's LATENCY, >= 1
//   BW         bank number bits, clog2(N) (at least 1)
// Host port (used only while running_o is 0; the slave checks it)
//   host_we_i, host_re_i   a write, a read of word host_word_i of row
//                          host_row_i of bank host_bank_i in memory
//                          host_sel_i: 1 awake list, 2 carried, 3 inputs
//   host_wdata_i           the word; for the awake list bit 31 empty,
//                          [RW-1:0] the object's row
//   host_rdata_o           a read's word five cycles later; the awake list's
//                          entry as its object's number (row x N + bank),
//                          0xFFFFFFFF when empty
// Run
//   start_i, steps_i, rounds_i   fp3_spatial_feeder's (R = ceil(COUNT / N))
//   tail_i       the entries of the last round, COUNT - (R - 1) N, 1 .. N:
//                the banks p >= tail_i are not fed in that round (their
//                entries are beyond COUNT)
//   running_o, done_o, cycles_o  fp3_spatial_feeder's
// Pipelines (p's fields at [p * width +: width])
//   pv_o, pin_o, py_o   an object enters pipeline p: valid, in_i, y_i
//   pv_i, pyo_i         pipeline p's valid_o and y_o
//   pflags_i            pipeline p's flags_o (5 bits: IEEE 754 flags its
//                       cores raised on objects)
// Flags
//   flags_o  the run's sticky exception flags: the OR of every pflags_i
//            since the last START was taken (cleared by it and by
//            reset).  A pipeline's flags come at most 2 cycles after its
//            last write-back, so they are in flags_o by the cycle after
//            done_o rises, before a host can read DONE (fp3_spatial_axil
//            answers a read RD_CYCLES = 6 cycles after performing it).
// Write-back (observation; what the state memory writes this cycle)
//   wb_v_o[p]           bank p writes an object's new carried values back
//                       at the edge that ends this cycle (running and
//                       pv_i[p]: the memory's write enable)
//   wb_row_o            ... at row wb_row_o[p*RW +: RW] (object row * N + p);
//                       the words are pyo_i's.  Left unconnected, they cost
//                       nothing: the memory's own enable and address.
// Reset: rst_i, synchronous, active high (the feeder and the feed's valid
// bits; the memories keep their contents).
`default_nettype none
module fp3_spatial_frame #(
  parameter integer PIPELINES = 1,
  parameter integer INPUTS    = 1,
  parameter integer CARRIED   = 1,
  parameter integer ROWS      = 2,
  parameter integer RW        = 1,
  parameter integer RB        = 2,
  parameter integer LATENCY   = 1,
  parameter integer BW        = 1
) (
  input  wire                              clk_i,
  input  wire                              rst_i,
  // host port
  input  wire                              host_we_i,
  input  wire                              host_re_i,
  input  wire [1:0]                        host_sel_i,
  input  wire [BW-1:0]                     host_bank_i,
  input  wire [RW-1:0]                     host_row_i,
  input  wire [7:0]                        host_word_i,
  input  wire [31:0]                       host_wdata_i,
  output wire [31:0]                       host_rdata_o,
  // run
  input  wire                              start_i,
  input  wire [31:0]                       steps_i,
  input  wire [RB-1:0]                     rounds_i,
  input  wire [BW:0]                       tail_i,
  output wire                              running_o,
  output wire                              done_o,
  output wire [63:0]                       cycles_o,
  // pipelines
  output wire [PIPELINES-1:0]              pv_o,
  output wire [PIPELINES*32*INPUTS-1:0]    pin_o,
  output wire [PIPELINES*32*CARRIED-1:0]   py_o,
  input  wire [PIPELINES-1:0]              pv_i,
  input  wire [PIPELINES*32*CARRIED-1:0]   pyo_i,
  input  wire [PIPELINES*5-1:0]            pflags_i,
  output wire [4:0]                        flags_o,
  // write-back
  output wire [PIPELINES-1:0]              wb_v_o,
  output wire [PIPELINES*RW-1:0]           wb_row_o
);
  localparam [1:0] SEL_AWAKE = 2'd1;
  localparam [1:0] SEL_STATE = 2'd2;
  localparam [1:0] SEL_INPUT = 2'd3;
  localparam integer NC = CARRIED;
  localparam integer NI = INPUTS;

  wire          running;
  wire          feed, last;
  wire [RB-1:0] round;
  fp3_spatial_feeder #(.RB(RB), .PERIOD(LATENCY + 3), .DRAIN(LATENCY + 4)) u_feeder (
    .clk_i     (clk_i),
    .rst_i     (rst_i),
    .start_i   (start_i),
    .steps_i   (steps_i),
    .rounds_i  (rounds_i),
    .feed_o    (feed),
    .round_o   (round),
    .last_o    (last),
    .running_o (running),
    .done_o    (done_o),
    .cycles_o  (cycles_o)
  );
  assign running_o = running;


  // The host's word of a row, as a write enable of one word.
  wire [NC-1:0] host_state_word;
  wire [NI-1:0] host_input_word;
  genvar k;
  generate
    for (k = 0; k < NC; k = k + 1) begin : g_sw
      assign host_state_word[k] = host_word_i == k[7:0];
    end
    for (k = 0; k < NI; k = k + 1) begin : g_iw
      assign host_input_word[k] = host_word_i == k[7:0];
    end
  endgenerate

  // Every bank's rows as read, for the host's read multiplexer.
  wire [PIPELINES*(RW+1)-1:0]     awake_rd;
  wire [PIPELINES*32*NC-1:0]      state_rd;
  wire [PIPELINES*32*NI-1:0]      input_rd;

  genvar b;
  generate
    for (b = 0; b < PIPELINES; b = b + 1) begin : g_bank
      wire host_here = host_bank_i == b[BW-1:0];
      wire we        = host_we_i && host_here;

      // the awake list: entry {empty, row}
      wire [RW:0] entry;
      fp3_spatial_mem #(.WORDS(1), .WIDTH(RW + 1), .ROWS(ROWS), .RW(RW)) u_awake (
        .clk_i   (clk_i),
        .we_i    (we && host_sel_i == SEL_AWAKE),
        .waddr_i (host_row_i),
        .wdata_i ({host_wdata_i[31], host_wdata_i[RW-1:0]}),
        .raddr_i (running ? round[RW-1:0] : host_row_i),
        .rdata_o (entry)
      );
      assign awake_rd[b*(RW+1) +: RW+1] = entry;

      // The round's entry leaves the awake list two cycles after the
      // round; in the last round, only the banks below tail_i hold one.
      reg fv1_q, fv2_q;
      always @(posedge clk_i) begin
        fv1_q <= !rst_i && feed && (!last || b[BW:0] < tail_i);
        fv2_q <= !rst_i && fv1_q;
      end

      // the object the entry names: read its row (cycle t + 2), and its
      // row enters the delay line to the write-back
      wire          fetch = fv2_q && !entry[RW];
      wire [RW-1:0] orow  = running ? entry[RW-1:0] : host_row_i;

      // ... it enters the pipeline (cycle t + 4)
      reg          pv1_q, pv_q;
      always @(posedge clk_i) begin
        pv1_q <= !rst_i && fetch;
        pv_q  <= !rst_i && pv1_q;
      end
      wire [RW-1:0] wb_row;
      wire          unused_wb_valid;
      fp_pipe #(.WIDTH(RW), .DEPTH(LATENCY + 2)) u_row (
        .clk_i   (clk_i),
        .rst_i   (rst_i),
        .valid_i (1'b0),
        .data_i  (entry[RW-1:0]),
        .valid_o (unused_wb_valid),
        .data_o  (wb_row)
      );

      // carried values: read by the feed or the host, written back by the
      // pipeline (all words) or by the host (one)
      wire [32*NC-1:0] y_rd;
      fp3_spatial_mem #(.WORDS(NC), .ROWS(ROWS), .RW(RW)) u_state (
        .clk_i   (clk_i),
        .we_i    (running ? {NC{pv_i[b]}}
                          : {NC{we && host_sel_i == SEL_STATE}} & host_state_word),
        .waddr_i (running ? wb_row : host_row_i),
        .wdata_i (running ? pyo_i[b*32*NC +: 32*NC] : {NC{host_wdata_i}}),
        .raddr_i (orow),
        .rdata_o (y_rd)
      );
      assign state_rd[b*32*NC +: 32*NC] = y_rd;

      // inputs: read by the feed or the host, written by the host
      wire [32*NI-1:0] in_rd;
      fp3_spatial_mem #(.WORDS(NI), .ROWS(ROWS), .RW(RW)) u_input (
        .clk_i   (clk_i),
        .we_i    ({NI{we && host_sel_i == SEL_INPUT}} & host_input_word),
        .waddr_i (host_row_i),
        .wdata_i ({NI{host_wdata_i}}),
        .raddr_i (orow),
        .rdata_o (in_rd)
      );
      assign input_rd[b*32*NI +: 32*NI] = in_rd;

      assign wb_v_o[b] = running && pv_i[b];
      assign wb_row_o[b*RW +: RW] = wb_row;
      assign pv_o[b] = pv_q;
      assign pin_o[b*32*NI +: 32*NI] = in_rd;
      assign py_o[b*32*NC +: 32*NC]  = y_rd;
    end
  endgenerate

  // ---- the host's reads: the selected word, in three registered stages ------
  // Stage 1, in each bank: the word of the read (an awake entry as it is
  // stored, a carried word or an input word) into the bank's register
  // bank_q; stage 2: the read's bank into word_q; stage 3: an awake entry
  // as its object's number into rdata_q.  The banks' block RAMs are
  // spread over the chip: one multiplexer from all of them to a single
  // register was a placed chip's critical path (about three quarters of
  // it routing), and so was the entry's conversion (two carry chains)
  // after either route.  Each stage has one route or one piece of logic.
  // Cost: two cycles of read latency more than one multiplexer and its
  // register would take (the slave's RD_CYCLES), 32 flip-flops a bank and
  // one more word.
  reg [1:0]    rsel_q;
  reg [BW-1:0] rbank_q;
  reg [7:0]    rword_q;
  reg [31:0]   word_q, rdata_q;
  always @(posedge clk_i) begin
    if (host_re_i) begin
      rsel_q  <= host_sel_i;
      rbank_q <= host_bank_i;
      rword_q <= host_word_i;
    end
  end
  // (word and bank are in range: the slave answers SLVERR otherwise; it
  // has one read in flight, so rsel_q, rbank_q and rword_q hold through
  // the stages).  Multiplexers by comparison with constants, so that no
  // index is multiplied (synthesis would spend multiplier blocks on it).
  reg [32*PIPELINES-1:0] bank_q;
  integer i, j;
  always @(posedge clk_i) begin
    for (i = 0; i < PIPELINES; i = i + 1) begin
      case (rsel_q)
        SEL_AWAKE: bank_q[i*32 +: 32] <= {awake_rd[i*(RW+1) + RW], {(31 - RW){1'b0}},
                                           awake_rd[i*(RW+1) +: RW]};
        SEL_STATE: begin
          bank_q[i*32 +: 32] <= 32'd0;
          for (j = 0; j < NC; j = j + 1)
            if (rword_q == j[7:0]) bank_q[i*32 +: 32] <= state_rd[(i*NC + j)*32 +: 32];
        end
        default: begin
          bank_q[i*32 +: 32] <= 32'd0;
          for (j = 0; j < NI; j = j + 1)
            if (rword_q == j[7:0]) bank_q[i*32 +: 32] <= input_rd[(i*NI + j)*32 +: 32];
        end
      endcase
    end
  end
  reg [31:0] bank_word;
  integer    m;
  always @(*) begin
    bank_word = 32'd0;
    for (m = 0; m < PIPELINES; m = m + 1)
      if (rbank_q == m[BW-1:0]) bank_word = bank_q[m*32 +: 32];
  end
  // an awake entry {empty, row} of bank rbank_q as its object's number,
  // row x N + bank, or 0xFFFFFFFF when empty (row x N as shifts and adds
  // of the row by N's bits: no multiplier block)
  reg [31:0] row_n;
  integer    n;
  always @(*) begin
    row_n = {{(32-BW){1'b0}}, rbank_q};
    for (n = 0; n < 8; n = n + 1)
      if (PIPELINES[n]) row_n = row_n + ({{(32-RW){1'b0}}, word_q[RW-1:0]} << n);
  end
  always @(posedge clk_i) begin
    word_q  <= bank_word;
    rdata_q <= rsel_q != SEL_AWAKE ? word_q : word_q[31] ? 32'hFFFFFFFF : row_n;
  end
  assign host_rdata_o = rdata_q;

  // ---- the run's sticky exception flags ---------------------------------------
  reg  [4:0] flags_q;
  reg  [4:0] pflags_or;
  integer    f;
  always @(*) begin
    pflags_or = 5'd0;
    for (f = 0; f < PIPELINES; f = f + 1) pflags_or = pflags_or | pflags_i[f*5 +: 5];
  end
  always @(posedge clk_i)
    flags_q <= rst_i || (start_i && !running) ? 5'd0 : flags_q | pflags_or;
  assign flags_o = flags_q;

  // A round's number is below ROWS: its top bit (RB > RW) is not needed to
  // address a row.
  wire unused_round = &{1'b0, round};
endmodule
`default_nettype wire
