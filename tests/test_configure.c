/*
 * test_configure.c -- hardware sized to the scene (sw/compiler/configure.c) and the
 * missing-unit check (fp3_config_check_program, sw/engine/engine.c):
 *
 *  - the check names the unit, the pc and the parameter, for each unit and
 *    for sub on an adder without HAS_SUB; a complete build accepts all;
 *    fp3_engine_load refuses; the ISS reports every unit;
 *  - fp3_configure_model derives exact parameters for the example ship
 *    scenes, read as scenes of models/ship.fp3m with its rk4se
 *    (scenes/drift.scene: no sub; coast, harbour) and synthetic ones
 *    (one object, 100 objects one context each, euler), the ROUND/FTZ rule
 *    follows the budget, one write-back port unless asked for four (the
 *    program then compiled for the default latencies), bad options fail;
 *  - the lane cost models (sw/compiler/device.c) give the measured chip
 *    builds back (16 contexts x 32 registers on the LFE5U-85F: 8 lanes
 *    with four write-back ports, 16 with one, LUT4s the binding limit; one
 *    lane more is over the share that routes), scale lane 0 and the EBR
 *    with the registers, and bound NUM_LANES through --device; a device
 *    without room for one lane is an error;
 *  - the scene-sized Verilated build `drift` (mk/rtl.mk RTL_CFG_drift:
 *    NUM_CONTEXTS=4 NUM_REGS=11 HAS_SUB=0 ROUND=1 FTZ=1, one write-back
 *    port, ADD_LATENCY = MUL_LATENCY = 4) reports exactly
 *    the parameters fp3 configure derives for scenes/drift.scene, runs that
 *    scene's compiled program bit-exact with its golden model, refuses a
 *    program with sub naming HAS_SUB, and -- loaded past the host's check
 *    -- stops such a program with ILLEGAL_INSN at the sub's pc.
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
#include "configure.h"
#include "engine.h"
#include "fp3_isa.h"
#include "image.h"
#include "mscene.h"
#include "objects.h"
#include "../sim/fp3_model.h"

extern const fp3_model_ops fp3_model_drift;

static fp3_config full_config(void) {
  fp3_config c;
  memset(&c, 0, sizeof c);
  c.num_contexts = 1;
  c.num_regs = 32;
  c.imem_depth = 256;
  c.has_add = c.has_sub = c.has_mul = 1;
  c.has_div = c.has_sqrt = c.has_sign = 1;
  return c;
}

static void test_check_units(void **state) {
  (void)state;
  const uint64_t prog[] = {
      fp3_insn_make(FP3_OP_LI, 1, 0, 0, 0x3F800000u), fp3_insn_make(FP3_OP_ADD, 2, 1, 1, 0),
      fp3_insn_make(FP3_OP_MUL, 3, 2, 1, 0),          fp3_insn_make(FP3_OP_SUB, 4, 3, 1, 0),
      fp3_insn_make(FP3_OP_ENDI, 0, 0, 0, 1),
  };
  const size_t n = sizeof prog / sizeof prog[0];
  char msg[256];
  fp3_config c = full_config();
  assert_int_equal(fp3_config_check_program(&c, prog, n, msg, sizeof msg), 0);
  assert_int_equal(fp3_config_check_program(&c, prog, 0, msg, sizeof msg), 0);

  c.has_mul = 0;
  assert_int_equal(fp3_config_check_program(&c, prog, n, msg, sizeof msg), -1);
  assert_string_equal(msg, "the program uses mul (pc 2), but this hardware has no multiplier "
                           "(built with HAS_MUL=0)");
  /* only the words given count */
  assert_int_equal(fp3_config_check_program(&c, prog, 2, msg, sizeof msg), 0);

  c = full_config();
  c.has_sub = 0;
  assert_int_equal(fp3_config_check_program(&c, prog, n, msg, sizeof msg), -1);
  assert_string_equal(msg, "the program uses sub (pc 3), but this hardware has an adder that "
                           "cannot subtract (built with HAS_SUB=0)");
  assert_int_equal(fp3_config_check_program(&c, prog, 3, msg, sizeof msg), 0);

  c = full_config();
  c.has_add = 0;
  assert_int_equal(fp3_config_check_program(&c, prog, n, msg, sizeof msg), -1);
  assert_string_equal(msg, "the program uses add (pc 1), but this hardware has no adder "
                           "(built with HAS_ADD=0)");
  /* sub needs the adder too */
  const uint64_t sub_only[] = {fp3_insn_make(FP3_OP_NOP, 0, 0, 0, 0),
                               fp3_insn_make(FP3_OP_SUB, 1, 2, 3, 0)};
  c.has_sub = 1;
  assert_int_equal(fp3_config_check_program(&c, sub_only, 2, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "uses sub (pc 1)"));
  assert_non_null(strstr(msg, "HAS_ADD=0"));

  /* div, sqrt and the sign group, each on its own parameter */
  const uint64_t ext[] = {fp3_insn_make(FP3_OP_SQRT, 1, 2, 0, 0),
                          fp3_insn_make(FP3_OP_MAX, 2, 1, 1, 0),
                          fp3_insn_make(FP3_OP_DIV, 3, 2, 1, 0)};
  c = full_config();
  assert_int_equal(fp3_config_check_program(&c, ext, 3, msg, sizeof msg), 0);
  c.has_div = 0;
  assert_int_equal(fp3_config_check_program(&c, ext, 3, msg, sizeof msg), -1);
  assert_string_equal(msg, "the program uses div (pc 2), but this hardware has no divider "
                           "(built with HAS_DIV=0)");
  assert_int_equal(fp3_config_check_program(&c, ext, 2, msg, sizeof msg), 0);
  c = full_config();
  c.has_sqrt = 0;
  assert_int_equal(fp3_config_check_program(&c, ext, 3, msg, sizeof msg), -1);
  assert_string_equal(msg, "the program uses sqrt (pc 0), but this hardware has no square root "
                           "(built with HAS_SQRT=0)");
  c = full_config();
  c.has_sign = 0;
  assert_int_equal(fp3_config_check_program(&c, ext, 3, msg, sizeof msg), -1);
  assert_string_equal(msg, "the program uses max (pc 1), but this hardware has no sign group "
                           "(built with HAS_SIGN=0)");
}

