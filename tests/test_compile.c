/*
 * test_compile.c -- the compiler (sw/compiler/compile.c) on scenes of the
 * ship model (models/ship.fp3m), the paper's Equations (1):
 *
 *  - exact instruction counts of rk4se: literal = the paper's program,
 *    folded (the affine fold: h f(v) = hmT - hmC v), no drag, no thrust;
 *    folding never adds instructions;
 *  - dead code elimination removes what nothing reads;
 *  - the literal IR (no folding, no zero removal) is the integrator's
 *    literal golden model (fp3_model_step_literal) bit for bit, and
 *    removing zero terms keeps it so on scenes without exact zeros;
 *  - the IR golden model equals the ISS bit for bit, every object after
 *    every integration, for random scenes and every integrator and option;
 *    and the RTL for a small scene, whose measured cycles per integration
 *    equal the scheduler's estimate for the engine's latencies, on the
 *    default build and on the build for clock rate (FMAX_PIPE);
 *  - the folded coefficients are the host's binary32 products;
 *  - the emitted text assembles to the compiled image; bad input fails.
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

#include "asm.h"
#include "compile.h"
#include "engine.h"
#include "fpref.h"
#include "model.h"
#include "mscene.h"
#include "objects.h"
#include "../sim/fp3_model.h"

/* FMAX_PIPE 1 (mk/rtl.mk RTL_CFG_nc3, RTL_CFG_fmax) */
extern const fp3_model_ops fp3_model_nc3, fp3_model_fmax;

#define SHIP "models/ship.fp3m"
/* the ship's programs' integrators (programs/ship_*.s), and the model's rk4 */
static const char *const integrators[] = {"euler", "symeuler", "rk2", "rk4se", "rk4"};
#define N_INTEG (sizeof integrators / sizeof integrators[0])

/* Random ship scene `seed` of n objects; drag 0: every C = 0, thrust 0:
 * every T = 0. */
static void scene(uint64_t seed, size_t n, int drag, int thrust, fp3_mscene *sc) {
  fp3_scene ships;
  char msg[300];
  assert_int_equal(fp3_scene_generate(seed, n, 1.0f / 60.0f, &ships), 0);
  for (size_t i = 0; i < n; i++) {
    if (!drag) ships.objs[i].C = 0.0f;
    if (!thrust) ships.objs[i].T = 0.0f;
    if (ships.objs[i].T == 0.0f && thrust) ships.objs[i].T = 1.0f;
  }
  if (fp3_mscene_from_ships(&ships, SHIP, "test", sc, msg, sizeof msg)) fail_msg("%s", msg);
  fp3_scene_free(&ships);
}

static fp3_compiled *compile_opts(const fp3_mscene *sc, const char *ig, fp3_compile_opts *o) {
  unsigned char zero[FP3_MODEL_MAX_VARS];
  fp3_mscene_zero(sc, zero);
  fp3_compiled *c = NULL;
  char msg[300];
  if (fp3_compile_model(sc->model, ig, o, zero, &c, msg, sizeof msg)) fail_msg("%s: %s", ig, msg);
  return c;
}

static fp3_compiled *compile(const fp3_mscene *sc, const char *ig, int fold, int drop_zero) {
  fp3_compile_opts o;
  fp3_compile_defaults(&o);
  o.fold = fold;
  o.drop_zero = drop_zero;
  return compile_opts(sc, ig, &o);
}

static unsigned body_insns(const fp3_mscene *sc, const char *ig, int fold, int drop_zero) {
  fp3_compiled *c = compile(sc, ig, fold, drop_zero);
  unsigned k = fp3_compiled_stats(c)->body_insns;
  assert_int_equal(k, fp3_image_body_insns(fp3_compiled_image(c)));
  fp3_compiled_free(c);
  return k;
}

/* Object i's params and initial state. */
static const float *obj_in(const fp3_mscene *sc, size_t i) { return sc->in + i * sc->model->nparam; }
static const float *obj_y0(const fp3_mscene *sc, size_t i) { return sc->y0 + i * sc->model->nstate; }

/* Start compiled program c's golden model on object i of sc. */
static void gold_start(fp3_compiled *c, const fp3_mscene *sc, size_t i) {
  unsigned reg[64];
  uint32_t val[64];
  fp3_compiled_model_start(c, obj_in(sc, i), obj_y0(sc, i), reg, val, 64);
}

/* ---- instruction counts ------------------------------------------------------ */

