/*
 * test_engines.c -- the Verilated RTL against the instruction-set simulator
 * and the golden model, bit for bit.
 *
 *  - every program in programs/ on RTL and ISS, several parameter sets:
 *    per-register write-back sequences (values and integration tags),
 *    final registers, status and flags equal; the ship's v and s after
 *    every integration equal the golden model's;
 *  - hazards: dependent chains, WAW, move bypass, the div/sqrt unit, with
 *    exact stall counts derived from the model's latencies;
 *  - random hazard-dense programs (every unit the build has, div and sqrt
 *    included) and random instruction words (errors);
 *  - a program with an instruction of a unit the build lacks (div, sqrt
 *    on a build without HAS_DIV, HAS_SQRT) refused naming the parameter.
 */
#include <errno.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>
#ifdef FP3_MPI
#include <mpi.h>
#endif

#include "asm.h"
#include "engine.h"
#include "fp3_isa.h"
#include "fpenv.h"
#include "fpref.h"
#include "compile.h"
#include "mscene.h"
#include "objects.h"
#include "image.h"
#include "model.h"
#include "../sim/fp3_model.h"

/* Test builds of the processor with 1 and 3 contexts (mk/rtl.mk). */
extern const fp3_model_ops fp3_model_nc1, fp3_model_nc3, fp3_model_fmax, fp3_model_l4,
    fp3_model_lf, fp3_model_drift;

#define MAX_REGS 256

/* ---- capture of one run ---------------------------------------------------- */

typedef struct wseq {
  uint32_t *value;
  uint32_t *integ;
  size_t n, cap;
} wseq;

typedef struct capture {
  wseq reg[MAX_REGS];
  uint64_t *endi_cycle;
  size_t endis, endi_cap;
  fp3_status st;
  uint32_t final[MAX_REGS];
} capture;

static void on_write(void *ctx, unsigned reg, uint32_t value, uint32_t integ) {
  capture *c = ctx;
  assert_true(reg < MAX_REGS);
  wseq *s = &c->reg[reg];
  if (s->n == s->cap) {
    s->cap = s->cap ? 2 * s->cap : 64;
    s->value = realloc(s->value, s->cap * sizeof *s->value);
    s->integ = realloc(s->integ, s->cap * sizeof *s->integ);
    assert_non_null(s->value);
    assert_non_null(s->integ);
  }
  s->value[s->n] = value;
  s->integ[s->n] = integ;
  s->n++;
}

static void on_endi(void *ctx, uint32_t integ, uint64_t cycle) {
  capture *c = ctx;
  assert_int_equal(integ, c->endis + 1);
  if (c->endis == c->endi_cap) {
    c->endi_cap = c->endi_cap ? 2 * c->endi_cap : 64;
    c->endi_cycle = realloc(c->endi_cycle, c->endi_cap * sizeof *c->endi_cycle);
    assert_non_null(c->endi_cycle);
  }
  c->endi_cycle[c->endis++] = cycle;
}

static void capture_free(capture *c) {
  for (int r = 0; r < MAX_REGS; r++) {
    free(c->reg[r].value);
    free(c->reg[r].integ);
  }
  free(c->endi_cycle);
  memset(c, 0, sizeof *c);
}

/* The four FP core configurations: RNE, RTZ, RNE+FTZ, RTZ+FTZ. */
static const fpref_mode all_modes[4] = {
    {FPREF_RNE, 0}, {FPREF_RTZ, 0}, {FPREF_RNE, 1}, {FPREF_RTZ, 1}};

/* Engines are created once: building the RTL model's state is cheap, but
 * one per test keeps the output short. */
static fp3_engine *rtl, *iss;

static void run_on(fp3_engine *e, const fp3_image *img, const uint32_t *init, unsigned ninit,
                   uint32_t steps, capture *c) {
  memset(c, 0, sizeof *c);
  if (fp3_engine_load(e, img->words, img->n) != 0) fail_msg("%s", fp3_engine_error(e));
  for (unsigned r = 0; r < e->config.num_regs; r++) {
    assert_int_equal(fp3_engine_write_reg(e, r, r < ninit ? init[r] : 0), 0);
  }
  fp3_observer obs = {.ctx = c, .on_write = on_write, .on_endi = on_endi};
  if (fp3_engine_run(e, steps, &obs, &c->st) != 0) fail_msg("%s", fp3_engine_error(e));
  for (unsigned r = 0; r < e->config.num_regs; r++) {
    assert_int_equal(fp3_engine_read_reg(e, r, &c->final[r]), 0);
  }
}

/* RTL and ISS agree on everything architectural. */
static void compare_captures(const capture *a, const capture *b, const char *what) {
  assert_int_equal(a->st.error, b->st.error);
  assert_int_equal(a->st.fault_pc, b->st.fault_pc);
  assert_int_equal(a->st.steps_done, b->st.steps_done);
  assert_int_equal(a->st.flags, b->st.flags);
  assert_int_equal(a->st.issued, b->st.issued);
  assert_int_equal(a->endis, b->endis);
  for (int r = 0; r < MAX_REGS; r++) {
    const wseq *x = &a->reg[r], *y = &b->reg[r];
    if (x->n != y->n) fail_msg("%s: r%d written %zu times on RTL, %zu on ISS", what, r, x->n, y->n);
    for (size_t i = 0; i < x->n; i++) {
      if (x->value[i] != y->value[i] || x->integ[i] != y->integ[i]) {
        fail_msg("%s: r%d write %zu: RTL 0x%08X (integration %u), ISS 0x%08X (integration %u)",
                 what, r, i, x->value[i], x->integ[i], y->value[i], y->integ[i]);
      }
    }
    if (a->final[r] != b->final[r]) {
      fail_msg("%s: final r%d RTL 0x%08X ISS 0x%08X", what, r, a->final[r], b->final[r]);
    }
  }
}

static void assemble(const char *src, fp3_image *img) {
  char *errors = NULL;
  fp3_image_init(img);
  if (fp3_asm_string(src, "test.s", img, &errors) != 0) {
    fprintf(stderr, "%s", errors ? errors : "");
    free(errors);
    fail_msg("assembly failed");
  }
}

/* ---- the ship programs against the golden model ---------------------------- */

typedef struct ship_case {
  const char *name;
  float T, C, m, h, v0, s0;
} ship_case;

static const ship_case ship_cases[] = {
    {"patrol boat", 50000.0f, 5000.0f, 10000.0f, 1.0f / 60.0f, 0.0f, 0.0f},
    {"no drag", 2000.0f, 0.0f, 1000.0f, 0.01f, 1.0f, -5.0f},
    {"tanker", 2.0e6f, 1.0e5f, 3.0e8f, 0.5f, 3.0f, 1000.0f},
    {"dinghy reversing", -30.0f, 12.0f, 0.75f, 0.02f, 4.0f, 0.0f},
    {"coasting, no thrust", 0.0f, 300.0f, 5000.0f, 0.1f, 12.5f, 100.0f},
    {"coarse step near the RK4 bound", 1000.0f, 100.0f, 100.0f, 2.5f, 0.0f, 0.0f},
    /* Velocities and forces in the subnormal range: FTZ changes them. */
    {"drifting in the subnormals", 3.0e-39f, 0.5f, 1.0f, 0.25f, 1.0e-37f, 0.0f},
};

/* A ship program (programs/ship_*.s) bound by name to models/ship.fp3m:
 * its golden model is the literal one of its `.integrator`. */
typedef struct ship_prog {
  fp3_compiled *c;
  int vreg, sreg; /* the registers of v and s */
} ship_prog;

static void ship_bind(const fp3_image *img, const char *path, const fp3_engine *e,
                      ship_prog *sp) {
  static fp3_model m;
  static int loaded;
  char msg[300];
  if (!loaded && fp3_model_load("models/ship.fp3m", &m, msg, sizeof msg)) fail_msg("%s", msg);
  loaded = 1;
  fp3_compile_opts o;
  fp3_compile_opts_for(&o, &e->config);
  if (fp3_compile_bind(&m, img, path, &o, &sp->c, msg, sizeof msg)) fail_msg("%s", msg);
  sp->vreg = (int)fp3_compiled_state_reg(sp->c, 0);
  sp->sreg = (int)fp3_compiled_state_reg(sp->c, 1);
}

/* The registers the host writes for ship case sc (v0 raised by dv) into
 * init[] (the others left alone), computed in core options `mode`, and
 * the golden model started on it. */
static void ship_init(ship_prog *sp, const ship_case *sc, float dv, fpref_mode mode,
                      uint32_t *init) {
  const float in[4] = {sc->h, sc->T, sc->C, sc->m}, y0[2] = {sc->v0 + dv, sc->s0};
  unsigned reg[16];
  uint32_t val[16];
  fpenv_saved env;
  assert_int_equal(fpenv_enter(mode, &env), 0);
  const size_t nw = fp3_compiled_model_start(sp->c, in, y0, reg, val, 16);
  fpenv_leave(&env);
  for (size_t w = 0; w < nw; w++) init[reg[w]] = val[w];
}

/* One golden integration in core options `mode`: v and s (bits). */
static void ship_step(ship_prog *sp, fpref_mode mode, uint32_t *v, uint32_t *s) {
  float y[2 * FP3_MODEL_MAX_VARS];
  fpenv_saved env;
  assert_int_equal(fpenv_enter(mode, &env), 0);
  fp3_compiled_model_step(sp->c, y);
  fpenv_leave(&env);
  *v = fpref_bits(y[0]);
  *s = fpref_bits(y[1]);
}

/* Value of register `reg` after integration k (1-based): the last write
 * tagged with an integration <= k, or the initial value. */
static uint32_t value_after(const wseq *s, uint32_t init, uint32_t k, size_t *pos) {
  uint32_t v = *pos ? s->value[*pos - 1] : init;
  while (*pos < s->n && s->integ[*pos] <= k) v = s->value[(*pos)++];
  return v;
}

/* Run the ship program on RTL and ISS of one core configuration for every
 * case, `steps` integrations, compare them and the golden model (run in
 * that configuration); finals[k] gets the final v of case k. */
