/*
 * test_model.c -- the model language (sw/model/, docs/models.md):
 *
 *  - the parser: every shipped model parses; precedence, associativity,
 *    unary minus, hex floats and named constants give the tree the
 *    grammar says (checked by the literal golden model against the same
 *    formula in plain C); every kind of bad input is refused with
 *    FILE:LINE:COL and its reason;
 *  - the literal golden model: models/ship.fp3m equals the ship golden
 *    model (sw/ref/golden.c) bit for bit in v under rk4 and in v and s
 *    under euler, where the literal forms coincide;
 *  - the GSL reference (rk8pd at 1e-12) equals the `exact` lines of the
 *    ship and the damped spring to 1e-9, and each shipped model's
 *    literal rk4 golden model stays within a bound of it;
 *  - the compiled program (sw/compiler/compile.c, fp3_compile_model): its
 *    IR golden model in literal mode equals the literal golden model bit
 *    for bit; literal and folded programs bit-exact on the ISS and the RTL
 *    after every integration; a model that needs an instruction the ISA
 *    lacks is refused naming the unit (and its ISS/RTL runs are skipped,
 *    with the reason printed, while the ISA lacks it).
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "compile.h"
#include "engine.h"
#include "fpref.h"
#include "golden.h"
#include "model.h"
#include "modelref.h"

static const char *const shipped[] = {"models/ship.fp3m", "models/spring.fp3m",
                                      "models/projectile.fp3m", "models/orbit.fp3m",
                                      "models/spring3d.fp3m", "models/oscillator.fp3m"};

static fp3_model *load(const char *path) {
  fp3_model *m = malloc(sizeof *m);
  assert_non_null(m);
  char msg[512];
  if (fp3_model_load(path, m, msg, sizeof msg)) fail_msg("%s", msg);
  return m;
}

static fp3_model *parse(const char *src) {
  fp3_model *m = malloc(sizeof *m);
  assert_non_null(m);
  char msg[512];
  if (fp3_model_parse(src, "t.fp3m", m, msg, sizeof msg)) fail_msg("%s", msg);
  return m;
}

static void test_shipped_parse(void **st) {
  (void)st;
  for (size_t i = 0; i < sizeof shipped / sizeof shipped[0]; i++) {
    fp3_model *m = load(shipped[i]);
    assert_true(m->nstate >= 2);
    free(m);
  }
  fp3_model *m = load("models/projectile.fp3m");
  assert_string_equal(m->name, "projectile");
  assert_int_equal(m->nstate, 6);
  assert_int_equal(m->nparam, 3); /* h, kd, g */
  assert_string_equal(m->param[0], "h");
  assert_string_equal(m->state[3], "vx");
  assert_true(fp3_model_uses(m, FP3_ME_SQRT));
  assert_false(fp3_model_uses(m, FP3_ME_DIV));
  free(m);
  m = load("models/ship.fp3m");
  assert_true(fp3_model_split(m));
  assert_true(fp3_model_uses(m, FP3_ME_DIV)); /* 1/m: host-computed when compiled */
  free(m);
}

