/*
 * fpref.c -- reference binary32 add, sub, mul, div, sqrt and the sign and
 * compare operations (see fpref.h).
 *
 * The arithmetic is the host's IEEE float under <fenv.h> rounding control;
 * everything a host might do differently is made explicit here:
 *
 *   - NaN operands are handled before the host sees them (fpref.h rules),
 *     an invalid operation returns 0xFFC00000;
 *   - underflow is computed, not read from the host: tininess is detected
 *     after rounding (x86, TestFloat -tininessafter), so a host that
 *     detects it before rounding (e.g. ARM) still gives x86 flags;
 *   - FTZ: subnormal operands are replaced by zero of the same sign with no
 *     flag (x86 DAZ); a tiny nonzero result (tiny after rounding, as
 *     above, also when exact) becomes zero of the same sign with underflow
 *     and inexact (x86 MXCSR.FTZ; checked against the host MXCSR in
 *     tests/test_fpu.c).
 *
 * Portable C11.  Compile with -frounding-math (the Makefile does), so the
 * compiler does not fold or move the operations across fesetround; the
 * operands are volatile for the same reason.  The caller's rounding mode
 * and exception flags are preserved.
 */
#include "fpref.h"

#include <fenv.h>
#include <math.h>
#include <string.h>

#include "fp3_isa.h"

#define SIGN_BIT    0x80000000u
#define EXP_MASK    0x7F800000u
#define FRAC_MASK   0x007FFFFFu
#define QUIET_BIT   0x00400000u
#define MIN_NORMAL  0x00800000u
#define DEFAULT_NAN 0xFFC00000u

const fpref_mode FPREF_IEEE = {FPREF_RNE, 0};

enum ref_op { REF_ADD, REF_SUB, REF_MUL, REF_DIV, REF_SQRT };

uint32_t fpref_bits(float f) {
  uint32_t u;
  memcpy(&u, &f, sizeof u);
  return u;
}

float fpref_float(uint32_t bits) {
  float f;
  memcpy(&f, &bits, sizeof f);
  return f;
}

int fpref_is_nan(uint32_t bits) {
  return (bits & EXP_MASK) == EXP_MASK && (bits & FRAC_MASK) != 0;
}

static int is_snan(uint32_t bits) {
  return fpref_is_nan(bits) && (bits & QUIET_BIT) == 0;
}

/* DAZ: a subnormal reads as zero of the same sign. */
static uint32_t flush_input(uint32_t bits, int ftz) {
  if (ftz && (bits & EXP_MASK) == 0) return bits & SIGN_BIT;
  return bits;
}

/* Is the quotient x / y (finite, nonzero, RNE), which rounded to 2^-126,
 * tiny after rounding?  Rounded to 24 bits with an unbounded exponent it
 * is q * 2^(ea - eb), q the quotient of the significands (in [0.5, 1),
 * exact) rounded in float: a normal number, so rounded to 24 bits. */
static int div_tiny_at_min_normal(float x, float y) {
  int ea, eb;
  volatile float fa = frexpf(x, &ea);
  volatile float fb = frexpf(y, &eb);
  volatile float q = fa / fb;
  double v = ldexp((double)q, ea - eb);
  return fabs(v) < 0x1p-126;
}

