/*
 * test_integrators.c -- the paper's hand-written ship programs
 * (programs/ship_<name>.s), each bound by name to models/ship.fp3m and
 * checked against the literal golden model of its `.integrator`
 * (fp3_model_step_literal):
 *
 *  - every program bit-exact with its golden model after every
 *    integration, on the RTL and on the ISS, for several scenes, and the
 *    RTL's per-integration cycles periodic and as docs/numerics.md quotes;
 *  - orders of accuracy (error ratio when h halves, against the model's
 *    exact solution);
 *  - stiffness: stable just below each theoretical bound on h/tau (tau =
 *    m/C), diverging from the first step just above it, on the golden
 *    model and on the RTL; bisection finds the bound;
 *  - compensation: after 10^5 integrations the compensated program keeps
 *    v and s far closer than the plain one (s0 = 2^24 m, where the plain
 *    s never moves);
 *  - extreme parameters: no silent NaN or infinity.
 */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "asm.h"
#include "compile.h"
#include "engine.h"
#include "fp3_isa.h"
#include "fpref.h"
#include "model.h"
#include "mscene.h"
#include "objects.h"

#define SHIP "models/ship.fp3m"
#define RK4_BOUND 2.785293563405282 /* RK4's stability interval on the real axis */

/* The ship's programs: file, model integrator, orders of v and s, the
 * stability bound on h/tau of the linear decay v' = -(v - T/C)/tau. */
static const struct prog {
  const char *file, *integ;
  int order_v, order_s;
  double bound;
} progs[] = {
    {"programs/ship_euler.s", "euler", 1, 1, 2.0},
    {"programs/ship_symeuler.s", "symeuler", 1, 1, 2.0},
    {"programs/ship_verlet.s", "verletp", 2, 2, 2.0},
    {"programs/ship_rk2.s", "rk2", 2, 2, 2.0},
    {"programs/ship_rk4.s", "rk4se", 4, 1, RK4_BOUND},
    {"programs/ship_rk4vs.s", "rk4vs", 4, 4, RK4_BOUND},
    {"programs/ship_rk4comp.s", "rk4secomp", 4, 1, RK4_BOUND},
    {"programs/ship_rk4vscomp.s", "rk4vscomp", 4, 4, RK4_BOUND},
};
#define NPROGS (sizeof progs / sizeof progs[0])

static fp3_engine *rtl, *iss;
static fp3_model ship;

/* Program k bound to the ship model, compiled for engine e's build. */
static fp3_compiled *bind(size_t k, const fp3_engine *e) {
  char msg[300];
  fp3_compile_opts o;
  fp3_compile_opts_for(&o, &e->config);
  fp3_compiled *c = NULL;
  if (fp3_compile_bind_file(&ship, progs[k].file, &o, &c, msg, sizeof msg)) fail_msg("%s", msg);
  assert_string_equal(fp3_compiled_image(c)->integrator, progs[k].integ);
  return c;
}

/* One engine run of program c on ship p, `steps` integrations. */
typedef struct run {
  fp3_state_result res;
  float v, s;
  int nonfinite;     /* the golden state went non-finite (and when)     */
} run;

static void run_checked(fp3_engine *e, fp3_compiled *c, const fp3_ship_params *p, uint32_t steps,
                        run *r) {
  fp3_scene one = {(fp3_ship_params *)p, 1};
  fp3_mscene sc;
  char msg[300];
  if (fp3_mscene_from_ships(&one, SHIP, "test", &sc, msg, sizeof msg)) fail_msg("%s", msg);
  fp3_scene_gold g;
  fp3_scene_gold_init(&g, c, &sc);
  const fp3_image *img = fp3_compiled_image(c);
  if (fp3_run_state_objects(e, img->words, img->n, 1, steps, FPREF_IEEE, &g.golden, &r->res, msg,
                            sizeof msg))
    fail_msg("%s", msg);
  if (r->res.mismatches)
    fail_msg("%s: %llu golden mismatches, first at integration %u", e->ops->name,
             (unsigned long long)r->res.mismatches, r->res.first_step);
  assert_int_equal(r->res.error, FP3_ERR_NONE);
  r->v = fpref_float(r->res.y[0]);
  r->s = fpref_float(r->res.y[1]);
  r->nonfinite = r->res.nonfinite_object != SIZE_MAX;
  fp3_state_result_free(&r->res);
  r->res.y = NULL;
  fp3_mscene_free(&sc);
}

/* The golden model of integrator `integ` on ship p for n integrations:
 * v and s after each into v[], s[] (may be NULL), the final ones
 * returned in *vf, *sf. */