/* The tree: precedence, left associativity, unary minus, numbers. */
static void test_tree(void **st) {
  (void)st;
  fp3_model *m = parse("param a, b, c\nconst k = -0x1.8p1\nstate x\n"
                       "x' = a - b - c*a/b + -a*k + (a - (b - c)) / 3.1 - max(a, -b) + abs(-c)\n");
  const float in[4] = {0.25f, 1.1f, 3.3f, 7.7f}; /* h, a, b, c */
  float y = 0.0f, f, val[FP3_MODEL_MAX_NODES];
  fp3_model_eval_f(m, in, &y, &f, val);
  const float a = in[1], b = in[2], c = in[3], k = -3.0f;
  float want = a - b;
  want = want - (c * a) / b;
  want = want + (-a) * k;
  want = want + (a - (b - c)) / 3.1f;
  want = want - fmaxf(a, -b);
  want = want + fabsf(-c);
  assert_int_equal(fpref_bits(f), fpref_bits(want));
  free(m);
  /* unary minus flips the sign exactly: -(0) is -0 */
  m = parse("state x\nx' = -x\n");
  y = 0.0f;
  fp3_model_eval_f(m, in, &y, &f, val);
  assert_int_equal(fpref_bits(f), 0x80000000u);
  free(m);
  /* min and max: -0 below +0, a NaN propagates */
  m = parse("state x, y\nx' = min(x, y)\ny' = max(y, x)\n");
  float yy[2] = {0.0f, -0.0f}, ff[2];
  fp3_model_eval_f(m, in, yy, ff, val);
  assert_int_equal(fpref_bits(ff[0]), 0x80000000u);
  assert_int_equal(fpref_bits(ff[1]), 0x00000000u);
  yy[0] = NAN;
  fp3_model_eval_f(m, in, yy, ff, val);
  assert_true(isnan(ff[0]) && isnan(ff[1]));
  free(m);
}

