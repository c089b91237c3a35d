/*
 * test_fpu.c -- tests of the binary32 FP cores (rtl/fp_add.v, rtl/fp_mul.v,
 * rtl/fp_div.v, rtl/fp_sqrt.v) through the Verilated models (sim/fpu_model.h), of the reference
 * sw/ref/fpref.c, and of the TestFloat runner sw/engine/testfloat.c.
 *
 *   - random operand pairs of mixed classes, 10^6 per operation and
 *     rounding configuration: RTL == fpref bit for bit, results and flags;
 *     fpref == the host's float for every non-NaN result (on x86 also the
 *     flags, and the FTZ configurations against MXCSR.FTZ/DAZ), for add,
 *     sub, mul, div and sqrt;
 *   - directed cases (subnormals, ties, overflow, signed zeros, invalid,
 *     divide by zero, NaN propagation, FTZ, sqrt(-0)) on fpref and on the
 *     RTL; the sign and compare references (abs, neg, min, max);
 *   - pipelining: measured latency of every built model, a new operation
 *     every cycle with random bubbles, reset in flight;
 *   - every TestFloat file in ../shared/testfloat through the matching
 *     core (and the latency variants) and through fpref, zero failures;
 *   - the `fp3 testfloat` command line.
 *
 * Run from the repository root.  `test_fpu --bench N` instead measures the
 * throughput of the models (make bench-fp).
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <dirent.h>
#include <fenv.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#define HAVE_MXCSR 1
#define MXCSR_FTZ_DAZ 0x8040u
#else
#define HAVE_MXCSR 0
#endif

#include "fp3_isa.h"
#include "fpref.h"
#include "../sim/fpu_model.h" /* relative: no -Isim needed */
#include "cmd_testfloat.h"
#include "testfloat.h"

#define TESTFLOAT_DIR "../shared/testfloat"
#define RANDOM_PER_OP 1000000ul
#define RANDOM_LAT 100000ul
#define BATCH 4096
#define MAX_REPORT 10

#define SIGN 0x80000000u
#define INF 0x7F800000u
#define NV FP3_FLAG_INVALID
#define OF FP3_FLAG_OVERFLOW
#define UF FP3_FLAG_UNDERFLOW
#define NX FP3_FLAG_INEXACT
#define DZ FP3_FLAG_INFINITE

/* The arithmetic operations (TestFloat's, fpu_op 0 .. 4) and, after them,
 * the sign and compare operations of fp_sign. */
#define NUM_OPS 5
#define NUM_ALL_OPS 9
static const char *const op_name[NUM_ALL_OPS] = {
    "add", "sub", "mul", "div", "sqrt", "abs", "neg", "min", "max"};
static const fpref_mode modes[4] = {
    {FPREF_RNE, 0}, {FPREF_RTZ, 0}, {FPREF_RNE, 1}, {FPREF_RTZ, 1}};
static const char *const mode_name[4] = {"rne", "rtz", "ftz", "rtz_ftz"};

/* ---- random operands ---------------------------------------------------- */

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;

static uint32_t rng32(void) {
  rng_state ^= rng_state >> 12;
  rng_state ^= rng_state << 25;
  rng_state ^= rng_state >> 27;
  return (uint32_t)((rng_state * 0x2545F4914F6CDD1Dull) >> 32);
}

static uint32_t rng_below(uint32_t n) {
  return (uint32_t)(((uint64_t)rng32() * n) >> 32);
}

static uint32_t pack(uint32_t sign, uint32_t exp, uint32_t frac) {
  return sign | (exp << 23) | (frac & 0x7FFFFFu);
}

/* One operand of a random class. */
static uint32_t gen_operand(void) {
  static const uint32_t edges[] = {0x00000001u, 0x007FFFFFu, 0x00800000u,
                                   0x00800001u, 0x7F7FFFFFu, 0x7F7FFFFEu,
                                   0x3F800000u, 0x3F7FFFFFu, 0x00400000u,
                                   0x7F000000u, 0x3F000000u, 0x00FFFFFFu};
  uint32_t s = rng32() & SIGN;
  switch (rng_below(16)) {
  case 0: return s;                                    /* zero          */
  case 1: return s | (1u + rng_below(0x7FFFFFu));      /* subnormal     */
  case 2: return s | (rng32() >> (9 + rng_below(23)))  /* small subnorm */
                 | 1u;
  case 3: return s | edges[rng_below(sizeof edges / sizeof edges[0])];
  case 4: return s | INF;                              /* infinity      */
  case 5: return s | 0x7FC00000u | (rng32() & 0x3FFFFFu); /* qNaN       */
  case 6: return s | INF | (1u + rng_below(0x3FFFFFu));   /* sNaN       */
  case 7: return pack(s, 1u + rng_below(40), rng32()); /* tiny normal   */
  case 8: return pack(s, 200u + rng_below(55), rng32()); /* huge normal */
  case 9:
  case 10: return pack(s, 100u + rng_below(55), rng32()); /* moderate    */
  case 11: /* few significant bits: exact products and ties */
    return pack(s, 90u + rng_below(75),
                rng32() & (0x7FFFFFu << rng_below(24)));
  default: return rng32();                             /* any pattern   */
  }
}

/* A sqrt operand: of a random class, or an exact square (a root of at most
 * 12 significant bits squared: exact results, and roots one ulp away). */
static uint32_t gen_sqrt_operand(void) {
  uint32_t k = rng_below(8);
  if (k < 4) return gen_operand();
  if (k < 6) {
    uint32_t root = pack(0, 40u + rng_below(175), rng32() & 0x7FF000u);
    unsigned fl = 0;
    uint32_t sq = fpref_mul(root, root, FPREF_IEEE, &fl);
    return sq + (k == 5 ? (uint32_t)rng_below(3) - 1u : 0u);
  }
  if (k == 6) return 1u + rng_below(0x7FFFFFu); /* positive subnormal */
  return rng32() & 0x7FFFFFFFu;                  /* positive, any     */
}

/* A divisor derived from the dividend a: quotients near 2^-126 (tiny,
 * rounding to the smallest normal), near 2^128 (overflow), of few
 * significant bits (exact quotients, ties of subnormal quotients), near
 * 1 (the recurrence's first bit on both sides). */
static uint32_t gen_divisor(uint32_t a, uint32_t k) {
  uint32_t s = rng32() & SIGN;
  int ea = (int)((a >> 23) & 0xFF);
  int eb;
  uint32_t frac = rng32() & 0x7FFFFF;
  switch (k) {
  case 4: /* ea - eb + 127 around 1 */
    eb = (ea ? ea : 1) + 126 + (int)rng_below(5) - 2;
    break;
  case 5: /* ea - eb + 127 around 254 */
    eb = (ea ? ea : 1) - 127 + (int)rng_below(5) - 2;
    break;
  case 6: /* few significant bits */
    eb = 100 + (int)rng_below(55);
    frac &= 0x7FFFFFu << (10 + rng_below(14));
    break;
  default: /* the dividend's significand a few ulps away */
    eb = 100 + (int)rng_below(55);
    frac = (a + rng_below(9) - 4u) & 0x7FFFFF;
    break;
  }
  if (eb < 1) eb = 0; /* subnormal */
  if (eb > 254) eb = 254;
  return s | ((uint32_t)eb << 23) | frac;
}