static void test_counts_rk4(void **state) {
  (void)state;
  fp3_mscene all, nodrag, nothrust;
  scene(1, 16, 1, 1, &all);
  scene(2, 16, 0, 1, &nodrag);
  scene(3, 16, 1, 0, &nothrust);
  /* the literal program is the paper's: the body of programs/ship_rk4.s */
  fp3_image ship;
  char *errs = NULL;
  assert_int_equal(fp3_asm_file("programs/ship_rk4.s", &ship, &errs), 0);
  free(errs);
  assert_int_equal(body_insns(&all, "rk4se", 0, 0), fp3_image_body_insns(&ship));
  assert_int_equal(body_insns(&all, "rk4se", 0, 0), 31);
  /* folded: h f(x) = hmT - hmC x (2 instead of 4 per stage), the sum as
   * (k1 + k4) + 2 (k2 + k3): 21 arithmetic + endi */
  assert_int_equal(body_insns(&all, "rk4se", 1, 1), 22);
  assert_int_equal(body_insns(&all, "rk4se", 1, 0), 22); /* nothing zero */
  /* no drag: every k = hmT, the sum is loop invariant: v += dv; s += h v */
  assert_int_equal(body_insns(&nodrag, "rk4se", 1, 1), 4);
  assert_int_equal(body_insns(&nodrag, "rk4se", 0, 1), 4);
  /* no thrust: the four subtractions go, negations fold into consumers;
   * unfolded, -k1 - 2 k2 keeps -k1 as a value (a product with the host's
   * -h), as -(k1 + 2 k2) would differ in the sign of an exact zero */
  assert_int_equal(body_insns(&nothrust, "rk4se", 1, 1), 18);
  assert_int_equal(body_insns(&nothrust, "rk4se", 0, 1), 28);
  /* the same scenes keeping zero terms: as the general program */
  assert_int_equal(body_insns(&nodrag, "rk4se", 1, 0), 22);
  assert_int_equal(body_insns(&nothrust, "rk4se", 0, 0), 31);
  fp3_mscene_free(&all);
  fp3_mscene_free(&nodrag);
  fp3_mscene_free(&nothrust);
}

/* Folding and zero removal never cost instructions or estimated cycles,
 * for any integrator. */
static void test_folding_never_worse(void **state) {
  (void)state;
  for (int kind = 0; kind < 3; kind++) {
    fp3_mscene sc;
    scene(10 + (uint64_t)kind, 8, kind != 1, kind != 2, &sc);
    for (size_t i = 0; i < N_INTEG; i++) {
      fp3_compiled *lit = compile(&sc, integrators[i], 0, 0);
      fp3_compiled *fold = compile(&sc, integrators[i], 1, 1);
      const fp3_compile_stats *a = fp3_compiled_stats(lit), *b = fp3_compiled_stats(fold);
      assert_true(b->body_insns <= a->body_insns);
      assert_true(b->est_cycles_later <= a->est_cycles_later);
      assert_int_equal(a->literal_body_insns, a->body_insns);
      assert_int_equal(b->literal_body_insns, a->body_insns);
      fp3_compiled_free(lit);
      fp3_compiled_free(fold);
    }
    fp3_mscene_free(&sc);
  }
}

/* ---- dead code elimination ------------------------------------------------------- */

static void test_dce(void **state) {
  (void)state;
  fp3_mscene nodrag;
  scene(4, 4, 0, 1, &nodrag);
  /* rk4se builds the trial velocities y2_v .. y4_v; without drag no force
   * reads them: removed */
  fp3_compiled *c = compile(&nodrag, "rk4se", 1, 1);
  assert_true(fp3_compiled_stats(c)->dead_removed > 0);
  assert_null(strstr(fp3_compiled_text(c), "y2_v"));
  assert_null(strstr(fp3_compiled_text(c), "y4_v"));
  fp3_compiled_free(c);
  /* with drag they are read */
  fp3_mscene all;
  scene(5, 4, 1, 1, &all);
  c = compile(&all, "rk4se", 1, 1);
  assert_non_null(strstr(fp3_compiled_text(c), "y4_v"));
  fp3_compiled_free(c);
  fp3_mscene_free(&nodrag);
  fp3_mscene_free(&all);
}

/* ---- golden models ------------------------------------------------------------- */

/* The IR golden model of (fold, drop_zero) against the integrator's own,
 * object by object, `steps` integrations. */