/* Bad input: each message starts FILE:LINE:COL and names the reason. */
static void test_errors(void **st) {
  (void)st;
  static const struct {
    const char *src, *want;
  } cases[] = {
      {"state x\nx' = x +\n", "t.fp3m:2:9: expected an expression"},
      {"state x\nx' = (x\n", "t.fp3m:2:8: expected ')'"},
      {"state x\nx' = y\n", "t.fp3m:2:6: unknown name 'y'"},
      {"state x, v\nx' = v\n", "t.fp3m:1:10: state 'v' has no equation"},
      {"state x\nx' = 1\nx' = 2\n", "t.fp3m:3:1: state 'x' has two equations (the first at line 2)"},
      {"state x\nlet a = a + 1\nx' = a\n", "t.fp3m:2:9: let 'a' refers to itself (a cycle)"},
      {"state x\nlet a = b\nlet b = a\nx' = a\n",
       "t.fp3m:2:9: 'b' is a let defined later, at line 3"},
      {"param k\nstate k\nk' = 1\n", "t.fp3m:2:7: 'k' is declared twice (a param, line 1)"},
      {"param h\nstate x\nx' = 1\n", "t.fp3m:1:7: 'h' is reserved"},
      {"state x\nx' = sqrt(x, x)\n", "t.fp3m:2:12: sqrt takes 1 argument"},
      {"state x\nx' = exp(x)\n", "t.fp3m:2:6: exp() is only for `exact` lines"},
      {"state x\nx' = 1.5q\n", "t.fp3m:2:6: bad number '1.5q'"},
      {"state x\nmodel m\nx' = 1\n", "t.fp3m:2:1: `model NAME` must be the first statement"},
      {"state x\ny' = 1\n", "t.fp3m:2:1: 'y' is not a state variable"},
      {"state x\nx' = 1 2\n", "t.fp3m:2:8: unexpected '2'"},
      {"param a\n", "the model declares no state"},
      {"position x\nstate v\nx' = v\nv' = 1\n", "a split state needs"},
      {"state x\nconst c = x\nx' = c\n", "t.fp3m:2:11: a const is a number"},
      {"state x\nx' = foo(x)\n", "t.fp3m:2:6: unknown function 'foo'"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    fp3_model *m = malloc(sizeof *m);
    char msg[512] = "";
    assert_int_equal(fp3_model_parse(cases[i].src, "t.fp3m", m, msg, sizeof msg), -1);
    if (!strstr(msg, cases[i].want))
      fail_msg("case %zu: got \"%s\", want \"%s\"", i, msg, cases[i].want);
    free(m);
  }
  char msg[512];
  fp3_model m;
  assert_int_equal(fp3_model_load("models/no-such.fp3m", &m, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "models/no-such.fp3m: cannot read"));
}

/* models/ship.fp3m under the literal golden model is the ship's golden
 * model where the literal forms coincide: v under rk4 (s differs: the
 * ship program updates s by h v1, the model by RK4 on s' = v), v and s
 * under euler. */
static void test_ship_literal(void **st) {
  (void)st;
  fp3_model *m = load("models/ship.fp3m");
  fp3_ship_params p;
  fp3_ship_default(&p);
  p.v0 = 1.5f;
  p.s0 = -3.0f;
  const float in[4] = {p.h, p.T, p.C, p.m};
  float y[2] = {p.v0, p.s0};
  fp3_ship_state g;
  fp3_golden_init(&g, &p);
  for (int k = 0; k < 2000; k++) {
    assert_int_equal(fp3_model_step_literal(m, "rk4", in, y), 0);
    fp3_golden_step(&g);
    assert_int_equal(fpref_bits(y[0]), fpref_bits(g.v));
  }
  /* euler: v += h a(v), s += h v_old */
  float ye[2] = {p.v0, p.s0}, v = p.v0, s = p.s0;
  const float minv = 1.0f / p.m;
  for (int k = 0; k < 2000; k++) {
    assert_int_equal(fp3_model_step_literal(m, "euler", in, ye), 0);
    const float a = (p.T - p.C * v) * minv;
    const float v1 = v + p.h * a;
    s = s + p.h * v;
    v = v1;
    assert_int_equal(fpref_bits(ye[0]), fpref_bits(v));
    assert_int_equal(fpref_bits(ye[1]), fpref_bits(s));
  }
  assert_int_equal(fp3_model_step_literal(m, "verlet", in, ye), -1);
  free(m);
}

/* GSL rk8pd against the `exact` lines (ship, damped spring). */
static void test_gsl_exact(void **st) {
  (void)st;
  static const struct {
    const char *file;
    double in[4], y0[2];
  } cases[] = {
      {"models/ship.fp3m", {1.0 / 64, 50000, 5000, 10000}, {1.5, -3}},
      {"models/spring.fp3m", {1.0 / 64, 40, 0.8, 2}, {0.5, -0.25}},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    fp3_model *m = load(cases[i].file);
    double y[2];
    char msg[256];
    if (fp3_model_gsl(m, cases[i].in, cases[i].y0, 640, NULL, NULL, y, msg, sizeof msg))
      fail_msg("%s", msg);
    for (unsigned k = 0; k < 2; k++) {
      double ex;
      assert_int_equal(fp3_model_exact(m, k, cases[i].in, cases[i].y0, 640 * cases[i].in[0], &ex), 0);
      if (!(fabs(y[k] - ex) <= 1e-9 * (1 + fabs(ex))))
        fail_msg("%s %s: gsl %.17g exact %.17g", cases[i].file, m->state[k], y[k], ex);
    }
    free(m);
  }
}

/* Every shipped model's literal rk4 golden model stays near GSL. */
static void test_golden_vs_gsl(void **st) {
  (void)st;
  static const struct {
    const char *file;
    float in[4];
    float y0[6];
    double tol; /* relative to the state's largest magnitude */
  } cases[] = {
      {"models/ship.fp3m", {1.0f / 64, 50000, 5000, 10000}, {1.5f, -3}, 1e-4},
      {"models/spring.fp3m", {1.0f / 64, 40, 0.8f, 2}, {0.5f, -0.25f}, 1e-4},
      {"models/projectile.fp3m", {1.0f / 64, 0.002f, 9.81f}, {0, 2, 0, 30, 40, -5}, 1e-4},
      {"models/orbit.fp3m", {1.0f / 64, 1.0f}, {1, 0, 0, 1.1f}, 1e-4},
      {"models/spring3d.fp3m", {1.0f / 64, 30, 1.0f, 1.5f}, {1.5f, 0.2f, -0.3f, 0, 0.8f, 0.1f}, 1e-4},
  };
  const uint32_t steps = 640;
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    fp3_model *m = load(cases[i].file);
    float y[6];
    double in[4], y0[6], ref[6];
    for (unsigned k = 0; k < m->nparam; k++) in[k] = cases[i].in[k];
    for (unsigned k = 0; k < m->nstate; k++) y[k] = cases[i].y0[k], y0[k] = y[k];
    for (uint32_t k = 0; k < steps; k++) fp3_model_step_literal(m, "rk4", cases[i].in, y);
    char msg[256];
    if (fp3_model_gsl(m, in, y0, steps, NULL, NULL, ref, msg, sizeof msg)) fail_msg("%s", msg);
    double scale = 1;
    for (unsigned k = 0; k < m->nstate; k++)
      if (fabs(ref[k]) > scale) scale = fabs(ref[k]);
    for (unsigned k = 0; k < m->nstate; k++)
      if (!(fabs(y[k] - ref[k]) <= cases[i].tol * scale))
        fail_msg("%s %s: golden %.9g gsl %.17g", cases[i].file, m->state[k], (double)y[k], ref[k]);
    free(m);
  }
}