static void golden(const char *integ, const fp3_ship_params *p, uint32_t n, float *v, float *s,
                   float *vf, float *sf) {
  const float in[4] = {p->h, p->T, p->C, p->m};
  float y[4] = {p->v0, p->s0, 0, 0};
  fp3_model_start_literal(&ship, integ, in, y);
  for (uint32_t k = 0; k < n; k++) {
    assert_int_equal(fp3_model_step_literal(&ship, integ, in, y), 0);
    if (v) v[k] = y[0];
    if (s) s[k] = y[1];
  }
  *vf = y[0];
  *sf = y[1];
}

/* The exact solution at time t (the model's `exact` lines). */
static void exact(const fp3_ship_params *p, double t, double *v, double *s) {
  const double in[4] = {p->h, p->T, p->C, p->m}, y0[2] = {p->v0, p->s0};
  assert_int_equal(fp3_model_exact(&ship, 0, in, y0, t, v), 0);
  assert_int_equal(fp3_model_exact(&ship, 1, in, y0, t, s), 0);
}

/* ---- bit-exact on both engines -------------------------------------------- */

static const fp3_ship_params scenes[] = {
    /* T, C, m, h, v0, s0 */
    {50000.0f, 5000.0f, 10000.0f, 1.0f / 60.0f, 0.0f, 0.0f},  /* patrol boat  */
    {2000.0f, 0.0f, 1000.0f, 0.01f, 1.0f, -5.0f},             /* no drag      */
    {2.0e6f, 1.0e5f, 3.0e8f, 0.5f, 3.0f, 1000.0f},            /* tanker       */
    {-30.0f, 12.0f, 0.75f, 0.02f, 4.0f, 0.0f},                /* reversing    */
    {1000.0f, 100.0f, 100.0f, 1.9f, 0.0f, 0.0f},              /* coarse step  */
};

static void test_bit_exact(void **state) {
  (void)state;
  for (size_t i = 0; i < NPROGS; i++) {
    fp3_compiled *cr = bind(i, rtl), *ci = bind(i, iss);
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
      run a, b;
      run_checked(rtl, cr, &scenes[k], 300, &a);
      run_checked(iss, ci, &scenes[k], 300, &b);
      assert_int_equal(fpref_bits(a.v), fpref_bits(b.v));
      assert_int_equal(fpref_bits(a.s), fpref_bits(b.s));
      assert_int_equal(a.res.flags, b.res.flags);
    }
    fp3_compiled_free(cr);
    fp3_compiled_free(ci);
  }
}

/* The costs docs/numerics.md quotes (ADD_LATENCY 4, MUL_LATENCY 3: a
 * dependent add issues 5 cycles after its producer, a dependent mul 4;
 * one context issues at most every other cycle): one object's cycles of
 * the first integration and each later one, periodic. */
static void test_cycles(void **state) {
  (void)state;
  if (rtl->config.add_latency != 4 || rtl->config.mul_latency != 3) skip();
  static const unsigned first[NPROGS] = {23, 32, 70, 49, 121, 116, 144, 134};
  static const unsigned later[NPROGS] = {22, 30, 51, 44, 113, 107, 128, 117};
  for (size_t i = 0; i < NPROGS; i++) {
    fp3_compiled *c = bind(i, rtl);
    const fp3_image *img = fp3_compiled_image(c);
    unsigned f = 0, l1 = 0, l2 = 0;
    assert_int_equal(fp3_engine_endi_cycles(rtl, img->words, img->n, 20, &f, &l1), 0);
    assert_int_equal(fp3_engine_endi_cycles(rtl, img->words, img->n, 21, &f, &l2), 0);
    print_message("%-10s %3u cycles first, %3u per integration\n", progs[i].integ, f, l2);
    assert_int_equal(l1, l2); /* periodic */
    if (f != first[i] || l2 != later[i])
      fail_msg("%s: %u / %u cycles, want %u / %u", progs[i].integ, f, l2, first[i], later[i]);
    fp3_compiled_free(c);
  }
}

/* ---- accuracy --------------------------------------------------------------- */

/* Error at t = 4 s (two tau): the binary32 golden model is accurate
 * enough at these coarse steps to show the order: halving h divides the
 * error by about 2^p (up to higher-order terms). */