/* A pair; b is often derived from a: cancellation, ties, alignment. */
static void gen_pair(fpu_op op, uint32_t *a, uint32_t *b) {
  if (op >= FPU_OP_ABS) { /* sign, compare: equal, opposite, +-0 pairs */
    *a = gen_operand();
    switch (rng_below(8)) {
    case 0: *b = *a; break;
    case 1: *b = *a ^ SIGN; break;
    case 2: *b = (*a & SIGN) ^ SIGN; *a &= SIGN; break;
    case 3: *b = *a + rng_below(5) - 2u; break;
    default: *b = gen_operand(); break;
    }
    return;
  }
  if (op == FPU_OP_SQRT) {
    *a = gen_sqrt_operand();
    *b = 0;
    return;
  }
  *a = gen_operand();
  uint32_t k = rng_below(8);
  if (k < 4) {
    *b = gen_operand();
    return;
  }
  if (op == FPU_OP_DIV) {
    *b = gen_divisor(*a, k);
    return;
  }
  uint32_t s = rng32() & SIGN;
  int64_t mag = *a & 0x7FFFFFFF;
  if (op != FPU_OP_MUL) {
    switch (k) {
    case 4: /* a few ulps away: cancellation, exact zero */
      mag += (int64_t)rng_below(9) - 4;
      break;
    case 5: /* shifted into the guard bits; power of two: ties */
      mag = (mag & 0x7F800000) - ((int64_t)(20 + rng_below(8)) << 23);
      break;
    case 6: /* shifted by a little, random low bits */
      mag = mag - ((int64_t)rng_below(28) << 23) + (int64_t)rng_below(16) - 8;
      break;
    default: /* same exponent */
      mag = (mag & 0x7F800000) | (rng32() & 0x7FFFFF);
      break;
    }
  } else {
    /* Exponent sums near the subnormal and overflow boundaries, or few
     * significant bits (ties). */
    int ea = (int)((*a >> 23) & 0xFF);
    int eb;
    switch (k) {
    case 4: /* product near 2^-126: ea + eb - 127 around 1 */
      eb = 128 - (ea ? ea : 1) + (int)rng_below(5) - 2;
      break;
    case 5: /* product near 2^128: ea + eb - 127 around 254 */
      eb = 381 - (ea ? ea : 1) + (int)rng_below(5) - 2;
      break;
    default: /* few significant bits: ties */
      eb = 100 + (int)rng_below(55);
      break;
    }
    if (eb < 1) eb = 0;   /* subnormal */
    if (eb > 254) eb = 254;
    uint32_t frac = rng32() & 0x7FFFFF;
    if (k > 5) frac &= 0x7FFFFFu << (10 + rng_below(14));
    mag = ((int64_t)eb << 23) | frac;
  }
  if (mag < 0) mag = 0;
  if (mag > 0x7FFFFFFF) mag = 0x7F7FFFFF;
  *b = s | (uint32_t)mag;
}

/* ---- reference helpers -------------------------------------------------- */

static uint32_t ref_op(fpu_op op, uint32_t a, uint32_t b, fpref_mode mode,
                       unsigned *flags) {
  *flags = 0;
  switch (op) {
  case FPU_OP_ADD: return fpref_add(a, b, mode, flags);
  case FPU_OP_SUB: return fpref_sub(a, b, mode, flags);
  case FPU_OP_MUL: return fpref_mul(a, b, mode, flags);
  case FPU_OP_DIV: return fpref_div(a, b, mode, flags);
  case FPU_OP_SQRT: return fpref_sqrt(a, mode, flags);
  case FPU_OP_ABS: return fpref_abs(a);
  case FPU_OP_NEG: return fpref_neg(a);
  case FPU_OP_MIN: return fpref_min(a, b, flags);
  default:         return fpref_max(a, b, flags);
  }
}

/* The host's own float operation in `mode`.  Returns 0 when the host
 * cannot run that mode (FTZ off x86); *flags is -1 when the host flags are
 * not comparable (not x86: tininess may be detected before rounding). */
static int host_op(fpu_op op, uint32_t a, uint32_t b, fpref_mode mode,
                   uint32_t *r, int *flags) {
  /* No host instruction for these (test_sign_compare checks them against
   * the host's comparisons). */
  if (op >= FPU_OP_ABS) return 0;
#if HAVE_MXCSR
  unsigned csr = _mm_getcsr();
  if (mode.ftz) _mm_setcsr(csr | MXCSR_FTZ_DAZ);
#else
  if (mode.ftz) return 0;
#endif
  int round = fegetround();
  fesetround(mode.round == FPREF_RTZ ? FE_TOWARDZERO : FE_TONEAREST);
  feclearexcept(FE_ALL_EXCEPT);
  volatile float x = fpref_float(a), y = fpref_float(b), z;
  switch (op) {
  case FPU_OP_ADD: z = x + y; break;
  case FPU_OP_SUB: z = x - y; break;
  case FPU_OP_MUL: z = x * y; break;
  case FPU_OP_DIV: z = x / y; break;
  default:         z = sqrtf(x); break;
  }
  int e = fetestexcept(FE_ALL_EXCEPT);
  fesetround(round);
#if HAVE_MXCSR
  _mm_setcsr(csr);
  *flags = ((e & FE_INEXACT) ? NX : 0) | ((e & FE_UNDERFLOW) ? UF : 0) |
           ((e & FE_OVERFLOW) ? OF : 0) | ((e & FE_INVALID) ? NV : 0) |
           ((e & FE_DIVBYZERO) ? DZ : 0);
#else
  (void)e;
  *flags = -1;
#endif
  *r = fpref_bits(z);
  return 1;
}

/* ---- fixtures ----------------------------------------------------------- */

typedef struct fixture {
  fpu_model *model[4]; /* the four rounding configurations */
} fixture;

static int setup(void **state) {
  fixture *fx = calloc(1, sizeof *fx);
  if (!fx) return -1;
  for (int i = 0; i < 4; i++) {
    fx->model[i] = fpu_model_new((int)modes[i].round, modes[i].ftz, 0, 0);
    if (!fx->model[i]) {
      fprintf(stderr, "no model built for %s\n", mode_name[i]);
      return -1;
    }
  }
  *state = fx;
  return 0;
}

static int teardown(void **state) {
  fixture *fx = *state;
  for (int i = 0; i < 4; i++) fpu_model_free(fx->model[i]);
  free(fx);
  return 0;
}

/* ---- random RTL vs fpref vs host ---------------------------------------- */

typedef struct rand_buf {
  uint32_t a[BATCH], b[BATCH], y[BATCH];
  uint8_t fl[BATCH];
} rand_buf;

/* n random pairs through `m` (mode `mode`); returns the mismatch count. */
static unsigned long random_check(fpu_model *m, fpu_op op, fpref_mode mode,
                                  const char *name, unsigned long n,
                                  unsigned long *host_checked) {
  rand_buf *rb = malloc(sizeof *rb);
  assert_non_null(rb);
  unsigned long bad = 0, bad_host = 0;
  for (unsigned long done = 0; done < n;) {
    size_t k = n - done < BATCH ? (size_t)(n - done) : BATCH;
    for (size_t i = 0; i < k; i++) gen_pair(op, &rb->a[i], &rb->b[i]);
    assert_int_equal(fpu_model_run(m, op, k, rb->a, rb->b, rb->y, rb->fl), 0);
    for (size_t i = 0; i < k; i++) {
      unsigned rf;
      uint32_t r = ref_op(op, rb->a[i], rb->b[i], mode, &rf);
      if (r != rb->y[i] || rf != rb->fl[i]) {
        if (bad++ < MAX_REPORT)
          print_error("%s %s %08X %08X: fpref %08X/%02X, RTL %08X/%02X\n",
                      name, op_name[op], rb->a[i], rb->b[i], r, rf,
                      rb->y[i], rb->fl[i]);
      }
      if (fpref_is_nan(r)) continue;
      uint32_t h;
      int hf;
      if (!host_op(op, rb->a[i], rb->b[i], mode, &h, &hf)) continue;
      (*host_checked)++;
      if (h != r || (hf >= 0 && (unsigned)hf != rf)) {
        if (bad_host++ < MAX_REPORT)
          print_error("%s %s %08X %08X: fpref %08X/%02X, host %08X/%02X\n",
                      name, op_name[op], rb->a[i], rb->b[i], r, rf, h,
                      (unsigned)hf);
      }
    }
    done += k;
  }
  free(rb);
  return bad + bad_host;
}