static void check_ship_program(const char *path, fp3_engine *er, fp3_engine *ei,
                               uint32_t steps, uint32_t *finals) {
  fp3_image img;
  char *errors = NULL;
  fp3_image_init(&img);
  if (fp3_asm_file(path, &img, &errors) != 0) {
    fprintf(stderr, "%s", errors ? errors : "");
    free(errors);
    fail_msg("%s does not assemble", path);
  }
  ship_prog sp;
  ship_bind(&img, path, er, &sp);
  for (size_t k = 0; k < sizeof ship_cases / sizeof ship_cases[0]; k++) {
    const ship_case *sc = &ship_cases[k];
    uint32_t init[MAX_REGS] = {0};
    ship_init(&sp, sc, 0.0f, er->config.mode, init);
    capture a, b;
    run_on(er, &img, init, MAX_REGS, steps, &a);
    run_on(ei, &img, init, MAX_REGS, steps, &b);
    assert_int_equal(a.st.error, FP3_ERR_NONE);
    assert_int_equal(a.st.steps_done, steps);
    compare_captures(&a, &b, sc->name);

    /* Golden model, every integration. */
    const int vreg = sp.vreg, sreg = sp.sreg;
    size_t vpos = 0, spos = 0;
    for (uint32_t i = 1; i <= steps; i++) {
      uint32_t gv, gs;
      ship_step(&sp, er->config.mode, &gv, &gs);
      uint32_t v = value_after(&a.reg[vreg], init[vreg], i, &vpos);
      uint32_t s = value_after(&a.reg[sreg], init[sreg], i, &spos);
      if (v != gv || s != gs) {
        fail_msg("%s, %s: integration %u: RTL v=0x%08X s=0x%08X, golden v=0x%08X s=0x%08X", path,
                 sc->name, i, v, s, gv, gs);
      }
    }
    finals[k] = a.final[vreg];
    capture_free(&a);
    capture_free(&b);
  }
  fp3_compiled_free(sp.c);
}

#define NCASES (sizeof ship_cases / sizeof ship_cases[0])

static void test_ship_rk4(void **state) {
  (void)state;
  uint32_t finals[NCASES];
  check_ship_program("programs/ship_rk4.s", rtl, iss, 300, finals);
}

/* Sleeping (programs/ship_rk4_sleep.s): bit-identical to the paper's RK4
 * in every integration of long runs, in which the ships settle. */
static void test_ship_rk4_sleep(void **state) {
  (void)state;
  uint32_t finals[NCASES];
  check_ship_program("programs/ship_rk4_sleep.s", rtl, iss, 4000, finals);
}

/* An object at rest sleeps from its second integration: 4 instructions
 * (beq, mul, add, endi) instead of 33, each costing exact cycles; a woken
 * one (vp = -v0 after its thrust changed) runs every stage again. */
static void test_sleep_at_rest(void **state) {
  (void)state;
  fp3_image img;
  char *errors = NULL;
  fp3_image_init(&img);
  assert_int_equal(fp3_asm_file("programs/ship_rk4_sleep.s", &img, &errors), 0);
  size_t body = 0, awake = 0;
  while (fp3_insn_opc(img.words[body]) == FP3_OP_LI) body++;
  awake = img.n - body;
  const uint32_t steps = 40;
  ship_case p = {"at rest", 0.0f, 5000.0f, 10000.0f, 1.0f / 60.0f, 0.0f, 42.0f};
  ship_prog sp;
  ship_bind(&img, "programs/ship_rk4_sleep.s", rtl, &sp);
  for (int woken = 0; woken < 2; woken++) {
    uint32_t init[MAX_REGS] = {0};
    ship_init(&sp, &p, 0.0f, rtl->config.mode, init);
    capture a, b;
    run_on(rtl, &img, init, MAX_REGS, steps, &a);
    run_on(iss, &img, init, MAX_REGS, steps, &b);
    compare_captures(&a, &b, woken ? "woken" : "at rest");
    if (!woken) {
      assert_int_equal(a.st.issued, body + awake + 4 * (steps - 1));
      /* Asleep: beq, then mul h v (FP3_BEQ_CYCLES later), add s (after
       * the product), endi (the issue spacing), the next beq (likewise). */
      uint64_t per = a.endi_cycle[steps - 1] - a.endi_cycle[steps - 2];
      assert_int_equal(per, FP3_BEQ_CYCLES + FP3_READ_CYCLES + rtl->config.mul_latency +
                                2 * FP3_ISSUE_SPACING);
      assert_int_equal(a.final[sp.sreg], fpref_bits(42.0f));
      p.T = 5000.0f; /* wake it */
    } else {
      assert_true(a.st.issued > body + awake * (steps - 1)); /* not asleep within 40 */
      assert_true(a.final[sp.vreg] != 0);
    }
    capture_free(&a);
    capture_free(&b);
  }
  fp3_compiled_free(sp.c);
}

/* Every FP core configuration (the RTL built with ROUND/FTZ, the ISS and
 * the golden model in that mode) is bit-exact, and the configurations
 * really differ: a model of the wrong configuration would be caught. */
static void test_ship_rk4_core_configs(void **state) {
  (void)state;
  const fpref_mode *modes = all_modes;
  uint32_t finals[4][NCASES];
  for (int m = 0; m < 4; m++) {
    fp3_engine *er = fp3_engine_rtl_new_mode(modes[m], NULL);
    fp3_engine *ei = fp3_engine_iss_new_mode(modes[m]);
    assert_non_null(er);
    assert_non_null(ei);
    assert_int_equal(er->config.mode.round, modes[m].round);
    assert_int_equal(er->config.mode.ftz, modes[m].ftz);
    check_ship_program("programs/ship_rk4.s", er, ei, 300, finals[m]);
    fp3_engine_free(er);
    fp3_engine_free(ei);
  }
  /* RTZ changes the patrol boat; FTZ changes the subnormal drift. */
  assert_int_not_equal(finals[0][0], finals[1][0]);
  assert_int_not_equal(finals[0][NCASES - 1], finals[2][NCASES - 1]);
  assert_int_not_equal(finals[1][NCASES - 1], finals[3][NCASES - 1]);
}

/* The paper's figure of merit: cycles per integration after the first. */
static void test_ship_rk4_cycles(void **state) {
  (void)state;
  fp3_image img;
  char *errors = NULL;
  fp3_image_init(&img);
  assert_int_equal(fp3_asm_file("programs/ship_rk4.s", &img, &errors), 0);
  capture a;
  uint32_t init[MAX_REGS] = {0};
  run_on(rtl, &img, init, MAX_REGS, 50, &a);
  assert_int_equal(a.endis, 50);
  uint64_t per = a.endi_cycle[1] - a.endi_cycle[0];
  for (size_t i = 2; i < a.endis; i++) {
    /* Every later integration costs the same: the schedule is periodic. */
    assert_int_equal(a.endi_cycle[i] - a.endi_cycle[i - 1], per);
  }
  print_message("ship_rk4: first integration %llu cycles, then %llu per integration\n",
                (unsigned long long)(a.endi_cycle[0] + 1), (unsigned long long)per);
  assert_true(per <= 130); /* issue #2 target; the paper: 418 */
  capture_free(&a);
}

/* A harbour of the ship model frame by frame (mscene.h
 * fp3_run_state_frames): awake, sleeping in the program, and sleeping
 * with the host skipping objects at rest, with a wake (thrust T = 4 C for
 * 3 moored ships); every object equals the golden model of the program's
 * .integrator (or of integ, when not NULL: a wrong one) after every
 * frame in each. */
static void run_harbour_on(fp3_engine *e, const char *program, const char *integ,
                           int rest_skip, uint32_t wake_frame, fp3_state_frames_result *res) {
  fp3_image img;
  char *errors = NULL, msg[512];
  fp3_image_init(&img);
  assert_int_equal(fp3_asm_file(program, &img, &errors), 0);
  if (integ) snprintf(img.integrator, sizeof img.integrator, "%s", integ);
  fp3_scene ships;
  fp3_mscene sc;
  assert_int_equal(fp3_scene_harbour(7, 48, 1.0f / 60.0f, &ships), 0);
  if (fp3_mscene_from_ships(&ships, img.model, "harbour", &sc, msg, sizeof msg))
    fail_msg("%s", msg);
  fp3_scene_free(&ships);
  fp3_compile_opts o;
  fp3_compile_opts_for(&o, &e->config);
  fp3_compiled *c = NULL;
  if (fp3_compile_bind(sc.model, &img, program, &o, &c, msg, sizeof msg)) fail_msg("%s", msg);
  fp3_scene_gold g;
  fp3_scene_gold_init(&g, c, &sc);
  fp3_scene_waker w;
  if (wake_frame &&
      fp3_scene_waker_init(&w, c, &sc, wake_frame, 3, "T", 4.0f, "C", msg, sizeof msg))
    fail_msg("%s", msg);
  if (fp3_run_state_frames(e, img.words, img.n, sc.n, 40, rest_skip, wake_frame ? &w.wake : NULL,
                           e->config.mode, &g.stepper, res, msg, sizeof msg))
    fail_msg("%s", msg);
  fp3_compiled_free(c);
  fp3_mscene_free(&sc);
  assert_int_equal(res->error, FP3_ERR_NONE);
  assert_int_equal(res->object_frames + res->skipped, 48 * 40);
}

static void run_harbour(const char *program, const char *integ, int rest_skip,
                        uint32_t wake_frame, fp3_state_frames_result *res) {
  run_harbour_on(rtl, program, integ, rest_skip, wake_frame, res);
}

/* fp3 frames on the lanes build (8 contexts x 4 lanes): the awake
 * objects packed into 32 slots a batch; the sleeping program's beq is
 * taken only where every lane of a context sleeps, and every object stays
 * bit-exact with its golden model in every frame either way. */
static void test_frames_lanes(void **state) {
  (void)state;
  fp3_engine *e = fp3_engine_rtl_new_model(&fp3_model_l4, NULL);
  assert_non_null(e);
  fp3_state_frames_result awake, beq, rest;
  run_harbour_on(e, "programs/ship_rk4.s", NULL, 0, 0, &awake);
  run_harbour_on(e, "programs/ship_rk4_sleep.s", NULL, 0, 0, &beq);
  run_harbour_on(e, "programs/ship_rk4_sleep.s", NULL, 1, 0, &rest);
  assert_int_equal(awake.lanes, 4);
  assert_int_equal(awake.contexts, 8);
  assert_int_equal(awake.mismatches, 0);
  assert_int_equal(beq.mismatches, 0);
  assert_int_equal(rest.mismatches, 0);
  assert_int_equal(awake.batches, 2 * 40);   /* 48 objects in slots of 32 */
  assert_true(rest.issued < awake.issued && rest.skipped > 0);
  print_message("harbour of 48 on 8 x 4 lanes, 40 frames: %.1f, %.1f, %.1f cycles per frame "
                "(awake, beq, beq + rest)\n", awake.cycles / 40.0, beq.cycles / 40.0,
                rest.cycles / 40.0);
  fp3_engine_free(e);
}