static void test_orders(void **state) {
  (void)state;
  for (size_t i = 0; i < NPROGS; i++) {
    double err[2][2];
    for (int j = 0; j < 2; j++) {
      fp3_ship_params p = scenes[0];
      uint32_t n = j ? 8 : 4; /* h = 1 s, 0.5 s (h/tau 0.5, 0.25) to 4 s */
      p.h = 4.0f / (float)n;
      float v, s;
      double ve, se;
      golden(progs[i].integ, &p, n, NULL, NULL, &v, &s);
      exact(&p, 4.0, &ve, &se);
      err[j][0] = fabs(v - ve);
      err[j][1] = fabs(s - se);
    }
    for (int w = 0; w < 2; w++) {
      int order = w ? progs[i].order_s : progs[i].order_v;
      double ratio = err[0][w] / err[1][w];
      double want = pow(2.0, order);
      if (!(ratio > 0.6 * want && ratio < 1.6 * want))
        fail_msg("%s: %s error ratio %.3f for h/2, want ~%.0f (order %d)", progs[i].integ,
                 w ? "s" : "v", ratio, want, order);
    }
  }
}

/* ---- stability --------------------------------------------------------------- */

static fp3_ship_params at_ratio(double x) {
  fp3_ship_params p = scenes[0];
  p.h = (float)(x * (double)p.m / (double)p.C);
  return p;
}

/* 1 if |v - T/C| grows from the first integration on and keeps growing
 * over n golden integrations (v0 = 0: the distance starts at T/C); 0 if
 * it never grows. */
static int diverges(const char *integ, const fp3_ship_params *p, uint32_t n) {
  float *v = malloc(n * sizeof *v), vf, sf;
  assert_non_null(v);
  golden(integ, p, n, v, NULL, &vf, &sf);
  const double vinf = (double)p->T / (double)p->C;
  double d = fabs((double)p->v0 - vinf);
  int grew = 0, shrank = 0;
  for (uint32_t k = 0; k < n && isfinite(v[k]); k++) {
    const double dk = fabs((double)v[k] - vinf);
    grew |= dk > d;
    shrank |= dk < d;
    d = dk;
  }
  free(v);
  if (grew && shrank) fail_msg("%s at h = %g: neither stable nor diverging", integ, (double)p->h);
  return grew;
}

static void test_stability_bounds(void **state) {
  (void)state;
  for (size_t i = 0; i < NPROGS; i++) {
    fp3_ship_params lo = at_ratio(0.99 * progs[i].bound);
    fp3_ship_params hi = at_ratio(1.01 * progs[i].bound);
    if (diverges(progs[i].integ, &lo, 5000))
      fail_msg("%s diverges at 0.99 of its bound", progs[i].integ);
    if (!diverges(progs[i].integ, &hi, 5000))
      fail_msg("%s stable at 1.01 of its bound", progs[i].integ);
    /* the same on the RTL, bit-exact with the golden model */
    fp3_compiled *c = bind(i, rtl);
    run r;
    float vf, sf;
    run_checked(rtl, c, &hi, 400, &r);
    golden(progs[i].integ, &hi, 400, NULL, NULL, &vf, &sf);
    assert_int_equal(fpref_bits(r.v), fpref_bits(vf));
    assert_true(fabs((double)r.v - 10.0) > 1e3);
    run_checked(rtl, c, &lo, 400, &r);
    assert_true(fabs((double)r.v - 10.0) < 10.0);
    fp3_compiled_free(c);
  }
}

/* Bisection on the golden model finds the bound to 1e-3 (binary32, 20000
 * steps). */
static void test_measured_bound(void **state) {
  (void)state;
  for (size_t i = 0; i < NPROGS; i++) {
    double lo = 0.5 * progs[i].bound, hi = 1.5 * progs[i].bound;
    while (hi - lo > 1e-4 * progs[i].bound) {
      const double mid = 0.5 * (lo + hi);
      fp3_ship_params p = at_ratio(mid);
      if (diverges(progs[i].integ, &p, 20000)) hi = mid;
      else lo = mid;
    }
    if (!(fabs(hi - progs[i].bound) < 1e-3 * progs[i].bound))
      fail_msg("%s: measured bound %.6f, theory %.6f", progs[i].integ, hi, progs[i].bound);
  }
}

/* ---- long runs: stagnation and compensation ----------------------------------- */

