/*
 * bench_parallel.c -- throughput of many objects sharing one arithmetic
 * unit (make bench-parallel).
 *
 * For each Verilated build (NUM_CONTEXTS 1, 3, 8, 16, 32, 64) and each
 * scene size N = 1, 2, 4, ..., 64 objects of a model (generated from the
 * model file's default values, fp3_mscene_generate, seed 1), run the
 * program for STEPS integrations (every object checked bit for bit against
 * the golden model) and report cycles per object-step, the issue bound
 * (instructions issued per object-step: one issue per cycle), and the
 * utilization of the adder and the multiplier.  Cycle counts are exact,
 * so a short run measures them.
 *
 * The program: --program FILE.s (hand-written, bound to its `.model` or
 * --model, fp3_compile_bind), or the model compiled for --integrator
 * (--literal for the literal form) for each build's latencies; by
 * default the paper's programs/ship_rk4.s on models/ship.fp3m.
 *
 * Usage: bench_parallel [--model FILE.fp3m] [--program FILE.s |
 *        --integrator NAME [--literal]] [--steps N] [--csv FILE]
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asm.h"
#include "bench.h"
#include "compile.h"
#include "engine.h"
#include "model.h"
#include "mscene.h"
#include "../sim/fp3_model.h"

extern const fp3_model_ops fp3_model_nc1, fp3_model_nc3, fp3_model_nc16,
    fp3_model_nc32, fp3_model_nc64;

#define DEFAULT_PROGRAM "programs/ship_rk4.s"

static int usage(int rc) {
  fprintf(rc ? stderr : stdout,
          "usage: bench_parallel [--model FILE.fp3m] [--program FILE.s | --integrator NAME "
          "[--literal]]\n                      [--steps N] [--csv FILE]\n");
  return rc;
}

/* The program of model m for engine e: the bound image, or m compiled
 * for integ (literal or folded) for e's build.  NULL with a message. */
static fp3_compiled *program_for(const fp3_model *m, const fp3_image *img, const char *path,
                                 const char *integ, int literal, const fp3_engine *e) {
  fp3_compile_opts o;
  fp3_compile_opts_for(&o, &e->config);
  fp3_compiled *c = NULL;
  char msg[512];
  int bad;
  if (path) {
    bad = fp3_compile_bind(m, img, path, &o, &c, msg, sizeof msg);
  } else {
    o.fold = o.drop_zero = !literal;
    bad = fp3_compile_model(m, integ, &o, NULL, &c, msg, sizeof msg);
  }
  if (bad) fprintf(stderr, "bench_parallel: %s\n", msg);
  return bad ? NULL : c;
}