static void expect_ir_is_integrator(const fp3_mscene *sc, const char *ig, int drop_zero,
                                    uint32_t steps) {
  fp3_compiled *c = compile(sc, ig, 0, drop_zero);
  const fp3_model *m = sc->model;
  for (size_t i = 0; i < sc->n; i++) {
    float y1[2 * FP3_MODEL_MAX_VARS], y2[2 * FP3_MODEL_MAX_VARS];
    gold_start(c, sc, i);
    memcpy(y2, obj_y0(sc, i), m->nstate * sizeof *y2);
    fp3_model_start_literal(m, ig, obj_in(sc, i), y2);
    for (uint32_t k = 1; k <= steps; k++) {
      fp3_compiled_model_step(c, y1);
      assert_int_equal(fp3_model_step_literal(m, ig, obj_in(sc, i), y2), 0);
      if (fpref_bits(y1[0]) != fpref_bits(y2[0]) || fpref_bits(y1[1]) != fpref_bits(y2[1]))
        fail_msg("%s, object %zu, integration %u: IR v %a s %a, integrator v %a s %a", ig, i,
                 k, (double)y1[0], (double)y1[1], (double)y2[0], (double)y2[1]);
    }
  }
  fp3_compiled_free(c);
}

static void test_literal_ir_is_integrator(void **state) {
  (void)state;
  fp3_mscene all, nodrag;
  scene(6, 12, 1, 1, &all);
  scene(7, 12, 0, 1, &nodrag);
  for (size_t i = 0; i < N_INTEG; i++) {
    expect_ir_is_integrator(&all, integrators[i], 0, 2000);
    expect_ir_is_integrator(&all, integrators[i], 1, 2000);
    /* the drag terms removed: the same values (T != -0, v finite) */
    expect_ir_is_integrator(&nodrag, integrators[i], 1, 2000);
  }
  fp3_mscene_free(&all);
  fp3_mscene_free(&nodrag);
}

/* fp3_compile_model_ir (the IR without a program, for the spatial back
 * end) has the same IR and the same golden model as fp3_compile_model,
 * and its accessors give a topological order whose operations read
 * nodes before them. */
static void test_ir_only(void **state) {
  (void)state;
  fp3_mscene sc;
  scene(8, 6, 1, 1, &sc);
  unsigned char zero[FP3_MODEL_MAX_VARS];
  fp3_mscene_zero(&sc, zero);
  for (size_t i = 0; i < N_INTEG; i++)
    for (int fold = 0; fold < 2; fold++) {
      fp3_compile_opts o;
      fp3_compile_defaults(&o);
      o.fold = o.drop_zero = fold;
      fp3_compiled *c = compile_opts(&sc, integrators[i], &o), *r = NULL;
      char msg[300];
      if (fp3_compile_model_ir(sc.model, integrators[i], &o, zero, &r, msg, sizeof msg))
        fail_msg("%s: %s", integrators[i], msg);
      assert_null(fp3_compiled_text(r));
      assert_int_equal(fp3_ir_nodes(r), fp3_ir_nodes(c));
      for (unsigned k = 0; k < fp3_ir_nodes(r); k++) {
        fp3_ir_node x, y;
        fp3_ir_node_get(r, k, &x);
        fp3_ir_node_get(c, k, &y);
        assert_int_equal(x.kind, y.kind);
        assert_int_equal(x.a, y.a);
        assert_int_equal(x.b, y.b);
        assert_int_equal(x.live, y.live);
        if (x.kind >= FP3_IR_ADD) {
          assert_true(x.a >= 0 && (unsigned)x.a < k);
          assert_true(x.b < (int)k);
        }
      }
      const unsigned nc = fp3_compiled_carried(c);
      assert_int_equal(fp3_compiled_carried(r), nc);
      for (unsigned w = 0; w < nc; w++)
        assert_int_equal(fp3_ir_carried_next(r, w), fp3_ir_carried_next(c, w));
      for (size_t obj = 0; obj < sc.n; obj++) {
        float yc[2 * FP3_MODEL_MAX_VARS] = {0}, yr[2 * FP3_MODEL_MAX_VARS] = {0};
        memcpy(yc, obj_y0(&sc, obj), sc.model->nstate * sizeof *yc);
        memcpy(yr, yc, sizeof yr);
        for (int step = 0; step < 50; step++) {
          float nc_[2 * FP3_MODEL_MAX_VARS], nr[2 * FP3_MODEL_MAX_VARS];
          fp3_compiled_model_step_from(c, obj_in(&sc, obj), yc, nc_);
          fp3_compiled_model_step_from(r, obj_in(&sc, obj), yr, nr);
          for (unsigned w = 0; w < nc; w++) {
            assert_int_equal(fpref_bits(nc_[w]), fpref_bits(nr[w]));
            yc[w] = nc_[w];
            yr[w] = nr[w];
          }
        }
      }
      fp3_compiled_free(c);
      fp3_compiled_free(r);
    }
  fp3_mscene_free(&sc);
}