static void random_mode(void **state, int mi) {
  fixture *fx = *state;
  for (int op = 0; op < NUM_ALL_OPS; op++) {
    unsigned long host = 0;
    unsigned long bad = random_check(fx->model[mi], (fpu_op)op, modes[mi],
                                     mode_name[mi], RANDOM_PER_OP, &host);
    print_message("%s %s: %lu random pairs, RTL == fpref; %lu fpref == host\n",
                  mode_name[mi], op_name[op], RANDOM_PER_OP, host);
    assert_int_equal(bad, 0);
  }
}

static void test_random_rne(void **state) { random_mode(state, 0); }
static void test_random_rtz(void **state) { random_mode(state, 1); }
static void test_random_ftz(void **state) { random_mode(state, 2); }
static void test_random_rtz_ftz(void **state) { random_mode(state, 3); }

/* ---- directed cases ----------------------------------------------------- */

/* Mode masks of a directed case. */
#define M_RNE 1
#define M_RTZ 2
#define M_FTZ 4
#define M_RFZ 8
#define M_IEEE (M_RNE | M_RTZ)
#define M_ALL 15

typedef struct directed {
  int op;
  unsigned modes;
  uint32_t a, b, y;
  unsigned flags;
  const char *what;
} directed;

#define A FPU_OP_ADD
#define S FPU_OP_SUB
#define X FPU_OP_MUL
#define D FPU_OP_DIV
#define Q FPU_OP_SQRT
static const directed cases[] = {
    /* division: by zero, invalid, infinities, signed zeros (IEEE 754-2019
     * 7.2, 7.3, 6.3) */
    {D, M_ALL, 0x3F800000, 0x00000000, 0x7F800000, DZ, "1 / +0 = +inf"},
    {D, M_ALL, 0xBF800000, 0x00000000, 0xFF800000, DZ, "-1 / +0 = -inf"},
    {D, M_ALL, 0x3F800000, 0x80000000, 0xFF800000, DZ, "1 / -0 = -inf"},
    {D, M_ALL, 0x00000000, 0x00000000, 0xFFC00000, NV, "0 / 0"},
    {D, M_ALL, 0x80000000, 0x00000000, 0xFFC00000, NV, "-0 / 0"},
    {D, M_ALL, 0x7F800000, 0xFF800000, 0xFFC00000, NV, "inf / -inf"},
    {D, M_ALL, 0x7F800000, 0x00000000, 0x7F800000, 0, "inf / 0 = inf, no flag"},
    {D, M_ALL, 0xFF800000, 0x40000000, 0xFF800000, 0, "-inf / 2"},
    {D, M_ALL, 0x00000000, 0x7F800000, 0x00000000, 0, "0 / inf"},
    {D, M_ALL, 0x3F800000, 0xFF800000, 0x80000000, 0, "1 / -inf = -0"},
    {D, M_ALL, 0x80000000, 0x3F800000, 0x80000000, 0, "-0 / 1 = -0"},
    {D, M_ALL, 0x7FC00001, 0x00000000, 0x7FC00001, 0, "qNaN / 0: NaN, no divide by zero"},
    {D, M_ALL, 0x3F800000, 0xFF800001, 0xFFC00001, NV, "1 / sNaN: b quieted"},
    {D, M_ALL, 0x7F812345, 0x7FC00000, 0x7FC12345, NV, "sNaN / qNaN: a quieted"},
    /* division: rounding, subnormal quotients and dividends, overflow */
    {D, M_ALL, 0x40C00000, 0x40400000, 0x40000000, 0, "6 / 3 = 2"},
    {D, M_RNE | M_FTZ, 0x3F800000, 0x40400000, 0x3EAAAAAB, NX, "1 / 3"},
    {D, M_RTZ | M_RFZ, 0x3F800000, 0x40400000, 0x3EAAAAAA, NX, "RTZ 1 / 3"},
    {D, M_IEEE, 0x00800000, 0x40000000, 0x00400000, 0, "2^-126 / 2: exact subnormal quotient"},
    {D, M_FTZ | M_RFZ, 0x00800000, 0x40000000, 0x00000000, UF | NX, "FTZ: exact tiny quotient flushed"},
    {D, M_IEEE, 0x00400000, 0x3F000000, 0x00800000, 0, "subnormal dividend"},
    {D, M_FTZ | M_RFZ, 0x00400000, 0x3F000000, 0x00000000, 0, "DAZ: subnormal dividend reads as 0"},
    {D, M_RNE, 0x00FFFFFF, 0x40000000, 0x00800000, UF | NX, "tie rounds to 2^-126, tiny after rounding"},
    {D, M_RTZ, 0x00FFFFFF, 0x40000000, 0x007FFFFF, UF | NX, "RTZ: below 2^-126"},
    {D, M_FTZ | M_RFZ, 0x00FFFFFF, 0x40000000, 0x00000000, UF | NX, "FTZ: tiny quotient flushed"},
    {D, M_IEEE, 0x00000001, 0x40000000, 0x00000000, UF | NX, "min sub / 2: tie to 0"},
    {D, M_RNE, 0x00000003, 0x40000000, 0x00000002, UF | NX, "3 min sub / 2: tie to even"},
    {D, M_RTZ, 0x00000003, 0x40000000, 0x00000001, UF | NX, "RTZ 3 min sub / 2"},
    {D, M_IEEE, 0x00000001, 0x4B000000, 0x00000000, UF | NX, "min sub / 2^23 underflows to 0"},
    {D, M_IEEE, 0x00000001, 0x00000001, 0x3F800000, 0, "sub / sub = 1"},
    {D, M_FTZ | M_RFZ, 0x00000001, 0x00000001, 0xFFC00000, NV, "DAZ: sub / sub = 0 / 0"},
    {D, M_RNE, 0x3F800000, 0x00000001, 0x7F800000, OF | NX, "1 / min sub overflows"},
    {D, M_RTZ, 0x3F800000, 0x00000001, 0x7F7FFFFF, OF | NX, "RTZ 1 / min sub = max"},
    {D, M_FTZ | M_RFZ, 0x3F800000, 0x00000001, 0x7F800000, DZ, "DAZ: 1 / sub = 1 / 0"},
    {D, M_RNE | M_FTZ, 0x7F7FFFFF, 0x3F000000, 0x7F800000, OF | NX, "max / 0.5 = inf"},
    {D, M_RTZ | M_RFZ, 0x7F7FFFFF, 0x3F000000, 0x7F7FFFFF, OF | NX, "RTZ max / 0.5 = max"},
    /* square root (IEEE 754-2019 5.4.1: sqrt(-0) = -0) */
    {Q, M_ALL, 0x80000000, 0, 0x80000000, 0, "sqrt(-0) = -0"},
    {Q, M_ALL, 0x00000000, 0, 0x00000000, 0, "sqrt(+0) = +0"},
    {Q, M_ALL, 0x7F800000, 0, 0x7F800000, 0, "sqrt(+inf) = +inf"},
    {Q, M_ALL, 0xFF800000, 0, 0xFFC00000, NV, "sqrt(-inf)"},
    {Q, M_ALL, 0xBF800000, 0, 0xFFC00000, NV, "sqrt(-1)"},
    {Q, M_IEEE, 0x80000001, 0, 0xFFC00000, NV, "sqrt of a negative subnormal"},
    {Q, M_FTZ | M_RFZ, 0x80000001, 0, 0x80000000, 0, "DAZ: sqrt(-sub) = sqrt(-0)"},
    {Q, M_IEEE, 0x00000001, 0, 0x1A3504F3, NX, "sqrt(min sub)"},
    {Q, M_IEEE, 0x00400000, 0, 0x1FB504F3, NX, "sqrt(2^-127)"},
    {Q, M_FTZ | M_RFZ, 0x00000001, 0, 0x00000000, 0, "DAZ: sqrt(sub) = 0"},
    {Q, M_ALL, 0x00800000, 0, 0x20000000, 0, "sqrt(2^-126) = 2^-63"},
    {Q, M_ALL, 0x40800000, 0, 0x40000000, 0, "sqrt(4) = 2"},
    {Q, M_ALL, 0x40000000, 0, 0x3FB504F3, NX, "sqrt(2)"},
    {Q, M_RNE | M_FTZ, 0x40A00000, 0, 0x400F1BBD, NX, "sqrt(5) rounds up"},
    {Q, M_RTZ | M_RFZ, 0x40A00000, 0, 0x400F1BBC, NX, "RTZ sqrt(5)"},
    {Q, M_ALL, 0x7F7FFFFF, 0, 0x5F7FFFFF, NX, "sqrt(max)"},
    {Q, M_ALL, 0x7FC12345, 0, 0x7FC12345, 0, "sqrt(qNaN)"},
    {Q, M_ALL, 0xFF812345, 0, 0xFFC12345, NV, "sqrt(-sNaN): quieted, sign kept"},
    {Q, M_ALL, 0xFFC00001, 0, 0xFFC00001, 0, "sqrt(-qNaN): no flag"},
    /* subnormal inputs and outputs */
    {A, M_IEEE, 0x00000001, 0x00000001, 0x00000002, 0, "min sub + min sub"},
    {A, M_IEEE, 0x007FFFFF, 0x00000001, 0x00800000, 0, "max sub + ulp = min normal"},
    {S, M_IEEE, 0x00800001, 0x00800000, 0x00000001, 0, "exact subnormal difference"},
    {S, M_FTZ | M_RFZ, 0x00800001, 0x00800000, 0x00000000, UF | NX, "FTZ flushes an exact tiny difference"},
    {S, M_FTZ | M_RFZ, 0x80800001, 0x80800000, 0x80000000, UF | NX, "FTZ flush keeps the sign"},
    {A, M_FTZ | M_RFZ, 0x007FFFFF, 0x00000001, 0x00000000, 0, "DAZ: sub + sub = 0, no flag"},
    {A, M_FTZ | M_RFZ, 0x80000001, 0x00000000, 0x00000000, 0, "DAZ: -sub + +0 = +0"},
    {A, M_FTZ | M_RFZ, 0x80000001, 0x80000000, 0x80000000, 0, "DAZ: -sub + -0 = -0"},
    {A, M_FTZ | M_RFZ, 0x3F800000, 0x00400000, 0x3F800000, 0, "DAZ: 1 + sub exact"},
    {X, M_IEEE, 0x00800000, 0x3F000000, 0x00400000, 0, "exact subnormal product"},
    {X, M_RNE, 0x00800001, 0x3F000000, 0x00400000, UF | NX, "tiny tie to even"},
    {X, M_RNE, 0x00800003, 0x3F000000, 0x00400002, UF | NX, "tiny tie up to even"},
    {X, M_RTZ, 0x00800003, 0x3F000000, 0x00400001, UF | NX, "tiny truncated"},
    {X, M_RNE, 0x3F7FFFFF, 0x00800000, 0x00800000, UF | NX, "rounds to 2^-126 but tiny after rounding"},
    {X, M_RTZ, 0x3F7FFFFF, 0x00800000, 0x007FFFFF, UF | NX, "below 2^-126 truncated"},
    {X, M_RNE, 0x3F7FFFFE, 0x00800001, 0x00800000, NX, "rounds to 2^-126, not tiny"},
    {X, M_FTZ, 0x3F7FFFFF, 0x00800000, 0x00000000, UF | NX, "FTZ: tiny after rounding is flushed"},
    {X, M_FTZ, 0x3F7FFFFE, 0x00800001, 0x00800000, NX, "FTZ: not tiny, kept"},
    {X, M_FTZ | M_RFZ, 0x00800000, 0x3F000000, 0x00000000, UF | NX, "FTZ: exact tiny product flushed"},
    {X, M_FTZ | M_RFZ, 0x00000001, 0x7F800000, 0xFFC00000, NV, "DAZ: sub * inf = 0 * inf"},
    {X, M_IEEE, 0x00000001, 0x7F800000, 0x7F800000, 0, "sub * inf = inf"},
    {X, M_IEEE, 0x00000001, 0x4B000000, 0x00800000, 0, "min sub * 2^23 = 2^-126"},
    {X, M_IEEE, 0x00000001, 0x00000001, 0x00000000, UF | NX, "sub * sub underflows to 0"},
    {X, M_RNE, 0x00000001, 0x3F000000, 0x00000000, UF | NX, "min sub / 2: tie to 0"},
    {X, M_RNE, 0x00000001, 0x3F000001, 0x00000001, UF | NX, "just above half min sub"},
    {X, M_IEEE, 0x00000001, 0x3F800000, 0x00000001, 0, "min sub * 1"},
    {X, M_IEEE, 0x00400000, 0x40800000, 0x01000000, 0, "subnormal input, normal product"},
    /* ties (round to even both ways) */
    {A, M_RNE, 0x3F800000, 0x33800000, 0x3F800000, NX, "1 + 2^-24: tie down to even"},
    {A, M_RNE, 0x3F800001, 0x33800000, 0x3F800002, NX, "tie up to even"},
    {A, M_RTZ, 0x3F800001, 0x33800000, 0x3F800001, NX, "RTZ truncates a tie"},
    {S, M_RNE, 0x3F800000, 0x33000000, 0x3F800000, NX, "1 - 2^-25: tie up to 1"},
    {S, M_RTZ, 0x3F800000, 0x33000000, 0x3F7FFFFF, NX, "RTZ 1 - 2^-25"},
    {X, M_RNE, 0x3F800001, 0x3FC00000, 0x3FC00002, NX, "product tie up to even"},
    {X, M_RNE, 0x3F800003, 0x3FC00000, 0x3FC00004, NX, "product tie down to even"},
    {X, M_RTZ, 0x3F800001, 0x3FC00000, 0x3FC00001, NX, "RTZ product tie"},
    {A, M_RNE, 0x4B7FFFFF, 0x3F000000, 0x4B800000, NX, "carry out of rounding"},
    /* overflow */
    {A, M_RNE | M_FTZ, 0x7F7FFFFF, 0x7F7FFFFF, 0x7F800000, OF | NX, "max + max = inf"},
    {A, M_RTZ | M_RFZ, 0x7F7FFFFF, 0x7F7FFFFF, 0x7F7FFFFF, OF | NX, "RTZ max + max = max"},
    {A, M_RNE, 0xFF7FFFFF, 0xFF7FFFFF, 0xFF800000, OF | NX, "-max - max = -inf"},
    {A, M_RTZ, 0xFF7FFFFF, 0xFF7FFFFF, 0xFF7FFFFF, OF | NX, "RTZ -max - max = -max"},
    {A, M_RNE, 0x7F7FFFFF, 0x73000000, 0x7F800000, OF | NX, "max + half ulp rounds over"},
    {A, M_RNE, 0x7F7FFFFF, 0x72800000, 0x7F7FFFFF, NX, "max + quarter ulp stays"},
    {X, M_RNE | M_FTZ, 0x7F000000, 0x40000000, 0x7F800000, OF | NX, "2^127 * 2 = inf"},
    {X, M_RTZ | M_RFZ, 0x7F000000, 0xC0000000, 0xFF7FFFFF, OF | NX, "RTZ 2^127 * -2 = -max"},
    {X, M_RNE, 0x7F7FFFFF, 0x7F7FFFFF, 0x7F800000, OF | NX, "max * max"},
    /* signed zeros, cancellation (IEEE 754 6.3) */
    {S, M_ALL, 0x3F800000, 0x3F800000, 0x00000000, 0, "x - x = +0"},
    {S, M_ALL, 0xBF800000, 0xBF800000, 0x00000000, 0, "-x - -x = +0"},
    {A, M_ALL, 0xBF800000, 0x3F800000, 0x00000000, 0, "-x + x = +0"},
    {A, M_ALL, 0x80000000, 0x80000000, 0x80000000, 0, "-0 + -0 = -0"},
    {A, M_ALL, 0x80000000, 0x00000000, 0x00000000, 0, "-0 + +0 = +0"},
    {S, M_ALL, 0x80000000, 0x00000000, 0x80000000, 0, "-0 - +0 = -0"},
    {S, M_ALL, 0x00000000, 0x00000000, 0x00000000, 0, "+0 - +0 = +0"},
    {S, M_ALL, 0x00000000, 0x80000000, 0x00000000, 0, "+0 - -0 = +0"},
    {A, M_ALL, 0x80000000, 0x3F800000, 0x3F800000, 0, "-0 + 1 = 1"},
    {S, M_IEEE, 0x00000005, 0x00000005, 0x00000000, 0, "subnormal cancellation = +0"},
    {X, M_ALL, 0x80000000, 0x3F800000, 0x80000000, 0, "-0 * 1 = -0"},
    {X, M_ALL, 0x80000000, 0x80000000, 0x00000000, 0, "-0 * -0 = +0"},
    {X, M_ALL, 0x00000000, 0xFF7FFFFF, 0x80000000, 0, "+0 * -max = -0"},
    /* invalid */
    {S, M_ALL, 0x7F800000, 0x7F800000, 0xFFC00000, NV, "inf - inf"},
    {A, M_ALL, 0xFF800000, 0x7F800000, 0xFFC00000, NV, "-inf + inf"},
    {A, M_ALL, 0x7F800000, 0x7F800000, 0x7F800000, 0, "inf + inf"},
    {S, M_ALL, 0x7F800000, 0xFF800000, 0x7F800000, 0, "inf - -inf"},
    {A, M_ALL, 0x7F800000, 0xFF7FFFFF, 0x7F800000, 0, "inf + -max"},
    {S, M_ALL, 0x3F800000, 0x7F800000, 0xFF800000, 0, "1 - inf = -inf"},
    {X, M_ALL, 0x00000000, 0xFF800000, 0xFFC00000, NV, "0 * -inf"},
    {X, M_ALL, 0x7F800000, 0x80000000, 0xFFC00000, NV, "inf * -0"},
    {X, M_ALL, 0xFF800000, 0xBF800000, 0x7F800000, 0, "-inf * -1"},
    /* NaN propagation: a first, quieted; sub does not flip b's sign */
    {A, M_ALL, 0x7FC12345, 0xFFC54321, 0x7FC12345, 0, "qNaN + qNaN: a"},
    {A, M_ALL, 0x7F812345, 0x3F800000, 0x7FC12345, NV, "sNaN + 1: a quieted"},
    {A, M_ALL, 0x7FC12345, 0x7F800001, 0x7FC12345, NV, "qNaN + sNaN: a, invalid"},
    {A, M_ALL, 0x3F800000, 0xFF800001, 0xFFC00001, NV, "1 + sNaN: b quieted"},
    {S, M_ALL, 0x3F800000, 0xFF800001, 0xFFC00001, NV, "1 - sNaN: sign kept"},
    {S, M_ALL, 0x7F800000, 0x7FC00000, 0x7FC00000, 0, "inf - qNaN"},
    {S, M_ALL, 0xFFBFFFFF, 0x7F800000, 0xFFFFFFFF, NV, "sNaN - inf"},
    {X, M_ALL, 0xFFA00000, 0x7FC00001, 0xFFE00000, NV, "sNaN * qNaN"},
    {X, M_ALL, 0x00000000, 0x7F800001, 0x7FC00001, NV, "0 * sNaN"},
    {X, M_ALL, 0x7FC00000, 0x7F800000, 0x7FC00000, 0, "qNaN * inf"},
    {X, M_FTZ, 0x00000001, 0xFFC00007, 0xFFC00007, 0, "DAZ sub * qNaN: NaN"},
    /* plain cases */
    {A, M_ALL, 0x3F800000, 0x40000000, 0x40400000, 0, "1 + 2 = 3"},
    {X, M_ALL, 0x40400000, 0xC0000000, 0xC0C00000, 0, "3 * -2 = -6"},
    {A, M_RNE, 0x3DCCCCCD, 0x3E4CCCCD, 0x3E99999A, NX, "0.1 + 0.2"},
    {A, M_RTZ, 0x3DCCCCCD, 0x3E4CCCCD, 0x3E999999, NX, "RTZ 0.1 + 0.2"},
};
#undef A
#undef S
#undef X
#undef D
#undef Q

