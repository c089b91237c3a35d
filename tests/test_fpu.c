/*
 * test_fpu.c -- tests of the binary32 FP cores (rtl/fp_add.v, rtl/fp_mul.v)
 * through the Verilated models (sim/fpu_model.h), of the reference
 * sw/ref/fpref.c, and of the TestFloat runner sw/engine/testfloat.c.
 *
 *   - random operand pairs of mixed classes, 10^6 per operation and
 *     rounding configuration: RTL == fpref bit for bit, results and flags;
 *     fpref == the host's float for every non-NaN result (on x86 also the
 *     flags, and the FTZ configurations against MXCSR.FTZ/DAZ);
 *   - directed cases (subnormals, ties, overflow, signed zeros, invalid,
 *     NaN propagation, FTZ) on fpref and on the RTL;
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

static const char *const op_name[3] = {"add", "sub", "mul"};
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

/* A pair; b is often derived from a: cancellation, ties, alignment. */
static void gen_pair(fpu_op op, uint32_t *a, uint32_t *b) {
  *a = gen_operand();
  uint32_t k = rng_below(8);
  if (k < 4) {
    *b = gen_operand();
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
  default:         return fpref_mul(a, b, mode, flags);
  }
}

/* The host's own float operation in `mode`.  Returns 0 when the host
 * cannot run that mode (FTZ off x86); *flags is -1 when the host flags are
 * not comparable (not x86: tininess may be detected before rounding). */
static int host_op(fpu_op op, uint32_t a, uint32_t b, fpref_mode mode,
                   uint32_t *r, int *flags) {
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
  default:         z = x * y; break;
  }
  int e = fetestexcept(FE_ALL_EXCEPT);
  fesetround(round);