/* ---- compiled models on the engines ------------------------------------- */

typedef struct obs_hist {
  unsigned nstate, reg[FP3_MODEL_MAX_VARS];
  uint32_t steps;
  uint32_t *v; /* v[(k-1) * nstate + i]: state i written in integration k */
  unsigned char *seen;
} obs_hist;

static void hist_write(void *ctx, unsigned reg, uint32_t value, uint32_t k) {
  obs_hist *h = ctx;
  for (unsigned i = 0; i < h->nstate; i++)
    if (h->reg[i] == reg && k >= 1 && k <= h->steps) {
      h->v[(k - 1) * h->nstate + i] = value;
      h->seen[(k - 1) * h->nstate + i] = 1;
    }
}

/* Per-object inputs of a shipped model (h, params; initial state). */
static const struct {
  const char *file;
  float in[4], y0[6];
} objs[] = {
    {"models/ship.fp3m", {1.0f / 64, 50000, 5000, 10000}, {1.5f, -3}},
    {"models/spring.fp3m", {1.0f / 64, 40, 0.8f, 2}, {0.5f, -0.25f}},
    {"models/projectile.fp3m", {1.0f / 64, 0.002f, 9.81f}, {0, 2, 0, 30, 40, -5}},
    {"models/orbit.fp3m", {1.0f / 64, 1.0f}, {1, 0, 0, 1.1f}},
    {"models/spring3d.fp3m", {1.0f / 64, 30, 1.0f, 1.5f}, {1.5f, 0.2f, -0.3f, 0, 0.8f, 0.1f}},
    {"models/oscillator.fp3m", {1.0f / 64, 3.0f}, {0.75f, -0.5f}},
};

/* Run the compiled model on engine e for `steps` integrations and compare
 * every state variable after every integration with the IR golden model
 * (and, literal, with fp3_model_step_literal). */