static void test_frames_sleeping(void **state) {
  (void)state;
  fp3_state_frames_result awake, beq, rest, woken, wrong;
  run_harbour("programs/ship_rk4.s", NULL, 0, 0, &awake);
  run_harbour("programs/ship_rk4_sleep.s", NULL, 0, 0, &beq);
  run_harbour("programs/ship_rk4_sleep.s", NULL, 1, 0, &rest);
  run_harbour("programs/ship_rk4_sleep.s", NULL, 1, 20, &woken);
  assert_int_equal(awake.mismatches, 0);
  assert_int_equal(beq.mismatches, 0);
  assert_int_equal(rest.mismatches, 0);
  assert_int_equal(woken.mismatches, 0);
  /* each kind of sleeping saves issue cycles; the moored ships rest */
  assert_int_equal(awake.skipped, 0);
  assert_true(beq.issued < awake.issued / 2);
  assert_true(rest.issued < beq.issued && rest.skipped > 0);
  assert_true(rest.asleep_last >= 48 / 3);
  assert_int_equal(woken.woken, 3);
  assert_int_equal(woken.asleep_last, rest.asleep_last - 3); /* still accelerating */
  print_message("harbour of 48, 40 frames: %.1f, %.1f, %.1f cycles per frame (awake, beq, "
                "beq + rest)\n", awake.cycles / 40.0, beq.cycles / 40.0, rest.cycles / 40.0);
  /* the check can fail: another integrator's golden model differs */
  run_harbour("programs/ship_rk4_sleep.s", "rk2", 1, 0, &wrong);
  assert_true(wrong.mismatches > 0);
}

/* ---- hazards with exact cycle accounting ---------------------------------- */

/* src on the RTL engine e (a) and on the ISS (b), which must agree. */
static void run_both_on(fp3_engine *e, const char *src, uint32_t steps, capture *a, capture *b) {
  fp3_image img;
  assemble(src, &img);
  uint32_t init[8];
  for (unsigned r = 0; r < 8; r++) init[r] = fpref_bits(1.0f + 0.25f * (float)r);
  run_on(e, &img, init, 8, steps, a);
  run_on(iss, &img, init, 8, steps, b);
  compare_captures(a, b, src);
}

static void run_both(const char *src, uint32_t steps, capture *a, capture *b) {
  run_both_on(rtl, src, steps, a, b);
}

/* Stall cycles of a run on one context, beside its hazards: the cycle in
 * which the first instruction's readiness is decided, and the issue
 * spacing before an independent instruction (FP3_ISSUE_SPACING). */
#define START_STALLS 1
#define SPACING_STALLS (FP3_ISSUE_SPACING - 1)

static void test_dependent_add_chain(void **state) {
  (void)state;
  capture a, b;
  run_both("add r1, r1, r2\nadd r1, r1, r2\nadd r1, r1, r2\nadd r1, r1, r2\n"
           "add r1, r1, r2\nadd r1, r1, r2\nhalt\n", 1, &a, &b);
  /* Each dependent add waits until the previous result is on the bypass:
   * the read stage plus the core's latency after its producer issued. */
  assert_int_equal(a.st.stalls, START_STALLS + 5 * (FP3_READ_CYCLES + rtl->config.add_latency - 1) +
                                    SPACING_STALLS /* halt */);
  assert_int_equal(a.st.issued, 7);
  assert_int_equal(a.final[1], fpref_bits(1.25f + 6 * 1.5f));
  capture_free(&a);
  capture_free(&b);
}

static void test_dependent_mul_chain(void **state) {
  (void)state;
  capture a, b;
  run_both("mul r3, r3, r2\nmul r3, r3, r2\nmul r3, r3, r2\nmul r3, r3, r2\nhalt\n", 1, &a, &b);
  assert_int_equal(a.st.stalls, START_STALLS + 3 * (FP3_READ_CYCLES + rtl->config.mul_latency - 1) +
                                    SPACING_STALLS);
  capture_free(&a);
  capture_free(&b);
}

static void test_independent_ops_spacing(void **state) {
  (void)state;
  capture a, b;
  run_both("mul r1, r2, r3\nadd r4, r2, r3\nsub r5, r2, r3\nmul r6, r2, r3\n"
           "li r7, 0.5\nmov r0, r2\nmov r1, r7\nhalt\n", 1, &a, &b);
  /* One issue every FP3_ISSUE_SPACING cycles: mov r1, r7 issues in cycle
   * 6 * spacing, when r7 (li) is on the bypass; only r1 may still be busy:
   * WAW on the first mul. */
  unsigned lm = FP3_READ_CYCLES + rtl->config.mul_latency;
  unsigned at = 6 * FP3_ISSUE_SPACING;
  assert_int_equal(a.st.stalls, START_STALLS + 7 * SPACING_STALLS + (lm > at ? lm - at : 0));
  assert_int_equal(a.final[1], fpref_bits(0.5f));
  capture_free(&a);
  capture_free(&b);
}

static void test_waw_same_register(void **state) {
  (void)state;
  capture a, b;
  /* The later li must land after the earlier mul: WAW stall until the
   * mul's result is on its write-back port. */
  run_both("mul r1, r2, r3\nli r1, 7.0\nhalt\n", 1, &a, &b);
  assert_int_equal(a.final[1], fpref_bits(7.0f));
  assert_int_equal(a.st.stalls, START_STALLS + FP3_READ_CYCLES + rtl->config.mul_latency - 1 +
                                    SPACING_STALLS);
  assert_int_equal(a.reg[1].n, 2);
  /* An add then a mul to one register: the mul's result is last. */
  capture_free(&a);
  capture_free(&b);
  run_both("add r4, r2, r3\nmul r4, r2, r3\nadd r5, r4, r4\nhalt\n", 1, &a, &b);
  assert_int_equal(a.final[4], fpref_bits(1.5f * 1.75f));
  assert_int_equal(a.final[5], fpref_add(fpref_bits(1.5f * 1.75f), fpref_bits(1.5f * 1.75f),
                                         FPREF_IEEE, NULL));
  capture_free(&a);
  capture_free(&b);
}

static void test_move_bypass(void **state) {
  (void)state;
  capture a, b;
  run_both("li r1, 3.0\nmov r2, r1\nmov r3, r2\nadd r4, r3, r3\nhalt\n", 1, &a, &b);
  /* Three dependent links on the one-cycle move path: each waits for the
   * read stage only (the result is on the bypass in the cycle after). */
  assert_int_equal(a.st.stalls, START_STALLS + 3 * FP3_READ_CYCLES + SPACING_STALLS);
  assert_int_equal(a.final[4], fpref_bits(6.0f));
  capture_free(&a);
  capture_free(&b);
}

/* The sign group runs on the move path: each dependent link waits for the
 * read stage only, as a mov; min of a signalling NaN raises invalid. */
static void test_sign_chain(void **state) {
  (void)state;
  capture a, b;
  run_both("li r1, -3.0\nabs r2, r1\nneg r3, r2\nmin r4, r3, r2\nmax r5, r4, r2\n"
           "add r6, r5, r5\nhalt\n", 1, &a, &b);
  assert_int_equal(a.st.stalls, START_STALLS + 5 * FP3_READ_CYCLES + SPACING_STALLS);
  assert_int_equal(a.st.issued, 7);
  assert_int_equal(a.final[4], fpref_bits(-3.0f));
  assert_int_equal(a.final[5], fpref_bits(3.0f));
  assert_int_equal(a.final[6], fpref_bits(6.0f));
  assert_int_equal(a.st.flags, 0);
  capture_free(&a);
  capture_free(&b);
  run_both("li r1, 0x7F800001\nmin r2, r1, r3\nneg r4, r1\nmax r5, r3, r4\nhalt\n", 1, &a, &b);
  assert_int_equal(a.final[2], 0x7FC00001u);
  assert_int_equal(a.final[4], 0xFF800001u);
  assert_int_equal(a.final[5], 0xFFC00001u);
  assert_int_equal(a.st.flags, FP3_FLAG_INVALID);
  capture_free(&a);
  capture_free(&b);
}

/* The div/sqrt unit (fp_div and fp_sqrt on one write-back port and tag
 * line, DIV_LATENCY cycles): each dependent link waits for the read stage
 * plus DIV_LATENCY, as an add or mul chain does for its core; div and sqrt
 * issued back to back leave in issue order on the shared port; a div's
 * destination written again waits for its write-back (WAW); x / 0, 0 / 0
 * and sqrt(-1) raise their flags; every result and flag as the ISS
 * computes it. */
static void test_div_sqrt(void **state) {
  (void)state;
  assert_true(rtl->config.has_div && rtl->config.has_sqrt);
  const unsigned ld = FP3_READ_CYCLES + rtl->config.div_latency;
  capture a, b;
  run_both("div r1, r1, r2\ndiv r1, r1, r2\nsqrt r1, r1\nsqrt r1, r1\nhalt\n", 1, &a, &b);
  assert_int_equal(a.st.stalls, START_STALLS + 3 * (ld - 1) + SPACING_STALLS);
  assert_int_equal(a.st.issued, 5);
  uint32_t want = fpref_bits(1.25f);
  want = fpref_div(want, fpref_bits(1.5f), FPREF_IEEE, NULL);
  want = fpref_div(want, fpref_bits(1.5f), FPREF_IEEE, NULL);
  want = fpref_sqrt(fpref_sqrt(want, FPREF_IEEE, NULL), FPREF_IEEE, NULL);
  assert_int_equal(a.final[1], want);
  assert_int_equal(a.reg[1].n, 4);
  capture_free(&a);
  capture_free(&b);
  /* Independent: one issue every FP3_ISSUE_SPACING cycles, the add waits
   * for the sqrt issued second. */
  run_both("div r3, r2, r1\nsqrt r4, r2\ndiv r5, r1, r2\nsqrt r6, r1\nadd r7, r3, r4\nhalt\n",
           1, &a, &b);
  unsigned at = 4 * FP3_ISSUE_SPACING, ready = FP3_ISSUE_SPACING + ld;
  assert_int_equal(a.st.stalls, START_STALLS + 5 * SPACING_STALLS + (ready > at ? ready - at : 0));
  assert_int_equal(a.final[3], fpref_div(fpref_bits(1.5f), fpref_bits(1.25f), FPREF_IEEE, NULL));
  assert_int_equal(a.final[6], fpref_sqrt(fpref_bits(1.25f), FPREF_IEEE, NULL));
  capture_free(&a);
  capture_free(&b);
  /* WAW: the li lands after the div. */
  run_both("div r1, r2, r3\nli r1, 7.0\nhalt\n", 1, &a, &b);
  assert_int_equal(a.st.stalls, START_STALLS + ld - 1 + SPACING_STALLS);
  assert_int_equal(a.final[1], fpref_bits(7.0f));
  assert_int_equal(a.reg[1].n, 2);
  capture_free(&a);
  capture_free(&b);
  /* The flags: divide by zero, invalid (0 / 0, sqrt of a negative). */
  run_both("li r1, 1.0\nli r2, 0.0\ndiv r3, r1, r2\nhalt\n", 1, &a, &b);
  assert_int_equal(a.final[3], 0x7F800000u);
  assert_int_equal(a.st.flags, FP3_FLAG_INFINITE);
  capture_free(&a);
  capture_free(&b);
  run_both("li r2, 0.0\nli r1, -1.0\ndiv r3, r2, r2\nsqrt r4, r1\nsqrt r5, r2\nhalt\n", 1, &a,
           &b);
  assert_int_equal(a.final[3], 0xFFC00000u);
  assert_int_equal(a.final[4], 0xFFC00000u);
  assert_int_equal(a.final[5], 0u);
  assert_int_equal(a.st.flags, FP3_FLAG_INVALID);
  capture_free(&a);
  capture_free(&b);
}

