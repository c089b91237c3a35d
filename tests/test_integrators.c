/*
 * test_integrators.c -- the ship integrators (sw/ref/integrators.c,
 * programs/ship_<name>.s):
 *
 *  - every program bit-exact with its golden model after every
 *    integration, on the RTL and on the ISS, for several scenes, and the
 *    RTL's per-integration cycles periodic;
 *  - orders of accuracy (error ratio when h halves) and the GSL peers;
 *  - stiffness: stable just below each theoretical bound, diverging just
 *    above it (golden model; RTL for one point of each), divergence
 *    reported from its first step;
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

#include "analytic.h"
#include "asm.h"
#include "engine.h"
#include "fp3_isa.h"
#include "fpref.h"
#include "gslref.h"
#include "integrators.h"
#include "objects.h"

/* ---- the ship programs on an engine and the golden runs -------------------- */

/* (this test's own: fp3 bench benchmarks models, sw/cli/cmd_bench.c) */

/* Result of one integrator program run on an engine. */
typedef struct fp3_irun {
  fp3_status st;           /* engine status and counters                  */
  uint32_t steps_done;     /* integrations whose v and s were compared    */
  uint64_t mismatches;     /* v or s != golden, bit for bit               */
  uint32_t first_mismatch; /* integration of the first one (0: none)      */
  double cycles_first;     /* cycles of integration 1 (RTL: exact)        */
  double cycles_per;       /* cycles per later integration (mean; NAN < 2)*/
  int periodic;            /* 1 if every later integration cost the same  */
  float v, s;              /* engine results after the last integration   */
  fp3_diverge div;         /* divergence watch on the engine's v and s    */
} fp3_irun;

/* Error of a golden (binary32) integration against the exact solution. */
typedef struct fp3_gerr {
  float v, s;                 /* after the last integration                 */
  double v_final_abs, v_final_rel, v_max_abs;   /* [m/s], 1, [m/s]          */
  double s_final_abs, s_final_rel, s_max_abs;   /* [m], 1, [m]              */
  /* max_k |v_k - v(t_k)| / max_k |v(t_k)| and the same for s; the larger */
  double err_norm;
  fp3_diverge div;            /* divergence watch                           */
  uint32_t v_last_change;     /* last integration that changed v            */
  uint64_t s_unmoved;         /* integrations that left s unchanged although
                                 its increment was not zero (stagnation)    */
} fp3_gerr;

enum { RV = 0, RS = 1 };

typedef struct irun_ctx {
  const fp3_integrator *ig;
  fp3_istate g[2]; /* golden state advanced for v and for s separately */
  fp3_track t;     /* v and s after every integration */
  fp3_irun *r;
  uint64_t first_cyc, prev_cyc, per0;
  uint32_t endis;
} irun_ctx;

static void irun_final(void *ctx, int which, uint32_t k, uint32_t bits) {
  irun_ctx *c = ctx;
  c->ig->step(&c->g[which]);
  float want = which == RV ? c->g[which].v : c->g[which].s;
  if (bits != fpref_bits(want)) {
    if (!c->r->mismatches) c->r->first_mismatch = k;
    c->r->mismatches++;
  }
  float got = fpref_float(bits);
  if (which == RV) {
    fp3_diverge_update(&c->r->div, k, got, 0.0f);
    c->r->v = got;
  } else {
    if (!isfinite(got) && (!c->r->div.nonfinite || k < c->r->div.nonfinite))
      c->r->div.nonfinite = k;
    c->r->s = got;
  }
}

static void irun_write(void *ctx, unsigned reg, uint32_t value,
                       uint32_t integration) {
  fp3_track_write(&((irun_ctx *)ctx)->t, reg, value, integration);
}

static void irun_endi(void *ctx, uint32_t integration, uint64_t cycle) {
  irun_ctx *c = ctx;
  if (integration == 1) c->first_cyc = cycle;
  if (integration == 2) c->per0 = cycle - c->prev_cyc;
  if (integration > 2 && cycle - c->prev_cyc != c->per0) c->r->periodic = 0;
  c->prev_cyc = cycle;
  c->endis = integration;
}