static void run_check(fp3_engine *e, fp3_compiled *c, const fp3_model *m, const float *in,
                      const float *y0, uint32_t steps, int literal, const char *what) {
  unsigned reg[80];
  uint32_t val[80];
  size_t nw = fp3_compiled_model_start(c, in, y0, reg, val, 80);
  const fp3_image *img = fp3_compiled_image(c);
  if (fp3_engine_load(e, img->words, img->n)) fail_msg("%s: %s", what, fp3_engine_error(e));
  for (size_t w = 0; w < nw; w++) assert_int_equal(fp3_engine_write_reg(e, reg[w], val[w]), 0);
  obs_hist h = {m->nstate, {0}, steps, calloc((size_t)steps * m->nstate, 4),
                calloc((size_t)steps * m->nstate, 1)};
  assert_non_null(h.v);
  assert_non_null(h.seen);
  for (unsigned i = 0; i < m->nstate; i++) h.reg[i] = fp3_compiled_state_reg(c, i);
  fp3_observer obs = {.ctx = &h, .on_write = hist_write};
  fp3_status st;
  if (fp3_engine_run(e, steps, &obs, &st)) fail_msg("%s: %s", what, fp3_engine_error(e));
  assert_int_equal(st.error, FP3_ERR_NONE);
  assert_int_equal(st.steps_done, steps);
  float y[FP3_MODEL_MAX_VARS], yl[FP3_MODEL_MAX_VARS];
  uint32_t cur[FP3_MODEL_MAX_VARS];
  for (unsigned i = 0; i < m->nstate; i++) yl[i] = y0[i], cur[i] = fpref_bits(y0[i]);
  for (uint32_t k = 1; k <= steps; k++) {
    fp3_compiled_model_step(c, y);
    if (literal) {
      const char *integ = strstr(what, "rk4") ? "rk4" : strstr(what, "rk2") ? "rk2"
                        : strstr(what, "symeuler") ? "symeuler"
                        : strstr(what, "verlet") ? "verlet" : "euler";
      fp3_model_step_literal(m, integ, in, yl);
    }
    for (unsigned i = 0; i < m->nstate; i++) {
      size_t q = (size_t)(k - 1) * m->nstate + i;
      if (h.seen[q]) cur[i] = h.v[q];
      if (cur[i] != fpref_bits(y[i]))
        fail_msg("%s: %s after integration %u: engine 0x%08X golden 0x%08X", what,
                 m->state[i], k, cur[i], fpref_bits(y[i]));
      if (literal && fpref_bits(yl[i]) != fpref_bits(y[i]))
        fail_msg("%s: %s after integration %u: IR golden 0x%08X literal 0x%08X", what,
                 m->state[i], k, fpref_bits(y[i]), fpref_bits(yl[i]));
    }
  }
  for (unsigned i = 0; i < m->nstate; i++) {
    uint32_t r;
    assert_int_equal(fp3_engine_read_reg(e, h.reg[i], &r), 0);
    assert_int_equal(r, cur[i]);
  }
  free(h.v);
  free(h.seen);
}

/* Whether a program has a div or a sqrt (the 3-D models' speed |v|). */
static int uses_div_sqrt(const fp3_image *img) {
  for (size_t k = 0; k < img->n; k++) {
    const unsigned opc = fp3_insn_opc(img->words[k]);
    if (opc == FP3_OP_DIV || opc == FP3_OP_SQRT) return 1;
  }
  return 0;
}

/* Every shipped model, integrators euler, rk2, rk4 (and symeuler where
 * split, verlet where its accelerations read no velocity), literal and
 * folded, on the ISS (200 integrations) and on the RTL (rk4, euler and
 * verlet, 60 integrations; the 3-D models' div and sqrt on the RTL's
 * div/sqrt unit). */
