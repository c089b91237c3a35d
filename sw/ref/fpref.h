/*
 * fpref.h -- reference binary32 add, sub and mul on bit patterns, with
 * IEEE 754 exception flags, in every configuration the FP cores support.
 *
 * This is what the RTL cores must equal bit for bit, and what the ISS
 * executes.  Results are those of the host CPU's IEEE float (x86-64 SSE),
 * with the NaN rules made explicit so that they do not depend on the order
 * in which a compiler puts the operands of a commutative operation:
 *
 *   - a is NaN            -> a quieted (bit 22 set), sign and payload kept
 *   - else b is NaN       -> b quieted (also for sub: the sign is not flipped)
 *   - else invalid (inf - inf, 0 * inf) -> default NaN 0xFFC00000
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

/* Bit-pattern helpers. */
uint32_t fpref_bits(float f);
float fpref_float(uint32_t bits);
int fpref_is_nan(uint32_t bits);

#endif /* FP3_FPREF_H */