static void test_engine_load_refuses(void **state) {
  (void)state;
  fp3_engine *e = fp3_engine_iss_new();
  assert_non_null(e);
  assert_int_equal(e->config.has_add, 1);
  assert_int_equal(e->config.has_sub, 1);
  assert_int_equal(e->config.has_mul, 1);
  const uint64_t prog[] = {fp3_insn_make(FP3_OP_MUL, 1, 2, 3, 0),
                           fp3_insn_make(FP3_OP_HALT, 0, 0, 0, 0)};
  assert_int_equal(fp3_engine_load(e, prog, 2), 0);
  e->config.has_mul = 0; /* as if the build had no multiplier */
  assert_int_equal(fp3_engine_load(e, prog, 2), -1);
  assert_non_null(strstr(fp3_engine_error(e), "uses mul (pc 0)"));
  assert_non_null(strstr(fp3_engine_error(e), "HAS_MUL=0"));
  fp3_engine_free(e);
}

#define SHIP "models/ship.fp3m"

/* A ship scene file as a scene of the ship model. */
static void read_scene(const char *path, fp3_mscene *sc) {
  char msg[300];
  if (fp3_mscene_read_any(path, SHIP, sc, msg, sizeof msg)) fail_msg("%s", msg);
}

/* n generated ships (seed) as a scene of the ship model. */
static void generate(uint64_t seed, size_t n, fp3_mscene *sc) {
  fp3_scene ships;
  char msg[300];
  assert_int_equal(fp3_scene_generate(seed, n, 1.0f / 60.0f, &ships), 0);
  if (fp3_mscene_from_ships(&ships, SHIP, "test", sc, msg, sizeof msg)) fail_msg("%s", msg);
  fp3_scene_free(&ships);
}