static int fp3_irun_program(fp3_engine *e, const fp3_integrator *ig,
                     const fp3_image *img, const fp3_ship_params *p,
                     uint32_t steps, fp3_irun *r, char *msg, size_t n) {
  memset(r, 0, sizeof *r);
  r->periodic = 1;
  r->cycles_per = NAN;
  if (img->out_reg[FP3_OUT_V] < 0 || img->out_reg[FP3_OUT_S] < 0) {
    snprintf(msg, n, "the program binds no '.out v' or '.out s'");
    return -1;
  }
  irun_ctx c;
  memset(&c, 0, sizeof c);
  c.ig = ig;
  c.r = r;
  c.t.last = steps;
  c.t.final = irun_final;
  c.t.ctx = &c;
  ig->init(&c.g[RV], p);
  ig->init(&c.g[RS], p);
  fp3_diverge_init(&r->div, p);
  float inval[FP3_IN_COUNT];
  fp3_in_values(p, inval);
  int erc = fp3_engine_load(e, img->words, img->n);
  for (int i = 0; i < FP3_IN_COUNT && erc == 0; i++)
    if (img->in_reg[i] >= 0)
      erc = fp3_engine_write_reg(e, (unsigned)img->in_reg[i],
                                 fpref_bits(inval[i]));
  c.t.reg[RV] = img->out_reg[FP3_OUT_V];
  c.t.reg[RS] = img->out_reg[FP3_OUT_S];
  for (int w = 0; w < 2 && erc == 0; w++) {
    c.t.next_k[w] = 1;
    erc = fp3_engine_read_reg(e, (unsigned)c.t.reg[w], &c.t.cur[w]);
  }
  if (erc == 0) {
    fp3_observer obs = {.ctx = &c, .on_write = irun_write, .on_endi = irun_endi};
    erc = fp3_engine_run(e, steps, &obs, &r->st);
  }
  if (erc != 0) {
    snprintf(msg, n, "%s engine: %s", e->ops->name, fp3_engine_error(e));
    return -1;
  }
  uint32_t done = r->st.steps_done < steps ? r->st.steps_done : steps;
  for (int w = 0; w < 2; w++) fp3_track_advance(&c.t, w, done + 1);
  r->steps_done = done;
  if (c.endis >= 1) r->cycles_first = (double)c.first_cyc + 1.0;
  if (c.endis >= 2)
    r->cycles_per =
        (double)(c.prev_cyc - c.first_cyc) / (double)(c.endis - 1);
  return 0;
}

/* ---- golden runs ---------------------------------------------------------- */

static void fp3_golden_errors(const fp3_integrator *ig, const fp3_ship_params *p,
                       uint32_t n, fp3_gerr *e) {
  memset(e, 0, sizeof *e);
  fp3_istate st;
  ig->init(&st, p);
  fp3_diverge_init(&e->div, p);
  double vmax = 0.0, smax = 0.0;
  for (uint32_t k = 1; k <= n; k++) {
    float v0 = st.v, s0 = st.s;
    ig->step(&st);
    if (st.v != v0) e->v_last_change = k;
    if (st.s == s0 && st.v != 0.0f) e->s_unmoved++;
    double ve, se;
    fp3_ship_exact(p->T, p->C, p->m, p->v0, p->s0, (double)k * (double)p->h,
                   &ve, &se);
    double dv = fabs((double)st.v - ve), ds = fabs((double)st.s - se);
    if (!(dv <= e->v_max_abs)) e->v_max_abs = dv;
    if (!(ds <= e->s_max_abs)) e->s_max_abs = ds;
    if (fabs(ve) > vmax) vmax = fabs(ve);
    if (fabs(se) > smax) smax = fabs(se);
    e->v_final_abs = dv;
    e->s_final_abs = ds;
    e->v_final_rel = ve != 0.0 ? dv / fabs(ve) : dv;
    e->s_final_rel = se != 0.0 ? ds / fabs(se) : ds;
    fp3_diverge_update(&e->div, k, st.v, st.s);
  }
  e->v = st.v;
  e->s = st.s;
  double ev = vmax > 0.0 ? e->v_max_abs / vmax : e->v_max_abs;
  double es = smax > 0.0 ? e->s_max_abs / smax : e->s_max_abs;
  e->err_norm = ev > es || isnan(ev) ? ev : es;
}