/* The build for clock rate (FMAX_PIPE, the 3-context model: ADD_LATENCY 4,
 * MUL_LATENCY 3) keeps the dependent-issue distances of the default
 * pipeline (write-backs are announced earlier, for its pick, read and
 * registered issue stages) for latencies of at least
 * FP3_FMAX_PIPE_FULL_LEAD_LATENCY, counts shorter ones as that, has a
 * 3-cycle move path, and resolves a beq FP3_FMAX_PIPE_CYCLES later than
 * the default build; every result as the ISS computes it.  fmax_cycles: the cycles of
 * one integration of src on e, checked against the ISS. */
static long fmax_cycles(fp3_engine *e, const char *src) {
  capture a, b;
  run_both_on(e, src, 1, &a, &b);
  long cycles = (long)a.st.cycles;
  capture_free(&a);
  capture_free(&b);
  return cycles;
}

/* The latency a unit's consumers see on the build for clock rate. */
static unsigned fmax_latency(unsigned latency) {
  return latency < FP3_FMAX_PIPE_FULL_LEAD_LATENCY ? FP3_FMAX_PIPE_FULL_LEAD_LATENCY : latency;
}

static void test_fmax_pipe(void **state) {
  (void)state;
  fp3_engine *e = fp3_engine_rtl_new_model(&fp3_model_nc3, NULL);
  assert_non_null(e);
  assert_int_equal(e->config.fmax_pipe, 1);
  assert_int_equal(rtl->config.fmax_pipe, 0);
  /* Host writes read back at once, each the cycle after the last (its
   * register file reads LUT RAM, whose writes land a cycle late: the read
   * takes them from the bypass), overwritten and in another context. */
  uint32_t v = 0;
  assert_int_equal(fp3_engine_write_reg(e, 7, 0x3F800000u), 0);
  assert_int_equal(fp3_engine_read_reg(e, 7, &v), 0);
  assert_int_equal(v, 0x3F800000u);
  assert_int_equal(fp3_engine_write_reg(e, 7, 0xC0490FDBu), 0);
  assert_int_equal(fp3_engine_write_reg(e, 8, 0x12345678u), 0);
  assert_int_equal(fp3_engine_read_reg(e, 7, &v), 0);
  assert_int_equal(v, 0xC0490FDBu);
  assert_int_equal(fp3_engine_read_reg(e, 8, &v), 0);
  assert_int_equal(v, 0x12345678u);
  assert_int_equal(fp3_engine_write_ctx_reg(e, 2, 7, 0x40000000u), 0);
  assert_int_equal(fp3_engine_read_ctx_reg(e, 2, 7, &v), 0);
  assert_int_equal(v, 0x40000000u);
  assert_int_equal(fp3_engine_read_reg(e, 7, &v), 0);
  assert_int_equal(v, 0xC0490FDBu);
  /* One more link in a dependent chain costs FP3_READ_CYCLES + latency, as
   * on the default build, for a latency of at least
   * FP3_FMAX_PIPE_FULL_LEAD_LATENCY (a shorter one counts as that).  A
   * context fetches every fifth cycle here, and a
   * word only with a slot of its queue free: the halt behind a chain of
   * two joins late enough to end the run, so the chains compared are of
   * three and four, whose ends the dependences decide. */
  const char *add3 = "add r1, r1, r2\nadd r1, r1, r2\nadd r1, r1, r2\nhalt\n";
  const char *add4 = "add r1, r1, r2\nadd r1, r1, r2\nadd r1, r1, r2\nadd r1, r1, r2\nhalt\n";
  const char *mul3 = "mul r3, r3, r2\nmul r3, r3, r2\nmul r3, r3, r2\nhalt\n";
  const char *mul4 = "mul r3, r3, r2\nmul r3, r3, r2\nmul r3, r3, r2\nmul r3, r3, r2\nhalt\n";
  assert_int_equal(fmax_cycles(e, add4) - fmax_cycles(e, add3),
                   FP3_READ_CYCLES + fmax_latency(e->config.add_latency));
  assert_int_equal(fmax_cycles(e, mul4) - fmax_cycles(e, mul3),
                   FP3_READ_CYCLES + fmax_latency(e->config.mul_latency));
  const char *div3 = "div r3, r3, r2\nsqrt r3, r3\ndiv r3, r3, r2\nhalt\n";
  const char *div4 = "div r3, r3, r2\nsqrt r3, r3\ndiv r3, r3, r2\nsqrt r3, r3\nhalt\n";
  assert_true(e->config.has_div && e->config.has_sqrt);
  assert_int_equal(fmax_cycles(e, div4) - fmax_cycles(e, div3),
                   FP3_READ_CYCLES + fmax_latency(e->config.div_latency));
  /* The 3-cycle move path, bit-exact. */
  fmax_cycles(e, "li r1, 3.0\nmov r2, r1\nmov r3, r2\nadd r4, r3, r3\nhalt\n");
  /* A taken beq costs FP3_BEQ_CYCLES on the default build, and
   * FP3_FMAX_PIPE_CYCLES more on this one, against a nop before the halt
   * (which costs the issue spacing there, the fetch spacing here). */
  const char *plain = "nop\nhalt\n", *br = "beq r1, r1, out\nnop\nout:\nhalt\n";
  long d_rtl = fmax_cycles(rtl, br) - fmax_cycles(rtl, plain);
  long d_e = fmax_cycles(e, br) - fmax_cycles(e, plain);
  assert_int_equal(d_rtl, FP3_BEQ_CYCLES - FP3_ISSUE_SPACING);
  assert_int_equal(d_e, FP3_BEQ_CYCLES + FP3_FMAX_PIPE_CYCLES - FP3_FMAX_PIPE_FETCH_SPACING);
  fp3_engine_free(e);
}

/* The lanes' broadcast stages (rtl/fp3_simd.v, docs/lanes.md): on the
 * lanes build (8 contexts x 4 lanes, the default latencies) a run ends
 * FP3_LANES_STAGE_CYCLES later than on the default build, and a taken beq
 * costs FP3_LANES_BEQ_CYCLES more; everything else issues in the same
 * cycles.  Every result as the ISS computes it. */
static void test_lanes_stages(void **state) {
  (void)state;
  fp3_engine *e = fp3_engine_rtl_new_model(&fp3_model_l4, NULL);
  assert_non_null(e);
  assert_int_equal(e->config.num_lanes, 4);
  assert_int_equal(e->config.add_latency, rtl->config.add_latency);
  assert_int_equal(e->config.mul_latency, rtl->config.mul_latency);
  const char *plain = "nop\nhalt\n", *br = "beq r1, r1, out\nnop\nout:\nhalt\n";
  const char *chain = "add r1, r1, r2\nmul r3, r1, r1\nadd r4, r3, r1\nhalt\n";
  assert_int_equal(fmax_cycles(e, plain) - fmax_cycles(rtl, plain), FP3_LANES_STAGE_CYCLES);
  assert_int_equal(fmax_cycles(e, chain) - fmax_cycles(rtl, chain), FP3_LANES_STAGE_CYCLES);
  assert_int_equal(fmax_cycles(e, br) - fmax_cycles(rtl, br),
                   FP3_LANES_STAGE_CYCLES + FP3_LANES_BEQ_CYCLES);
  fp3_engine_free(e);
}

static void test_loop_overlap(void **state) {
  (void)state;
  capture a, b;
  /* A body with one long-latency result: integrations overlap, and each
   * write is tagged with the integration that issued it. */
  run_both("li r7, 2.0\nbody:\nmul r1, r1, r7\nadd r2, r2, r7\nendi body\n", 20, &a, &b);
  assert_int_equal(a.endis, 20);
  assert_int_equal(a.reg[1].n, 20);
  for (uint32_t i = 0; i < 20; i++) assert_int_equal(a.reg[1].integ[i], i + 1);
  capture_free(&a);
  capture_free(&b);
}

/* ---- errors ---------------------------------------------------------------- */

static void test_errors_agree(void **state) {
  (void)state;
  capture a, b;
  fp3_image img;
  assemble("li r1, 1.0\n.word 0x0F00000000000000\nhalt\n", &img);
  run_on(rtl, &img, NULL, 0, 1, &a);
  run_on(iss, &img, NULL, 0, 1, &b);
  assert_int_equal(a.st.error, FP3_ERR_ILLEGAL_INSN);
  assert_int_equal(a.st.fault_pc, 1);
  compare_captures(&a, &b, "illegal opcode");
  capture_free(&a);
  capture_free(&b);

  /* A program without halt or endi runs off the end of the memory. */
  assemble("li r1, 1.0\n", &img);
  run_on(rtl, &img, NULL, 0, 1, &a);
  run_on(iss, &img, NULL, 0, 1, &b);
  assert_int_equal(a.st.error, FP3_ERR_PC_OVERFLOW);
  assert_int_equal(a.st.fault_pc, rtl->config.imem_depth - 1);
  compare_captures(&a, &b, "PC overflow");
  capture_free(&a);
  capture_free(&b);

  assemble("halt\n", &img);
  run_on(rtl, &img, NULL, 0, 0, &a);
  run_on(iss, &img, NULL, 0, 0, &b);
  assert_int_equal(a.st.error, FP3_ERR_BAD_STEPS);
  assert_int_equal(b.st.error, FP3_ERR_BAD_STEPS);
  capture_free(&a);
  capture_free(&b);
}

/* ---- random programs -------------------------------------------------------- */

static uint64_t rng_state = 0x9E3779B97F4A7C15ull;
static uint64_t rnd(void) {
  rng_state ^= rng_state << 13;
  rng_state ^= rng_state >> 7;
  rng_state ^= rng_state << 17;
  return rng_state;
}

/* A binary32 from every special-value class. */
static uint32_t random_value(void) {
  static const uint32_t special[] = {
      0x00000000, 0x80000000, 0x00000001, 0x807FFFFF, 0x00800000, 0x7F7FFFFF, 0xFF7FFFFF,
      0x7F800000, 0xFF800000, 0x7FC00000, 0x7F800001, 0xFFC12345, 0x3F800000, 0x3F800001,
      0x4B000000, 0x33800000,
  };
  switch (rnd() % 4) {
    case 0: return special[rnd() % (sizeof special / sizeof special[0])];
    case 1: return (uint32_t)rnd();
    default: return fpref_bits((float)((int)(rnd() % 2001) - 1000) / 64.0f);
  }
}

/* One of the operations a build with configuration c has, for a random
 * program's register-to-register slot: div, sqrt (HAS_DIV, HAS_SQRT) and
 * abs, neg, min, max (HAS_SIGN) when built, else an add or a mul. */
