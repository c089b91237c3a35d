/*
 * test_model.c -- the model language (sw/model/, docs/models.md):
 *
 *  - the parser: every shipped model parses; precedence, associativity,
 *    unary minus, hex floats and named constants give the tree the
 *    grammar says (checked by the literal golden model against the same
 *    formula in plain C); every kind of bad input is refused with
 *    FILE:LINE:COL and its reason; defaults (`param k = 40`, `param h =
 *    STEP`, `position x = 0.5`) are read as const reads a number, leave
 *    the equations as they are, and every shipped model gives them all;
 *  - the literal golden model: models/ship.fp3m under euler is Equations
 *    (1) written out in C, and under each integrator of the paper's
 *    programs it gives the digest of that program's C golden model, bit
 *    for bit after every integration (test_ship_integrators);
 *  - the GSL reference (rk8pd at 1e-12) equals the `exact` lines of the
 *    ship and the damped spring to 1e-9, and each shipped model's
 *    literal rk4 golden model stays within a bound of it;
 *  - the compiled program (sw/compiler/compile.c, fp3_compile_model): its
 *    IR golden model in literal mode equals the literal golden model bit
 *    for bit; every shipped model x every integrator that applies
 *    (rk4comp included), literal and folded, bit-exact after every
 *    integration on the ISS shaped as the build it needs, and on the RTL:
 *    the default build, or, for the programs that need more than its 32
 *    registers, the test build with NUM_REGS=40 (the output says which
 *    ran where);
 *  - registers: bounded register pressure fits 3-D RK4 into 32 where the
 *    latency-first schedule needs more; what does not fit is refused with
 *    the numbers, or compiled for a larger build (`.regs N`); the
 *    40-register RTL build refuses a word naming r40 and runs r39, as
 *    the ISS of that build does;
 *  - the rigid body (13 states, quaternion orientation): its GSL solution
 *    keeps |q|, the rotational energy and the angular momentum in world
 *    axes; its RK4 is refused for IMEM_DEPTH, with the numbers;
 *  - a model scene on lanes (the l4 build, 8 contexts x 4 lanes): one
 *    batch where the one-lane build needs three, the same bits;
 *  - rk4comp keeps the low bits RK4 loses over many small steps.
 * Everything a test allocates is freed by its teardown, failed or not.
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
#include "objects.h"
#include "model.h"
#include "modelref.h"
#include "mscene.h"
#include "../sim/fp3_model.h"

/* The RTL build with lanes that make test already builds (mk/rtl.mk
 * RTL_CFG_l4: 8 contexts x 4 lanes), and its build with more registers
 * than the default 32 (RTL_CFG_nc3: NUM_REGS=40, 3 contexts, FMAX_PIPE). */
extern const fp3_model_ops fp3_model_l4, fp3_model_nc3;

/* Every shipped model, with an object's inputs (h, params; initial state). */
static const struct {
  const char *file;
  float in[5], y0[13];
} objs[] = {
    {"models/ship.fp3m", {1.0f / 64, 50000, 5000, 10000}, {1.5f, -3}},
    {"models/spring.fp3m", {1.0f / 64, 40, 0.8f, 2}, {0.5f, -0.25f}},
    {"models/projectile.fp3m", {1.0f / 64, 0.002f, 9.81f}, {0, 2, 0, 30, 40, -5}},
    {"models/orbit.fp3m", {1.0f / 64, 1.0f}, {1, 0, 0, 1.1f}},
    {"models/spring3d.fp3m", {1.0f / 64, 30, 1.0f, 1.5f}, {1.5f, 0.2f, -0.3f, 0, 0.8f, 0.1f}},
    {"models/oscillator.fp3m", {1.0f / 64, 3.0f}, {0.75f, -0.5f}},
    /* g, Ix, Iy, Iz; x y z, q = 1, v, w: spinning about its major axis */
    {"models/rigidbody.fp3m", {1.0f / 64, 9.81f, 1, 2, 3},
     {0, 10, 0, 1, 0, 0, 0, 1, 5, 0, 0.3f, 0.2f, 2}},
};
#define NOBJS (sizeof objs / sizeof objs[0])

/* What a test allocates is owned here and freed by drop(), or by
 * teardown() after the test: cmocka runs teardown after a failed test
 * too (fail_msg and the asserts leave the test by longjmp), so a failure
 * path leaks nothing under ASan. */
#define MAX_OWNED 64
static struct {
  void *p;
  void (*fn)(void *);
} owned[MAX_OWNED];
static size_t n_owned;

static void free_engine(void *p) { fp3_engine_free(p); }
static void free_compiled(void *p) { fp3_compiled_free(p); }

/* Take p (NULL: nothing) to be freed by fn; returns p. */
static void *own(void *p, void (*fn)(void *)) {
  if (!p) return NULL;
  if (n_owned == MAX_OWNED) {
    fn(p);
    fail_msg("more than %d owned allocations", MAX_OWNED);
  }
  owned[n_owned].p = p;
  owned[n_owned++].fn = fn;
  return p;
}

/* Free p now (it must be owned, or NULL). */
static void drop(void *p) {
  for (size_t i = n_owned; i-- > 0;)
    if (owned[i].p == p) {
      owned[i].fn(p);
      owned[i] = owned[--n_owned];
      return;
    }
}

static int teardown(void **st) {
  (void)st;
  while (n_owned > 0) {
    n_owned--;
    owned[n_owned].fn(owned[n_owned].p);
  }
  return 0;
}

/* fp3_compile_model, the program (if any) owned. */
static int compile(const fp3_model *m, const char *integ, const fp3_compile_opts *o,
                   fp3_compiled **c, char *msg, size_t n) {
  int rc = fp3_compile_model(m, integ, o, NULL, c, msg, n);
  own(*c, free_compiled);
  return rc;
}

static fp3_model *load(const char *path) {
  fp3_model *m = own(malloc(sizeof *m), free);
  assert_non_null(m);
  char msg[512];
  if (fp3_model_load(path, m, msg, sizeof msg)) fail_msg("%s", msg);
  return m;
}

static fp3_model *parse(const char *src) {
  fp3_model *m = own(malloc(sizeof *m), free);
  assert_non_null(m);
  char msg[512];
  if (fp3_model_parse(src, "t.fp3m", m, msg, sizeof msg)) fail_msg("%s", msg);
  return m;
}