static void test_directed(void **state) {
  fixture *fx = *state;
  unsigned long bad = 0, checked = 0;
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    const directed *c = &cases[i];
    for (int mi = 0; mi < 4; mi++) {
      if (!(c->modes & (1u << mi))) continue;
      unsigned rf;
      uint32_t r = ref_op((fpu_op)c->op, c->a, c->b, modes[mi], &rf);
      uint32_t y;
      uint8_t fl;
      assert_int_equal(
          fpu_model_run(fx->model[mi], (fpu_op)c->op, 1, &c->a, &c->b, &y, &fl),
          0);
      checked++;
      if (r != c->y || rf != c->flags) {
        bad++;
        print_error("%s %s %08X %08X (%s): want %08X/%02X, fpref %08X/%02X\n",
                    mode_name[mi], op_name[c->op], c->a, c->b, c->what, c->y,
                    c->flags, r, rf);
      }
      if (y != c->y || fl != c->flags) {
        bad++;
        print_error("%s %s %08X %08X (%s): want %08X/%02X, RTL %08X/%02X\n",
                    mode_name[mi], op_name[c->op], c->a, c->b, c->what, c->y,
                    c->flags, y, fl);
      }
    }
  }
  print_message("%lu directed checks\n", checked);
  assert_int_equal(bad, 0);
}