static int fp3_golden_diverges(const fp3_integrator *ig, const fp3_ship_params *p,
                        uint32_t n, uint32_t *began) {
  fp3_istate st;
  fp3_diverge d;
  ig->init(&st, p);
  fp3_diverge_init(&d, p);
  for (uint32_t k = 1; k <= n; k++) {
    ig->step(&st);
    if (fp3_diverge_update(&d, k, st.v, st.s)) break;
  }
  if (began) *began = d.detected ? d.began : d.nonfinite;
  return d.detected || d.nonfinite;
}

static int diverges_at(const fp3_integrator *ig, const fp3_ship_params *p,
                       uint32_t n, double x) {
  fp3_ship_params q = *p;
  q.h = (float)(x * (double)p->m / (double)p->C);
  return fp3_golden_diverges(ig, &q, n, NULL);
}

static double fp3_measure_bound(const fp3_integrator *ig, const fp3_ship_params *p,
                         uint32_t n, double lo, double hi) {
  if (!(p->C > 0.0f) || diverges_at(ig, p, n, lo) || !diverges_at(ig, p, n, hi))
    return NAN;
  while (hi - lo > 1e-6 * hi) {
    double mid = 0.5 * (lo + hi);
    if (diverges_at(ig, p, n, mid))
      hi = mid;
    else
      lo = mid;
  }
  return lo;
}

static fp3_engine *rtl, *iss;

static void load(const fp3_integrator *ig, fp3_image *img) {
  char *errors = NULL;
  fp3_image_init(img);
  if (fp3_asm_file(ig->program, img, &errors) != 0) {
    fprintf(stderr, "%s", errors ? errors : "");
    free(errors);
    fail_msg("%s does not assemble", ig->program);
  }
  free(errors);
}

static void run_checked(fp3_engine *e, const fp3_integrator *ig,
                        const fp3_image *img, const fp3_ship_params *p,
                        uint32_t steps, fp3_irun *r) {
  char msg[300];
  if (fp3_irun_program(e, ig, img, p, steps, r, msg, sizeof msg) != 0)
    fail_msg("%s: %s", ig->name, msg);
  if (r->mismatches)
    fail_msg("%s on %s: %llu golden mismatches, first at integration %u",
             ig->name, e->ops->name, (unsigned long long)r->mismatches,
             r->first_mismatch);
  assert_int_equal(r->st.error, FP3_ERR_NONE);
  assert_int_equal(r->steps_done, steps);
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
  size_t ni;
  const fp3_integrator *ig = fp3_integrators(&ni);
  assert_true(ni >= 8);
  for (size_t i = 0; i < ni; i++) {
    fp3_image img;
    load(&ig[i], &img);
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
      fp3_irun a, b;
      run_checked(rtl, &ig[i], &img, &scenes[k], 300, &a);
      run_checked(iss, &ig[i], &img, &scenes[k], 300, &b);
      assert_int_equal(fpref_bits(a.v), fpref_bits(b.v));
      assert_int_equal(fpref_bits(a.s), fpref_bits(b.s));
      assert_int_equal(a.st.flags, b.st.flags);
      assert_true(a.periodic);
      if (k == 0)
        print_message("%-8s %3.0f cycles first, %3.0f per integration\n",
                      ig[i].name, a.cycles_first, a.cycles_per);
    }
  }
}

/* The costs docs/numerics.md quotes (ADD_LATENCY 4, MUL_LATENCY 3: a dependent
 * add issues 5 cycles after its producer, a dependent mul 4; one context
 * issues at most every other cycle). */
static void test_cycles(void **state) {
  (void)state;
  if (rtl->config.add_latency != 4 || rtl->config.mul_latency != 3) skip();
  static const struct {
    const char *name;
    double per;
  } want[] = {{"euler", 22},  {"symeuler", 30}, {"verlet", 51}, {"rk2", 44},
              {"rk4", 113},   {"rk4vs", 107},   {"rk4comp", 128},
              {"rk4vscomp", 117}};
  for (size_t i = 0; i < sizeof want / sizeof want[0]; i++) {
    const fp3_integrator *ig = fp3_integrator_find(want[i].name);
    assert_non_null(ig);
    fp3_image img;
    load(ig, &img);
    fp3_irun r;
    run_checked(rtl, ig, &img, &scenes[0], 20, &r);
    if (r.cycles_per != want[i].per)
      fail_msg("%s: %.2f cycles per integration, want %.0f", ig->name,
               r.cycles_per, want[i].per);
  }
}