static void test_shipped_parse(void **st) {
  (void)st;
  for (size_t i = 0; i < NOBJS; i++) {
    fp3_model *m = load(objs[i].file);
    assert_true(m->nstate >= 2);
    drop(m);
  }
  fp3_model *m = load("models/projectile.fp3m");
  assert_string_equal(m->name, "projectile");
  assert_int_equal(m->nstate, 6);
  assert_int_equal(m->nparam, 3); /* h, kd, g */
  assert_string_equal(m->param[0], "h");
  assert_string_equal(m->state[3], "vx");
  assert_true(fp3_model_uses(m, FP3_ME_SQRT));
  assert_false(fp3_model_uses(m, FP3_ME_DIV));
  drop(m);
  m = load("models/ship.fp3m");
  assert_true(fp3_model_split(m));
  assert_true(fp3_model_uses(m, FP3_ME_DIV)); /* 1/m: host-computed when compiled */
  drop(m);
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
  drop(m);
  /* unary minus flips the sign exactly: -(0) is -0 */
  m = parse("state x\nx' = -x\n");
  y = 0.0f;
  fp3_model_eval_f(m, in, &y, &f, val);
  assert_int_equal(fpref_bits(f), 0x80000000u);
  drop(m);
  /* min and max: -0 below +0, a NaN propagates */
  m = parse("state x, y\nx' = min(x, y)\ny' = max(y, x)\n");
  float yy[2] = {0.0f, -0.0f}, ff[2];
  fp3_model_eval_f(m, in, yy, ff, val);
  assert_int_equal(fpref_bits(ff[0]), 0x80000000u);
  assert_int_equal(fpref_bits(ff[1]), 0x00000000u);
  yy[0] = NAN;
  fp3_model_eval_f(m, in, yy, ff, val);
  assert_true(isnan(ff[0]) && isnan(ff[1]));
  drop(m);
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
      /* defaults: a signed number, finite in binary32, once; h only so, > 0 */
      {"param k = 1e39\nstate x\nx' = k\n", "t.fp3m:1:11: number '1e39' overflows binary32"},
      {"param k = inf\nstate x\nx' = k\n", "t.fp3m:1:11: a default is a signed number"},
      {"param k = x\nstate x\nx' = k\n", "t.fp3m:1:11: a default is a signed number"},
      {"state x =\nx' = 1\n", "t.fp3m:1:10: a default is a signed number"},
      {"position x = 0.5q\nvelocity v\nx' = v\nv' = 1\n", "t.fp3m:1:14: bad number '0.5q'"},
      {"param k = 1 = 2\nstate x\nx' = k\n", "t.fp3m:1:7: 'k' is given a default twice"},
      {"param h = 0.5\nstate x\nparam a, h = 0.25\nx' = a\n",
       "t.fp3m:3:10: 'h' is given a default twice (the first at line 1)"},
      {"param h = 0\nstate x\nx' = 1\n", "t.fp3m:1:11: the step h must be above 0"},
      {"param h = -0.5\nstate x\nx' = 1\n",
       "t.fp3m:1:11: the step h must be above 0 (its default is -0.5)"},
      {"param h = -0\nstate x\nx' = 1\n", "t.fp3m:1:11: the step h must be above 0"},
      {"state h = 1\nh' = 1\n", "t.fp3m:1:7: 'h' is reserved"},
      {"param k = 2 3\nstate x\nx' = k\n", "t.fp3m:1:13: unexpected '3'"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    fp3_model *m = own(malloc(sizeof *m), free);
    assert_non_null(m);
    char msg[512] = "";
    assert_int_equal(fp3_model_parse(cases[i].src, "t.fp3m", m, msg, sizeof msg), -1);
    if (!strstr(msg, cases[i].want))
      fail_msg("case %zu: got \"%s\", want \"%s\"", i, msg, cases[i].want);
    drop(m);
  }
  char msg[512];
  fp3_model m;
  assert_int_equal(fp3_model_load("models/no-such.fp3m", &m, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "models/no-such.fp3m: cannot read"));
}

/* Defaults: `param NAME = NUMBER` (h too), `state NAME = NUMBER`: flags,
 * binary32 values as strtof and const read them (a minus flips the sign
 * bit), the strtod value; the equations are the same with or without. */