/* ---- pipelining and latency --------------------------------------------- */

/* The five cores of a model, for the cycle-level tests. */
#define NUM_UNITS 5
static const char *const unit_name[NUM_UNITS] = {"add", "mul", "div", "sqrt",
                                                 "sign"};

static unsigned unit_latency(const fpu_model_info *in, int u) {
  return u == 0   ? in->add_latency
         : u == 1 ? in->mul_latency
         : u == 4 ? FPU_SIGN_LATENCY
                  : in->div_latency;
}

/* Present (or, valid 0, withdraw) an operation at core u's inputs. */
static void unit_set(fpu_model *m, int u, int valid, int sub, uint32_t a,
                     uint32_t b) {
  switch (u) {
  case 0: fpu_model_set_add(m, valid, sub, a, b); break;
  case 1: fpu_model_set_mul(m, valid, a, b); break;
  case 2: fpu_model_set_div(m, valid, a, b); break;
  case 3: fpu_model_set_sqrt(m, valid, a); break;
  default: fpu_model_set_sign(m, valid, (unsigned)sub, a, b); break;
  }
}

static int unit_out(const fpu_model *m, int u, uint32_t *y, unsigned *fl) {
  switch (u) {
  case 0: return fpu_model_add_out(m, y, fl);
  case 1: return fpu_model_mul_out(m, y, fl);
  case 2: return fpu_model_div_out(m, y, fl);
  case 3: return fpu_model_sqrt_out(m, y, fl);
  default: return fpu_model_sign_out(m, y, fl);
  }
}