/* The defaults for a ship scene: the paper's RK4. */
static void ship_defaults(fp3_configure_opts *o) {
  fp3_configure_defaults(o);
  o->integrator = "rk4se";
}

static fp3_configure_result configure(const fp3_mscene *sc, const fp3_configure_opts *o) {
  fp3_configure_result r;
  char msg[300];
  if (fp3_configure_model(sc, o, &r, NULL, msg, sizeof msg)) fail_msg("%s", msg);
  return r;
}

/* Program c on engine e for every object of sc, `steps` integrations,
 * checked against c's golden model: 0 with *res, or -1 with msg. */
static int run_scene(fp3_engine *e, fp3_compiled *c, const fp3_mscene *sc, uint32_t steps,
                     fp3_state_result *res, char *msg, size_t n) {
  fp3_scene_gold g;
  fp3_scene_gold_init(&g, c, sc);
  const fp3_image *img = fp3_compiled_image(c);
  return fp3_run_state_objects(e, img->words, img->n, sc->n, steps, e->config.mode, &g.golden,
                               res, msg, n);
}

static void expect_line(const fp3_configure_result *r, const char *want) {
  char line[256];
  fp3_configure_line(&r->cfg, line, sizeof line);
  assert_string_equal(line, want);
}

static void test_derive_scenes(void **state) {
  (void)state;
  fp3_configure_opts o;
  ship_defaults(&o);
  static const struct {
    const char *path, *line;
  } cases[] = {
      {"scenes/drift.scene", "NUM_CONTEXTS=4 NUM_LANES=2 NUM_REGS=11 HAS_ADD=1 HAS_SUB=0 HAS_MUL=1 HAS_DIV=0 HAS_SQRT=0 HAS_SIGN=0 ROUND=1 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=4 WB_PORTS=1"},
      {"scenes/coast.scene", "NUM_CONTEXTS=5 NUM_LANES=2 NUM_REGS=11 HAS_ADD=1 HAS_SUB=1 HAS_MUL=1 HAS_DIV=0 HAS_SQRT=0 HAS_SIGN=0 ROUND=1 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=4 WB_PORTS=1"},
      {"scenes/harbour.scene",
       "NUM_CONTEXTS=5 NUM_LANES=7 NUM_REGS=12 HAS_ADD=1 HAS_SUB=1 HAS_MUL=1 HAS_DIV=0 HAS_SQRT=0 HAS_SIGN=0 ROUND=1 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=4 WB_PORTS=1"},
  };
  for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
    fp3_mscene sc;
    read_scene(cases[i].path, &sc);
    fp3_configure_result r = configure(&sc, &o);
    expect_line(&r, cases[i].line);
    /* RNE is the reference: allowed, nothing added */
    assert_true(r.allowed[0]);
    assert_true(r.added[0] == 0.0);
    assert_true(r.err[0] > 0.0 && r.err[0] < 1e-2);
    fp3_mscene_free(&sc);
  }

  /* drift: where the units are (pcs of the compiled program) */
  fp3_mscene sc;
  read_scene("scenes/drift.scene", &sc);
  fp3_configure_result r = configure(&sc, &o);
  assert_int_equal(r.unit_pc[1], -1);
  assert_true(r.unit_pc[0] >= 0 && r.unit_pc[2] >= 0);
  assert_int_equal(r.body_insns, 4);
  assert_int_equal(r.contexts_issue, 4);

  /* four write-back ports asked for: the default latencies, and the
   * harbour's contexts follow its shorter integration (86 cycles for 22
   * instructions, against 94 with one port) */
  fp3_mscene hb;
  read_scene("scenes/harbour.scene", &hb);
  o.wb_ports = 4;
  r = configure(&hb, &o);
  expect_line(&r, "NUM_CONTEXTS=4 NUM_LANES=8 NUM_REGS=12 HAS_ADD=1 HAS_SUB=1 HAS_MUL=1 HAS_DIV=0 HAS_SQRT=0 HAS_SIGN=0 ROUND=1 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=3 WB_PORTS=4");
  assert_int_equal(r.est_later, 86);
  o.wb_ports = 1;
  r = configure(&hb, &o);
  assert_int_equal(r.cfg.wb_ports, 1);
  assert_int_equal(r.est_later, 94);
  assert_int_equal(r.contexts_issue, 5);
  fp3_mscene_free(&hb);
  ship_defaults(&o);

  /* a budget no mode meets but RNE's own: only FTZ, which adds nothing
   * here (no subnormals), is allowed besides RNE */
  o.budget = 1e-15;
  r = configure(&sc, &o);
  assert_false(r.allowed[1]);
  assert_true(r.allowed[2]);
  assert_int_equal(r.cfg.mode.round, FPREF_RNE);
  assert_int_equal(r.cfg.mode.ftz, 1);

  /* one object: one context */
  const size_t drift_n = sc.n;
  sc.n = 1;
  ship_defaults(&o);
  r = configure(&sc, &o);
  assert_int_equal(r.cfg.num_contexts, 1);
  sc.n = drift_n;
  fp3_mscene_free(&sc);

  /* 100 objects, one context each: 64 */
  generate(5, 100, &sc);
  o.context_per_object = 1;
  r = configure(&sc, &o);
  assert_int_equal(r.cfg.num_contexts, 64);
  assert_int_equal(r.cfg.num_lanes, 2);   /* ceil(100 / 64) */
  o.context_per_object = 0;
  r = configure(&sc, &o);
  assert_int_equal(r.cfg.num_contexts, 5);
  assert_int_equal(r.cfg.num_lanes, FP3_CONFIGURE_MAX_LANES);   /* ceil(100 / 5) = 20, capped */
  o.max_lanes = 5;
  r = configure(&sc, &o);
  assert_int_equal(r.cfg.num_lanes, 5);
  o.max_lanes = FP3_CONFIGURE_MAX_LANES;
  /* euler: 6 instructions, 14 cycles: 3 contexts; 7 registers */
  o.integrator = "euler";
  r = configure(&sc, &o);
  expect_line(&r, "NUM_CONTEXTS=3 NUM_LANES=16 NUM_REGS=7 HAS_ADD=1 HAS_SUB=1 HAS_MUL=1 HAS_DIV=0 HAS_SQRT=0 HAS_SIGN=0 ROUND=1 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=4 WB_PORTS=1");

  /* a device bounds the lanes: 100 objects at 5 contexts want 20 lanes,
   * the LFE5U-45F holds fewer (by the one-port model) */
  o.integrator = "rk4se";
  o.device = fp3_device_find("ecp5-45");
  assert_non_null(o.device);
  r = configure(&sc, &o);
  assert_int_equal(r.lanes_scene, 20);
  assert_int_equal(r.cfg.num_lanes, r.fit.max_lanes);
  assert_int_equal(r.fit.wb_ports, 1);
  assert_true(r.fit.max_lanes >= 1 && r.fit.max_lanes < FP3_CONFIGURE_MAX_LANES);
  /* ... and fewer still with four ports */
  const unsigned lanes1 = r.fit.max_lanes;
  o.wb_ports = 4;
  r = configure(&sc, &o);
  assert_int_equal(r.fit.wb_ports, 4);
  assert_true(r.fit.max_lanes >= 1 && r.fit.max_lanes < lanes1);
  o.wb_ports = 0;
  o.device = NULL;

  /* bad options and input */
  char msg[300];
  fp3_configure_result bad;
  o.integrator = "leapfrog";
  assert_int_equal(fp3_configure_model(&sc, &o, &bad, NULL, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "leapfrog"));
  ship_defaults(&o);
  o.budget = 0.0;
  assert_int_equal(fp3_configure_model(&sc, &o, &bad, NULL, msg, sizeof msg), -1);
  o.budget = NAN;
  assert_int_equal(fp3_configure_model(&sc, &o, &bad, NULL, msg, sizeof msg), -1);
  ship_defaults(&o);
  o.steps = 0;
  assert_int_equal(fp3_configure_model(&sc, &o, &bad, NULL, msg, sizeof msg), -1);
  ship_defaults(&o);
  o.wb_ports = 2;
  assert_int_equal(fp3_configure_model(&sc, &o, &bad, NULL, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "want 1 or 4"));
  const size_t all_n = sc.n;
  sc.n = 0;
  ship_defaults(&o);
  assert_int_equal(fp3_configure_model(&sc, &o, &bad, NULL, msg, sizeof msg), -1);
  sc.n = all_n;
  o.device = fp3_device_find("ecp5-25");
  o.wb_ports = 4;   /* the one-port model finds room for 2 lanes */
  assert_int_equal(fp3_configure_model(&sc, &o, &bad, NULL, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "LFE5U-25F"));
  assert_non_null(strstr(msg, "does not hold one lane"));
  fp3_mscene_free(&sc);
}

