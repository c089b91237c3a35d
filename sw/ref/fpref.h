/*
 * fpref.h -- reference binary32 add, sub, mul, div and sqrt on bit
 * patterns, with IEEE 754 exception flags, in every configuration the FP
 * cores support; and the exact sign and compare operations abs, neg, min,
 * max.
 *
 * This is what the RTL cores must equal bit for bit, and what the ISS
 * executes.  Results are those of the host CPU's IEEE float (x86-64 SSE),
 * with the NaN rules made explicit so that they do not depend on the order
 * in which a compiler puts the operands of a commutative operation:
 *
 *   - a is NaN            -> a quieted (bit 22 set), sign and payload kept
 *   - else b is NaN       -> b quieted (also for sub: the sign is not flipped)
 *   - else invalid (inf - inf, 0 * inf, 0 / 0, inf / inf, sqrt of a
 *     number below zero) -> default NaN 0xFFC00000
 *
 * Division by zero (a finite nonzero a over a zero b, IEEE 754-2019 §7.3)
 * gives an infinity of the XOR sign and the flag FP3_FLAG_INFINITE.
 * sqrt(-0) = -0 (§5.4.1), sqrt(+inf) = +inf, both exact.
 *
 * Flags use FP3_FLAG_* (fp3_isa.h), the Berkeley SoftFloat bit order;
 * tininess is detected after rounding (x86, TestFloat -tininessafter).
 */
#ifndef FP3_FPREF_H
#define FP3_FPREF_H

#include <stdint.h>

/* Rounding of the cores (build-time parameter ROUND of fp_add / fp_mul). */
typedef enum fpref_round {
  FPREF_RNE = 0, /* round to nearest, ties to even (default) */
  FPREF_RTZ = 1  /* round toward zero (TestFloat "minMag")  */
} fpref_round;

/* A core configuration. */
typedef struct fpref_mode {
  fpref_round round;
  int ftz; /* 1: subnormal inputs read as zero and subnormal results
              flushed to zero, sign kept (parameter FTZ) */
} fpref_mode;

/* The default configuration: RNE, subnormals supported. */
extern const fpref_mode FPREF_IEEE;

/* a + b, a - b, a * b.  *flags (may be NULL) gets the exception flags of
 * this operation OR-ed into it. */
uint32_t fpref_add(uint32_t a, uint32_t b, fpref_mode mode, unsigned *flags);
uint32_t fpref_sub(uint32_t a, uint32_t b, fpref_mode mode, unsigned *flags);
uint32_t fpref_mul(uint32_t a, uint32_t b, fpref_mode mode, unsigned *flags);

/* a / b (IEEE 754-2019 §5.4.1 division) and sqrt(a) (§5.4.1
 * squareRoot), correctly rounded in `mode`, flags as above.  A quotient's
 * tininess is detected after rounding like the others'; a square root is
 * never tiny and never overflows (its exponent is about half the
 * operand's), so it raises only inexact and invalid. */
uint32_t fpref_div(uint32_t a, uint32_t b, fpref_mode mode, unsigned *flags);
uint32_t fpref_sqrt(uint32_t a, fpref_mode mode, unsigned *flags);

/* The exact sign and compare operations.  None rounds; none reads a
 * subnormal as zero or flushes one (FTZ does not apply: they return one
 * of their operands' bit patterns, or it with the sign changed).
 *
 * abs, neg: IEEE 754-2019 §5.5.1 sign bit operations: clear or flip bit
 *   31, also of a NaN, no flag (quiet even for a signalling NaN).
 * min, max: IEEE 754-2019 §9.6 minimum and maximum: a NaN operand gives
 *   a NaN (a quieted if a is NaN, else b quieted, as the arithmetic),
 *   invalid only when an operand is a signalling NaN; -0 is less than
 *   +0 (min(+0, -0) = -0, max(-0, +0) = +0); otherwise the smaller or
 *   larger operand, exactly. */
uint32_t fpref_abs(uint32_t a);
uint32_t fpref_neg(uint32_t a);
uint32_t fpref_min(uint32_t a, uint32_t b, unsigned *flags);
uint32_t fpref_max(uint32_t a, uint32_t b, unsigned *flags);

/* Bit-pattern helpers. */
uint32_t fpref_bits(float f);
float fpref_float(uint32_t bits);
int fpref_is_nan(uint32_t bits);

#endif /* FP3_FPREF_H */