/* Issue one exact operation on core u (2 + 3, 2 * 3, 6 / 3, sqrt(4),
 * abs(-2)), count edges until valid_o: must be the latency, and valid_o
 * must be high for one cycle only. */
static void check_latency(fpu_model *m, int u, unsigned want) {
  static const uint32_t a[NUM_UNITS] = {0x40000000u, 0x40000000u,
                                        0x40C00000u, 0x40800000u, 0xC0000000u};
  static const uint32_t expect[NUM_UNITS] = {0x40A00000u, 0x40C00000u,
                                             0x40000000u, 0x40000000u,
                                             0x40000000u};
  unit_set(m, u, 1, 0, a[u], 0x40400000u);
  unsigned got = 0, highs = 0;
  for (unsigned k = 1; k <= want + 4; k++) {
    fpu_model_clock(m);
    if (k == 1) unit_set(m, u, 0, 0, 0, 0);
    uint32_t y;
    if (unit_out(m, u, &y, NULL)) {
      highs++;
      if (!got) got = k;
      assert_int_equal(y, expect[u]);
    }
  }
  assert_int_equal(got, want);
  assert_int_equal(highs, 1);
}

typedef struct pending {
  uint64_t due;
  uint32_t y;
  unsigned flags;
} pending;

#define PEND 64 /* more than the longest latency */

/* Every core at once, an operation in most cycles, checked cycle by cycle. */
static void stream_check(fpu_model *m, unsigned cycles) {
  const fpu_model_info *in = fpu_model_get_info(m);
  fpref_mode mode = {(fpref_round)in->round, in->ftz};
  static pending q[NUM_UNITS][PEND];
  unsigned head[NUM_UNITS] = {0}, count[NUM_UNITS] = {0};
  for (uint64_t t = 0; t < cycles + PEND; t++) {
    int issue = t < cycles;
    for (int u = 0; u < NUM_UNITS; u++) {
      int valid = issue && rng_below(8) != 0;
      uint32_t a, b;
      /* add: sub or not; sign: the operation 0 .. 3 */
      int sub = (int)rng_below(u == 4 ? 4 : 2);
      static const fpu_op unit_op[NUM_UNITS] = {FPU_OP_ADD, FPU_OP_MUL,
                                                FPU_OP_DIV, FPU_OP_SQRT,
                                                FPU_OP_ABS};
      fpu_op op = (u == 0 && sub) ? FPU_OP_SUB
                  : u == 4        ? (fpu_op)(FPU_OP_ABS + sub)
                                  : unit_op[u];
      gen_pair(op, &a, &b);
      unit_set(m, u, valid, sub, a, b);
      if (valid) {
        assert_true(count[u] < PEND);
        pending *p = &q[u][(head[u] + count[u]++) % PEND];
        p->due = t + unit_latency(in, u);
        p->y = ref_op(op, a, b, mode, &p->flags);
      }
    }
    fpu_model_clock(m);
    /* Now in cycle t + 1. */
    for (int u = 0; u < NUM_UNITS; u++) {
      uint32_t y;
      unsigned fl;
      int v = unit_out(m, u, &y, &fl);
      int due = count[u] && q[u][head[u]].due == t + 1;
      assert_int_equal(v, due);
      if (!v) continue;
      pending *p = &q[u][head[u]];
      if (y != p->y || fl != p->flags)
        print_error("%s %s cycle %llu: want %08X/%02X, got %08X/%02X\n",
                    in->name, unit_name[u], (unsigned long long)t, p->y,
                    p->flags, y, fl);
      assert_int_equal(y, p->y);
      assert_int_equal(fl, p->flags);
      head[u] = (head[u] + 1) % PEND;
      count[u]--;
    }
  }
  for (int u = 0; u < NUM_UNITS; u++) assert_int_equal(count[u], 0);
}

/* Reset with operations in flight: nothing comes out afterwards. */
static void reset_check(fpu_model *m) {
  const fpu_model_info *in = fpu_model_get_info(m);
  for (int k = 0; k < 3; k++) {
    for (int u = 0; u < NUM_UNITS; u++)
      unit_set(m, u, 1, 0, 0x3F800000u, 0x3F800000u);
    fpu_model_clock(m);
  }
  fpu_model_reset(m);
  unsigned maxlat = 0;
  for (int u = 0; u < NUM_UNITS; u++)
    if (unit_latency(in, u) > maxlat) maxlat = unit_latency(in, u);
  for (unsigned k = 0; k < maxlat + 2; k++) {
    for (int u = 0; u < NUM_UNITS; u++)
      assert_int_equal(unit_out(m, u, NULL, NULL), 0);
    fpu_model_clock(m);
  }
}

static void test_pipeline(void **state) {
  (void)state;
  size_t n = fpu_model_count();
  uint64_t seen[NUM_UNITS] = {0}; /* bit L: latency L covered */
  assert_true(n >= 4);
  for (size_t i = 0; i < n; i++) {
    const fpu_model_info *in = fpu_model_info_at(i);
    fpu_model *m = fpu_model_new_named(in->name);
    assert_non_null(m);
    for (int u = 0; u < NUM_UNITS; u++) {
      check_latency(m, u, unit_latency(in, u));
      seen[u] |= 1ull << unit_latency(in, u);
    }
    stream_check(m, 20000);
    reset_check(m);
    stream_check(m, 200);
    print_message("%s: latency add %u, mul %u, div/sqrt %u, streaming ok\n",
                  in->name, in->add_latency, in->mul_latency, in->div_latency);
    fpu_model_free(m);
  }
  print_message("latencies covered: add 0x%llX, mul 0x%llX, div/sqrt 0x%llX "
                "(bit L = L)\n",
                (unsigned long long)seen[0],
                (unsigned long long)seen[1], (unsigned long long)seen[2]);
}

/* A model of the default latencies (the CLI's). */
static int default_latencies(const fpu_model_info *in) {
  const fpu_model_info *d = fpu_model_info_at(0);
  return in->add_latency == FP3_DEFAULT_ADD_LATENCY &&
         in->mul_latency == FP3_DEFAULT_MUL_LATENCY &&
         in->div_latency == d->div_latency;
}

/* Models at other latencies: random pairs against fpref. */
static void test_latency_variants(void **state) {
  (void)state;
  size_t n = fpu_model_count(), variants = 0;
  for (size_t i = 0; i < n; i++) {
    const fpu_model_info *in = fpu_model_info_at(i);
    if (default_latencies(in)) continue;
    fpu_model *m = fpu_model_new_named(in->name);
    assert_non_null(m);
    fpref_mode mode = {(fpref_round)in->round, in->ftz};
    for (int op = 0; op < NUM_ALL_OPS; op++) {
      unsigned long host = 0;
      assert_int_equal(
          random_check(m, (fpu_op)op, mode, in->name, RANDOM_LAT, &host), 0);
    }
    fpu_model_free(m);
    variants++;
  }
  print_message("%zu latency variants, %lu random pairs per operation each\n",
                variants, RANDOM_LAT);
}

/* ---- TestFloat vectors -------------------------------------------------- */