static uint64_t random_ext_op(const fp3_config *c, unsigned rd, unsigned ra, unsigned rb) {
  switch (rnd() % 6) {
    case 0: if (c->has_div) return fp3_insn_make(FP3_OP_DIV, rd, ra, rb, 0); break;
    case 1: if (c->has_sqrt) return fp3_insn_make(FP3_OP_SQRT, rd, ra, 0, 0); break;
    case 2: if (c->has_sign) return fp3_insn_make(FP3_OP_ABS, rd, ra, 0, 0); break;
    case 3: if (c->has_sign) return fp3_insn_make(FP3_OP_NEG, rd, ra, 0, 0); break;
    case 4: if (c->has_sign) return fp3_insn_make(FP3_OP_MIN, rd, ra, rb, 0); break;
    default: if (c->has_sign) return fp3_insn_make(FP3_OP_MAX, rd, ra, rb, 0); break;
  }
  return fp3_insn_make(rnd() % 2 ? FP3_OP_ADD : FP3_OP_MUL, rd, ra, rb, 0);
}

/* A div or a sqrt where the build has them (dense hazards on the div/sqrt
 * unit, its shared write-back port and its longer latency), else a nop. */
static uint64_t random_div_op(const fp3_config *c, unsigned rd, unsigned ra, unsigned rb) {
  if (c->has_div && (rnd() % 2 || !c->has_sqrt)) return fp3_insn_make(FP3_OP_DIV, rd, ra, rb, 0);
  if (c->has_sqrt) return fp3_insn_make(FP3_OP_SQRT, rd, ra, 0, 0);
  return fp3_insn_make(FP3_OP_NOP, 0, 0, 0, 0);
}

/* Hazard-dense: few registers, all units of configuration c (every
 * operation the build has), a loop. */
static void random_program(fp3_image *img, unsigned nregs, const fp3_config *c) {
  fp3_image_init(img);
  size_t n = 0;
  img->words[n++] = fp3_insn_make(FP3_OP_LI, (unsigned)(rnd() % nregs), 0, 0, random_value());
  size_t body = n;
  size_t len = 4 + rnd() % 24;
  for (size_t i = 0; i < len; i++) {
    unsigned rd = (unsigned)(rnd() % nregs), ra = (unsigned)(rnd() % nregs),
             rb = (unsigned)(rnd() % nregs);
    /* beq: ahead to any later word up to the endi (body + len); few
     * registers, copies and repeated constants make it taken often. */
    uint32_t target = (uint32_t)(n + 1 + rnd() % (body + len - n));
    switch (rnd() % 12) {
      case 9: case 10: img->words[n++] = random_ext_op(c, rd, ra, rb); break;
      case 11: img->words[n++] = random_div_op(c, rd, ra, rb); break;
      case 7: img->words[n++] = fp3_insn_make(FP3_OP_BEQ, 0, ra, rb, target); break;
      case 0: case 1: img->words[n++] = fp3_insn_make(FP3_OP_ADD, rd, ra, rb, 0); break;
      case 2: /* an adder without HAS_SUB adds */
        img->words[n++] = fp3_insn_make(c->has_sub ? FP3_OP_SUB : FP3_OP_ADD, rd, ra, rb, 0);
        break;
      case 3: case 4: img->words[n++] = fp3_insn_make(FP3_OP_MUL, rd, ra, rb, 0); break;
      case 5: img->words[n++] = fp3_insn_make(FP3_OP_LI, rd, 0, 0, random_value()); break;
      case 6: img->words[n++] = fp3_insn_make(FP3_OP_MOV, rd, ra, 0, 0); break;
      default: img->words[n++] = fp3_insn_make(FP3_OP_NOP, 0, 0, 0, 0); break;
    }
  }
  img->words[n++] = fp3_insn_make(FP3_OP_ENDI, 0, 0, 0, (uint32_t)body);
  img->n = n;
}

/* Which random programs run: FP3_RANDOM_PROGRAMS of them from index
 * FP3_RANDOM_FIRST (default 10^4 from 0; make bench-cosim runs 10^6 in
 * ranges side by side, scripts/bench-cosim.sh).  Program p of a sequence
 * starts the generator at program_start(sequence, p), so a range runs the
 * same programs as the whole run does, and a failure replays alone from
 * the seed it prints: FP3_RANDOM_SEED=<seed> runs that one program on
 * every build (random_replay). */
static long random_programs = 10000;
static long random_first = 0;
static int random_bench = 0;    /* FP3_RANDOM_PROGRAMS or _FIRST given */
static int random_replay = 0;   /* FP3_RANDOM_SEED given: replay_seed */
static uint64_t replay_seed;
/* The sum (mod 2^64) of the seeds of the programs run, over every build:
 * printed after a range (FP3_RANDOM_FIRST), so the ranges' sums add up to
 * the whole run's whatever the split (scripts/bench-cosim.sh adds them). */
static uint64_t random_digest = 0;
static long random_at = -1; /* the program being run (an MPI rank names it) */

/* Starts program p of sequence `seq` (one a test and build): the
 * generator at its seed, the splitmix64 output function (Steele, Lea and
 * Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014) of
 * seq's p-th step, never 0 (the xorshift generator's fixed point), or the
 * replayed seed; the seed counted in random_digest.  Returns the seed. */