static void test_defaults(void **st) {
  (void)st;
  static const char with[] = "param k = 40, c, m = 0x1.8p1\n"
                             "param h = 0.0166666675   # 1/60 in binary32\n"
                             "position x = -0.5\n"
                             "velocity v, u = -0\n"
                             "x' = v\nv' = -(k*x + c*v) / m\nu' = 1\n";
  static const char without[] = "param k, c, m\n\nposition x\nvelocity v, u\n"
                                "x' = v\nv' = -(k*x + c*v) / m\nu' = 1\n";
  fp3_model *m = parse(with), *b = parse(without);
  assert_int_equal(m->nparam, 4); /* h, k, c, m */
  assert_int_equal(m->param_has_def[0], 1);
  assert_int_equal(fpref_bits(m->param_def[0]), fpref_bits(1.0f / 60.0f));
  assert_int_equal(m->param_def_line[0], 2);
  assert_int_equal(m->param_line[0], 0);
  assert_int_equal(m->param_has_def[1], 1);
  assert_true(m->param_def[1] == 40.0f && m->param_def_d[1] == 40.0);
  assert_int_equal(m->param_def_line[1], 1);
  assert_int_equal(m->param_has_def[2], 0);
  assert_int_equal(m->param_def_line[2], 0);
  assert_true(m->param_has_def[3] && m->param_def[3] == 3.0f);
  assert_true(m->state_has_def[0] && m->state_def[0] == -0.5f && m->state_def_d[0] == -0.5);
  assert_int_equal(m->state_has_def[1], 0);
  assert_true(m->state_has_def[2]);
  assert_int_equal(fpref_bits(m->state_def[2]), 0x80000000u); /* -0 is -0 */
  assert_true(m->state_def_d[2] == 0.0 && signbit(m->state_def_d[2]));
  /* the double keeps what binary32 rounds: 0.1 */
  fp3_model *d = parse("state x = 0.1\nx' = 1\n");
  assert_true(d->state_def[0] == 0.1f && d->state_def_d[0] == 0.1);
  drop(d);
  /* the same equations, node for node */
  assert_int_equal(m->nn, b->nn);
  for (unsigned i = 0; i < m->nn; i++) {
    const fp3_mexpr *x = &m->node[i], *y = &b->node[i];
    assert_true(x->kind == y->kind && x->a == y->a && x->b == y->b && x->id == y->id &&
                x->bits == y->bits && x->dval == y->dval && x->exact_only == y->exact_only);
  }
  assert_memory_equal(m->deriv, b->deriv, sizeof m->deriv);
  drop(b);
  drop(m);
  /* mixed, and h not named: h has no default */
  m = parse("param T, C = 5000\nstate v\nv' = T - C*v\n");
  assert_false(m->param_has_def[0]);
  assert_false(m->param_has_def[1]);
  assert_true(m->param_has_def[2] && m->param_def[2] == 5000.0f);
  assert_false(m->state_has_def[0]);
  drop(m);
  /* a const still takes its signed number as before */
  m = parse("const k = - 0x1p-2\nstate x\nx' = k\n");
  assert_int_equal(m->node[m->def_node[0]].bits, fpref_bits(-0.25f));
  drop(m);
  /* every shipped model gives every value: fp3 run --model needs no --set */
  for (size_t i = 0; i < NOBJS; i++) {
    m = load(objs[i].file);
    for (unsigned k = 0; k < m->nparam; k++)
      if (!m->param_has_def[k])
        fail_msg("%s: param %s has no default", objs[i].file, m->param[k]);
    for (unsigned k = 0; k < m->nstate; k++)
      if (!m->state_has_def[k])
        fail_msg("%s: state %s has no default", objs[i].file, m->state[k]);
    drop(m);
  }
  m = load("models/ship.fp3m"); /* the paper's default scene */
  assert_int_equal(fpref_bits(m->param_def[0]), fpref_bits(1.0f / 60.0f));
  assert_true(m->param_def[1] == 50000.0f && m->param_def[2] == 5000.0f &&
              m->param_def[3] == 10000.0f);
  assert_true(m->state_def[0] == 0.0f && m->state_def[1] == 0.0f);
  drop(m);
}

/* models/ship.fp3m under the literal golden model: euler is v += h a(v),
 * s += h v_old, as Equations (1) written out in C. */
static void test_ship_literal(void **st) {
  (void)st;
  fp3_model *m = load("models/ship.fp3m");
  const float h = 1.0f / 60.0f, T = 50000, C = 5000, M = 10000;
  const float in[4] = {h, T, C, M};
  float ye[2] = {1.5f, -3.0f}, v = 1.5f, s = -3.0f;
  const float minv = 1.0f / M;
  for (int k = 0; k < 2000; k++) {
    assert_int_equal(fp3_model_step_literal(m, "euler", in, ye), 0);
    const float a = (T - C * v) * minv;
    const float v1 = v + h * a;
    s = s + h * v;
    v = v1;
    assert_int_equal(fpref_bits(ye[0]), fpref_bits(v));
    assert_int_equal(fpref_bits(ye[1]), fpref_bits(s));
  }
  assert_int_equal(fp3_model_step_literal(m, "verlet", in, ye), -1);
  drop(m);
}

/* FNV-1a (64 bits) of a 32-bit word, byte by byte, low byte first. */
static uint64_t fnv32(uint64_t hash, uint32_t w) {
  for (int i = 0; i < 4; i++) {
    hash ^= (w >> (8 * i)) & 0xFFu;
    hash *= 0x100000001B3ull;
  }
  return hash;
}

/* The literal golden model of each integrator of the paper's programs on
 * models/ship.fp3m is the ship's Equations (1) golden model of that
 * program, bit for bit after every integration: the digest of v and s
 * after each of 500 integrations of 40 ships (generated, seed 7: drag, no
 * drag; ship 0 the default, ship 1 the default moving backwards at s0 =
 * 2^24 m) equals the digest of the program's C golden model, the paper's
 * operations in C binary32 in the program's order. */
static void test_ship_integrators(void **st) {
  (void)st;
  static const struct {
    const char *integ;
    uint64_t digest;
  } want[] = {{"euler", 0xe936926b986a5fd1ull},     {"symeuler", 0x304a8dd1ceff173dull},
              {"verletp", 0xf8dc707ef374a078ull},   {"rk2", 0x86516007711ef051ull},
              {"rk4se", 0xff8fa377ef837ac7ull},     {"rk4vs", 0x5bc1c86955e63eb8ull},
              {"rk4secomp", 0xa3d5f30384ca877eull}, {"rk4vscomp", 0x31e9961c3fc0fc03ull}};
  fp3_model *m = load("models/ship.fp3m");
  fp3_scene sc;
  assert_int_equal(fp3_scene_generate(7, 40, 1.0f / 60.0f, &sc), 0);
  fp3_ship_default(&sc.objs[0]);
  sc.objs[1] = sc.objs[0];
  sc.objs[1].v0 = -12.5f;
  sc.objs[1].s0 = 16777216.0f;
  for (size_t q = 0; q < sizeof want / sizeof want[0]; q++) {
    const char *ig = want[q].integ;
    assert_true(fp3_model_integrator_applies(m, ig));
    assert_int_equal(fp3_model_carried(m, ig),
                     strstr(ig, "comp") || strcmp(ig, "verletp") == 0 ? 4 : 2);
    uint64_t hash = 0xCBF29CE484222325ull;
    for (size_t o = 0; o < sc.n; o++) {
      const fp3_ship_params *p = &sc.objs[o];
      const float in[4] = {p->h, p->T, p->C, p->m};
      float y[4] = {p->v0, p->s0, 0, 0};
      fp3_model_start_literal(m, ig, in, y);
      for (int k = 1; k <= 500; k++) {
        assert_int_equal(fp3_model_step_literal(m, ig, in, y), 0);
        hash = fnv32(fnv32(hash, fpref_bits(y[0])), fpref_bits(y[1]));
      }
    }
    if (hash != want[q].digest)
      fail_msg("%s: digest 0x%016llx, the paper's golden model 0x%016llx", ig,
               (unsigned long long)hash, (unsigned long long)want[q].digest);
  }
  fp3_scene_free(&sc);
  /* the shapes each needs: an unsplit model takes neither, a split one
   * whose position moves with an expression takes rk4se but not verletp */
  fp3_model *un = parse("param k\nstate x, v\nx' = v\nv' = -k*x\n");
  float in[2] = {0.015625f, 40}, y[4] = {0.5f, -0.25f, 0, 0};
  assert_false(fp3_model_integrator_applies(un, "rk4se"));
  assert_int_equal(fp3_model_step_literal(un, "rk4vs", in, y), -1);
  fp3_model *ex = parse("param k\nposition x\nvelocity v\nx' = 2*v\nv' = -k*x\n");
  assert_true(fp3_model_integrator_applies(ex, "rk4se"));
  assert_false(fp3_model_integrator_applies(ex, "verletp"));
  assert_int_equal(fp3_model_pair(ex, 0), -1);
  drop(ex);
  drop(un);
  assert_false(fp3_model_integrator_known("rk4x"));
  drop(m);
}