/* The lane cost model against the chip build it was measured on, and its
 * scaling and limits. */
static void test_device_lanes(void **state) {
  (void)state;
  fp3_device_fit fit;
  const fp3_device *d85 = fp3_device_find("ecp5-85");
  assert_non_null(d85);
  assert_string_equal(d85->part, "LFE5U-85F");
  assert_int_equal(d85->luts, 83640);
  assert_null(fp3_device_find("ecp5"));
  assert_null(fp3_device_find("ecp5-85x"));
  /* the chip build: 13,240 + 13,429 + 7 x 3,962 = 54,403 <= 54,449; a
   * ninth lane would need 58,365 */
  assert_int_equal(fp3_device_lanes(d85, 16, 32, 1, 4, &fit), 8);
  assert_int_equal(fit.wb_ports, 4);
  assert_int_equal(fit.luts_lane0, 13429);
  assert_int_equal(fit.luts_allowed, 54449);
  assert_int_equal(fit.ebr_lane, 8);
  assert_int_equal(fit.dsp_lane, 4);
  assert_string_equal(fit.limit, "LUT4s (routing)");
  /* a quarter of the registers: lane 0's flags and table a quarter,
   * rounded up */
  assert_int_equal(fp3_device_lanes(d85, 4, 32, 1, 4, &fit), 9);   /* 13,240 + 6,329 + 8 x 3,962 */
  assert_int_equal(fit.luts_lane0, 3962 + 2367);
  /* 64 contexts x 32 registers: lane 0's table four times the chip
   * build's (41,830 LUT4s), more than the share that routes beside the
   * fixed part; 4 EBR a bank */
  assert_int_equal(fp3_device_lanes(d85, 64, 32, 1, 4, &fit), 0);
  assert_int_equal(fit.luts_lane0, 3962 + 4 * 9467);
  assert_int_equal(fit.ebr_lane, 32);
  assert_string_equal(fit.limit, "LUT4s (routing)");
  /* no multiplier: no MULT18X18D */
  fp3_device_lanes(d85, 16, 32, 0, 4, &fit);
  assert_int_equal(fit.dsp_lane, 0);
  /* one write-back port, the chip build of 16 lanes: 10,281 + 16 x 348
   * (fp3_top and fp3_axil, 15,849) + 4,080 + 15 x 2,646 = 59,619 <=
   * 59,635 (71.3 %); a 17th lane would need 62,613 */
  assert_int_equal(fp3_device_lanes(d85, 16, 32, 1, 1, &fit), 16);
  assert_int_equal(fit.wb_ports, 1);
  assert_int_equal(fit.luts_fixed + fit.luts_lane0 + 15 * fit.luts_lane, 59619);
  assert_int_equal(fit.luts_allowed, 59635);
  assert_int_equal(fit.routable_permille, 713);
  assert_int_equal(fit.ebr_fixed + 16 * fit.ebr_lane, 35);   /* the build's 35 EBR */
  assert_int_equal(fit.dsp_lane, 4);
  assert_string_equal(fit.limit, "LUT4s (routing)");
  /* its lane 0 beyond a further lane (busy flags only) scales the same
   * way: 1,434 at 512 registers, a quarter at 128 */
  fp3_device_lanes(d85, 4, 32, 1, 1, &fit);
  assert_int_equal(fit.luts_lane0 - fit.luts_lane, 359);
  /* the LFE5U-45F, 128 registers: 13,240 + 6,329 + 2 x 3,962 <= 28,545,
   * a fourth lane not */
  const fp3_device *d45 = fp3_device_find("ecp5-45");
  assert_non_null(d45);
  assert_int_equal(fp3_device_lanes(d45, 8, 16, 1, 4, &fit), 3);
  /* the LFE5U-25F: the fixed part and lane 0 are 13,240 + 4,036 of 15,811 */
  const fp3_device *d25 = fp3_device_find("ecp5-25");
  assert_non_null(d25);
  assert_int_equal(fp3_device_lanes(d25, 1, 4, 1, 4, &fit), 0);
  /* ... with one port: 10,281 + 2,996 + 2,994 <= 17,317 (71.3 %) */
  assert_int_equal(fp3_device_lanes(d25, 1, 4, 1, 1, &fit), 2);
}