/* A folded program is a different rounding sequence: it must differ from
 * the literal one somewhere (else the test above proves nothing about
 * folding), yet stay close. */
static void test_folded_differs(void **state) {
  (void)state;
  fp3_mscene sc;
  scene(8, 16, 1, 1, &sc);
  fp3_compiled *lit = compile(&sc, "rk4se", 0, 0), *fold = compile(&sc, "rk4se", 1, 1);
  int differ = 0;
  for (size_t i = 0; i < sc.n; i++) {
    float a[2 * FP3_MODEL_MAX_VARS], b[2 * FP3_MODEL_MAX_VARS];
    gold_start(lit, &sc, i);
    gold_start(fold, &sc, i);
    for (int k = 0; k < 500; k++) {
      fp3_compiled_model_step(lit, a);
      fp3_compiled_model_step(fold, b);
      differ |= fpref_bits(a[0]) != fpref_bits(b[0]);
    }
    assert_true(fabsf(a[0] - b[0]) <= 1e-4f * (1.0f + fabsf(a[0])));
  }
  assert_true(differ);
  fp3_compiled_free(lit);
  fp3_compiled_free(fold);
  fp3_mscene_free(&sc);
}

/* ---- engines --------------------------------------------------------------------- */

static void run_on(fp3_engine *e, fp3_compiled *c, const fp3_mscene *sc, uint32_t steps,
                   fp3_state_result *res) {
  fp3_scene_gold g;
  fp3_scene_gold_init(&g, c, sc);
  const fp3_image *img = fp3_compiled_image(c);
  char msg[300];
  if (fp3_run_state_objects(e, img->words, img->n, sc->n, steps, FPREF_IEEE, &g.golden, res, msg,
                            sizeof msg))
    fail_msg("%s", msg);
  if (res->mismatches)
    fail_msg("%s: %llu mismatches, first object %zu integration %u", e->ops->name,
             (unsigned long long)res->mismatches, res->first_object, res->first_step);
  assert_int_equal(res->error, FP3_ERR_NONE);
}

static void test_ir_equals_iss(void **state) {
  (void)state;
  fp3_engine *iss = fp3_engine_iss_new();
  assert_non_null(iss);
  for (int kind = 0; kind < 4; kind++) { /* all, no drag, no thrust, neither */
    fp3_mscene sc;
    scene(20 + (uint64_t)kind, 10, kind != 1 && kind != 3, kind != 2 && kind != 3, &sc);
    for (size_t i = 0; i < N_INTEG; i++)
      for (int opt = 0; opt < 3; opt++) {
        fp3_compiled *c = compile(&sc, integrators[i], opt != 0, opt == 2);
        fp3_state_result res;
        run_on(iss, c, &sc, 1000, &res);
        fp3_state_result_free(&res);
        fp3_compiled_free(c);
      }
    fp3_mscene_free(&sc);
  }
  fp3_engine_free(iss);
}

#define ENDIS 8 /* integrations measured by endi_cycles */

/* One context running img on e for ENDIS integrations (cycles do not
 * depend on the register values): *first, cycles from START to the end of
 * the first integration (the cycle after its endi's issue, as fp3 run
 * counts it); *later, from the last endi but one to the last. */
static void endi_cycles(fp3_engine *e, const fp3_image *img, unsigned *first, unsigned *later) {
  assert_int_equal(fp3_engine_endi_cycles(e, img->words, img->n, ENDIS, first, later), 0);
}

/* On the RTL, compiled for the engine's own latencies and pipeline
 * (fp3_config.fmax_pipe): bit-exact, and one object's cycles of the first
 * and per later integration are the scheduler's estimates, for every
 * integrator, folded or not. */