/* GSL rk8pd against the `exact` lines of the models that have them (ship,
 * damped spring, oscillator), every state variable. */
static void test_gsl_exact(void **st) {
  (void)st;
  unsigned with_exact = 0;
  for (size_t i = 0; i < NOBJS; i++) {
    fp3_model *m = load(objs[i].file);
    double in[5], y0[13], y[13];
    for (unsigned k = 0; k < m->nparam; k++) in[k] = objs[i].in[k];
    for (unsigned k = 0; k < m->nstate; k++) y0[k] = objs[i].y0[k];
    if (m->exact[0] >= 0) {
      with_exact++;
      char msg[256];
      if (fp3_model_gsl(m, in, y0, 640, NULL, NULL, y, msg, sizeof msg)) fail_msg("%s", msg);
      for (unsigned k = 0; k < m->nstate; k++) {
        double ex;
        assert_true(m->exact[k] >= 0);
        assert_int_equal(fp3_model_exact(m, k, in, y0, 640 * in[0], &ex), 0);
        if (!(fabs(y[k] - ex) <= 1e-9 * (1 + fabs(ex))))
          fail_msg("%s %s: gsl %.17g exact %.17g", objs[i].file, m->state[k], y[k], ex);
      }
    }
    drop(m);
  }
  assert_int_equal(with_exact, 3);
}

/* Every shipped model's literal rk4 golden model stays near GSL: within
 * 1e-4 of the state's largest magnitude after 640 integrations. */
static void test_golden_vs_gsl(void **st) {
  (void)st;
  const uint32_t steps = 640;
  for (size_t i = 0; i < NOBJS; i++) {
    fp3_model *m = load(objs[i].file);
    float y[13];
    double in[5], y0[13], ref[13];
    for (unsigned k = 0; k < m->nparam; k++) in[k] = objs[i].in[k];
    for (unsigned k = 0; k < m->nstate; k++) y[k] = objs[i].y0[k], y0[k] = y[k];
    for (uint32_t k = 0; k < steps; k++) fp3_model_step_literal(m, "rk4", objs[i].in, y);
    char msg[256];
    if (fp3_model_gsl(m, in, y0, steps, NULL, NULL, ref, msg, sizeof msg)) fail_msg("%s", msg);
    double scale = 1;
    for (unsigned k = 0; k < m->nstate; k++)
      if (fabs(ref[k]) > scale) scale = fabs(ref[k]);
    for (unsigned k = 0; k < m->nstate; k++)
      if (!(fabs(y[k] - ref[k]) <= 1e-4 * scale))
        fail_msg("%s %s: golden %.9g gsl %.17g", objs[i].file, m->state[k], (double)y[k], ref[k]);
    drop(m);
  }
}

/* The rigid body's equations, checked by what the physics conserves:
 * along its GSL solution (10 s, 640 steps of 1/64 s) the quaternion
 * stays a unit, the rotational energy (Ix wx^2 + Iy wy^2 + Iz wz^2) / 2
 * stays, and so does the angular momentum in world axes, R(q) (Ix wx,
 * Iy wy, Iz wz), R(q) the rotation of q: a quaternion equation in the
 * wrong frame (q' = w q / 2 with w in body axes) keeps the first two and
 * breaks the third.  The centre of mass falls as y0 + vy0 t - g t^2 / 2. */
static void rb_invariants(const double *y, const double *in, double *out) {
  const double qw = y[3], qx = y[4], qy = y[5], qz = y[6];
  const double lx = in[2] * y[10], ly = in[3] * y[11], lz = in[4] * y[12];
  out[0] = qw * qw + qx * qx + qy * qy + qz * qz;
  out[1] = 0.5 * (lx * y[10] + ly * y[11] + lz * y[12]);
  /* R(q) L (the rotation matrix of a unit quaternion) */
  out[2] = (1 - 2 * (qy * qy + qz * qz)) * lx + 2 * (qx * qy - qw * qz) * ly +
           2 * (qx * qz + qw * qy) * lz;
  out[3] = 2 * (qx * qy + qw * qz) * lx + (1 - 2 * (qx * qx + qz * qz)) * ly +
           2 * (qy * qz - qw * qx) * lz;
  out[4] = 2 * (qx * qz - qw * qy) * lx + 2 * (qy * qz + qw * qx) * ly +
           (1 - 2 * (qx * qx + qy * qy)) * lz;
}