/* The compiled program registers: the one the derived NUM_REGS makes
 * fp3 run --scene compile must name registers below it. */
static void test_registers_fit(void **state) {
  (void)state;
  fp3_configure_opts o;
  ship_defaults(&o);
  const char *ig[] = {"euler", "symeuler", "rk2", "rk4se"};
  fp3_mscene sc;
  generate(11, 16, &sc);
  unsigned char zero[FP3_MODEL_MAX_VARS];
  fp3_mscene_zero(&sc, zero);
  for (size_t i = 0; i < 4; i++) {
    o.integrator = ig[i];
    fp3_configure_result r;
    fp3_compiled *c = NULL;
    char msg[300];
    assert_int_equal(fp3_configure_model(&sc, &o, &r, &c, msg, sizeof msg), 0);
    assert_true(r.regs_used <= r.cfg.num_regs);
    assert_true(r.cfg.num_regs <= r.regs_default);
    /* the program compiled for the build, as fp3 run --scene does */
    fp3_compile_opts co;
    fp3_compile_opts_for(&co, &r.cfg);
    fp3_compiled *c2 = NULL;
    assert_int_equal(fp3_compile_model(sc.model, ig[i], &co, zero, &c2, msg, sizeof msg), 0);
    assert_string_equal(fp3_compiled_text(c), fp3_compiled_text(c2));
    assert_int_equal(fp3_compiled_stats(c2)->est_cycles_later, r.est_later);
    fp3_compiled_free(c);
    fp3_compiled_free(c2);
  }
  fp3_mscene_free(&sc);
}