static void expect_compiled_exact(fp3_engine *rtl) {
  fp3_mscene sc, one;
  scene(30, 12, 1, 1, &sc);
  scene(31, 1, 1, 1, &one);
  for (size_t i = 0; i < N_INTEG; i++)
    for (int fold = 0; fold < 2; fold++) {
      fp3_compile_opts o;
      fp3_compile_defaults(&o);
      o.fold = o.drop_zero = fold;
      o.add_latency = rtl->config.add_latency;
      o.mul_latency = rtl->config.mul_latency;
      o.div_latency = rtl->config.div_latency;
      o.fmax_pipe = rtl->config.fmax_pipe;
      fp3_compiled *c = compile_opts(&sc, integrators[i], &o);
      fp3_state_result res, r1, r2;
      run_on(rtl, c, &sc, 300, &res);
      run_on(rtl, c, &one, 20, &r1);
      run_on(rtl, c, &one, 40, &r2);
      assert_int_equal((r2.cycles - r1.cycles) / 20, fp3_compiled_stats(c)->est_cycles_later);
      assert_int_equal((r2.cycles - r1.cycles) % 20, 0);
      unsigned first, later;
      endi_cycles(rtl, fp3_compiled_image(c), &first, &later);
      assert_int_equal(first, fp3_compiled_stats(c)->est_cycles_first);
      fp3_state_result_free(&res);
      fp3_state_result_free(&r1);
      fp3_state_result_free(&r2);
      fp3_compiled_free(c);
    }
  fp3_mscene_free(&sc);
  fp3_mscene_free(&one);
}

/* Moves, which compiled bodies lack, estimated exactly: dependence chains
 * through multiplies and a mov closing the loop (the first: its waits
 * fill the queue, which then limits the fetch; the second: two moves on
 * the chain, which the move path's latency decides); and the div/sqrt
 * unit (the third: a chain through a div and a sqrt, DIV_LATENCY each,
 * beside an independent sqrt on the same write-back port). */
static void expect_moves_exact(fp3_engine *rtl) {
  static const char *const progs[] = {
      "li r4, 1.0\nbody:\nmul r1, r2, r4\nmul r6, r1, r4\nmul r7, r6, r4\nmov r2, r7\n"
      "endi body\n",
      "li r4, 1.0\nli r2, 2.0\nbody:\nmul r1, r2, r4\nmov r5, r1\nmul r6, r5, r4\n"
      "mov r2, r6\nendi body\n",
      "li r4, 2.0\nli r2, 3.0\nbody:\ndiv r1, r2, r4\nsqrt r3, r4\nsqrt r6, r1\nmul r7, r6, r4\n"
      "mov r2, r7\nendi body\n",
  };
  fp3_compile_opts o;
  fp3_compile_defaults(&o);
  o.add_latency = rtl->config.add_latency;
  o.mul_latency = rtl->config.mul_latency;
  o.div_latency = rtl->config.div_latency;
  o.fmax_pipe = rtl->config.fmax_pipe;
  assert_true(rtl->config.has_div && rtl->config.has_sqrt);
  for (size_t i = 0; i < sizeof progs / sizeof progs[0]; i++) {
    fp3_image img;
    char *errs = NULL;
    if (fp3_asm_string(progs[i], "moves.s", &img, &errs)) fail_msg("%s", errs);
    free(errs);
    unsigned first, later, est_first, est_later;
    endi_cycles(rtl, &img, &first, &later);
    assert_int_equal(fp3_estimate_cycles(&img, &o, ENDIS, &est_first, &est_later), 0);
    assert_int_equal(first, est_first);
    assert_int_equal(later, est_later);
  }
}

/* Both on an RTL engine of build `fmax_pipe` (freed here). */
static void expect_estimates_exact(fp3_engine *rtl, unsigned fmax_pipe) {
  assert_non_null(rtl);
  assert_int_equal(rtl->config.fmax_pipe, fmax_pipe);
  expect_compiled_exact(rtl);
  expect_moves_exact(rtl);
  fp3_engine_free(rtl);
}

static void test_rtl(void **state) {
  (void)state;
  expect_estimates_exact(fp3_engine_rtl_new(NULL), 0);
}

/* The same on the build for clock rate (FMAX_PIPE): its 3-cycle move path,
 * fetch spacing, pick stages and registered issue stages, with latencies
 * below FP3_FMAX_PIPE_FULL_LEAD_LATENCY (the 3-context test model: add 4,
 * mul 3) and above it (the 8-context build of docs/fpga.md: add 9,
 * mul 10). */
static void test_rtl_fmax_pipe(void **state) {
  (void)state;
  expect_estimates_exact(fp3_engine_rtl_new_model(&fp3_model_nc3, NULL), 1);
  expect_estimates_exact(fp3_engine_rtl_new_model(&fp3_model_fmax, NULL), 1);
}

/* ---- inputs, text, errors -------------------------------------------------------- */

/* The affine fold's coefficients are the host's binary32 products
 * (h minv) T and (h minv) C, written with v0 and s0 before the run; minv
 * itself is folded away. */