static void check_compensated(size_t plain, size_t comp) {
  fp3_ship_params p = scenes[0];
  p.s0 = 16777216.0f; /* 2^24 m: ulp 2 m > 2 h v = 0.33 m */
  const uint32_t n = 100000;
  float *s = malloc(n * sizeof *s), va, sa, vb, sb;
  assert_non_null(s);
  double ve, se;
  exact(&p, (double)n * (double)p.h, &ve, &se);
  golden(progs[plain].integ, &p, n, NULL, s, &va, &sa);
  /* plain: v stalls short of T/C, s never moves */
  uint32_t unmoved = 0;
  for (uint32_t k = 0; k < n; k++) unmoved += s[k] == p.s0;
  assert_int_equal(unmoved, n);
  assert_true(fabs(va - ve) / ve > 1e-6);
  assert_true(fabs(sa - se) / se > 5e-5);
  /* compensated: both within 1e-6 */
  golden(progs[comp].integ, &p, n, NULL, NULL, &vb, &sb);
  assert_true(fabs(vb - ve) / ve <= 1e-6);
  assert_true(fabs(sb - se) / se <= 1e-6);
  free(s);
  /* and the ISS agrees bit for bit on a shorter run of both */
  fp3_compiled *c = bind(comp, iss);
  run r;
  run_checked(iss, c, &p, 20000, &r);
  fp3_compiled_free(c);
  c = bind(plain, iss);
  run_checked(iss, c, &p, 20000, &r);
  fp3_compiled_free(c);
  assert_int_equal(fpref_bits(r.s), fpref_bits(16777216.0f));
}

static void test_compensated(void **state) {
  (void)state;
  check_compensated(4, 6); /* rk4se, rk4secomp */
  check_compensated(5, 7); /* rk4vs, rk4vscomp */
}

/* ---- extreme parameters --------------------------------------------------------- */

static void test_extremes(void **state) {
  (void)state;
  static const fp3_ship_params ext[] = {
      {5e4f, 5e3f, 1e30f, 0.01f, 0.0f, 0.0f},     /* huge mass: a underflows  */
      {1.0f, 1.0f, 1e-30f, 0.01f, 0.0f, 0.0f},    /* tiny mass: h/tau 1e28    */
      {1e38f, 1e-38f, 1.0f, 0.5f, 0.0f, 0.0f},    /* T/C overflows binary32   */
      {1e-30f, 1e30f, 1.0f, 1e-35f, 0.0f, 0.0f},  /* huge C, tiny T and h     */
      {3e38f, 0.0f, 1.0f, 1.0f, 0.0f, 0.0f},      /* no drag, huge thrust     */
      {5e4f, 5e3f, 1e4f, 0.01f, 1e30f, 0.0f},     /* v0 far above T/C         */
      {5e4f, 5e3f, 1e4f, 0.01f, -1e30f, 0.0f},    /* v0 far below T/C         */
      {0.0f, 0.0f, 1.0f, 0.01f, 0.0f, 0.0f},      /* nothing moves            */
  };
  for (size_t i = 0; i < NPROGS; i++) {
    fp3_compiled *ci = bind(i, iss), *cr = bind(i, rtl);
    for (size_t k = 0; k < sizeof ext / sizeof ext[0]; k++) {
      const uint32_t steps = 50;
      run r, q;
      run_checked(iss, ci, &ext[k], steps, &r);
      if (i == 0 || k == 1) run_checked(rtl, cr, &ext[k], steps, &q);
      const int nonfinite = !isfinite(r.v) || !isfinite(r.s);
      /* a non-finite result never goes unreported: the run has it, and
       * the sticky flags say how it came */
      if (nonfinite) {
        assert_true(r.nonfinite);
        assert_true(r.res.flags & (FP3_FLAG_OVERFLOW | FP3_FLAG_INVALID));
      }
      if (r.res.flags & FP3_FLAG_INVALID) assert_true(r.nonfinite);
      /* a tiny-mass scene is far beyond every bound */
      if (k == 1) assert_true(r.nonfinite || fabs(r.v) > 1e3);
      /* decaying from far away stays finite */
      if (k == 5 || k == 6) assert_false(nonfinite);
      if (k == 7) {
        assert_int_equal(fpref_bits(r.v), 0);
        assert_int_equal(fpref_bits(r.s), 0);
      }
    }
    fp3_compiled_free(ci);
    fp3_compiled_free(cr);
  }
}

static int setup(void **state) {
  (void)state;
  char msg[300];
  if (fp3_model_load(SHIP, &ship, msg, sizeof msg)) return -1;
  rtl = fp3_engine_rtl_new(NULL);
  iss = fp3_engine_iss_new();
  return rtl && iss ? 0 : -1;
}

static int teardown(void **state) {
  (void)state;
  fp3_engine_free(rtl);
  fp3_engine_free(iss);
  return 0;
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_bit_exact),        cmocka_unit_test(test_cycles),
      cmocka_unit_test(test_orders),           cmocka_unit_test(test_stability_bounds),
      cmocka_unit_test(test_measured_bound),   cmocka_unit_test(test_compensated),
      cmocka_unit_test(test_extremes),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
