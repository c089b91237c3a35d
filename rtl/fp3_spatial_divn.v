// fp3_spatial_divn -- division of a W-bit number by the constant N:
// quotient and remainder, for the spatial chip's AXI slave (an object or
// entry number to its row, o / N, and bank, o mod N).
//
// N a power of two (1, 2, 4, ...): shifts and masks, the result at the
// edge that samples start_i.  Otherwise restoring division, one quotient
// bit a cycle from the top: W + 1 cycles after start_i (none when the
// dividend is the last one again, as for the words of one object), at
// the cost of a
// (bits of N + 1)-bit subtractor and two W-bit registers, where a
// combinational divider would cost thousands of LUTs (yosys synth_ecp5 of
// the slave for N = 3: 16,616 LUT4 and 3,041 CCU2C with six of them).
// The start edge only registers the dividend and whether it is the last
// one again; the division begins at the next edge, from those registers,
// so that the compare of the dividend (a bus input) is not on the path to
// the enables of the division's registers (on a placed chip that path,
// through the compare and its fanout, was the critical one).
// Restoring division: r = 0; for i = W-1 .. 0: r = 2r + x[i]; if r >= N
// then r = r - N and q[i] = 1, else q[i] = 0.
//
// Parameters
//   N   the divisor, 1 .. 255
//   W   dividend bits, >= 2
//   NB  remainder bits, clog2(N) at least 1
// Ports
//   start_i     sample x_i and begin (at this edge); at most every
//               second cycle (as the AXI slave's channels take words)
//   x_i         the dividend
//   ready_o     q_o and r_o hold the last dividend's quotient and
//               remainder (a register of its own, so that it starts a
//               path of the slave's arbitration with no logic before it;
//               1 after reset, when they are not yet any dividend's)
//   q_o, r_o    x / N and x mod N
// Reset: rst_i, synchronous, active high: ready.
`default_nettype none
module fp3_spatial_divn #(
  parameter integer N  = 3,
  parameter integer W  = 8,
  parameter integer NB = 2
) (
  input  wire          clk_i,
  input  wire          rst_i,
  input  wire          start_i,
  input  wire [W-1:0]  x_i,
  output wire          ready_o,
  output wire [W-1:0]  q_o,
  output wire [NB-1:0] r_o
);
  generate
    if ((N & (N - 1)) == 0) begin : g_shift
      localparam integer S = $clog2(N);
      localparam integer NB_MASK = N - 1;
      reg [W-1:0]  q_q;
      reg [NB-1:0] r_q;
      always @(posedge clk_i) begin
        if (start_i) begin
          q_q <= x_i >> S;
          r_q <= x_i[NB-1:0] & NB_MASK[NB-1:0];
        end
      end
      assign ready_o = 1'b1;
      assign q_o = q_q;
      assign r_o = r_q;
      wire unused = &{1'b0, rst_i};
    end else begin : g_restore
      localparam integer CW = $clog2(W + 1);
      localparam [NB:0]  ND = N[NB:0];
      reg [W-1:0]  x_q, q_q;
      reg [NB-1:0] r_q;
      reg [CW-1:0] left_q;  // quotient bits left to find
      reg          ready_q; // left_q == 0, as a register
      wire [NB:0]  r2 = {r_q, x_q[W-1]};       // 2r + the next bit
      wire         ge = r2 >= ND;
      wire [NB:0]  rn = ge ? r2 - ND : r2;
      // The last dividend: a start with the same one keeps (or goes on
      // finding) its result instead of dividing again.  The start edge
      // registers the dividend (xin_q) and that compare (same_q); the
      // division, when there is one, begins at the next (again).
      reg [W-1:0]  last_q, xin_q;
      reg          have_q, st_q, same_q;
      wire         same = have_q && x_i == last_q;
      wire         again = st_q && !same_q;
      always @(posedge clk_i) begin
        st_q <= !rst_i && start_i;
        if (start_i) begin
          xin_q  <= x_i;
          same_q <= same;
        end
        // ready: at a start, only for the last dividend with its result
        // found; else when no division begins and at most one bit is left
        // (left_q's next value is 0)
        ready_q <= rst_i || (start_i ? same && left_q == {CW{1'b0}}
                                     : !again && left_q <= {{(CW-1){1'b0}}, 1'b1});
        if (rst_i) begin
          left_q <= {CW{1'b0}};
          have_q <= 1'b0;
        end else if (again) begin
          left_q <= W[CW-1:0];
          have_q <= 1'b1;
        end else if (left_q != {CW{1'b0}}) begin
          left_q <= left_q - 1'b1;
        end
        if (again) begin
          last_q <= xin_q;
          x_q    <= xin_q;
          r_q    <= {NB{1'b0}};
        end else if (left_q != {CW{1'b0}}) begin
          x_q <= x_q << 1;
          q_q <= {q_q[W-2:0], ge};
          r_q <= rn[NB-1:0];
        end
      end
      assign ready_o = ready_q;
      assign q_o = q_q;
      assign r_o = r_q;
      // rn < N < 2^NB: its top bit is 0.
      wire unused = &{1'b0, rn[NB]};
    end
  endgenerate
endmodule
`default_nettype wire