static void test_folded_inputs(void **state) {
  (void)state;
  fp3_mscene sc;
  scene(40, 50, 1, 1, &sc);
  fp3_compiled *c = compile(&sc, "rk4se", 1, 1);
  const fp3_model *m = sc.model;
  const int iT = fp3_model_param(m, "T"), iC = fp3_model_param(m, "C"), im = fp3_model_param(m, "m");
  for (size_t i = 0; i < sc.n; i++) {
    const float *in = obj_in(&sc, i), *y0 = obj_y0(&sc, i);
    volatile float minv = 1.0f / in[im];
    volatile float hm = in[0] * minv;
    volatile float hmT = hm * in[iT], hmC = hm * in[iC];
    unsigned reg[64];
    uint32_t val[64];
    size_t nw = fp3_compiled_model_start(c, in, y0, reg, val, 64);
    int seen_T = 0, seen_C = 0, seen_v0 = 0, seen_minv = 0;
    for (size_t w = 0; w < nw; w++) {
      seen_T |= val[w] == fpref_bits(hmT);
      seen_C |= val[w] == fpref_bits(hmC);
      seen_v0 |= val[w] == fpref_bits(y0[0]);
      seen_minv |= val[w] == fpref_bits(minv) && minv != hmT && minv != hmC && minv != in[0];
    }
    assert_true(seen_T && seen_C && seen_v0);
    assert_false(seen_minv);
  }
  fp3_compiled_free(c);
  fp3_mscene_free(&sc);
}

static void test_text_assembles(void **state) {
  (void)state;
  fp3_mscene sc;
  scene(41, 3, 1, 1, &sc);
  for (size_t i = 0; i < N_INTEG; i++) {
    fp3_compiled *c = compile(&sc, integrators[i], 1, 1);
    fp3_image img;
    char *errs = NULL;
    assert_int_equal(fp3_asm_string(fp3_compiled_text(c), "t.s", &img, &errs), 0);
    free(errs);
    const fp3_image *ci = fp3_compiled_image(c);
    assert_int_equal(img.n, ci->n);
    assert_memory_equal(img.words, ci->words, img.n * sizeof img.words[0]);
    char msg[200];
    assert_int_equal(fp3_image_validate(&img, msg, sizeof msg), 0);
    assert_non_null(strstr(fp3_compiled_text(c), "instructions per integration"));
    fp3_compiled_free(c);
  }
  fp3_mscene_free(&sc);
}

static void test_errors(void **state) {
  (void)state;
  fp3_mscene sc;
  scene(42, 3, 1, 1, &sc);
  fp3_compile_opts o;
  fp3_compile_defaults(&o);
  fp3_compiled *c = NULL;
  char msg[300];
  const fp3_model *m = sc.model;
  assert_int_equal(fp3_compile_model(m, "leapfrog", &o, NULL, &c, msg, sizeof msg), -1);
  assert_null(c);
  assert_non_null(strstr(msg, "unknown integrator 'leapfrog'"));
  /* the ship's drag reads its velocity: no kick-drift-kick verlet */
  assert_int_equal(fp3_compile_model(m, "verlet", &o, NULL, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "verlet needs accelerations that do not read velocities"));
  o.num_regs = 8; /* rk4se needs more */
  assert_int_equal(fp3_compile_model(m, "rk4se", &o, NULL, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "registers"));
  fp3_compile_defaults(&o);
  o.fmax_pipe = 2;
  assert_int_equal(fp3_compile_model(m, "rk4se", &o, NULL, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "fmax_pipe 0 or 1"));
  o.fmax_pipe = 1;
  o.mul_latency = FP3_FMAX_PIPE_PICK_STAGES; /* the RTL refuses to elaborate it */
  assert_int_equal(fp3_compile_model(m, "rk4se", &o, NULL, &c, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "FMAX_PIPE needs"));
  fp3_mscene_free(&sc);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_counts_rk4),
      cmocka_unit_test(test_folding_never_worse),
      cmocka_unit_test(test_dce),
      cmocka_unit_test(test_literal_ir_is_integrator),
      cmocka_unit_test(test_folded_differs),
      cmocka_unit_test(test_ir_only),
      cmocka_unit_test(test_folded_inputs),
      cmocka_unit_test(test_text_assembles),
      cmocka_unit_test(test_errors),
      cmocka_unit_test(test_ir_equals_iss),
      cmocka_unit_test(test_rtl),
      cmocka_unit_test(test_rtl_fmax_pipe),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