int main(int argc, char **argv) {
  uint32_t steps = 200;
  const char *csv_path = "build/bench/parallel.csv", *model_path = NULL, *program = NULL;
  const char *integ = NULL;
  int literal = 0;
  for (int i = 1; i < argc; i++) {
    if (strcmp(argv[i], "--steps") == 0 && i + 1 < argc) {
      steps = (uint32_t)strtoul(argv[++i], NULL, 10);
    } else if (strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
      csv_path = argv[++i];
    } else if (strcmp(argv[i], "--model") == 0 && i + 1 < argc) {
      model_path = argv[++i];
    } else if (strcmp(argv[i], "--program") == 0 && i + 1 < argc) {
      program = argv[++i];
    } else if (strcmp(argv[i], "--integrator") == 0 && i + 1 < argc) {
      integ = argv[++i];
    } else if (strcmp(argv[i], "--literal") == 0) {
      literal = 1;
    } else {
      return usage(strcmp(argv[i], "--help") == 0 ? 0 : 2);
    }
  }
  if (steps == 0 || (program && integ)) {
    fprintf(stderr, "bench_parallel: --steps must be >= 1; --program or --integrator\n");
    return 2;
  }
  if (!program && !integ && !model_path) program = DEFAULT_PROGRAM;
  fp3_image img;
  char *errs = NULL, msg[512];
  fp3_image_init(&img);
  if (program && fp3_asm_file(program, &img, &errs)) {
    fprintf(stderr, "%s", errs ? errs : "bench_parallel: assembly failed\n");
    free(errs);
    return 2;
  }
  free(errs);
  if (!model_path) model_path = program && img.model[0] ? img.model : "models/ship.fp3m";
  fp3_model *m = malloc(sizeof *m);
  if (!m || fp3_model_load(model_path, m, msg, sizeof msg)) {
    fprintf(stderr, "bench_parallel: %s\n", m ? msg : "out of memory");
    free(m);
    return 2;
  }
  /* object 0: the model file's values; the others scaled from them */
  float in[FP3_MODEL_MAX_VARS], y0[FP3_MODEL_MAX_VARS];
  for (unsigned k = 0; k < m->nparam + m->nstate; k++) {
    const int st = k >= m->nparam;
    const unsigned q = st ? k - m->nparam : k;
    if (!(st ? m->state_has_def[q] : m->param_has_def[q])) {
      fprintf(stderr, "bench_parallel: %s gives %s '%s' no default value\n", m->file,
              st ? "state variable" : "param", st ? m->state[q] : m->param[q]);
      free(m);
      return 2;
    }
    if (st) y0[q] = m->state_def[q];
    else in[q] = m->param_def[q];
  }
  const struct {
    const char *name;
    const fp3_model_ops *ops; /* NULL: the default build */
  } builds[] = {{"nc1", &fp3_model_nc1},   {"nc3", &fp3_model_nc3},
                {"nc8", NULL},             {"nc16", &fp3_model_nc16},
                {"nc32", &fp3_model_nc32}, {"nc64", &fp3_model_nc64}};
  /* Written whole to a temporary name, renamed at the end. */
  char tmp[4200];
  FILE *csv = fp3_bench_csv_open(csv_path, tmp, sizeof tmp);
  if (!csv) {
    free(m);
    return 1;
  }
  printf("model %s (%s), %s %s\n", m->name, m->file, program ? "program" : "integrator",
         program ? program : integ ? integ : "rk4");
  fprintf(csv, "num_contexts,add_latency,mul_latency,objects,steps,cycles,cycles_per_object_step,"
               "issued_per_object_step,add_utilization,mul_utilization,golden_mismatches\n");
  printf("%12s %9s %8s %14s %12s %8s %8s\n", "NUM_CONTEXTS", "latencies", "objects",
         "cycles/obj-step", "issue bound", "adder", "mult");
  int rc = 0;
  for (size_t b = 0; b < sizeof builds / sizeof builds[0] && rc == 0; b++) {
    fp3_engine *e = builds[b].ops ? fp3_engine_rtl_new_model(builds[b].ops, NULL)
                                  : fp3_engine_rtl_new(NULL);
    if (!e) {
      fprintf(stderr, "bench_parallel: cannot create build %s\n", builds[b].name);
      rc = 1;
      break;
    }
    for (size_t n = 1; n <= 64 && rc == 0; n *= 2) {
      fp3_model *mc = malloc(sizeof *mc); /* the scene owns its copy */
      fp3_mscene sc;
      fp3_state_result res;
      memset(&res, 0, sizeof res);
      if (!mc) {
        rc = 1;
        break;
      }
      memcpy(mc, m, sizeof *mc);
      if (fp3_mscene_generate(mc, in, y0, n, 1, &sc)) {
        fprintf(stderr, "bench_parallel: out of memory\n");
        rc = 1;
        break;
      }
      fp3_compiled *c = program_for(sc.model, &img, program, integ ? integ : "rk4", literal, e);
      fp3_scene_gold g;
      if (c) fp3_scene_gold_init(&g, c, &sc);
      if (!c || fp3_run_state_objects(e, fp3_compiled_image(c)->words, fp3_compiled_image(c)->n,
                                      sc.n, steps, FPREF_IEEE, &g.golden, &res, msg,
                                      sizeof msg)) {
        if (c) fprintf(stderr, "bench_parallel: %s, %zu objects: %s\n", builds[b].name, n, msg);
        rc = 1;
      } else {
        double os = (double)n * steps;
        double cpos = (double)res.cycles / os, bound = (double)res.issued / os;
        double au = (double)res.unit_issued[FP3_UNIT_ADD] / (double)res.cycles;
        double mu = (double)res.unit_issued[FP3_UNIT_MUL] / (double)res.cycles;
        printf("%12u %6u/%-2u %8zu %14.2f %12.2f %7.1f%% %7.1f%%%s\n", e->config.num_contexts,
               e->config.add_latency, e->config.mul_latency, n, cpos, bound, 100 * au, 100 * mu,
               res.mismatches ? "  GOLDEN MISMATCH" : "");
        fprintf(csv, "%u,%u,%u,%zu,%" PRIu32 ",%" PRIu64 ",%.4f,%.4f,%.4f,%.4f,%" PRIu64 "\n",
                e->config.num_contexts, e->config.add_latency, e->config.mul_latency, n, steps,
                res.cycles, cpos, bound, au, mu, res.mismatches);
        if (res.mismatches || res.error) rc = 1;
      }
      fp3_state_result_free(&res);
      fp3_compiled_free(c);
      fp3_mscene_free(&sc);
    }
    fp3_engine_free(e);
  }
  free(m);
  if (rc) { /* a failed run leaves no CSV */
    fclose(csv);
    remove(tmp);
    return rc;
  }
  if (fp3_bench_csv_close(csv, tmp, csv_path)) return 1;
  printf("CSV: %s\n", csv_path);
  return 0;
}
