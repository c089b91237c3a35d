// fp3_rr_arbiter -- round-robin pick among N requesters: the first one
// after the last grant taken, else the first one from requester 0 on.
// The scheduler's issue arbiter (among the ready contexts) and its fetch
// arbiter (among the contexts that may fetch) are each one.
//
// The pick is combinational from req_i and a one-hot position register,
// pos (2N bits): bit g + 1 after a grant to requester g is taken (bit N,
// the second copy's first, after the last requester).  With x = {req_i,
// req_i}, the requests twice, d = x - pos borrows from x's first set bit
// at or after pos, so x & ~d keeps that bit and no set bit below it: the
// grant, found by a carry chain (the FPGA's adder) with no logic in front
// of it when req_i comes from flip-flops.  The two copies ORed give the
// one-hot pick.  After reset the round starts at requester 0.
//
// Parameters
//   N        requesters (>= 1)
// Ports
//   clk_i    clock, rising edge
//   rst_i    synchronous reset: the next round starts at requester 0
//   req_i    the requests of this cycle, N bits
//   pick_o   the one-hot pick among req_i, N bits (zero if req_i is)
//   take_i   a grant is taken this cycle (need not be pick_o: the caller
//            may mask it)
//   taken_i  ... that grant, one-hot, N bits: the next round starts after
//            it
//
// Formal properties (`ifdef FORMAL; formal/rr_arbiter.sby proves them with
// the callers' disciplines, formal/fp3_rr_fair.v): the pick is a subset of
// the requests, at most one bit, and not empty when a request is; the
// position stays one-hot, at bit N or below, after the first cycle (every trace starts with a
// reset: assumed), given the caller's contract (asserted here: a taken
// grant is one-hot).  The define
// FP3_MUTANT_RR_STUCK is a deliberately broken copy for the mutation test
// (tests/test_formal_mutant.sh): the position never moves, so a context
// behind others that keep requesting starves; the fairness proof must fail.
`default_nettype none
module fp3_rr_arbiter #(
  parameter integer N = 8
) (
  input  wire         clk_i,
  input  wire         rst_i,
  input  wire [N-1:0] req_i,
  output wire [N-1:0] pick_o,
  input  wire         take_i,
  input  wire [N-1:0] taken_i
);
  reg  [2*N-1:0] pos_q;
  wire [2*N-1:0] x  = {req_i, req_i};
  wire [2*N-1:0] d  = x - pos_q;
  wire [2*N-1:0] lo = x & ~d;
  assign pick_o = lo[N-1:0] | lo[2*N-1:N];

  always @(posedge clk_i) begin
    if (rst_i)       pos_q <= {{(2*N-1){1'b0}}, 1'b1};
`ifdef FP3_MUTANT_RR_STUCK
    else if (take_i) pos_q <= pos_q;
`else
    else if (take_i) pos_q <= {{N{1'b0}}, taken_i} << 1;
`endif
  end

`ifdef FORMAL
  // Every trace starts with a reset (the scheduler resets the arbiter
  // while it is not running); from the next cycle on the position is
  // one-hot.
  reg f_past_valid = 1'b0;
  always @(posedge clk_i) f_past_valid <= 1'b1;
  always @(*) if (!f_past_valid) assume (rst_i);
  always @(*) begin
    if (f_past_valid) begin
      rr_pick_requested: assert ((pick_o & ~req_i) == {N{1'b0}});
      rr_pick_onehot0:   assert ($onehot0(pick_o));
      rr_pick_nonempty:  assert (req_i == {N{1'b0}} || pick_o != {N{1'b0}});
      rr_pos_onehot:     assert ($onehot(pos_q));
      rr_pos_range:      assert ((pos_q >> (N + 1)) == {2*N{1'b0}});  // bit N at most
      if (!rst_i && take_i) rr_taken_onehot: assert ($onehot(taken_i));
    end
  end
`endif
endmodule
`default_nettype wire