/* f32_<op>_<rne|rtz>_... -> op and rounding; 0 if the name does not fit. */
static int parse_vector_name(const char *name, testfloat_op *op,
                             fpref_round *round) {
  if (strncmp(name, "f32_", 4) != 0) return 0;
  int o = -1;
  size_t len = 0;
  for (int k = 0; k < NUM_OPS; k++) {
    size_t l = strlen(op_name[k]);
    if (strncmp(name + 4, op_name[k], l) == 0 && name[4 + l] == '_') {
      o = k;
      len = l;
    }
  }
  if (o < 0) return 0;
  const char *r = name + 5 + len;
  if (strncmp(r, "rne_", 4) == 0)
    *round = FPREF_RNE;
  else if (strncmp(r, "rtz_", 4) == 0)
    *round = FPREF_RTZ;
  else
    return 0;
  *op = (testfloat_op)o;
  return strstr(name, ".txt") != NULL;
}

static void test_testfloat_vectors(void **state) {
  fixture *fx = *state;
  DIR *d = opendir(TESTFLOAT_DIR);
  assert_non_null(d);
  struct dirent *de;
  unsigned files = 0;
  unsigned long total = 0;
  while ((de = readdir(d)) != NULL) {
    testfloat_op op;
    fpref_round round;
    if (!parse_vector_name(de->d_name, &op, &round)) continue;
    char path[512];
    snprintf(path, sizeof path, "%s/%s", TESTFLOAT_DIR, de->d_name);
    fpref_mode mode = {round, 0};
    testfloat_stats st;
    /* The core of that configuration. */
    assert_int_equal(testfloat_run(path, op, mode, fx->model[round], stderr,
                                   MAX_REPORT, stderr, &st), 0);
    print_message("%s: RTL %lu passed, %lu failed\n", de->d_name, st.passed,
                  st.failed);
    assert_int_equal(st.failed, 0);
    assert_true(st.passed > 0);
    total += st.passed;
    /* The reference. */
    assert_int_equal(testfloat_run(path, op, mode, NULL, stderr, MAX_REPORT,
                                   stderr, &st), 0);
    print_message("%s: fpref %lu passed, %lu failed\n", de->d_name, st.passed,
                  st.failed);
    assert_int_equal(st.failed, 0);
    /* The other latencies of that configuration. */
    for (size_t i = 0; i < fpu_model_count(); i++) {
      const fpu_model_info *in = fpu_model_info_at(i);
      if (in->round != (int)round || in->ftz || default_latencies(in))
        continue;
      fpu_model *m = fpu_model_new_named(in->name);
      assert_non_null(m);
      assert_int_equal(
          testfloat_run(path, op, mode, m, stderr, MAX_REPORT, stderr, &st), 0);
      fpu_model_free(m);
      assert_int_equal(st.failed, 0);
    }
    files++;
  }
  closedir(d);
  print_message("%u TestFloat files, %lu vectors on the default cores\n", files,
                total);
  assert_true(files >= 9);
}

/* ---- the command line --------------------------------------------------- */

static int run_cli(const char *a1, const char *a2, const char *a3,
                   const char *a4) {
  char *argv[6] = {(char *)"testfloat", (char *)a1, (char *)a2, (char *)a3,
                   (char *)a4, NULL};
  int argc = 1;
  while (argc < 5 && argv[argc]) argc++;
  fflush(stdout);
  int rc = fp3_cmd_testfloat(argc, argv);
  fflush(stdout);
  return rc;
}

static void write_file(const char *path, const char *text) {
  FILE *f = fopen(path, "w");
  assert_non_null(f);
  fputs(text, f);
  fclose(f);
}

static void test_cli(void **state) {
  (void)state;
  char good[] = "/tmp/test_fpu_good_XXXXXX";
  char bad[] = "/tmp/test_fpu_bad_XXXXXX";
  char wrong[] = "/tmp/test_fpu_wrong_XXXXXX";
  int fd;
  assert_true((fd = mkstemp(good)) >= 0);
  close(fd);
  assert_true((fd = mkstemp(bad)) >= 0);
  close(fd);
  assert_true((fd = mkstemp(wrong)) >= 0);
  close(fd);
  write_file(good, "3F800000 3F800000 40000000 00\n"
                   "7F800000 FF800000 FFC00000 10\n"
                   "7F800000 FF800000 7FC00000 10\n"); /* any NaN matches */
  write_file(bad, "3F800000 3F800000 40000000 00\n3F800000 zz 0 0\n");
  write_file(wrong, "3F800000 3F800000 40000001 00\n"
                    "3F800000 3F800000 40000000 01\n");

  assert_int_equal(run_cli("--help", NULL, NULL, NULL), 0);
  assert_int_equal(run_cli("add", good, NULL, NULL), 0);
  assert_int_equal(run_cli("--round", "rtz", "add", good), 0);
  assert_int_equal(run_cli("--ftz", "add", good, NULL), 0);
  assert_int_equal(run_cli("--ref", "add", good, NULL), 0);
  assert_int_equal(run_cli("--round=rne", "add", good, NULL), 0);
  assert_int_not_equal(run_cli("add", wrong, NULL, NULL), 0);
  assert_int_not_equal(run_cli("add", bad, NULL, NULL), 0);
  assert_int_not_equal(run_cli("fma", good, NULL, NULL), 0);
  assert_int_not_equal(run_cli("--bogus", "add", good, NULL), 0);
  assert_int_not_equal(run_cli("--round", "rup", "add", good), 0);
  assert_int_not_equal(run_cli("add", NULL, NULL, NULL), 0);
  assert_int_not_equal(run_cli("add", "/nonexistent/vectors.gz", NULL, NULL), 0);
  assert_int_equal(
      run_cli("mul", TESTFLOAT_DIR "/f32_mul_rne_l1.txt.gz", NULL, NULL), 0);

  /* The failure and error reports name the file and line. */
  testfloat_stats st;
  char buf[1024] = {0};
  FILE *mem = fmemopen(buf, sizeof buf - 1, "w");
  assert_non_null(mem);
  assert_int_equal(testfloat_run(bad, TESTFLOAT_ADD, FPREF_IEEE, NULL, mem, 5,
                                 mem, &st), -1);
  fclose(mem);
  char want[128];
  snprintf(want, sizeof want, "%s:2: malformed", bad);
  assert_non_null(strstr(buf, want));
  memset(buf, 0, sizeof buf);
  mem = fmemopen(buf, sizeof buf - 1, "w");
  assert_int_equal(testfloat_run(wrong, TESTFLOAT_ADD, FPREF_IEEE, NULL, mem, 5,
                                 mem, &st), 0);
  fclose(mem);
  assert_int_equal(st.failed, 2);
  assert_int_equal(st.passed, 0);
  snprintf(want, sizeof want, "%s:1: add 3F800000 3F800000: expected 40000001",
           wrong);
  assert_non_null(strstr(buf, want));

  /* sqrt files have one operand; a two-operand line is malformed. */
  write_file(good, "40800000 40000000 00\n80000000 80000000 00\n"
                   "BF800000 7FC00000 10\n");
  write_file(bad, "40800000 40000000 00\n\n40800000 3F800000 40000000 00\n");
  assert_int_equal(run_cli("sqrt", good, NULL, NULL), 0);
  assert_int_equal(run_cli("--ref", "sqrt", good, NULL), 0);
  assert_int_equal(run_cli("--ftz", "sqrt", good, NULL), 0);
  assert_int_not_equal(run_cli("sqrt", bad, NULL, NULL), 0);
  assert_int_not_equal(run_cli("add", good, NULL, NULL), 0); /* 3 fields */
  assert_int_equal(
      run_cli("sqrt", TESTFLOAT_DIR "/f32_sqrt_rne_l1.txt.gz", NULL, NULL), 0);
  assert_int_equal(run_cli("--round", "rtz", "div",
                           TESTFLOAT_DIR "/f32_div_rtz_l1.txt.gz"), 0);
  memset(buf, 0, sizeof buf);
  mem = fmemopen(buf, sizeof buf - 1, "w");
  assert_non_null(mem);
  assert_int_equal(testfloat_run(bad, TESTFLOAT_SQRT, FPREF_IEEE, NULL, mem, 5,
                                 mem, &st), -1);
  fclose(mem);
  snprintf(want, sizeof want, "%s:3: malformed line (want \"A RESULT FLAGS\"",
           bad);
  assert_non_null(strstr(buf, want));
  /* A sqrt failure names the one operand. */
  write_file(wrong, "40800000 40000001 00\n");
  memset(buf, 0, sizeof buf);
  mem = fmemopen(buf, sizeof buf - 1, "w");
  assert_int_equal(testfloat_run(wrong, TESTFLOAT_SQRT, FPREF_IEEE, NULL, mem,
                                 5, mem, &st), 0);
  fclose(mem);
  assert_int_equal(st.failed, 1);
  snprintf(want, sizeof want, "%s:1: sqrt 40800000: expected 40000001", wrong);
  assert_non_null(strstr(buf, want));

  unlink(good);
  unlink(bad);
  unlink(wrong);
}

