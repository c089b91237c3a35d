// fp_recur_unpack.v -- one binary32 operand of the digit-recurrence cores
// fp_div and fp_sqrt, unpacked (combinational): its class, its
// significand and the left shift that normalises it to a leading one at
// bit 23.  The shift itself is the core's next step (man_o << lz_o), so
// that a register may stand between the leading-zero count and it.
//
// Parameters:
//   FTZ  0: IEEE subnormals; 1: a subnormal operand reads as zero of its
//        sign (x86 DAZ): zero_o, no flag
//
// Ports:
//   x_i     the operand's magnitude (binary32 bits 30:0: the sign does
//           not enter)
//   nan_o   x_i is a NaN
//   snan_o  x_i is a signalling NaN (quiet bit 22 clear)
//   inf_o   x_i is an infinity
//   zero_o  x_i is a zero (FTZ: or a subnormal)
//   man_o   significand with the weight of the exponent field
//           (fp_mul_unpack_norm): {1, fraction} for a normal x_i (also
//           an infinity or a NaN: its payload is man_o[21:0]),
//           {fraction, 0} for a subnormal one
//   lz_o    the normalising shift: 0 for a normal x_i, 0 to 22 for a
//           subnormal one, 24 for a zero (always 0 with FTZ); man_o <<
//           lz_o has its leading one at bit 23 for a finite nonzero x_i,
//           with the exponent field less lz_o as its exponent, a
//           subnormal's field counting as 0
//
// Standards: IEEE 754-2019 §3.4 (encodings: NaN, infinity, zero,
// subnormal), §6.2.1 (the quiet bit of a NaN).
`default_nettype none

module fp_recur_unpack #(
  parameter integer FTZ = 0 // 1: subnormal operands read as zero
) (
  input  wire [30:0] x_i,
  output wire        nan_o,
  output wire        snan_o,
  output wire        inf_o,
  output wire        zero_o,
  output wire [23:0] man_o,
  output wire [4:0]  lz_o
);

  localparam [7:0] EXP_MAX = 8'hFF;

  wire [7:0] exp = x_i[30:23];
  wire       fnz = |x_i[22:0];

  fp_mul_unpack_norm #(.FTZ(FTZ)) u_norm (
    .exp_i  (exp),
    .frac_i (x_i[22:0]),
    .man_o  (man_o),
    .lz_o   (lz_o)
  );

  assign nan_o  = (exp == EXP_MAX) & fnz;
  assign snan_o = nan_o & ~x_i[22];
  assign inf_o  = (exp == EXP_MAX) & ~fnz;
  assign zero_o = (exp == 8'd0) & ((FTZ != 0) | ~fnz);

endmodule

`default_nettype wire
