// fp_lzc.v -- leading-zero count of a word of up to 31 bits
// (combinational), a balanced tree for the FP cores' normalisation.
//
// Parameters:
//   WIDTH  bits of the word, 1 to 31
//
// Ports:
//   v_i  the word; bit WIDTH-1 is the most significant
//   n_o  number of zeros above the most significant one, WIDTH if v_i == 0
//
// Structure: the word is padded on the right with ones to 32 bits, cut
// into eight nibbles, and counted as a tree (nibble, byte, half, word):
// each level combines the all-zero flag and count of two halves, so the
// depth is four small functions instead of a priority chain.
`default_nettype none

module fp_lzc #(
  parameter integer WIDTH = 24 // bits of v_i, 1 to 31
) (
  input  wire [WIDTH-1:0] v_i,
  output wire [4:0]       n_o
);

  generate
    if ((WIDTH < 1) || (WIDTH > 31)) begin : g_bad_width
      // Elaboration error on purpose: WIDTH must be 1 to 31.
      fp_lzc_error_WIDTH_must_be_1_to_31 u_error ();
    end
  endgenerate

  // Ones below the word bound the count at WIDTH.
  wire [31:0] w = {v_i, {(32 - WIDTH){1'b1}}};

  // Level 0: the nibbles, k = 0 the most significant.
  wire [7:0]  z0;        // nibble k all zero
  wire [15:0] c0;        // its count, 2 bits at [2k +: 2]
  // Level 1: bytes, level 2: halves (zero flag and count per part).
  wire [3:0]  z1;
  wire [11:0] c1;        // 3 bits at [3k +: 3]
  wire [1:0]  z2;
  wire [7:0]  c2;        // 4 bits at [4k +: 4]

  genvar k;
  generate
    for (k = 0; k < 8; k = k + 1) begin : g_nib
      wire [3:0] q = w[31 - 4*k -: 4];
      assign z0[k]         = (q == 4'd0);
      assign c0[2*k +: 2]  = q[3] ? 2'd0 : q[2] ? 2'd1 : q[1] ? 2'd2 : 2'd3;
    end
    for (k = 0; k < 4; k = k + 1) begin : g_byte
      assign z1[k]        = z0[2*k] & z0[2*k+1];
      assign c1[3*k +: 3] = z0[2*k] ? {1'b1, c0[2*(2*k+1) +: 2]}
                                    : {1'b0, c0[2*(2*k) +: 2]};
    end
    for (k = 0; k < 2; k = k + 1) begin : g_half
      assign z2[k]        = z1[2*k] & z1[2*k+1];
      assign c2[4*k +: 4] = z1[2*k] ? {1'b1, c1[3*(2*k+1) +: 3]}
                                    : {1'b0, c1[3*(2*k) +: 3]};
    end
  endgenerate

  // The padding makes the whole word nonzero, so the count is at most 31;
  // the zero flag of the lower half is not needed.
  assign n_o = z2[0] ? {1'b1, c2[7:4]} : {1'b0, c2[3:0]};

  wire unused_z = &{1'b0, z2[1], 1'b0};

endmodule

`default_nettype wire