static void test_engines(void **st) {
  (void)st;
  fp3_engine *iss = fp3_engine_iss_new(), *rtl = fp3_engine_rtl_new(NULL);
  assert_non_null(iss);
  assert_non_null(rtl);
  static const char *const integs[] = {"euler", "rk2", "rk4", "symeuler", "verlet"};
  unsigned ran = 0, skipped = 0, on_rtl_3d = 0;
  for (size_t i = 0; i < sizeof objs / sizeof objs[0]; i++) {
    fp3_model *m = load(objs[i].file);
    for (size_t g = 0; g < sizeof integs / sizeof integs[0]; g++)
      for (int lit = 1; lit >= 0; lit--) {
        if (strcmp(integs[g], "symeuler") == 0 && !fp3_model_split(m)) continue;
        if (strcmp(integs[g], "verlet") == 0 && !fp3_model_verlet_ok(m, NULL, NULL)) continue;
        fp3_compile_opts o;
        fp3_compile_defaults(&o);
        o.fold = o.drop_zero = !lit;
        fp3_compiled *c = NULL;
        char msg[512], what[128];
        snprintf(what, sizeof what, "%s %s %s", m->name, integs[g], lit ? "literal" : "folded");
        if (fp3_compile_model(m, integs[g], &o, NULL, &c, msg, sizeof msg)) {
          /* only a missing div or sqrt instruction, or a 3-D rk4 that
           * needs more than a context's NUM_REGS registers (the compiler
           * has no spilling and refuses it with the numbers), may stop a
           * shipped model */
          if (!strstr(msg, "this build has no HAS_SQRT unit") &&
              !strstr(msg, "this build has no HAS_DIV unit") &&
              !strstr(msg, "registers of a context (NUM_REGS is"))
            fail_msg("%s: %s", what, msg);
          if (!lit) continue;
          printf("SKIP (ISS, RTL): %s: %s\n", what, msg);
          skipped++;
          continue;
        }
        run_check(iss, c, m, objs[i].in, objs[i].y0, 200, lit, what);
        const fp3_image *img = fp3_compiled_image(c);
        /* The default build has every unit (div and sqrt included): the
         * host takes every compiled model. */
        if (fp3_config_check_program(&rtl->config, img->words, img->n, msg, sizeof msg))
          fail_msg("%s: refused by the default RTL build: %s", what, msg);
        if (strcmp(integs[g], "rk4") == 0 || strcmp(integs[g], "euler") == 0 ||
            strcmp(integs[g], "verlet") == 0) {
          run_check(rtl, c, m, objs[i].in, objs[i].y0, 60, lit, what);
          if (uses_div_sqrt(img)) on_rtl_3d++;
        }
        ran++;
        fp3_compiled_free(c);
      }
    free(m);
  }
  printf("compiled models bit-exact on the engines: %u programs, %u skipped; %u with div or "
         "sqrt on the RTL\n", ran, skipped, on_rtl_3d);
  assert_true(ran >= 8);
  /* projectile, orbit, spring3d: euler (and verlet where it applies),
   * literal and folded, at least */
  assert_true(on_rtl_3d >= 6);
  fp3_engine_free(iss);
  fp3_engine_free(rtl);
}

/* The compiler's refusals: a missing unit names it; too many words names
 * IMEM_DEPTH; too few registers names NUM_REGS. */
static void test_compile_refusals(void **st) {
  (void)st;
  fp3_model *m = load("models/projectile.fp3m");
  fp3_compile_opts o;
  fp3_compile_defaults(&o);
  fp3_compiled *c = NULL;
  char msg[512];
  if (fp3_opc_lookup("sqrt") < 0) {
    assert_int_equal(fp3_compile_model(m, "rk4", &o, NULL, &c, msg, sizeof msg), -1);
    assert_non_null(strstr(msg, "model projectile needs sqrt: this build has no HAS_SQRT unit"));
  }
  free(m);
  m = parse("param a\nstate x\nx' = x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x"
            "*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*a\n");
  assert_int_equal(fp3_compile_model(m, "rk4", &o, NULL, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "instructions; IMEM_DEPTH is 256"));
  free(m);
  m = load("models/spring.fp3m");
  o.num_regs = 6;
  assert_int_equal(fp3_compile_model(m, "rk4", &o, NULL, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "NUM_REGS"));
  o.num_regs = FP3_DEFAULT_NUM_REGS;
  assert_int_equal(fp3_compile_model(m, "verlet", &o, NULL, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "verlet needs accelerations that do not read velocities: v' "
                             "reads velocity v"));
  assert_int_equal(fp3_compile_model(m, "leapfrog", &o, NULL, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "unknown integrator 'leapfrog'"));
  free(m);
  m = load("models/projectile.fp3m");
  assert_int_equal(fp3_compile_model(m, "symeuler", &o, NULL, &c, msg, sizeof msg), -1);
  assert_int_equal(fp3_compile_model(m, "verlet", &o, NULL, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "needs the state split"));
  free(m);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_shipped_parse), cmocka_unit_test(test_tree),
      cmocka_unit_test(test_errors),        cmocka_unit_test(test_ship_literal),
      cmocka_unit_test(test_gsl_exact),     cmocka_unit_test(test_golden_vs_gsl),
      cmocka_unit_test(test_engines),       cmocka_unit_test(test_compile_refusals),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