static void test_rigidbody_invariants(void **st) {
  (void)st;
  fp3_model *m = load("models/rigidbody.fp3m");
  assert_int_equal(m->nstate, 13);
  const size_t o = NOBJS - 1;
  assert_string_equal(objs[o].file, "models/rigidbody.fp3m");
  double in[5], y0[13], y[13], a[5], b[5];
  for (unsigned k = 0; k < m->nparam; k++) in[k] = objs[o].in[k];
  for (unsigned k = 0; k < m->nstate; k++) y0[k] = objs[o].y0[k];
  const uint32_t steps = 640;
  char msg[256];
  if (fp3_model_gsl(m, in, y0, steps, NULL, NULL, y, msg, sizeof msg)) fail_msg("%s", msg);
  rb_invariants(y0, in, a);
  rb_invariants(y, in, b);
  printf("rigidbody, GSL over %u steps: |q|^2 %.12f, energy %.12f -> %.12f, L (%.9f %.9f %.9f) "
         "-> (%.9f %.9f %.9f)\n", steps, b[0], a[1], b[1], a[2], a[3], a[4], b[2], b[3], b[4]);
  for (int k = 0; k < 5; k++) assert_true(fabs(b[k] - a[k]) <= 1e-8 * (1 + fabs(a[k])));
  const double t = steps * in[0];
  assert_true(fabs(y[1] - (y0[1] + y0[8] * t - 0.5 * in[1] * t * t)) <= 1e-8 * fabs(y0[1]));
  /* the body turns: q is far from its start */
  assert_true(fabs(y[3] - y0[3]) > 0.1);
  drop(m);
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
  obs_hist h = {m->nstate, {0}, steps, own(calloc((size_t)steps * m->nstate, 4), free),
                own(calloc((size_t)steps * m->nstate, 1), free)};
  assert_non_null(h.v);
  assert_non_null(h.seen);
  for (unsigned i = 0; i < m->nstate; i++) h.reg[i] = fp3_compiled_state_reg(c, i);
  fp3_observer obs = {.ctx = &h, .on_write = hist_write};
  fp3_status st;
  if (fp3_engine_run(e, steps, &obs, &st)) fail_msg("%s: %s", what, fp3_engine_error(e));
  assert_int_equal(st.error, FP3_ERR_NONE);
  assert_int_equal(st.steps_done, steps);
  /* the state, then what the integrator carries (compensations, accelerations) */
  float y[FP3_MODEL_MAX_VARS], yl[2 * FP3_MODEL_MAX_VARS] = {0};
  uint32_t cur[FP3_MODEL_MAX_VARS];
  char integ[32] = "";
  sscanf(what, "%*s %31s", integ); /* "MODEL INTEGRATOR literal|folded" */
  for (unsigned i = 0; i < m->nstate; i++) yl[i] = y0[i], cur[i] = fpref_bits(y0[i]);
  if (literal) fp3_model_start_literal(m, integ, in, yl);
  for (uint32_t k = 1; k <= steps; k++) {
    fp3_compiled_model_step(c, y);
    if (literal) assert_int_equal(fp3_model_step_literal(m, integ, in, yl), 0);
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
  drop(h.v);
  drop(h.seen);
}

/* The highest register a program's words name (rd, ra, rb). */
static unsigned top_reg(const fp3_image *img) {
  unsigned top = 0;
  for (size_t k = 0; k < img->n; k++) {
    const uint64_t w = img->words[k];
    const unsigned r[3] = {fp3_insn_rd(w), fp3_insn_ra(w), fp3_insn_rb(w)};
    for (int q = 0; q < 3; q++)
      if (r[q] > top) top = r[q];
  }
  return top;
}

/* A program that needs more registers than the default build has, on the
 * RTL build with NUM_REGS=40 (nc3): compiled for that build (its
 * latencies, FMAX_PIPE and registers, no growing: a program that does
 * not fit is refused with the numbers and fails the test), bit-exact
 * after every integration on it (60 integrations) and on the ISS shaped
 * as it (200).  Returns the highest register the program names. */
static int run_big(fp3_engine *big, const fp3_model *m, const char *integ, int lit,
                   size_t obj, const char *what) {
  fp3_compile_opts o;
  fp3_compile_opts_for(&o, &big->config);
  o.fold = o.drop_zero = !lit;
  fp3_compiled *c = NULL;
  char msg[512];
  if (compile(m, integ, &o, &c, msg, sizeof msg)) {
    /* the rigid body's split RK4 forms need more than 40 registers */
    if (strcmp(m->name, "rigidbody") == 0 && strstr(msg, "; NUM_REGS is 40")) {
      printf("ISS only: %s: %s\n", what, msg);
      return -1;
    }
    fail_msg("%s on the RTL build with NUM_REGS=%u: %s", what, big->config.num_regs, msg);
  }
  const fp3_compile_stats *cs = fp3_compiled_stats(c);
  assert_int_equal(cs->num_regs, big->config.num_regs);
  const fp3_image *img = fp3_compiled_image(c);
  if (fp3_config_check_program(&big->config, img->words, img->n, msg, sizeof msg))
    fail_msg("%s: %s", what, msg);
  const unsigned top = top_reg(img);
  fp3_engine *iss = own(fp3_engine_iss_new_config(&big->config), free_engine);
  assert_non_null(iss);
  run_check(iss, c, m, objs[obj].in, objs[obj].y0, 200, lit, what);
  drop(iss);
  run_check(big, c, m, objs[obj].in, objs[obj].y0, 60, lit, what);
  printf("RTL NUM_REGS=%u: %s: needs %u registers, names up to r%u, %u cycles estimated per "
         "later integration of one object\n", big->config.num_regs, what, cs->regs_needed, top,
         cs->est_cycles_later);
  drop(c);
  return (int)top;
}

/* Every shipped model x every integrator that applies (symeuler where
 * split, verlet where its accelerations read no velocity), literal and
 * folded, compiled for the default RTL build (its latencies and NUM_REGS;
 * a program that needs more registers is compiled for the fewest it fits,
 * max_regs): on the ISS shaped as that build (200 integrations), and on
 * the RTL (60 integrations): the default build when it has the program's
 * units (HAS_DIV, HAS_SQRT, as the Verilated model reports them) and
 * registers, else, for want of registers, the build with NUM_REGS=40
 * (run_big); a program refused by both fails the test.  Only RK4 of the
 * rigid body is refused, by the compiler: it is longer than IMEM_DEPTH. */
static void test_engines(void **st) {
  (void)st;
  fp3_engine *rtl = own(fp3_engine_rtl_new(NULL), free_engine);
  fp3_engine *big = own(fp3_engine_rtl_new_model(&fp3_model_nc3, NULL), free_engine);
  assert_non_null(rtl);
  assert_non_null(big);
  assert_true(big->config.num_regs > rtl->config.num_regs);
  static const char *const integs[] = {"euler",   "rk2",       "rk4",   "rk4comp",
                                       "symeuler", "verlet",   "rk4se", "rk4secomp",
                                       "rk4vs",    "rk4vscomp", "verletp"};
  unsigned ran = 0, on_rtl = 0, on_big = 0, iss_only = 0, most_regs = 0, big_top = 0, refused = 0;
  unsigned too_big = 0; /* more registers than the NUM_REGS=40 build: the ISS only */
  for (size_t i = 0; i < NOBJS; i++) {
    fp3_model *m = load(objs[i].file);
    for (size_t g = 0; g < sizeof integs / sizeof integs[0]; g++)
      for (int lit = 1; lit >= 0; lit--) {
        if (!fp3_model_integrator_applies(m, integs[g])) continue;
        fp3_compile_opts o;
        fp3_compile_opts_for(&o, &rtl->config);
        o.fold = o.drop_zero = !lit;
        o.max_regs = FP3_MAX_REGS;
        fp3_compiled *c = NULL;
        char msg[512], what[128];
        snprintf(what, sizeof what, "%s %s %s", m->name, integs[g], lit ? "literal" : "folded");
        if (compile(m, integs[g], &o, &c, msg, sizeof msg)) {
          /* RK4 of the 13-state rigid body is longer than the instruction
           * memory: refused with the numbers */
          if (strcmp(m->name, "rigidbody") != 0 || strncmp(integs[g], "rk4", 3) != 0 ||
              !strstr(msg, " instructions; IMEM_DEPTH is 256"))
            fail_msg("%s: %s", what, msg);
          printf("refused: %s: %s\n", what, msg);
          refused++;
          continue;
        }
        const fp3_compile_stats *cs = fp3_compiled_stats(c);
        assert_true(cs->regs_needed <= cs->num_regs);
        if (cs->num_regs > most_regs) most_regs = cs->num_regs;
        /* each new state value is written into its register by the
         * instruction that makes it: no mov, except rk4comp's new y_i,
         * which (t - y_i) must not overwrite before reading y_i (every
         * compensated integrator), and verletp's carried accelerations,
         * at most one each, made while the old one is still read */
        const unsigned movs = cs->body_insns - cs->body_arith - 1;
        const int comp = strstr(integs[g], "comp") != NULL;
        if (comp ? movs != m->nstate
                 : strcmp(integs[g], "verletp") == 0 ? movs > m->nstate : movs != 0)
          fail_msg("%s: %u instructions per integration, %u arithmetic", what, cs->body_insns,
                   cs->body_arith);
        fp3_config icfg = rtl->config;
        icfg.num_contexts = FP3_MAX_CONTEXTS;
        icfg.num_lanes = 1;
        icfg.num_regs = cs->num_regs;
        fp3_engine *iss = own(fp3_engine_iss_new_config(&icfg), free_engine);
        assert_non_null(iss);
        run_check(iss, c, m, objs[i].in, objs[i].y0, 200, lit, what);
        drop(iss);
        const fp3_image *img = fp3_compiled_image(c);
        if (cs->num_regs > rtl->config.num_regs) {
          const int top = run_big(big, m, integs[g], lit, i, what);
          if (top < 0) {
            too_big++;
          } else {
            if ((unsigned)top > big_top) big_top = (unsigned)top;
            on_big++;
          }
        } else if (fp3_config_check_program(&rtl->config, img->words, img->n, msg,
                                            sizeof msg)) {
          /* only a unit the RTL is built without (HAS_DIV, HAS_SQRT = 0)
           * may keep a shipped model off it: the host refuses it */
          if (!strstr(msg, "HAS_SQRT=0") && !strstr(msg, "HAS_DIV=0"))
            fail_msg("%s: %s", what, msg);
          printf("ISS only: %s: %s\n", what, msg);
          iss_only++;
        } else {
          run_check(rtl, c, m, objs[i].in, objs[i].y0, 60, lit, what);
          on_rtl++;
        }
        ran++;
        drop(c);
      }
    drop(m);
  }
  printf("compiled models bit-exact with their golden models: %u programs on the ISS, %u of "
         "them also on the default RTL (HAS_DIV=%u HAS_SQRT=%u NUM_REGS=%u), %u on the RTL with "
         "NUM_REGS=%u (they need %u at most for the default build; they name up to r%u), %u "
         "on the ISS only for want of a unit, %u for want of registers\n", ran, on_rtl,
         rtl->config.has_div, rtl->config.has_sqrt, rtl->config.num_regs, on_big,
         big->config.num_regs, most_regs, big_top, iss_only, too_big);
  /* 7 models: euler, rk2, rk4, rk4comp each, but the rigid body's rk4
   * and rk4comp (refused); symeuler for 6 split ones, verlet for 3;
   * literal and folded; rk4se, rk4secomp, rk4vs and rk4vscomp for the 6
   * split ones but the rigid body's literal rk4vs and its rk4vscomp
   * (refused: longer than IMEM_DEPTH), verletp for the 5 whose positions
   * move with a velocity.  Of the rigid body's split RK4 forms, 4 need
   * more than 40 registers: bit-exact on the ISS, not run on an RTL */
  assert_int_equal(refused, 2 * 2 + 3);
  assert_int_equal(ran, 2 * (7 * 4 - 2 + 6 + 3) + (2 * 6 * 4 - 3) + 2 * 5);
  assert_int_equal(too_big, 4);
  /* with the div/sqrt unit (the default build) every program runs on an
   * RTL build; some need more than 32 registers (3-D RK4), and the
   * 40-register build's top register, r39, is among those they name */
  if (rtl->config.has_div && rtl->config.has_sqrt) assert_int_equal(iss_only, 0);
  assert_true(on_big > 0);
  assert_int_equal(big_top, big->config.num_regs - 1);
  drop(big);
  drop(rtl);
}

/* NUM_REGS=40, not a power of two: the RTL's register check is a compare
 * (r < NUM_REGS), not the field's high bits.  A word naming r39 runs; a
 * word naming r40 (rd, ra or rb) is an illegal instruction at its pc, on
 * the RTL and on the ISS of the same build alike; a host write of r40 is
 * refused. */
static void test_regs40(void **st) {
  (void)st;
  fp3_engine *big = own(fp3_engine_rtl_new_model(&fp3_model_nc3, NULL), free_engine);
  assert_non_null(big);
  assert_int_equal(big->config.num_regs, 40);
  fp3_engine *iss = own(fp3_engine_iss_new_config(&big->config), free_engine);
  assert_non_null(iss);
  const uint32_t one = 0x3F800000u;
  for (int k = 0; k < 4; k++) {
    /* k 0: add r39, r39, r39; then r40 as rd, ra, rb */
    const unsigned rd = 39 + (k == 1), ra = 39 + (k == 2), rb = 39 + (k == 3);
    uint64_t words[3] = {fp3_insn_make(FP3_OP_ADD, 0, 0, 0, 0),
                         fp3_insn_make(FP3_OP_ADD, rd, ra, rb, 0),
                         fp3_insn_make(FP3_OP_HALT, 0, 0, 0, 0)};
    fp3_engine *e[2] = {big, iss};
    for (int q = 0; q < 2; q++) {
      assert_int_equal(e[q]->ops->load_program(e[q], words, 3), 0);
      assert_int_equal(fp3_engine_write_reg(e[q], 39, one), 0);
      fp3_status s;
      assert_int_equal(fp3_engine_run(e[q], 1, NULL, &s), 0);
      if (k == 0) {
        uint32_t v = 0;
        assert_int_equal(s.error, FP3_ERR_NONE);
        assert_int_equal(fp3_engine_read_reg(e[q], 39, &v), 0);
        assert_int_equal(v, 0x40000000u); /* 1 + 1 */
      } else {
        assert_int_equal(s.error, FP3_ERR_ILLEGAL_INSN);
        assert_int_equal(s.fault_pc, 1);
      }
    }
  }
  assert_int_not_equal(fp3_engine_write_reg(big, 40, one), 0);
  assert_int_not_equal(fp3_engine_write_reg(iss, 40, one), 0);
  drop(iss);
  drop(big);
}

/* The compiler's refusals: a missing unit names it; too many words names
 * IMEM_DEPTH; too few registers names NUM_REGS and the registers needed;
 * bounded register pressure and builds with more registers. */
static void test_compile_refusals(void **st) {
  (void)st;
  fp3_model *m = load("models/projectile.fp3m");
  fp3_compile_opts o;
  fp3_compile_defaults(&o);
  fp3_compiled *c = NULL;
  char msg[512];
  if (fp3_opc_lookup("sqrt") < 0) {
    assert_int_equal(compile(m, "rk4", &o, &c, msg, sizeof msg), -1);
    assert_non_null(strstr(msg, "model projectile needs sqrt: this build has no HAS_SQRT unit"));
  }
  drop(m);
  m = parse("param a\nstate x\nx' = x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x"
            "*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*x*a\n");
  assert_int_equal(compile(m, "rk4", &o, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "instructions; IMEM_DEPTH is 256"));
  drop(m);
  m = load("models/spring.fp3m");
  o.num_regs = 6;
  assert_int_equal(compile(m, "rk4", &o, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, " registers; NUM_REGS is 6 ("));
  o.num_regs = FP3_DEFAULT_NUM_REGS;
  assert_int_equal(compile(m, "verlet", &o, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "verlet needs accelerations that do not read velocities: v' "
                             "reads velocity v"));
  assert_int_equal(compile(m, "leapfrog", &o, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "unknown integrator 'leapfrog'"));
  drop(m);
  m = load("models/projectile.fp3m");
  assert_int_equal(compile(m, "symeuler", &o, &c, msg, sizeof msg), -1);
  assert_int_equal(compile(m, "verlet", &o, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "needs the state split"));

  /* Registers without spilling.  Latency first, literal RK4 of the 3-D
   * spring needs more than 32 registers; bounded register pressure fits it
   * (and the projectile's) into the default 32.  Folded RK4 of the 3-D spring needs 33 even so:
   * refused with the numbers, or, with max_regs, compiled for a build of
   * 33 (`.regs 33`). */
  o.fold = o.drop_zero = 0;
  o.num_regs = FP3_MAX_REGS; /* room for the latency-first schedule */
  fp3_model *m3 = load("models/spring3d.fp3m");
  if (compile(m3, "rk4", &o, &c, msg, sizeof msg)) fail_msg("%s", msg);
  const unsigned latency_first = fp3_compiled_stats(c)->regs_needed;
  drop(c);
  printf("spring3d rk4 literal: latency first needs %u registers\n", latency_first);
  assert_true(latency_first > FP3_DEFAULT_NUM_REGS);
  o.num_regs = FP3_DEFAULT_NUM_REGS;
  if (compile(m3, "rk4", &o, &c, msg, sizeof msg)) fail_msg("%s", msg);
  assert_true(fp3_compiled_stats(c)->regs_needed <= FP3_DEFAULT_NUM_REGS);
  drop(c);
  drop(m3);
  if (compile(m, "rk4", &o, &c, msg, sizeof msg)) fail_msg("%s", msg);
  assert_true(fp3_compiled_stats(c)->regs_needed <= FP3_DEFAULT_NUM_REGS);
  assert_int_equal(fp3_compiled_stats(c)->num_regs, FP3_DEFAULT_NUM_REGS);
  assert_null(strstr(fp3_compiled_text(c), ".regs"));
  drop(c);
  drop(m);

  m = load("models/spring3d.fp3m");
  fp3_compile_defaults(&o);
  assert_int_equal(compile(m, "rk4", &o, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "the program needs 33 registers; NUM_REGS is 32"));
  o.max_regs = 32;
  assert_int_equal(compile(m, "rk4", &o, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "the program needs 33 registers; NUM_REGS is 32"));
  o.max_regs = FP3_MAX_REGS;
  if (compile(m, "rk4", &o, &c, msg, sizeof msg)) fail_msg("%s", msg);
  assert_int_equal(fp3_compiled_stats(c)->regs_needed, 33);
  assert_int_equal(fp3_compiled_stats(c)->num_regs, 33);
  assert_non_null(strstr(fp3_compiled_text(c), "\n.regs 33\n"));
  /* it names r32 and no higher */
  assert_int_equal(top_reg(fp3_compiled_image(c)), 32);
  drop(c);
  drop(m);
}

/* rk4comp: the ship with a small step, h = 1/1024 s for 200000
 * integrations: RK4's updates v += dv, s += ds lose the low bits of the
 * small increments (error against GSL of order 1e-3 in v, 1e-2 in s);
 * the Kahan-compensated updates keep them (within binary32 rounding of
 * the result, 10 times smaller at the least). */
static void test_rk4comp_long(void **st) {
  (void)st;
  fp3_model *m = load("models/ship.fp3m");
  const float in[4] = {0.0009765625f, 50000, 5000, 10000};
  const double din[4] = {in[0], in[1], in[2], in[3]}, dy0[2] = {0, 0};
  const uint32_t steps = 60000;
  double ref[2];
  char msg[256];
  if (fp3_model_gsl(m, din, dy0, steps, NULL, NULL, ref, msg, sizeof msg)) fail_msg("%s", msg);
  double err[2] = {0, 0};
  for (int comp = 0; comp < 2; comp++) {
    float y[4] = {0, 0, 0, 0}; /* v, s; rk4comp: then c_v, c_s */
    for (uint32_t k = 0; k < steps; k++)
      assert_int_equal(fp3_model_step_literal(m, comp ? "rk4comp" : "rk4", in, y), 0);
    for (int i = 0; i < 2; i++)
      if (fabs(y[i] - ref[i]) > err[comp]) err[comp] = fabs(y[i] - ref[i]);
  }
  printf("ship, h = 1/1024, %u integrations: largest error against GSL rk4 %.3g, rk4comp "
         "%.3g\n", steps, err[0], err[1]);
  assert_true(err[0] > 1e-3);
  assert_true(err[1] * 10 < err[0]);
}

/* ---- lanes ------------------------------------------------------------------ */

static void free_mscene(void *p) {
  fp3_mscene_free(p);
  free(p);
}

/* A model scene on a build with lanes packs its objects into contexts x
 * lanes (object slot s = lane s / NUM_CONTEXTS of context s %
 * NUM_CONTEXTS, engine.h), as ship scenes do: scenes/springs.scene's 24
 * objects run in one batch on the RTL build l4 (8 contexts x 4 lanes)
 * and on the ISS shaped so, where the one-lane default build needs 3;
 * every object bit-exact with the golden model after every integration,
 * its final state the one of the one-lane run; frame by frame (rest
 * skipping) the same. */
static void test_lanes(void **st) {
  (void)st;
  char msg[512];
  fp3_mscene *sc = own(calloc(1, sizeof *sc), free_mscene);
  assert_non_null(sc);
  if (fp3_mscene_read("scenes/springs.scene", sc, msg, sizeof msg)) fail_msg("%s", msg);
  const fp3_model *m = sc->model;
  fp3_compile_opts o;
  fp3_compile_defaults(&o);
  fp3_compiled *c = NULL;
  if (compile(m, "rk4", &o, &c, msg, sizeof msg)) fail_msg("%s", msg);
  fp3_scene_gold sg;
  fp3_scene_gold_init(&sg, c, sc);
  const fp3_image *img = fp3_compiled_image(c);
  const uint32_t steps = 20;
  fp3_engine *one = own(fp3_engine_rtl_new(NULL), free_engine);
  fp3_engine *l4 = own(fp3_engine_rtl_new_model(&fp3_model_l4, NULL), free_engine);
  assert_non_null(one);
  assert_non_null(l4);
  assert_int_equal(l4->config.num_lanes, 4);
  fp3_engine *iss = own(fp3_engine_iss_new_config(&l4->config), free_engine);
  assert_non_null(iss);
  fp3_state_result base, r;
  if (fp3_run_state_objects(one, img->words, img->n, sc->n, steps, FPREF_IEEE, &sg.golden, &base, msg,
                            sizeof msg))
    fail_msg("%s", msg);
  own(base.y, free);
  assert_int_equal(base.mismatches, 0);
  assert_int_equal(base.batches, 3);
  fp3_engine *lanes[2] = {l4, iss};
  for (int k = 0; k < 2; k++) {
    if (fp3_run_state_objects(lanes[k], img->words, img->n, sc->n, steps, FPREF_IEEE, &sg.golden, &r,
                              msg, sizeof msg))
      fail_msg("%s", msg);
    own(r.y, free);
    if (r.mismatches)
      fail_msg("%s: object %zu, integration %u, %s: 0x%08X, golden 0x%08X",
               lanes[k]->ops->name, r.first_object, r.first_step, m->state[r.first_var],
               r.first_got, r.first_want);
    assert_int_equal(r.error, FP3_ERR_NONE);
    assert_int_equal(r.contexts, 8);
    assert_int_equal(r.lanes, 4);
    assert_int_equal(r.batches, 1);
    assert_memory_equal(r.y, base.y, sc->n * m->nstate * sizeof *r.y);
    printf("lanes: springs.scene on %s, 8 contexts x 4 lanes: %zu objects in %zu batch, "
           "%.2f cycles per object-step (one lane: %zu batches, %.2f)\n", lanes[k]->ops->name,
           r.objects, r.batches, (double)r.cycles / ((double)sc->n * steps), base.batches,
           (double)base.cycles / ((double)sc->n * steps));
    drop(r.y);
  }
  fp3_state_frames_result fr;
  if (fp3_run_state_frames(l4, img->words, img->n, sc->n, 8, 1, NULL, FPREF_IEEE, &sg.stepper, &fr, msg,
                           sizeof msg))
    fail_msg("%s", msg);
  assert_int_equal(fr.mismatches, 0);
  assert_int_equal(fr.error, FP3_ERR_NONE);
  assert_int_equal(fr.lanes, 4);
  assert_int_equal(fr.batches, 8); /* one batch a frame: every spring moves */
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test_teardown(test_shipped_parse, teardown), cmocka_unit_test_teardown(test_tree, teardown),
      cmocka_unit_test_teardown(test_errors, teardown),
      cmocka_unit_test_teardown(test_defaults, teardown),
      cmocka_unit_test_teardown(test_ship_literal, teardown),
      cmocka_unit_test_teardown(test_ship_integrators, teardown),
      cmocka_unit_test_teardown(test_gsl_exact, teardown),     cmocka_unit_test_teardown(test_golden_vs_gsl, teardown),
      cmocka_unit_test_teardown(test_rigidbody_invariants, teardown),
      cmocka_unit_test_teardown(test_engines, teardown),       cmocka_unit_test_teardown(test_regs40, teardown),
      cmocka_unit_test_teardown(test_compile_refusals, teardown),
      cmocka_unit_test_teardown(test_lanes, teardown),
      cmocka_unit_test_teardown(test_rk4comp_long, teardown),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
