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
    else if (take_i) pos_q <= {{N{1'b0}}, taken_i} << 1;
  end
endmodule
`default_nettype wire