/* The scene-sized build runs its scene bit-exact and refuses the rest. */
static void test_sized_rtl(void **state) {
  (void)state;
  fp3_engine *e = fp3_engine_rtl_new_model(&fp3_model_drift, NULL);
  assert_non_null(e);
  fp3_mscene sc;
  read_scene("scenes/drift.scene", &sc);
  fp3_configure_opts o;
  ship_defaults(&o);
  fp3_configure_result r;
  fp3_compiled *c = NULL;
  char msg[300];
  assert_int_equal(fp3_configure_model(&sc, &o, &r, &c, msg, sizeof msg), 0);
  /* the model reports the derived parameters */
  assert_int_equal(e->config.num_contexts, r.cfg.num_contexts);
  assert_int_equal(e->config.num_lanes, r.cfg.num_lanes);
  assert_int_equal(e->config.num_regs, r.cfg.num_regs);
  assert_int_equal(e->config.has_add, r.cfg.has_add);
  assert_int_equal(e->config.has_sub, 0);
  assert_int_equal(e->config.has_sub, r.cfg.has_sub);
  assert_int_equal(e->config.has_mul, r.cfg.has_mul);
  assert_int_equal(e->config.has_div, r.cfg.has_div);
  assert_int_equal(e->config.has_sqrt, r.cfg.has_sqrt);
  assert_int_equal(e->config.has_sign, 0);
  assert_int_equal(e->config.has_sign, r.cfg.has_sign);
  assert_int_equal(e->config.mode.round, r.cfg.mode.round);
  assert_int_equal(e->config.mode.ftz, r.cfg.mode.ftz);
  assert_int_equal(e->config.wb_ports, 1);
  assert_int_equal(e->config.wb_ports, r.cfg.wb_ports);
  assert_int_equal(e->config.add_latency, r.cfg.add_latency);
  assert_int_equal(e->config.mul_latency, r.cfg.mul_latency);
  /* the program fp3 run --scene compiles for the build is configure's */
  fp3_compile_opts bo;
  fp3_compile_opts_for(&bo, &e->config);
  fp3_compiled *cb = NULL;
  unsigned char zero[FP3_MODEL_MAX_VARS];
  fp3_mscene_zero(&sc, zero);
  assert_int_equal(fp3_compile_model(sc.model, "rk4se", &bo, zero, &cb, msg, sizeof msg), 0);
  assert_string_equal(fp3_compiled_text(cb), fp3_compiled_text(c));
  fp3_compiled_free(cb);

  /* the scene's program, bit-exact, every object, every integration */
  fp3_state_result res;
  if (run_scene(e, c, &sc, 300, &res, msg, sizeof msg)) fail_msg("%s", msg);
  assert_int_equal(res.objects, 8);
  assert_int_equal(res.batches, 1);   /* 4 contexts x 2 lanes: all 8 at once */
  assert_int_equal(res.lanes, 2);
  assert_int_equal(res.error, FP3_ERR_NONE);
  assert_int_equal(res.mismatches, 0);
  fp3_state_result_free(&res);
  fp3_compiled_free(c);

  /* a scene with drag needs sub: refused before running, naming it */
  fp3_mscene coast;
  read_scene("scenes/coast.scene", &coast);
  fp3_compile_opts co;
  fp3_compile_opts_for(&co, &e->config);
  fp3_mscene_zero(&coast, zero);
  assert_int_equal(fp3_compile_model(coast.model, "rk4se", &co, zero, &c, msg, sizeof msg), 0);
  assert_int_equal(run_scene(e, c, &coast, 10, &res, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "uses sub (pc "));
  assert_non_null(strstr(msg, "built with HAS_SUB=0"));

  /* past the host's check the RTL itself stops at the sub */
  const fp3_image *img = fp3_compiled_image(c);
  uint32_t sub_pc = UINT32_MAX;
  for (size_t pc = 0; pc < img->n && sub_pc == UINT32_MAX; pc++)
    if (fp3_insn_opc(img->words[pc]) == FP3_OP_SUB) sub_pc = (uint32_t)pc;
  assert_true(sub_pc != UINT32_MAX);
  assert_int_equal(e->ops->load_program(e, img->words, img->n), 0);
  fp3_status st;
  assert_int_equal(fp3_engine_run(e, 5, NULL, &st), 0);
  assert_int_equal(st.error, FP3_ERR_ILLEGAL_INSN);
  assert_int_equal(st.fault_pc, sub_pc);
  fp3_compiled_free(c);
  fp3_mscene_free(&coast);
  fp3_mscene_free(&sc);
  fp3_engine_free(e);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_check_units),
      cmocka_unit_test(test_engine_load_refuses),
      cmocka_unit_test(test_derive_scenes),
      cmocka_unit_test(test_device_lanes),
      cmocka_unit_test(test_registers_fit),
      cmocka_unit_test(test_sized_rtl),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