/* ---- accuracy --------------------------------------------------------------- */

/* Error at t = 4 s (two tau): the binary32 golden model is accurate
 * enough at these coarse steps to show the order: halving h divides the
 * error by about 2^p (up to higher-order terms). */
static void test_orders(void **state) {
  (void)state;
  size_t ni;
  const fp3_integrator *ig = fp3_integrators(&ni);
  for (size_t i = 0; i < ni; i++) {
    double err[2][2];
    for (int j = 0; j < 2; j++) {
      fp3_ship_params p = scenes[0];
      uint32_t n = j ? 8 : 4; /* h = 1 s, 0.5 s (h/tau 0.5, 0.25) to 4 s */
      p.h = 4.0f / (float)n;
      fp3_gerr e;
      fp3_golden_errors(&ig[i], &p, n, &e);
      err[j][0] = e.v_final_abs;
      err[j][1] = e.s_final_abs;
    }
    for (int w = 0; w < 2; w++) {
      int order = w ? ig[i].order_s : ig[i].order_v;
      double ratio = err[0][w] / err[1][w];
      double want = pow(2.0, order);
      if (!(ratio > 0.6 * want && ratio < 1.6 * want))
        fail_msg("%s: %s error ratio %.3f for h/2, want ~%.0f (order %d)",
                 ig[i].name, w ? "s" : "v", ratio, want, order);
    }
  }
}

/* GSL peers: rk8pd adaptive at 1e-12 agrees with the exact solution, and
 * GSL's rk4 at a fixed step is a fourth-order method (double). */
static void test_gsl(void **state) {
  (void)state;
  fp3_ship_params p = scenes[0];
  double v, s, ve, se;
  unsigned long nst;
  assert_int_equal(fp3_gsl_adaptive("rk8pd", &p, 12.0, 1e-12, &v, &s, &nst), 0);
  fp3_ship_exact(p.T, p.C, p.m, p.v0, p.s0, 12.0, &ve, &se);
  assert_true(fabs(v - ve) < 1e-10 * ve);
  assert_true(fabs(s - se) < 1e-10 * se);
  double e1, e2;
  assert_int_equal(fp3_gsl_fixed("rk4", &p, 0.25, 8, NULL, NULL, &v, &s), 0);
  fp3_ship_exact(p.T, p.C, p.m, p.v0, p.s0, 2.0, &ve, &se);
  e1 = fabs(v - ve);
  assert_int_equal(fp3_gsl_fixed("rk4", &p, 0.125, 16, NULL, NULL, &v, &s), 0);
  e2 = fabs(v - ve);
  assert_true(e1 / e2 > 12.0 && e1 / e2 < 20.0);
  assert_int_equal(fp3_gsl_fixed("bogus", &p, 0.1, 1, NULL, NULL, &v, &s), -1);
  assert_false(fp3_gsl_known("bogus"));
}

/* ---- stability --------------------------------------------------------------- */

static fp3_ship_params at_ratio(double x) {
  fp3_ship_params p = scenes[0];
  p.h = (float)(x * (double)p.m / (double)p.C);
  return p;
}

static void test_stability_bounds(void **state) {
  (void)state;
  size_t ni;
  const fp3_integrator *ig = fp3_integrators(&ni);
  for (size_t i = 0; i < ni; i++) {
    fp3_ship_params lo = at_ratio(0.99 * ig[i].bound);
    fp3_ship_params hi = at_ratio(1.01 * ig[i].bound);
    uint32_t began = 0;
    if (fp3_golden_diverges(&ig[i], &lo, 5000, &began))
      fail_msg("%s diverges at 0.99 of its bound (from step %u)", ig[i].name,
               began);
    if (!fp3_golden_diverges(&ig[i], &hi, 5000, &began))
      fail_msg("%s stable at 1.01 of its bound", ig[i].name);
    assert_int_equal(began, 1);
    /* the same on the RTL, bit-exact, with the divergence seen there */
    fp3_image img;
    load(&ig[i], &img);
    fp3_irun r;
    run_checked(rtl, &ig[i], &img, &hi, 400, &r);
    assert_true(r.div.detected != 0);
    assert_int_equal(r.div.began, 1);
    run_checked(rtl, &ig[i], &img, &lo, 400, &r);
    assert_int_equal(r.div.detected, 0);
    assert_int_equal(r.div.nonfinite, 0);
  }
}