static uint64_t program_start(uint64_t seq, long p) {
  uint64_t z = (seq << 32) + 0x9E3779B97F4A7C15ull * (uint64_t)(p + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  rng_state = random_replay ? replay_seed : z ? z : 1;
  random_digest += rng_state;
  return rng_state;
}

/* Every program draws its core configuration from its own seed. */
static void test_random_programs(void **state) {
  (void)state;
  const long first = random_first, programs = random_programs;
  fp3_engine *er[4], *ei[4];
  for (int m = 0; m < 4; m++) {
    er[m] = fp3_engine_rtl_new_mode(all_modes[m], NULL);
    ei[m] = fp3_engine_iss_new_mode(all_modes[m]);
    assert_non_null(er[m]);
    assert_non_null(ei[m]);
  }
  for (long p = first; p < first + programs; p++) {
    uint64_t seed = program_start(0, p);
    random_at = p;
    int mi = (int)(rnd() % 4);
    if (p > first && (p - first) % 10000 == 0)
      print_message("%ld of %ld random programs\n", p - first, programs);
    fp3_image img;
    unsigned nregs = 2 + (unsigned)(rnd() % 5);
    random_program(&img, nregs, &er[mi]->config);
    uint32_t init[8];
    for (unsigned r = 0; r < 8; r++) init[r] = random_value();
    uint32_t steps = 1 + (uint32_t)(rnd() % 5);
    capture a, b;
    run_on(er[mi], &img, init, 8, steps, &a);
    run_on(ei[mi], &img, init, 8, steps, &b);
    char what[128];
    snprintf(what, sizeof what, "random program %ld (%s%s; replay: FP3_RANDOM_SEED=0x%016llx)",
             p, fpenv_round_name(all_modes[mi]), all_modes[mi].ftz ? "+ftz" : "",
             (unsigned long long)seed);
    compare_captures(&a, &b, what);
    capture_free(&a);
    capture_free(&b);
  }
  for (int m = 0; m < 4; m++) {
    fp3_engine_free(er[m]);
    fp3_engine_free(ei[m]);
  }
}

/* Random words, most of them illegal: both engines agree on the verdict. */
static void test_random_words(void **state) {
  (void)state;
  for (int i = 0; i < 300; i++) {
    fp3_image img;
    fp3_image_init(&img);
    uint64_t w = rnd();
    /* Bias towards known opcodes so legal words are exercised too. */
    if (i % 2) w = (w & 0x00FFFFFFFFFFFFFFull) | ((uint64_t)(rnd() % 16) << FP3_OPC_LSB);
    /* ... and a beq sometimes to its legal target, the halt */
    if (i % 8 == 3) w = fp3_insn_make(FP3_OP_BEQ, 0, (unsigned)(rnd() % 4), (unsigned)(rnd() % 4), 1);
    if (i % 4 == 1) w &= 0xFF1F1F1F00000000ull | (rnd() & 0xFFFFFFFFull);
    img.words[0] = w;
    img.words[1] = fp3_insn_make(FP3_OP_HALT, 0, 0, 0, 0);
    img.n = 2;
    char why[128];
    int legal = fp3_insn_check_at(w, 0, rtl->config.num_regs, rtl->config.imem_depth, why, sizeof why) == 0;
    if (fp3_config_check_program(&rtl->config, &w, 1, why, sizeof why) != 0) {
      /* an opcode of a unit this build lacks (the host looks at the
       * opcode only): the host refuses it, and past the host's check the
       * RTL raises ILLEGAL_INSN on it, legal fields or not */
      assert_int_equal(fp3_engine_load(rtl, img.words, img.n), -1);
      assert_int_equal(rtl->ops->load_program(rtl, img.words, img.n), 0);
      fp3_status st;
      assert_int_equal(fp3_engine_run(rtl, 1, NULL, &st), 0);
      assert_int_equal(st.error, FP3_ERR_ILLEGAL_INSN);
      assert_int_equal(st.fault_pc, 0);
      continue;
    }
    capture a, b;
    run_on(rtl, &img, NULL, 0, 1, &a);
    run_on(iss, &img, NULL, 0, 1, &b);
    char what[64];
    snprintf(what, sizeof what, "word 0x%016llx", (unsigned long long)w);
    compare_captures(&a, &b, what);
    if (legal) assert_int_not_equal(a.st.error, FP3_ERR_ILLEGAL_INSN);
    else assert_int_equal(a.st.error, FP3_ERR_ILLEGAL_INSN);
    capture_free(&a);
    capture_free(&b);
  }
}

/* Every new operation on the default build and on a build without the
 * div/sqrt unit: those a build has run bit-exact against the ISS (a
 * dependent chain through each); those it lacks are refused by the host,
 * naming the parameter, and raise ILLEGAL_INSN at their pc when loaded
 * past the host's check. */
static void test_new_ops_or_refusal(void **state) {
  (void)state;
  static const struct {
    const char *src, *mnem, *param;
    unsigned has_off; /* offset of the fp3_config field */
  } ops[] = {
      {"li r1, 2.0\nli r2, 3.0\ndiv r3, r1, r2\nmul r4, r3, r2\nhalt\n", "div", "HAS_DIV",
       offsetof(fp3_config, has_div)},
      {"li r1, 2.0\nli r2, 3.0\nsqrt r3, r1\nmul r4, r3, r3\nhalt\n", "sqrt", "HAS_SQRT",
       offsetof(fp3_config, has_sqrt)},
      {"li r1, -2.0\nli r2, 3.0\nabs r3, r1\nmul r4, r3, r2\nhalt\n", "abs", "HAS_SIGN",
       offsetof(fp3_config, has_sign)},
      {"li r1, -2.0\nli r2, 3.0\nneg r3, r1\nmul r4, r3, r2\nhalt\n", "neg", "HAS_SIGN",
       offsetof(fp3_config, has_sign)},
      {"li r1, -2.0\nli r2, 3.0\nmin r3, r1, r2\nmul r4, r3, r2\nhalt\n", "min", "HAS_SIGN",
       offsetof(fp3_config, has_sign)},
      {"li r1, -2.0\nli r2, 3.0\nmax r3, r1, r2\nmul r4, r3, r2\nhalt\n", "max", "HAS_SIGN",
       offsetof(fp3_config, has_sign)},
  };
  /* The default build (every unit) and the one-context build without the
   * div/sqrt unit (HAS_DIV = HAS_SQRT = 0, mk/rtl.mk nc1). */
  fp3_engine *nc1 = fp3_engine_rtl_new_model(&fp3_model_nc1, NULL);
  assert_non_null(nc1);
  assert_true(rtl->config.has_div && rtl->config.has_sqrt && rtl->config.has_sign);
  assert_true(!nc1->config.has_div && !nc1->config.has_sqrt);
  fp3_engine *const engines[] = {rtl, nc1};
  unsigned refused = 0;
  for (size_t k = 0; k < 2; k++)
    for (size_t i = 0; i < sizeof ops / sizeof ops[0]; i++) {
      fp3_engine *e = engines[k];
      fp3_image img;
      assemble(ops[i].src, &img);
      const unsigned has = *(const unsigned *)((const char *)&e->config + ops[i].has_off);
      if (has) {
        capture a, b;
        run_on(e, &img, NULL, 0, 1, &a);
        run_on(iss, &img, NULL, 0, 1, &b);
        compare_captures(&a, &b, ops[i].mnem);
        capture_free(&a);
        capture_free(&b);
        continue;
      }
      assert_int_equal(fp3_engine_load(e, img.words, img.n), -1);
      char want[128];
      snprintf(want, sizeof want, "uses %s (pc 2)", ops[i].mnem);
      if (!strstr(fp3_engine_error(e), want) || !strstr(fp3_engine_error(e), ops[i].param))
        fail_msg("%s: refusal '%s' lacks '%s' or %s", ops[i].mnem, fp3_engine_error(e), want,
                 ops[i].param);
      /* Past the host's check, the scheduler finds the word illegal. */
      assert_int_equal(e->ops->load_program(e, img.words, img.n), 0);
      fp3_status st;
      assert_int_equal(fp3_engine_run(e, 1, NULL, &st), 0);
      assert_int_equal(st.error, FP3_ERR_ILLEGAL_INSN);
      assert_int_equal(st.fault_pc, 2);
      refused++;
    }
  assert_int_equal(refused, 2);   /* div and sqrt on nc1 */
  fp3_engine_free(nc1);
}

/* ---- many objects: contexts sharing one arithmetic unit -------------------- */

typedef struct multi_capture {
  capture c[FP3_MAX_CONTEXTS];
  unsigned contexts;
} multi_capture;

static void on_ctx_write(void *ctx, unsigned context, unsigned reg, uint32_t value,
                         uint32_t integ) {
  multi_capture *m = ctx;
  assert_true(context < m->contexts);
  on_write(&m->c[context], reg, value, integ);
}

static void on_ctx_endi(void *ctx, unsigned context, uint32_t integ, uint64_t cycle) {
  multi_capture *m = ctx;
  assert_true(context < m->contexts);
  on_endi(&m->c[context], integ, cycle);
}

/* Run `contexts` object slots (engine.h: contexts x lanes), slot k
 * starting from init[k]; per-slot captures hold the slot's status, the
 * totals go to *st. */
static void run_contexts_on(fp3_engine *e, const fp3_image *img, uint32_t (*init)[MAX_REGS],
                            unsigned contexts, uint32_t steps, multi_capture *m,
                            fp3_status *st) {
  memset(m, 0, sizeof *m);
  /* A bad count (tested) still reads back the contexts that exist. */
  const unsigned slots = fp3_config_slots(&e->config);
  assert_true(slots <= FP3_MAX_CONTEXTS);   /* (the captures' size) */
  m->contexts = contexts < slots ? contexts : slots;
  if (fp3_engine_load(e, img->words, img->n) != 0) fail_msg("%s", fp3_engine_error(e));
  for (unsigned k = 0; k < m->contexts; k++)
    for (unsigned r = 0; r < e->config.num_regs; r++)
      assert_int_equal(fp3_engine_write_ctx_reg(e, k, r, init[k][r]), 0);
  fp3_observer obs = {.ctx = m, .on_ctx_write = on_ctx_write, .on_ctx_endi = on_ctx_endi};
  if (fp3_engine_run_contexts(e, steps, contexts, &obs, st) != 0)
    fail_msg("%s", fp3_engine_error(e));
  for (unsigned k = 0; k < m->contexts; k++) {
    fp3_ctx_status cs;
    assert_int_equal(fp3_engine_ctx_status(e, k, &cs), 0);
    m->c[k].st.error = cs.error;
    m->c[k].st.fault_pc = cs.fault_pc;
    m->c[k].st.steps_done = cs.steps_done;
    m->c[k].st.flags = cs.flags; /* sticky per context */
    for (unsigned r = 0; r < e->config.num_regs; r++)
      assert_int_equal(fp3_engine_read_ctx_reg(e, k, r, &m->c[k].final[r]), 0);
  }
}

static void multi_free(multi_capture *m) {
  for (unsigned k = 0; k < m->contexts; k++) capture_free(&m->c[k]);
}

/* The RTL builds with 1 context (ADD_LATENCY 1, MUL_LATENCY 2), 3 contexts
 * (ADD_LATENCY 4, MUL_LATENCY 3, FMAX_PIPE: write-back tag lines too short
 * for the announcement's full lead, fp3_wb_tag), the default build, and
 * the build for clock rate (8 contexts, ADD_LATENCY 9, MUL_LATENCY 10,
 * FMAX_PIPE: the full announcement lead; mk/rtl.mk): the
 * FMAX_PIPE scheduler's contexts 3 to 7 run only there (a mutation of
 * context 3's hazard compares passed every test before it was here);
 * the lanes build (8 contexts x 4 lanes, the default latencies);
 * lanes in the build for clock rate (4 contexts x 3 lanes, the chip
 * build's latencies, broadcast stages and split host read); and the
 * scene-sized build `drift` (4 contexts x 2 lanes, one write-back port
 * without FMAX_PIPE, ADD_LATENCY = MUL_LATENCY = 4, RTZ + FTZ, no
 * subtractor, sign group or div/sqrt unit: random programs only). */
static const struct {
  const fp3_model_ops *model;  /* NULL: the default build */
  unsigned contexts;           /* what the build must report */
  unsigned lanes;
  int fmax_pipe;
  unsigned wb_ports;  /* WB_PORTS, as INFO2 reports it */
  int ship;           /* 1: runs programs/ship_rk4.s (0: no subtractor) */
} context_builds[] = {
  {&fp3_model_nc1, 1, 1, 0, 4, 1},
  {&fp3_model_nc3, 3, 1, 1, 4, 1},
  {NULL, FP3_DEFAULT_NUM_CONTEXTS, 1, 0, 4, 1},
  {&fp3_model_fmax, 8, 1, 1, 4, 1},
  {&fp3_model_l4, 8, 4, 0, 4, 1},
  {&fp3_model_lf, 4, 3, 1, 1, 1},
  {&fp3_model_drift, 4, 2, 0, 1, 0},
};
#define CONTEXT_BUILDS (int)(sizeof context_builds / sizeof context_builds[0])
static fp3_engine *context_build(int which) {
  const fp3_model_ops *m = context_builds[which].model;
  return m ? fp3_engine_rtl_new_model(m, NULL) : fp3_engine_rtl_new(NULL);
}

/* Different ships in every object slot (context and lane): each bit-exact
 * with the ISS and with its own golden model after every integration; no
 * context starves; with enough contexts an object-step costs about one
 * cycle per instruction of the loop body, divided by the lanes. */
static void test_many_ships(void **state) {
  (void)state;
  fp3_image img;
  char *errors = NULL;
  fp3_image_init(&img);
  assert_int_equal(fp3_asm_file("programs/ship_rk4.s", &img, &errors), 0);
  const uint32_t steps = 200;
  static multi_capture ma, mb;
  static uint32_t init[FP3_MAX_CONTEXTS][MAX_REGS];
  for (int which = 0; which < CONTEXT_BUILDS; which++) {
    fp3_engine *er = context_build(which);
    assert_non_null(er);
    assert_int_equal(er->config.num_contexts, context_builds[which].contexts);
    assert_int_equal(er->config.num_lanes, context_builds[which].lanes);
    assert_int_equal(er->config.fmax_pipe, context_builds[which].fmax_pipe);
    assert_int_equal(er->config.wb_ports, context_builds[which].wb_ports);
    if (!context_builds[which].ship) {
      fp3_engine_free(er);
      continue;
    }
    fp3_engine *is = fp3_engine_iss_new_config(&er->config);   /* lanes in lock step */
    assert_non_null(is);
    unsigned nctx = fp3_config_slots(&er->config);
    memset(init, 0, sizeof init);
    ship_prog sp;
    ship_bind(&img, "programs/ship_rk4.s", er, &sp);
    for (unsigned k = 0; k < nctx; k++)
      ship_init(&sp, &ship_cases[k % NCASES], (float)k, er->config.mode, init[k]);
    fp3_status sa, sb;
    run_contexts_on(er, &img, init, nctx, steps, &ma, &sa);
    run_contexts_on(is, &img, init, nctx, steps, &mb, &sb);
    assert_int_equal(sa.any_error, 0);
    assert_int_equal(sa.flags, sb.flags);
    assert_int_equal(sa.issued, sb.issued);
    uint64_t first_done = UINT64_MAX, last_done = 0;
    for (unsigned k = 0; k < nctx; k++) {
      char what[64];
      snprintf(what, sizeof what, "%u objects, object %u", nctx, k);
      assert_int_equal(ma.c[k].st.steps_done, steps);
      compare_captures(&ma.c[k], &mb.c[k], what);
      /* golden model of this context's ship */
      uint32_t bank[MAX_REGS] = {0};
      ship_init(&sp, &ship_cases[k % NCASES], (float)k, er->config.mode, bank);
      const int vreg = sp.vreg, sreg = sp.sreg;
      size_t vpos = 0, spos = 0;
      for (uint32_t i = 1; i <= steps; i++) {
        uint32_t gv, gs;
        ship_step(&sp, er->config.mode, &gv, &gs);
        uint32_t v = value_after(&ma.c[k].reg[vreg], init[k][vreg], i, &vpos);
        uint32_t sv = value_after(&ma.c[k].reg[sreg], init[k][sreg], i, &spos);
        if (v != gv || sv != gs)
          fail_msg("%s: integration %u differs from the golden model", what, i);
      }
      uint64_t end = ma.c[k].endi_cycle[steps - 1];
      if (end < first_done) first_done = end;
      if (end > last_done) last_done = end;
    }
    /* Fair arbitration: the contexts finish within one integration of
     * each other (in cycles: the run's cycles per object-step times the
     * number of contexts). */
    double per_object_step = (double)sa.cycles / ((double)nctx * steps);
    assert_true((double)(last_done - first_done) <= per_object_step * nctx);
    print_message("%u contexts x %u lanes: %.2f cycles per object-step, %llu stalls\n",
                  er->config.num_contexts, er->config.num_lanes, per_object_step,
                  (unsigned long long)sa.stalls);
    if (er->config.num_contexts >= 8 && !er->config.fmax_pipe) {
      /* Issue bound: 31 instructions per body, one issued per cycle for
       * all lanes of a context (the build for clock rate's latencies are
       * longer than 8 contexts hide: 38.02 cycles per object-step,
       * docs/pipeline.md "Many objects"). */
      double bound = (double)sa.issued / ((double)nctx * steps);
      assert_true(per_object_step <= 1.1 * bound);
    }
    multi_free(&ma);
    multi_free(&mb);
    fp3_compiled_free(sp.c);
    fp3_engine_free(is);
    fp3_engine_free(er);
  }
}

/* Hazard-dense random programs, every object slot (context and lane)
 * with its own values: the lanes of a context disagree on most beqs. */
static void test_random_programs_contexts(void **state) {
  (void)state;
  static multi_capture ma, mb;
  static uint32_t init[FP3_MAX_CONTEXTS][MAX_REGS];
  for (int which = 0; which < CONTEXT_BUILDS; which++) {
    fp3_engine *er = context_build(which);
    assert_non_null(er);
    fp3_engine *is = fp3_engine_iss_new_config(&er->config);   /* lanes in lock step */
    assert_non_null(is);
    unsigned nctx = fp3_config_slots(&er->config);
    /* make bench-cosim's range on each lanes build and none on the
     * others (the default build's range is test_random_programs'); a
     * replay's one program on every build; else 300 a build */
    const int asked = random_replay || (random_bench && er->config.num_lanes > 1);
    const long first = asked ? random_first : 0;
    const long programs = asked ? random_programs : random_bench ? 0 : 300;
    for (long p = first; p < first + programs; p++) {
      if (p > first && (p - first) % 10000 == 0)
        print_message("%ld of %ld random programs on %u x %u slots\n", p - first, programs,
                      er->config.num_contexts, er->config.num_lanes);
      uint64_t seed = program_start(1u + (unsigned)which, p);
      random_at = p;
      fp3_image img;
      random_program(&img, 2 + (unsigned)(rnd() % 5), &er->config);
      memset(init, 0, sizeof init);
      for (unsigned k = 0; k < nctx; k++)
        for (unsigned r = 0; r < 8; r++) init[k][r] = random_value();
      unsigned contexts = 1 + (unsigned)(rnd() % nctx);
      uint32_t steps = 1 + (uint32_t)(rnd() % 4);
      fp3_status sa, sb;
      run_contexts_on(er, &img, init, contexts, steps, &ma, &sa);
      run_contexts_on(is, &img, init, contexts, steps, &mb, &sb);
      assert_int_equal(sa.flags, sb.flags);
      assert_int_equal(sa.issued, sb.issued);
      for (unsigned k = 0; k < contexts; k++) {
        char what[144];
        snprintf(what, sizeof what,
                 "random program %ld on %u x %u slots, slot %u (replay: FP3_RANDOM_SEED=0x%016llx)",
                 p, er->config.num_contexts, er->config.num_lanes, k, (unsigned long long)seed);
        compare_captures(&ma.c[k], &mb.c[k], what);
      }
      multi_free(&ma);
      multi_free(&mb);
    }
    fp3_engine_free(is);
    fp3_engine_free(er);
  }
}

/* ---- the host port's map, straight at the model ---------------------------- */

/* A host-port read: the address held for `read` cycles (1 + 3 FMAX_PIPE,
 * and FP3_LANES_HOST_READ_CYCLES more with lanes: fp3_top "Host port"), the
 * data of the last. */
static uint32_t model_read(const fp3_model_ops *ops, fp3_model *m, unsigned read,
                           unsigned addr) {
  fp3_model_in in = {0, (uint16_t)addr, 0};
  fp3_model_out out = {0};
  for (unsigned k = 0; k < read; k++) ops->cycle(m, &in, &out);
  return out.rdata;
}

/* The scalar registers read as documented, and every other word below the
 * register window as zero, in the default build and with FMAX_PIPE (whose
 * read multiplexer chooses the four words by address bits 4:2 and gates
 * them with the rest: an address 0x20 above ID must not read ID). */
static void test_host_map_reads(void **state) {
  (void)state;
  const struct { const fp3_model_ops *ops; unsigned read; } cfg[] = {
      {&fp3_model_rne, 1}, {&fp3_model_nc3, 4}};
  for (size_t i = 0; i < sizeof cfg / sizeof cfg[0]; i++) {
    fp3_model *m = cfg[i].ops->create(NULL);
    assert_non_null(m);
    assert_int_equal(model_read(cfg[i].ops, m, cfg[i].read, FP3_HR_ID), FP3_ID_VALUE);
    assert_int_equal(model_read(cfg[i].ops, m, cfg[i].read, FP3_HR_CONTEXTS), 1);
    for (unsigned a = FP3_HR_INFO2 + 1; a < FP3_HR_REG_BASE; a++) {
      uint32_t v = model_read(cfg[i].ops, m, cfg[i].read, a);
      if (v != 0) fail_msg("config %zu: word 0x%03X reads 0x%08X, want 0", i, a, v);
    }
    cfg[i].ops->destroy(m);
  }
}

/* LANE on the lanes build (8 contexts x 4 lanes), straight at the host
 * port: INFO2 reports the lanes; LANE takes 0 .. 3 and ignores 4 and more;
 * the register window writes and reads only the lane LANE names (and the
 * context CTX names); the C host refuses a slot beyond contexts x lanes. */
static void test_host_lane(void **state) {
  (void)state;
  const fp3_model_ops *ops = &fp3_model_l4;
  fp3_model *m = ops->create(NULL);
  assert_non_null(m);
  fp3_model_in in = {1, 0, 0};
  const unsigned rc = FP3_HOST_READ_CYCLES(0, 4);   /* the host port's read cycles */
#define HOST_WRITE(a, v) (in.addr = (uint16_t)(a), in.wdata = (uint32_t)(v), ops->cycle(m, &in, NULL))
  assert_int_equal(model_read(ops, m, rc, FP3_HR_INFO2) >> 24, 4);
  assert_int_equal(model_read(ops, m, rc, FP3_HR_LANE), 0);
  HOST_WRITE(FP3_HR_LANE, 3);
  assert_int_equal(model_read(ops, m, rc, FP3_HR_LANE), 3);
  HOST_WRITE(FP3_HR_LANE, 4);
  assert_int_equal(model_read(ops, m, rc, FP3_HR_LANE), 3);
  HOST_WRITE(FP3_HR_LANE, 0xFFFFFFFFu);
  assert_int_equal(model_read(ops, m, rc, FP3_HR_LANE), 3);
  for (unsigned c = 0; c < 8; c++)
    for (unsigned l = 0; l < 4; l++) {
      HOST_WRITE(FP3_HR_CTX, c);
      HOST_WRITE(FP3_HR_LANE, l);
      HOST_WRITE(FP3_HR_REG_BASE + 5, 0x1000u * c + l + 1);
    }
  for (unsigned c = 0; c < 8; c++)
    for (unsigned l = 0; l < 4; l++) {
      HOST_WRITE(FP3_HR_CTX, c);
      HOST_WRITE(FP3_HR_LANE, l);
      assert_int_equal(model_read(ops, m, rc, FP3_HR_REG_BASE + 5), 0x1000u * c + l + 1);
      assert_int_equal(model_read(ops, m, rc, FP3_HR_REG_BASE + 4), 0);
    }
#undef HOST_WRITE
  ops->destroy(m);
  fp3_engine *e = fp3_engine_rtl_new_model(&fp3_model_l4, NULL);
  assert_non_null(e);
  assert_int_equal(fp3_config_slots(&e->config), 32);
  uint32_t v;
  assert_int_equal(fp3_engine_write_ctx_reg(e, 31, 0, 1), 0);
  assert_int_equal(fp3_engine_read_ctx_reg(e, 31, 0, &v), 0);
  assert_int_equal(v, 1);
  assert_int_not_equal(fp3_engine_write_ctx_reg(e, 32, 0, 1), 0);
  assert_non_null(strstr(fp3_engine_error(e), "slot 32"));
  assert_int_not_equal(fp3_engine_read_ctx_reg(e, 32, 0, &v), 0);
  fp3_engine_free(e);
}

/* START in the cycle right after the last program write, straight at the
 * host port (which takes a write every cycle; AXI4-Lite every other one):
 * the run's first fetch must see that word.  The memory first holds halts;
 * the ship program is then written from its last word to its first (the
 * word fetched first is written last), START follows at once, and the
 * final registers must be the ISS's (a stale first word halts the run at
 * once).  In the default build and the build for clock rate (nc3, with
 * FMAX_PIPE: its program writes land two edges after the host's). */
static void test_start_after_program(void **state) {
  (void)state;
  fp3_image img, halts;
  char *errors = NULL;
  fp3_image_init(&img);
  assert_int_equal(fp3_asm_file("programs/ship_rk4.s", &img, &errors), 0);
  assemble("halt\n", &halts);
  const uint64_t halt = halts.words[0];
  static uint32_t init[MAX_REGS];
  memset(init, 0, sizeof init);
  ship_prog sp;
  ship_bind(&img, "programs/ship_rk4.s", iss, &sp);
  ship_init(&sp, &ship_cases[0], 0.0f, iss->config.mode, init);
  fp3_compiled_free(sp.c);
  const uint32_t steps = 3;
  static capture ref;
  run_on(iss, &img, init, MAX_REGS, steps, &ref);
  const struct { const fp3_model_ops *ops; unsigned read; } cfg[] = {
      {&fp3_model_rne, 1}, {&fp3_model_nc3, 4}};
  for (size_t i = 0; i < sizeof cfg / sizeof cfg[0]; i++) {
    const fp3_model_ops *ops = cfg[i].ops;
    fp3_model *m = ops->create(NULL);
    assert_non_null(m);
    fp3_model_in in = {1, 0, 0};
#define HOST_WRITE(a, v) (in.addr = (uint16_t)(a), in.wdata = (uint32_t)(v), ops->cycle(m, &in, NULL))
    for (size_t k = 0; k < img.n; k++) {
      HOST_WRITE(FP3_HR_IMEM_BASE + 2 * k, halt);
      HOST_WRITE(FP3_HR_IMEM_BASE + 2 * k + 1, halt >> 32);
    }
    for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS; r++) HOST_WRITE(FP3_HR_REG_BASE + r, init[r]);
    HOST_WRITE(FP3_HR_STEPS, steps);
    for (size_t k = img.n; k-- > 0;) {
      HOST_WRITE(FP3_HR_IMEM_BASE + 2 * k, img.words[k]);
      HOST_WRITE(FP3_HR_IMEM_BASE + 2 * k + 1, img.words[k] >> 32);
    }
    HOST_WRITE(FP3_HR_CTRL, FP3_CTRL_START);
#undef HOST_WRITE
    fp3_model_out out = {0};
    unsigned long cycles = 0;
    do {
      ops->cycle(m, NULL, &out);
      if (++cycles > 100000ul) fail_msg("config %zu: the run does not end", i);
    } while (!out.done);
    uint32_t status = model_read(ops, m, cfg[i].read, FP3_HR_STATUS);
    assert_int_equal((status >> FP3_STATUS_ERROR_LSB) & 0xF, FP3_ERR_NONE);
    assert_int_equal(model_read(ops, m, cfg[i].read, FP3_HR_STEPS_DONE), steps);
    for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS; r++) {
      uint32_t v = model_read(ops, m, cfg[i].read, FP3_HR_REG_BASE + r);
      if (v != ref.final[r])
        fail_msg("config %zu: r%u = 0x%08X, the ISS 0x%08X", i, r, v, ref.final[r]);
    }
    ops->destroy(m);
  }
  capture_free(&ref);
}