/* ---- the sign and compare references ------------------------------------ */

typedef struct minmax_case {
  uint32_t a, b, min, max;
  unsigned flags;
  const char *what;
} minmax_case;

/* IEEE 754-2019 9.6 minimum / maximum (fpref.h). */
static const minmax_case minmax_cases[] = {
    {0x3F800000, 0x40000000, 0x3F800000, 0x40000000, 0, "1, 2"},
    {0xC0000000, 0x3F800000, 0xC0000000, 0x3F800000, 0, "-2, 1"},
    {0xC0000000, 0xBF800000, 0xC0000000, 0xBF800000, 0, "-2, -1"},
    {0x00000000, 0x80000000, 0x80000000, 0x00000000, 0, "+0, -0: -0 < +0"},
    {0x80000000, 0x00000000, 0x80000000, 0x00000000, 0, "-0, +0"},
    {0x00000001, 0x80000001, 0x80000001, 0x00000001, 0, "subnormals, no flush"},
    {0x00000001, 0x00000000, 0x00000000, 0x00000001, 0, "sub above +0"},
    {0xFF800000, 0x7F800000, 0xFF800000, 0x7F800000, 0, "-inf, +inf"},
    {0x7F7FFFFF, 0x7F800000, 0x7F7FFFFF, 0x7F800000, 0, "max, inf"},
    {0x7FC00000, 0x3F800000, 0x7FC00000, 0x7FC00000, 0, "qNaN, 1: NaN"},
    {0x3F800000, 0xFFC00001, 0xFFC00001, 0xFFC00001, 0, "1, -qNaN: b"},
    {0x7F800001, 0x3F800000, 0x7FC00001, 0x7FC00001, NV, "sNaN, 1: quieted, invalid"},
    {0x3F800000, 0x7F800001, 0x7FC00001, 0x7FC00001, NV, "1, sNaN"},
    {0x7FC00002, 0x7F800001, 0x7FC00002, 0x7FC00002, NV, "qNaN, sNaN: a, invalid"},
    {0x40400000, 0x40400000, 0x40400000, 0x40400000, 0, "equal"},
};

static void test_sign_compare(void **state) {
  (void)state;
  unsigned long bad = 0;
  for (size_t i = 0; i < sizeof minmax_cases / sizeof minmax_cases[0]; i++) {
    const minmax_case *c = &minmax_cases[i];
    unsigned f1 = 0, f2 = 0;
    uint32_t mn = fpref_min(c->a, c->b, &f1);
    uint32_t mx = fpref_max(c->a, c->b, &f2);
    if (mn != c->min || mx != c->max || f1 != c->flags || f2 != c->flags) {
      bad++;
      print_error("min/max %08X %08X (%s): want %08X %08X /%02X, got %08X "
                  "%08X /%02X %02X\n", c->a, c->b, c->what, c->min, c->max,
                  c->flags, mn, mx, f1, f2);
    }
  }
  /* Random pairs: min/max against the host's comparison for numbers, the
   * two results are the two operands, abs and neg only touch bit 31. */
  for (unsigned long k = 0; k < RANDOM_LAT; k++) {
    uint32_t a = gen_operand(), b = gen_operand();
    unsigned fl = 0;
    uint32_t mn = fpref_min(a, b, &fl), mx = fpref_max(a, b, &fl);
    if (fpref_abs(a) != (a & ~SIGN) || fpref_neg(a) != (a ^ SIGN)) bad++;
    if (fpref_is_nan(a) || fpref_is_nan(b)) {
      if (!fpref_is_nan(mn) || mn != mx) bad++;
      continue;
    }
    float x = fpref_float(a), y = fpref_float(b);
    int ok = fl == 0 && !(fpref_float(mn) > fpref_float(mx)) &&
             ((mn == a && mx == b) || (mn == b && mx == a)) &&
             fpref_float(mn) == (x < y ? x : y) &&
             fpref_float(mx) == (x > y ? x : y);
    if (!ok && bad++ < MAX_REPORT)
      print_error("min/max %08X %08X: %08X %08X /%02X\n", a, b, mn, mx, fl);
  }
  print_message("%zu directed min/max cases, %lu random pairs\n",
                sizeof minmax_cases / sizeof minmax_cases[0], RANDOM_LAT);
  assert_int_equal(bad, 0);
}

/* ---- benchmark ---------------------------------------------------------- */

static double now_seconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int bench(unsigned long long n) {
  rand_buf *rb = malloc(sizeof *rb);
  if (!rb) return 1;
  printf("bench-fp: %llu random operations per operation and configuration\n",
         n);
  for (int mi = 0; mi < 4; mi++) {
    fpu_model *m = fpu_model_new((int)modes[mi].round, modes[mi].ftz, 0, 0);
    if (!m) {
      fprintf(stderr, "no model for %s\n", mode_name[mi]);
      free(rb);
      return 1;
    }
    for (int op = 0; op < NUM_ALL_OPS; op++) {
      double gen = 0, t0 = now_seconds();
      for (unsigned long long done = 0; done < n;) {
        size_t k = n - done < BATCH ? (size_t)(n - done) : BATCH;
        double g0 = now_seconds();
        for (size_t i = 0; i < k; i++) {
          rb->a[i] = rng32();
          rb->b[i] = rng32();
        }
        gen += now_seconds() - g0;
        if (fpu_model_run(m, (fpu_op)op, k, rb->a, rb->b, rb->y, rb->fl) != 0) {
          fprintf(stderr, "bench: model misbehaved\n");
          free(rb);
          return 1;
        }
        done += k;
      }
      double secs = now_seconds() - t0 - gen;
      printf("%-8s %s: %.3g ops in %.2f s: %.2f Mops/s (RTL model, one op "
             "per cycle)\n",
             mode_name[mi], op_name[op], (double)n, secs, (double)n / secs / 1e6);
      fflush(stdout);
    }
    fpu_model_free(m);
  }
  free(rb);
  return 0;
}

int main(int argc, char **argv) {
  if (argc >= 2 && strcmp(argv[1], "--bench") == 0) {
    unsigned long long n = argc >= 3 ? strtoull(argv[2], NULL, 0) : 100000000ull;
    return bench(n ? n : 1);
  }
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_directed),
      cmocka_unit_test(test_sign_compare),
      cmocka_unit_test(test_pipeline),
      cmocka_unit_test(test_random_rne),
      cmocka_unit_test(test_random_rtz),
      cmocka_unit_test(test_random_ftz),
      cmocka_unit_test(test_random_rtz_ftz),
      cmocka_unit_test(test_latency_variants),
      cmocka_unit_test(test_testfloat_vectors),
      cmocka_unit_test(test_cli),
  };
  return cmocka_run_group_tests_name("fpu", tests, setup, teardown);
}
