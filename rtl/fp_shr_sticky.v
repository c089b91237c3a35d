// fp_shr_sticky.v -- logical right shift of a word by 0 to 31 places that
// keeps the OR of the bits shifted out (combinational), for the
// multiplier's denormalisation shift (fp_mul).
//
// Parameters:
//   WIDTH  bits of the word (>= 1)
//
// Ports:
//   v_i       the word
//   amt_i     right shift, 0 to 31 places (>= WIDTH: all bits go to sticky)
//   sticky_i  sticky bit of earlier shifts, ORed into sticky_o
//   v_o       v_i >> amt_i
//   sticky_o  sticky_i OR any one bit shifted out
//
// Structure: five levels, 16, 8, 4, 2, 1 places; each level ORs the bits
// it drops into the sticky bit, so the sticky logic runs beside the
// multiplexers instead of after them.  A caller may split a shift over a
// register by using two instances, e.g. amt_i = {t[4:1], 1'b0} and then
// amt_i = {4'd0, t[0]} (the unused levels vanish as constants).
`default_nettype none

module fp_shr_sticky #(
  parameter integer WIDTH = 27 // bits of the word
) (
  input  wire [WIDTH-1:0] v_i,
  input  wire [4:0]       amt_i,
  input  wire             sticky_i,
  output wire [WIDTH-1:0] v_o,
  output wire             sticky_o
);

  // Level j shifts by 2^j places, 16 first.
  reg [WIDTH-1:0] v;
  reg             s;
  integer         j;
  always @* begin
    v = v_i;
    s = sticky_i;
    for (j = 4; j >= 0; j = j - 1) begin
      if (amt_i[j]) begin
        s = s | (|(v & ~({WIDTH{1'b1}} << (1 << j))));
        v = v >> (1 << j);
      end
    end
  end

  assign v_o      = v;
  assign sticky_o = s;

endmodule

`default_nettype wire
