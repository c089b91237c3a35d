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

#include "fpref.h"
#include "golden.h"
#include "model.h"
#include "modelref.h"

static const char *const shipped[] = {"models/ship.fp3m", "models/spring.fp3m",
                                      "models/projectile.fp3m", "models/orbit.fp3m",
                                      "models/spring3d.fp3m"};

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

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_shipped_parse), cmocka_unit_test(test_tree),
      cmocka_unit_test(test_errors),        cmocka_unit_test(test_ship_literal),
      cmocka_unit_test(test_gsl_exact),     cmocka_unit_test(test_golden_vs_gsl),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