/* Bisection finds the bound to a few 1e-4 (binary32, 20000 steps). */
static void test_measured_bound(void **state) {
  (void)state;
  size_t ni;
  const fp3_integrator *ig = fp3_integrators(&ni);
  for (size_t i = 0; i < ni; i++) {
    double b = fp3_measure_bound(&ig[i], &scenes[0], 20000, 0.5 * ig[i].bound,
                                 1.5 * ig[i].bound);
    if (!(fabs(b - ig[i].bound) < 1e-3 * ig[i].bound))
      fail_msg("%s: measured bound %.6f, theory %.6f", ig[i].name, b,
               ig[i].bound);
  }
}

/* ---- long runs: stagnation and compensation ----------------------------------- */

static void check_compensated(const char *plain_name, const char *comp_name) {
  const fp3_integrator *plain = fp3_integrator_find(plain_name);
  const fp3_integrator *comp = fp3_integrator_find(comp_name);
  fp3_ship_params p = scenes[0];
  p.s0 = 16777216.0f; /* 2^24 m: ulp 2 m > 2 h v = 0.33 m */
  fp3_gerr a, b;
  fp3_golden_errors(plain, &p, 100000, &a);
  fp3_golden_errors(comp, &p, 100000, &b);
  /* plain: v stalls short of T/C, s never moves */
  assert_true(a.v_final_rel > 1e-6);
  assert_int_equal(a.s_unmoved, 100000);
  assert_true(a.s_final_rel > 5e-5);
  /* compensated: both within 1e-6 */
  assert_true(b.v_final_rel <= 1e-6);
  assert_true(b.s_final_rel <= 1e-6);
  /* and the ISS agrees bit for bit on a shorter run of both */
  fp3_image img;
  fp3_irun r;
  load(comp, &img);
  run_checked(iss, comp, &img, &p, 20000, &r);
  load(plain, &img);
  run_checked(iss, plain, &img, &p, 20000, &r);
  assert_int_equal(fpref_bits(r.s), fpref_bits(16777216.0f));
}

static void test_compensated(void **state) {
  (void)state;
  check_compensated("rk4", "rk4comp");
  check_compensated("rk4vs", "rk4vscomp");
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
  size_t ni;
  const fp3_integrator *ig = fp3_integrators(&ni);
  for (size_t i = 0; i < ni; i++) {
    fp3_image img;
    load(&ig[i], &img);
    for (size_t k = 0; k < sizeof ext / sizeof ext[0]; k++) {
      const uint32_t steps = 50;
      fp3_irun r, q;
      run_checked(iss, &ig[i], &img, &ext[k], steps, &r);
      if (i == 0 || k == 1) run_checked(rtl, &ig[i], &img, &ext[k], steps, &q);
      int nonfinite = !isfinite(r.v) || !isfinite(r.s);
      /* a non-finite result never goes unreported: the watch has it, and
       * the sticky flags say how it came */
      if (nonfinite) {
        assert_true(r.div.nonfinite != 0);
        assert_true(r.st.flags & (FP3_FLAG_OVERFLOW | FP3_FLAG_INVALID));
      }
      if (r.st.flags & FP3_FLAG_INVALID) assert_true(r.div.nonfinite != 0);
      /* a tiny-mass scene is far beyond every bound: flagged diverging */
      if (k == 1) assert_true(r.div.detected || r.div.nonfinite);
      /* decaying from far away is not a divergence */
      if (k == 5 || k == 6) {
        assert_int_equal(r.div.detected, 0);
        assert_false(nonfinite);
      }
      if (k == 7) {
        assert_int_equal(fpref_bits(r.v), 0);
        assert_int_equal(fpref_bits(r.s), 0);
      }
    }
  }
}

static int setup(void **state) {
  (void)state;
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
      cmocka_unit_test(test_bit_exact),       cmocka_unit_test(test_cycles),
      cmocka_unit_test(test_orders),          cmocka_unit_test(test_gsl),
      cmocka_unit_test(test_stability_bounds), cmocka_unit_test(test_measured_bound),
      cmocka_unit_test(test_compensated),     cmocka_unit_test(test_extremes),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