static void test_bad_contexts(void **state) {
  (void)state;
  fp3_image img;
  assemble("halt\n", &img);
  static multi_capture m;
  static uint32_t init[FP3_MAX_CONTEXTS][MAX_REGS];
  unsigned bad[2] = {0, rtl->config.num_contexts + 1};
  for (int i = 0; i < 2; i++) {
    fp3_status sa, sb;
    run_contexts_on(rtl, &img, init, bad[i], 1, &m, &sa);
    assert_int_equal(sa.error, FP3_ERR_BAD_CONTEXTS);
    assert_int_equal(sa.any_error, 1);
    run_contexts_on(iss, &img, init, bad[i] ? iss->config.num_contexts + 1 : 0, 1, &m, &sb);
    assert_int_equal(sb.error, FP3_ERR_BAD_CONTEXTS);
  }
}

/* An illegal word met by some contexts only, among all the contexts of the
 * default build and of the build for clock rate: each records its own
 * error and faulting PC, as on the ISS, and the others halt cleanly.  The
 * odd contexts (r1 != r2) fall through the beq onto the illegal word. */
static void test_errors_every_context(void **state) {
  (void)state;
  fp3_image img;
  assemble("beq r1, r2, ok\n.word 0x0F00000000000000\nok: halt\n", &img);
  static multi_capture ma, mb;
  static uint32_t init[FP3_MAX_CONTEXTS][MAX_REGS];
  fp3_engine *fmax = fp3_engine_rtl_new_model(&fp3_model_nc3, NULL);
  assert_non_null(fmax);
  fp3_engine *builds[2] = {rtl, fmax};
  for (int i = 0; i < 2; i++) {
    unsigned nctx = builds[i]->config.num_contexts;
    memset(init, 0, sizeof init);
    for (unsigned k = 0; k < nctx; k++) init[k][1] = (k & 1) ? 0x3F800000u : 0;
    fp3_status sa, sb;
    run_contexts_on(builds[i], &img, init, nctx, 1, &ma, &sa);
    run_contexts_on(iss, &img, init, nctx, 1, &mb, &sb);
    assert_int_equal(sa.any_error, nctx > 1);
    for (unsigned k = 0; k < nctx; k++) {
      assert_int_equal(ma.c[k].st.error, (k & 1) ? FP3_ERR_ILLEGAL_INSN : FP3_ERR_NONE);
      assert_int_equal(ma.c[k].st.fault_pc, (k & 1) ? 1 : 0);
      assert_int_equal(ma.c[k].st.error, mb.c[k].st.error);
      assert_int_equal(ma.c[k].st.fault_pc, mb.c[k].st.fault_pc);
    }
    multi_free(&ma);
    multi_free(&mb);
  }
  fp3_engine_free(fmax);
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

/* An environment variable's value as a number from `least` to `most`,
 * or exit 2 naming it. */
static unsigned long long env_number(const char *name, unsigned long long least,
                                     unsigned long long most) {
  const char *v = getenv(name);
  char *end = NULL;
  errno = 0;
  unsigned long long n = strtoull(v, &end, 0);
  if (!*v || *end || errno || v[0] == '-' || n < least || n > most) {
    fprintf(stderr, "test_engines: %s='%s' is not a whole number from %llu to %llu\n", name, v,
            least, most);
    exit(2);
  }
  return n;
}

/* The largest program index or count a range takes (far beyond any run,
 * and first + count stays within a long). */
#define RANDOM_INDEX_MAX 1000000000000ull

#ifdef FP3_MPI
/* build/tests/test_engines-mpi (mk/mpi.mk; make bench-cosim MPI_NP=N):
 * the random programs FP3_RANDOM_FIRST .. FP3_RANDOM_FIRST +
 * FP3_RANDOM_PROGRAMS - 1 split across the MPI ranks as
 * scripts/bench-cosim.sh splits them across processes (an equal share
 * each, the first COUNT mod N ranks one more).  Each rank runs its range
 * on every build; MPI_Reduce adds the seed digests (mod 2^64: the
 * one-process digest, whatever the split) and the failed ranks on rank 0,
 * which prints a line per rank (host, range, seconds) and names each
 * failing rank's host, range and program (its own output names the seed
 * that replays it).  Exit status 1 if any rank failed. */
typedef struct rank_line {
  int32_t failed;
  int64_t first, count, at;
  double seconds;
  char host[64];
} rank_line;

static int mpi_campaign(void) {
  int rank, size;
  MPI_Init(NULL, NULL);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const long count = random_programs, base = count / size, extra = count % size;
  rank_line me;
  memset(&me, 0, sizeof me);
  me.count = base + (rank < extra);
  me.first = random_first + rank * base + (rank < extra ? rank : extra);
  int len = 0;
  char name[MPI_MAX_PROCESSOR_NAME];
  if (MPI_Get_processor_name(name, &len) == MPI_SUCCESS) snprintf(me.host, sizeof me.host, "%s", name);
  random_first = (long)me.first;
  random_programs = (long)me.count;
  random_bench = 1;
  double t0 = MPI_Wtime();
  if (me.count > 0) {
    const struct CMUnitTest random[] = {cmocka_unit_test(test_random_programs),
                                        cmocka_unit_test(test_random_programs_contexts)};
    me.failed = cmocka_run_group_tests(random, setup, teardown) != 0;
    me.at = random_at;
  }
  me.seconds = MPI_Wtime() - t0;
  unsigned long long digest = 0, mine = random_digest;
  int failed = 0;
  MPI_Reduce(&mine, &digest, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
  MPI_Reduce(&me.failed, &failed, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
  rank_line *all = rank == 0 ? calloc((size_t)size, sizeof *all) : NULL;
  if (rank == 0 && !all) MPI_Abort(MPI_COMM_WORLD, 1);
  MPI_Gather(&me, (int)sizeof me, MPI_BYTE, all, (int)sizeof me, MPI_BYTE, 0, MPI_COMM_WORLD);
  if (rank == 0) {
    fflush(stdout);
    for (int r = 0; r < size; r++) {
      printf("rank %d of %d (host %s): random programs %lld .. %lld: ", r, size, all[r].host,
             (long long)all[r].first, (long long)(all[r].first + all[r].count - 1));
      if (all[r].failed)
        printf("FAILED at random program %lld (its output above names the seed that replays "
               "it)", (long long)all[r].at);
      else
        printf("passed");
      printf(" in %.1f s\n", all[r].seconds);
    }
    printf("random programs %lld .. %lld on %d ranks: %d failed; seed digest 0x%016llx\n",
           (long long)all[0].first, (long long)(all[0].first + count - 1), size, failed, digest);
    free(all);
  }
  int any = 0;
  MPI_Allreduce(&me.failed, &any, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return any ? 1 : 0;
}
#endif

int main(void) {
  if (getenv("FP3_RANDOM_PROGRAMS")) {
    random_programs = (long)env_number("FP3_RANDOM_PROGRAMS", 1, RANDOM_INDEX_MAX);
    random_bench = 1;
  }
  if (getenv("FP3_RANDOM_FIRST")) {
    random_first = (long)env_number("FP3_RANDOM_FIRST", 0, RANDOM_INDEX_MAX);
    random_bench = 1;
  }
  if (getenv("FP3_RANDOM_SEED")) {
    replay_seed = env_number("FP3_RANDOM_SEED", 1, UINT64_MAX);
    random_replay = 1;
    random_programs = 1;
  }
#ifdef FP3_MPI
  if (random_replay) {
    fprintf(stderr, "test_engines-mpi: FP3_RANDOM_SEED replays one program: use build/tests/test_engines\n");
    return 2;
  }
  return mpi_campaign();
#endif
  if (random_bench || random_replay) {
    /* A range of random programs, or a replay: those tests alone. */
    const struct CMUnitTest random[] = {cmocka_unit_test(test_random_programs),
                                        cmocka_unit_test(test_random_programs_contexts)};
    int failed = cmocka_run_group_tests(random, setup, teardown);
    if (!random_replay)
      printf("random programs %ld .. %ld: seed digest 0x%016llx\n", random_first,
             random_first + random_programs - 1, (unsigned long long)random_digest);
    return failed;
  }
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_ship_rk4),
      cmocka_unit_test(test_ship_rk4_core_configs),
      cmocka_unit_test(test_ship_rk4_cycles),
      cmocka_unit_test(test_ship_rk4_sleep),
      cmocka_unit_test(test_sleep_at_rest),
      cmocka_unit_test(test_frames_sleeping),
      cmocka_unit_test(test_frames_lanes),
      cmocka_unit_test(test_lanes_stages),
      cmocka_unit_test(test_dependent_add_chain),
      cmocka_unit_test(test_dependent_mul_chain),
      cmocka_unit_test(test_independent_ops_spacing),
      cmocka_unit_test(test_waw_same_register),
      cmocka_unit_test(test_move_bypass),
      cmocka_unit_test(test_fmax_pipe),
      cmocka_unit_test(test_loop_overlap),
      cmocka_unit_test(test_errors_agree),
      cmocka_unit_test(test_random_programs),
      cmocka_unit_test(test_random_words),
      cmocka_unit_test(test_sign_chain),
      cmocka_unit_test(test_div_sqrt),
      cmocka_unit_test(test_new_ops_or_refusal),
      cmocka_unit_test(test_many_ships),
      cmocka_unit_test(test_random_programs_contexts),
      cmocka_unit_test(test_bad_contexts),
      cmocka_unit_test(test_errors_every_context),
      cmocka_unit_test(test_host_map_reads),
      cmocka_unit_test(test_host_lane),
      cmocka_unit_test(test_start_after_program),
  };
  return cmocka_run_group_tests(tests, setup, teardown);
}