static uint32_t ref_op(enum ref_op op, uint32_t a, uint32_t b,
                       fpref_mode mode, unsigned *flags) {
  unsigned fl = 0;
  uint32_t r;

  if (op == REF_SQRT) b = 0; /* one operand */
  if (fpref_is_nan(a) || fpref_is_nan(b)) {
    if (is_snan(a) || is_snan(b)) fl |= FP3_FLAG_INVALID;
    r = (fpref_is_nan(a) ? a : b) | QUIET_BIT;
  } else {
    a = flush_input(a, mode.ftz);
    b = flush_input(b, mode.ftz);

    int saved_round = fegetround();
    fexcept_t saved_flags;
    fegetexceptflag(&saved_flags, FE_ALL_EXCEPT);
    fesetround(mode.round == FPREF_RTZ ? FE_TOWARDZERO : FE_TONEAREST);
    feclearexcept(FE_ALL_EXCEPT);

    volatile float x = fpref_float(a);
    volatile float y = fpref_float(b);
    volatile float z;
    switch (op) {
    case REF_ADD: z = x + y; break;
    case REF_SUB: z = x - y; break;
    case REF_MUL: z = x * y; break;
    case REF_DIV: z = x / y; break;
    default:      z = sqrtf(x); break;
    }
    int host = fetestexcept(FE_INEXACT | FE_OVERFLOW | FE_INVALID |
                            FE_DIVBYZERO);
    /* Only RNE can round up to 2^-126 from below (see below). */
    int div_tiny = op == REF_DIV && mode.round == FPREF_RNE &&
                   (fpref_bits(z) & ~SIGN_BIT) == MIN_NORMAL &&
                   (host & FE_INEXACT) && div_tiny_at_min_normal(x, y);

    fesetexceptflag(&saved_flags, FE_ALL_EXCEPT);
    fesetround(saved_round);

    r = fpref_bits(z);
    if (fpref_is_nan(r)) { /* inf - inf, 0 * inf, 0 / 0, inf / inf, sqrt(-x) */
      r = DEFAULT_NAN;
      fl |= FP3_FLAG_INVALID;
    } else {
      int inexact = (host & FE_INEXACT) != 0;
      uint32_t mag = r & ~SIGN_BIT;
      /* Tiny after rounding: the exact result rounded to 24 bits with an
       * unbounded exponent is nonzero and below 2^-126.  Below 2^-126 after
       * the real rounding: tiny unless it is an exact zero.  Exactly 2^-126
       * and inexact: only a product can get there from below (a tiny sum
       * is always exact), and only in RNE; the product of two floats is
       * exact in double, and it rounds to 2^-126 with an unbounded exponent
       * iff it is at least 2^-126 - 2^-151.  A quotient can get there too
       * (div_tiny_at_min_normal); a square root is never tiny. */
      int tiny = 0;
      if (mag < MIN_NORMAL) {
        tiny = (mag != 0) || inexact;
      } else if (mag == MIN_NORMAL && inexact && op == REF_MUL &&
                 mode.round == FPREF_RNE) {
        double p = (double)x * (double)y;
        double limit = 0x1p-126 - 0x1p-151;
        tiny = (p < 0 ? -p : p) < limit;
      } else if (op == REF_DIV) {
        tiny = div_tiny;
      }
      if (inexact) fl |= FP3_FLAG_INEXACT;
      if (host & FE_OVERFLOW) fl |= FP3_FLAG_OVERFLOW;
      if (host & FE_DIVBYZERO) fl |= FP3_FLAG_INFINITE;
      if (tiny && inexact) fl |= FP3_FLAG_UNDERFLOW;
      if (mode.ftz && tiny) {
        r &= SIGN_BIT;
        fl |= FP3_FLAG_UNDERFLOW | FP3_FLAG_INEXACT;
      }
    }
  }
  if (flags) *flags |= fl;
  return r;
}

uint32_t fpref_add(uint32_t a, uint32_t b, fpref_mode mode, unsigned *flags) {
  return ref_op(REF_ADD, a, b, mode, flags);
}

uint32_t fpref_sub(uint32_t a, uint32_t b, fpref_mode mode, unsigned *flags) {
  return ref_op(REF_SUB, a, b, mode, flags);
}

uint32_t fpref_mul(uint32_t a, uint32_t b, fpref_mode mode, unsigned *flags) {
  return ref_op(REF_MUL, a, b, mode, flags);
}

uint32_t fpref_div(uint32_t a, uint32_t b, fpref_mode mode, unsigned *flags) {
  return ref_op(REF_DIV, a, b, mode, flags);
}

uint32_t fpref_sqrt(uint32_t a, fpref_mode mode, unsigned *flags) {
  return ref_op(REF_SQRT, a, 0, mode, flags);
}

uint32_t fpref_abs(uint32_t a) { return a & ~SIGN_BIT; }

uint32_t fpref_neg(uint32_t a) { return a ^ SIGN_BIT; }

/* The order of IEEE 754-2019 §9.6 on non-NaN bit patterns: -0 below +0.
 * Sign-magnitude to a monotonic unsigned key. */
static uint32_t order_key(uint32_t bits) {
  return (bits & SIGN_BIT) ? ~bits : bits | SIGN_BIT;
}

/* min (want_max 0) or max (1), fpref.h. */
static uint32_t ref_minmax(uint32_t a, uint32_t b, int want_max,
                           unsigned *flags) {
  if (fpref_is_nan(a) || fpref_is_nan(b)) {
    if ((is_snan(a) || is_snan(b)) && flags) *flags |= FP3_FLAG_INVALID;
    return (fpref_is_nan(a) ? a : b) | QUIET_BIT;
  }
  int a_below = order_key(a) < order_key(b);
  return (a_below != want_max) ? a : b;
}

uint32_t fpref_min(uint32_t a, uint32_t b, unsigned *flags) {
  return ref_minmax(a, b, 0, flags);
}

uint32_t fpref_max(uint32_t a, uint32_t b, unsigned *flags) {
  return ref_minmax(a, b, 1, flags);
}
