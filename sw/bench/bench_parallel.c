/*
 * bench_parallel.c -- throughput of many objects sharing one arithmetic
 * unit (make bench-parallel).
 *
 * For each Verilated build (NUM_CONTEXTS 1, 3, 8, 16, 32, 64) and each
 * scene size N = 1, 2, 4, ..., 64 generated ships, run the ship RK4
 * program for STEPS integrations (every object checked bit for bit
 * against the golden model) and report cycles per object-step, the issue
 * bound (instructions issued per object-step: one issue per cycle), and
 * the utilization of the adder and the multiplier.  Cycle counts are
 * exact, so a short run measures them.
 *
 * Usage: bench_parallel [--steps N] [--csv FILE]
 */
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "engine.h"
#include "integrators.h"
#include "objects.h"
#include "../sim/fp3_model.h"

extern const fp3_model_ops fp3_model_nc1, fp3_model_nc3, fp3_model_nc16,
    fp3_model_nc32, fp3_model_nc64;

int main(int argc, char **argv) {
  uint32_t steps = 200;
  const char *csv_path = "build/bench/parallel.csv";
  for (int i = 1; i < argc; i++) {
    if (strcmp(argv[i], "--steps") == 0 && i + 1 < argc) {
      steps = (uint32_t)strtoul(argv[++i], NULL, 10);
    } else if (strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
      csv_path = argv[++i];
    } else {
      fprintf(stderr, "usage: bench_parallel [--steps N] [--csv FILE]\n");
      return strcmp(argv[i], "--help") == 0 ? 0 : 2;
    }
  }
  if (steps == 0) {
    fprintf(stderr, "bench_parallel: --steps must be >= 1\n");
    return 2;
  }
  const struct {
    const char *name;
    const fp3_model_ops *ops; /* NULL: the default build */
  } builds[] = {{"nc1", &fp3_model_nc1},   {"nc3", &fp3_model_nc3},
                {"nc8", NULL},             {"nc16", &fp3_model_nc16},
                {"nc32", &fp3_model_nc32}, {"nc64", &fp3_model_nc64}};
  fp3_image img;
  fp3_integ_golden rk4_store;
  fp3_golden_ref rk4;
  if (fp3_bench_ship_rk4(&img, &rk4_store, &rk4)) return 2;
  /* Written whole to a temporary name, renamed at the end. */
  char tmp[4200];
  FILE *csv = fp3_bench_csv_open(csv_path, tmp, sizeof tmp);
  if (!csv) return 1;
  fprintf(csv, "num_contexts,add_latency,mul_latency,objects,steps,cycles,cycles_per_object_step,"
               "issued_per_object_step,add_utilization,mul_utilization,golden_mismatches\n");
  printf("%12s %9s %8s %14s %12s %8s %8s\n", "NUM_CONTEXTS", "latencies", "objects",
         "cycles/obj-step", "issue bound", "adder", "mult");
  int rc = 0;
  for (size_t b = 0; b < sizeof builds / sizeof builds[0]; b++) {
    fp3_engine *e = builds[b].ops ? fp3_engine_rtl_new_model(builds[b].ops, NULL)
                                  : fp3_engine_rtl_new(NULL);
    if (!e) {
      fprintf(stderr, "bench_parallel: cannot create build %s\n", builds[b].name);
      rc = 1;
      break;
    }
    for (size_t n = 1; n <= 64; n *= 2) {
      fp3_scene sc;
      fp3_objects_result res;
      char msg[512];
      if (fp3_scene_generate(1, n, 1.0f / 60.0f, &sc) ||
          fp3_run_objects(e, &img, &sc, steps, FPREF_IEEE, &rk4, &res, msg, sizeof msg)) {
        fprintf(stderr, "bench_parallel: %s, %zu objects: %s\n", builds[b].name, n, msg);
        rc = 1;
        fp3_scene_free(&sc);
        continue;
      }
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
      fp3_objects_result_free(&res);
      fp3_scene_free(&sc);
    }
    fp3_engine_free(e);
  }
  if (fp3_bench_csv_close(csv, tmp, csv_path)) return 1;
  printf("CSV: %s\n", csv_path);
  return rc;
}