#if HAVE_MXCSR
  _mm_setcsr(csr);
  *flags = ((e & FE_INEXACT) ? NX : 0) | ((e & FE_UNDERFLOW) ? UF : 0) |
           ((e & FE_OVERFLOW) ? OF : 0) | ((e & FE_INVALID) ? NV : 0);
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
  for (int op = 0; op < 3; op++) {
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
static const directed cases[] = {
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

/* Issue one operation, count edges until valid_o: must be the latency, and
 * valid_o must be high for one cycle only. */
static void check_latency(fpu_model *m, int mul, unsigned want) {
  if (mul)
    fpu_model_set_mul(m, 1, 0x40000000u, 0x40400000u);
  else
    fpu_model_set_add(m, 1, 0, 0x40000000u, 0x40400000u);
  unsigned got = 0, highs = 0;
  for (unsigned k = 1; k <= want + 4; k++) {
    fpu_model_clock(m);
    if (k == 1) {
      fpu_model_set_add(m, 0, 0, 0, 0);
      fpu_model_set_mul(m, 0, 0, 0);
    }
    uint32_t y;
    int v = mul ? fpu_model_mul_out(m, &y, NULL) : fpu_model_add_out(m, &y, NULL);
    if (v) {
      highs++;
      if (!got) got = k;
      assert_int_equal(y, mul ? 0x40C00000u : 0x40A00000u);
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

/* Both cores at once, an operation in most cycles, checked cycle by cycle. */
static void stream_check(fpu_model *m, unsigned cycles) {
  const fpu_model_info *in = fpu_model_get_info(m);
  fpref_mode mode = {(fpref_round)in->round, in->ftz};
  pending q[2][16];
  unsigned head[2] = {0, 0}, count[2] = {0, 0};
  unsigned lat[2] = {in->add_latency, in->mul_latency};
  unsigned long results = 0;
  for (uint64_t t = 0; t < cycles + 16; t++) {
    int issue = t < cycles;
    for (int u = 0; u < 2; u++) {
      int valid = issue && rng_below(8) != 0;
      uint32_t a, b;
      int sub = (int)rng_below(2);
      fpu_op op = u ? FPU_OP_MUL : (sub ? FPU_OP_SUB : FPU_OP_ADD);
      gen_pair(op, &a, &b);
      if (u)
        fpu_model_set_mul(m, valid, a, b);
      else
        fpu_model_set_add(m, valid, sub, a, b);
      if (valid) {
        assert_true(count[u] < 16);
        pending *p = &q[u][(head[u] + count[u]++) % 16];
        p->due = t + lat[u];
        p->y = ref_op(op, a, b, mode, &p->flags);
      }
    }
    fpu_model_clock(m);
    /* Now in cycle t + 1. */
    for (int u = 0; u < 2; u++) {
      uint32_t y;
      unsigned fl;
      int v = u ? fpu_model_mul_out(m, &y, &fl) : fpu_model_add_out(m, &y, &fl);
      int due = count[u] && q[u][head[u]].due == t + 1;
      assert_int_equal(v, due);
      if (!v) continue;
      pending *p = &q[u][head[u]];
      if (y != p->y || fl != p->flags)
        print_error("%s %s cycle %llu: want %08X/%02X, got %08X/%02X\n",
                    in->name, u ? "mul" : "add", (unsigned long long)t, p->y,
                    p->flags, y, fl);
      assert_int_equal(y, p->y);
      assert_int_equal(fl, p->flags);
      head[u] = (head[u] + 1) % 16;
      count[u]--;
      results++;
    }
  }
  assert_int_equal(count[0] + count[1], 0);
  (void)results;
}

/* Reset with operations in flight: nothing comes out afterwards. */
static void reset_check(fpu_model *m) {
  const fpu_model_info *in = fpu_model_get_info(m);
  for (int k = 0; k < 3; k++) {
    fpu_model_set_add(m, 1, 0, 0x3F800000u, 0x3F800000u);
    fpu_model_set_mul(m, 1, 0x3F800000u, 0x3F800000u);
    fpu_model_clock(m);
  }
  fpu_model_reset(m);
  unsigned maxlat = in->add_latency > in->mul_latency ? in->add_latency
                                                       : in->mul_latency;
  for (unsigned k = 0; k < maxlat + 2; k++) {
    assert_int_equal(fpu_model_add_out(m, NULL, NULL), 0);
    assert_int_equal(fpu_model_mul_out(m, NULL, NULL), 0);
    fpu_model_clock(m);
  }
}

static void test_pipeline(void **state) {
  (void)state;
  size_t n = fpu_model_count();
  unsigned seen_add = 0, seen_mul = 0; /* bit L: latency L covered */
  assert_true(n >= 4);
  for (size_t i = 0; i < n; i++) {
    const fpu_model_info *in = fpu_model_info_at(i);
    fpu_model *m = fpu_model_new_named(in->name);
    assert_non_null(m);
    check_latency(m, 0, in->add_latency);
    check_latency(m, 1, in->mul_latency);
    stream_check(m, 20000);
    reset_check(m);
    stream_check(m, 200);
    seen_add |= 1u << in->add_latency;
    seen_mul |= 1u << in->mul_latency;
    print_message("%s: add latency %u, mul latency %u, streaming ok\n",
                  in->name, in->add_latency, in->mul_latency);
    fpu_model_free(m);
  }
  print_message("latencies covered: add 0x%X, mul 0x%X (bit L = L)\n",
                seen_add, seen_mul);
}

/* Models at other latencies: random pairs against fpref. */
static void test_latency_variants(void **state) {
  (void)state;
  size_t n = fpu_model_count(), variants = 0;
  for (size_t i = 0; i < n; i++) {
    const fpu_model_info *in = fpu_model_info_at(i);
    if (in->add_latency == FP3_DEFAULT_ADD_LATENCY &&
        in->mul_latency == FP3_DEFAULT_MUL_LATENCY)
      continue;
    fpu_model *m = fpu_model_new_named(in->name);
    assert_non_null(m);
    fpref_mode mode = {(fpref_round)in->round, in->ftz};
    for (int op = 0; op < 3; op++) {
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
  static const char *const ops[3] = {"add", "sub", "mul"};
  if (strncmp(name, "f32_", 4) != 0 || strlen(name) < 12) return 0;
  int o = -1;
  for (int k = 0; k < 3; k++)
    if (strncmp(name + 4, ops[k], 3) == 0 && name[7] == '_') o = k;
  if (o < 0) return 0;
  if (strncmp(name + 8, "rne_", 4) == 0)
    *round = FPREF_RNE;
  else if (strncmp(name + 8, "rtz_", 4) == 0)
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
      if (in->round != (int)round || in->ftz ||
          (in->add_latency == FP3_DEFAULT_ADD_LATENCY &&
           in->mul_latency == FP3_DEFAULT_MUL_LATENCY))
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
  assert_true(files >= 5);
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
  assert_int_not_equal(run_cli("div", good, NULL, NULL), 0);
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

  unlink(good);
  unlink(bad);
  unlink(wrong);
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
    for (int op = 0; op < 3; op++) {
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
