/*
 * cmd_objects.c -- `fp3 run --objects N / --scene FILE`: many ships on the
 * contexts of an engine, every object checked against the golden model
 * after every integration, and the report (cmd_objects.h).
 */
#include "cmd_objects.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>

#include "analytic.h"
#include "fp3_isa.h"
#include "fpenv.h"
#include "fpref.h"
#include "report.h"

#define SHOW_OBJECTS 8 /* rows of the human report */

/* Exact v, s of object i after `steps` integrations. */
static void exact(const fp3_ship_params *o, uint32_t steps, double *v, double *s) {
  fp3_ship_exact(o->T, o->C, o->m, o->v0, o->s0, (double)steps * (double)o->h, v, s);
}

int fp3_cmd_run_objects(const fp3_objects_cmd *c) {
  fp3_scene sc;
  char msg[512];
  if (c->scene_path) {
    if (fp3_scene_read(c->scene_path, c->h, &sc, msg, sizeof msg)) {
      fprintf(stderr, "fp3 run: %s\n", msg);
      return 2;
    }
    if (c->objects && c->objects != sc.n) {
      fprintf(stderr, "fp3 run: --objects %zu, but %s has %zu objects\n", c->objects,
              c->scene_path, sc.n);
      fp3_scene_free(&sc);
      return 2;
    }
  } else if (fp3_scene_generate(c->seed, c->objects, c->h, &sc)) {
    fprintf(stderr, "fp3 run: out of memory for %zu objects\n", c->objects);
    return 1;
  }

  /* the scene compiler's program, compiled for this engine's latencies */
  const fp3_image *img = c->img;
  const fp3_golden_ref *golden = c->golden;
  const char *program = c->program;
  fp3_compiled *comp = NULL;
  fp3_golden_ref comp_golden;
  char comp_name[64];
  if (c->compile) {
    fp3_compile_opts o;
    if (c->copts) {
      o = *c->copts;
    } else {
      fp3_compile_opts_for(&o, &c->engine->config);
    }
    if (fp3_compile(&sc, c->integ_name, &o, c->scene_path, &comp, msg, sizeof msg)) {
      fprintf(stderr, "fp3 run: compiling the scene: %s\n", msg);
      fp3_scene_free(&sc);
      return 2;
    }
    img = fp3_compiled_image(comp);
    comp_golden = fp3_compiled_golden(comp);
    golden = &comp_golden;
    snprintf(comp_name, sizeof comp_name, "compiled (%s%s)", o.fold ? "folded" : "literal",
             o.drop_zero ? ", zero terms removed" : "");
    program = comp_name;
  }
  const unsigned insns = fp3_image_body_insns(img);

  fp3_objects_result res;
  if (fp3_run_objects(c->engine, img, &sc, c->steps, c->mode, golden, &res, msg,
                      sizeof msg)) {
    fprintf(stderr, "fp3 run: %s engine: %s\n", c->engine->ops->name, msg);
    fprintf(stderr, "FAIL: the %s engine failed\n", c->engine->ops->name);
    fp3_scene_free(&sc);
    fp3_compiled_free(comp);
    return 1;
  }
  const double object_steps = (double)res.objects * (double)c->steps;
  const double per_object_step = (double)res.cycles / object_steps;
  const double issue_bound = (double)res.issued / object_steps;
  const double add_util = res.cycles ? (double)res.unit_issued[FP3_UNIT_ADD] / (double)res.cycles : 0;
  const double mul_util = res.cycles ? (double)res.unit_issued[FP3_UNIT_MUL] / (double)res.cycles : 0;
  char flags[96];
  fp3_flags_text(res.flags, flags, sizeof flags);
  const int ok = res.mismatches == 0 && res.error == FP3_ERR_NONE;

  if (c->json) { /* the keys of every fp3 run (docs/json.md) */
    const char *eng = c->engine->ops->name;
    printf("{\"engine\": ");
    fp3_json_string(stdout, eng);
    printf(", \"cycles_counted\": \"%s\"",
           strcmp(eng, "iss") == 0 ? "instructions issued (the ISS issues one a cycle)"
                                   : "clock cycles");
    printf(", \"model\": \"ship\", \"model_file\": null, \"program\": ");
    if (comp) printf("null");
    else fp3_json_string(stdout, program);
    printf(", \"scene\": ");
    fp3_json_string(stdout, c->scene_path ? c->scene_path : "generated (--objects, --seed)");
    printf(", \"integrator\": ");
    fp3_json_string(stdout, c->integ_name);
    printf(", \"literal\": %s, \"words\": %zu, \"insns_per_step\": %u",
           comp ? "false" : "true", img->n, insns);
    printf(", \"registers_needed\": null, \"num_regs\": %u, \"est_cycles_per_step\": ",
           c->engine->config.num_regs);
    if (comp) printf("%u", fp3_compiled_stats(comp)->est_cycles_later);
    else printf("null");
    if (comp)
      printf(", \"literal_insns_per_step\": %u", fp3_compiled_stats(comp)->literal_body_insns);
    printf(", \"round\": \"%s\", \"ftz\": %s", fpenv_round_name(c->mode),
           c->mode.ftz ? "true" : "false");
    printf(", \"steps\": %" PRIu32 ", \"steps_done\": %" PRIu32 ", \"objects\": %zu", c->steps,
           res.error ? 0 : c->steps, res.objects);
    printf(", \"contexts\": %u, \"lanes\": %u, \"batches\": %zu", res.contexts, res.lanes,
           res.batches);
    printf(", \"cycles\": %" PRIu64 ", \"issued\": %" PRIu64 ", \"stalls\": %" PRIu64,
           res.cycles, res.issued, res.stalls);
    printf(", \"cycles_first_step\": null, \"cycles_later_step\": null");
    printf(", \"cycles_per_object_step\": %.9g", per_object_step);
    printf(", \"issued_per_object_step\": %.9g", issue_bound);
    printf(", \"utilization\": {\"add\": %.6f, \"mul\": %.6f}", add_util, mul_util);
    printf(", \"golden_mismatches\": %" PRIu64 ", \"first_mismatch\": ", res.mismatches);
    if (res.mismatches)
      printf("{\"object\": %zu, \"integration\": %" PRIu32 ", \"variable\": null}",
             res.first_object, res.first_step);
    else
      printf("null");
    printf(", \"nonfinite_from\": null, \"run_error\": ");
    if (res.error)
      printf("{\"error\": \"%s\", \"object\": %zu, \"pc\": %" PRIu32 "}",
             fp3_error_name(res.error), res.error_object, res.error_pc);
    else
      printf("null");
    printf(", \"flags\": \"%s\", \"flags_bits\": %" PRIu32, flags, res.flags);
    printf(", \"params\": null, \"max_error_ref\": null, \"results\": [");
    for (size_t i = 0; i < res.objects; i++) {
      double ve, se;
      exact(&sc.objs[i], c->steps, &ve, &se);
      printf("%s{\"v\": ", i ? ", " : "");
      fp3_json_float(stdout, fpref_float(res.v[i]));
      printf(", \"v_ref\": null");
      fp3_json_member_double(stdout, "v_exact", ve);
      fp3_json_member_float(stdout, "s", fpref_float(res.s[i]));
      printf(", \"s_ref\": null");
      fp3_json_member_double(stdout, "s_exact", se);
      printf("}");
    }
    printf("], \"pass\": %s}\n", ok ? "true" : "false");
  } else {
    printf("FP3 run: engine %s, program %s (%s), %zu objects, %" PRIu32 " integrations each\n",
           c->engine->ops->name, program, c->integ_name, res.objects, c->steps);
    printf("program: %u instructions per integration", insns);
    if (comp)
      printf(" (literal program %u); scheduler estimate %u cycles per integration of one object",
             fp3_compiled_stats(comp)->literal_body_insns,
             fp3_compiled_stats(comp)->est_cycles_later);
    printf("\n");
    printf("scene: %s; %u contexts x %u lanes per batch, %zu batch%s\n\n",
           c->scene_path ? c->scene_path : "generated (--seed)", res.contexts, res.lanes,
           res.batches, res.batches == 1 ? "" : "es");
    printf("  object          T          C          m          v    v exact          s    s exact\n");
    for (size_t i = 0; i < res.objects && i < SHOW_OBJECTS; i++) {
      const fp3_ship_params *o = &sc.objs[i];
      double ve, se;
      exact(o, c->steps, &ve, &se);
      printf("%8zu %10.4g %10.4g %10.4g %10.6g %10.6g %10.6g %10.6g\n", i, (double)o->T,
             (double)o->C, (double)o->m, (double)fpref_float(res.v[i]), ve,
             (double)fpref_float(res.s[i]), se);
    }
    if (res.objects > SHOW_OBJECTS) printf("     ... (%zu more)\n", res.objects - SHOW_OBJECTS);
    printf("\ngolden model: %" PRIu64 " mismatches in %.0f object-steps (v and s, bit for bit)\n",
           res.mismatches, object_steps);
    if (res.mismatches)
      printf("  first: object %zu, integration %" PRIu32 "\n", res.first_object, res.first_step);
    printf("cycles: %" PRIu64 " in all, %.2f per object-step (issued %.2f per object-step: "
           "the issue bound); paper: 418 per integration of one object\n",
           res.cycles, per_object_step, issue_bound);
    printf("utilization: adder %.1f %%, multiplier %.1f %%; %" PRIu64 " stall cycles\n",
           100.0 * add_util, 100.0 * mul_util, res.stalls);
    printf("flags: %s\n", flags);
    if (res.error)
      printf("error: object %zu: %s at pc %" PRIu32 "\n", res.error_object,
             fp3_error_text(res.error), res.error_pc);
    if (ok)
      printf("PASS: %zu objects x %" PRIu32 " integrations on %s bit-exact with the golden model\n",
             res.objects, c->steps, c->engine->ops->name);
    else
      printf("FAIL: %" PRIu64 " mismatches, error %s\n", res.mismatches,
             fp3_error_name(res.error));
  }
  fp3_objects_result_free(&res);
  fp3_scene_free(&sc);
  fp3_compiled_free(comp);
  return ok ? 0 : 1;
}
