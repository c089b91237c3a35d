/*
 * bench_chip.c -- lanes against the CPU (make bench-chip, docs/lanes.md).
 *
 * For each Verilated build of the lane series (8 contexts, NUM_LANES 1,
 * 2, 4, 8, 16; the default pipeline), the build for clock rate with one
 * lane and 8 or 16 contexts (fmax, f16) and the chip build (8 contexts
 * with the LFE5U-85F's lanes, mk/pnr.mk CHIP=ecp5-85) that are linked in,
 * run the ship's RK4 step (models/ship.fp3m, integrator rk4se) on
 * NUM_CONTEXTS x NUM_LANES ships (a generated scene), once with the
 * literal program (programs/ship_rk4.s, the paper's operations, bound to
 * the model by name) and once with the compiled one (fp3 compile, folded,
 * for the build's latencies); every object is checked against its golden
 * model after every integration (fp3_run_state_objects).  Reported: cycles per object-step, the
 * issue bound (instructions issued per object-step: the instructions of
 * one integration / NUM_LANES), their ratio (target <= 1.1), and how fast
 * the Verilated model runs on this host (object-steps per CPU second).
 *
 * Then, in the same run, the same binary32 step on this machine's CPU
 * (cpu_ship.c, -O3 -march=native -ffp-contract=off): one ship alone (a
 * dependent chain) and 1,024 ships in arrays; ns per object-step (median
 * of 5), every result checked bit for bit against the model's literal
 * rk4se golden model.  This reference is the ship's alone: it is C
 * written for the compiler to vectorize, the paper's comparison; a model's
 * own would need a C back end of the compiler.
 *
 * Then the spatial rows (docs/spatial.md): the ship's rk4se step, folded
 * and literal, as the spatial chip `make pnr-spatial` places it (the cores
 * of fp3_spatial_clock_cores, as many pipelines N as the area estimate
 * fits), on the
 * spatial engine (engine_spatial.h: the chip's Verilated RTL, built into
 * build/spatial-cache on first use, by $VERILATOR and $FP3_SPATIAL_CXX
 * if set, as fp3 run's): all of the engine's slots, at least
 * N (L + 3) objects, so the pipelines are full and the figure is their
 * rate, not their latency's.  Cycles are the chip's CYCLES register;
 * the bound is 1/N cycles per object-step.  Every object is checked
 * after every integration, as for the lanes.
 *
 * Last, the chip build's ns per object-step at the Fmax given with
 * --fmax-mhz (the median of the placement seeds, mk/pnr.mk; without it,
 * the table gives cycles only), and the spatial chips' at
 * --spatial-fmax-mhz (folded) and --spatial-literal-fmax-mhz (literal),
 * the medians of make pnr-spatial's seeds, against the paper's FPGA and
 * Pentium 4 and this CPU.
 *
 * Usage: bench_chip [--steps N] [--fmax-mhz F] [--spatial-fmax-mhz F]
 *                   [--spatial-literal-fmax-mhz F] [--csv FILE] [--no-spatial]
 */
#define _DEFAULT_SOURCE /* realpath */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "asm.h"
#include "bench.h"
#include "compile.h"
#include "cpu_ship.h"
#include "engine.h"
#include "engine_spatial.h"
#include "model.h"
#include "mscene.h"
#include "objects.h"
#include "spatial.h"
#include "../sim/fp3_model.h"

#define SHIP_MODEL "models/ship.fp3m"
#define SHIP_PROGRAM "programs/ship_rk4.s" /* the paper's RK4: rk4se */

/* The lane builds are linked as make bench-chip's BENCH_CHIP_MODELS say
 * (a model of many lanes takes long to Verilate and compile): weak, a build not
 * linked is reported and skipped. */
extern const fp3_model_ops fp3_model_l2 __attribute__((weak)),
    fp3_model_l4 __attribute__((weak)), fp3_model_l8 __attribute__((weak)),
    fp3_model_l16 __attribute__((weak)), fp3_model_fmax __attribute__((weak)),
    fp3_model_f16 __attribute__((weak)), fp3_model_chip __attribute__((weak));

/* The paper's figures (§5): ns per later integration of one ship on its
 * XC2V6000-4 at 8.888 ns, and the same step in software on a 3.4 GHz
 * Pentium 4. */
#define PAPER_FPGA_NS 3715.184
#define PAPER_P4_NS 56.11

/* CPU time of this process, in seconds: the host speeds and the CPU
 * reference are timed in it, not in wall-clock time, because the machine
 * is shared (another process's share of the cores is not this one's
 * cost). */
static double now_s(void) {
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

/* One measured run: a build, a program, n ships. */
typedef struct row {
  const char *build;
  unsigned contexts, lanes, fmax_pipe;
  const char *program;
  size_t objects;
  uint64_t cycles;
  double cpos, bound, host_osps;  /* cycles and issues per object-step, host speed */
  uint64_t mismatches;
  unsigned error;
} row;

/* n generated ships (seed 1) as a scene of the ship model. */
static int ship_scene(size_t n, fp3_mscene *sc) {
  fp3_scene ships;
  char msg[512];
  if (fp3_scene_generate(1, n, 1.0f / 60.0f, &ships)) {
    fprintf(stderr, "bench_chip: cannot generate %zu ships\n", n);
    return -1;
  }
  int rc = fp3_mscene_from_ships(&ships, SHIP_MODEL, "generated", sc, msg, sizeof msg);
  fp3_scene_free(&ships);
  if (rc) fprintf(stderr, "bench_chip: %s\n", msg);
  return rc;
}

/* Run program c on e for n generated ships, every object checked. */
static int measure(fp3_engine *e, const char *build, const char *prog_name, fp3_compiled *c,
                   size_t n, uint32_t steps, row *r) {
  fp3_mscene sc;
  fp3_state_result res;
  char msg[512];
  if (ship_scene(n, &sc)) return -1;
  fp3_scene_gold g;
  fp3_scene_gold_init(&g, c, &sc);
  const fp3_image *img = fp3_compiled_image(c);
  double t0 = now_s();
  int rc = fp3_run_state_objects(e, img->words, img->n, n, steps, e->config.mode, &g.golden, &res,
                                 msg, sizeof msg);
  double dt = now_s() - t0;
  fp3_mscene_free(&sc);
  if (rc) {
    fprintf(stderr, "bench_chip: %s, %s, %zu ships: %s\n", build, prog_name, n, msg);
    return -1;
  }
  const double os = (double)n * steps;
  *r = (row){build, e->config.num_contexts, e->config.num_lanes, e->config.fmax_pipe,
             prog_name, n, res.cycles, (double)res.cycles / os, (double)res.issued / os,
             os / dt, res.mismatches, res.error};
  fp3_state_result_free(&res);
  return 0;
}

/* The literal program (SHIP_PROGRAM, bound to model m) and the compiled
 * one, both for engine e's latencies and pipeline.  0, or -1 with the
 * message on stderr. */
static int ship_programs(const fp3_model *m, const fp3_engine *e, fp3_compiled **lit,
                         fp3_compiled **comp) {
  char msg[512];
  fp3_compile_opts o;
  fp3_compile_opts_for(&o, &e->config);
  const unsigned char zero[FP3_MODEL_MAX_VARS] = {0}; /* the generated ships use every term */
  if (fp3_compile_bind_file(m, SHIP_PROGRAM, &o, lit, msg, sizeof msg) ||
      fp3_compile_model(m, "rk4se", &o, zero, comp, msg, sizeof msg)) {
    fprintf(stderr, "bench_chip: %s\n", msg);
    return -1;
  }
  return 0;
}

/* A spatial row: the ship's rk4se, literal or folded, on the spatial
 * engine of the chip make pnr-spatial builds (as many pipelines as fit),
 * all of its slots.  *r as measure's, with contexts = the slots, lanes =
 * the pipelines, bound = 1 / pipelines; *lat the pipeline's latency.  0,
 * or -1 with the message on stderr. */
static int spatial_row(const fp3_model *m, int literal, uint32_t steps, row *r, unsigned *lat) {
  char msg[4096], root[4096];
  fp3_compile_opts co;
  fp3_compile_defaults(&co);
  co.fold = !literal;
  co.max_regs = FP3_MAX_REGS;
  const unsigned char zero[FP3_MODEL_MAX_VARS] = {0};
  fp3_compiled *c = NULL;
  fp3_spatial *sp = NULL;
  fp3_engine *e = NULL;
  int rc = -1;
  const char *prog = literal ? "literal" : "folded";
  if (fp3_compile_model(m, "rk4se", &co, zero, &c, msg, sizeof msg)) goto out;
  /* the pipelines that fit, from the generator's area estimate */
  fp3_spatial_opts so;
  fp3_spatial_defaults(&so);
  fp3_spatial_clock_cores(&so); /* what make pnr-spatial places */
  if (fp3_spatial_build(c, m, "rk4se", &so, &sp, msg, sizeof msg)) goto out;
  const unsigned fit = fp3_spatial_stats_of(sp)->fit;
  *lat = fp3_spatial_stats_of(sp)->latency;
  if (fit == 0) {
    snprintf(msg, sizeof msg, "the %s pipeline does not fit the LFE5U-85F once", prog);
    goto out;
  }
  if (!realpath(".", root)) {
    snprintf(msg, sizeof msg, "the working directory: %s", strerror(errno));
    goto out;
  }
  fp3_spatial_env env = {.root = root, .cache = "build/spatial-cache",
                         .verilator = getenv("VERILATOR"), .cxx = getenv("FP3_SPATIAL_CXX"),
                         .label = "bench_chip: spatial",
                         .pipelines = fit, .cores = &so};
  e = fp3_engine_spatial_new(c, m, "rk4se", FPREF_IEEE, &env, msg, sizeof msg);
  if (!e) goto out;
  const size_t n = e->config.num_contexts;
  if (n < (size_t)fit * (*lat + 3)) {
    snprintf(msg, sizeof msg, "%zu slots are fewer than %u pipelines x (L + 3) = %u", n, fit,
             fit * (*lat + 3));
    goto out;
  }
  if (measure(e, "spatial", prog, c, n, steps, r)) {
    msg[0] = 0;
    goto out;
  }
  r->lanes = fit;
  r->bound = 1.0 / fit;
  rc = 0;
out:
  if (rc && msg[0]) fprintf(stderr, "bench_chip: spatial, %s: %s\n", prog, msg);
  fp3_engine_free(e);
  fp3_spatial_free(sp);
  fp3_compiled_free(c);
  return rc;
}

/* The CPU reference over n ships of a generated scene: ns per object-step
 * (median of 5) of the array form (all n) and of one ship alone; -1 if a
 * result differs from the golden model's. */
static int cpu_reference(size_t n, uint32_t steps, double *array_ns, double *scalar_ns) {
  fp3_mscene sc;
  if (ship_scene(n, &sc)) return -1;
  const fp3_model *m = sc.model;
  const int iT = fp3_model_param(m, "T"), iC = fp3_model_param(m, "C"),
            im = fp3_model_param(m, "m"), iv = fp3_model_state(m, "v"),
            is = fp3_model_state(m, "s");
  float *mem = malloc(6 * n * sizeof *mem);
  if (!mem) {
    fp3_mscene_free(&sc);
    return -1;
  }
  cpu_ships a = {mem, mem + n, mem + 2 * n, mem + 3 * n, mem + 4 * n, mem + 5 * n, n};
  int rc = 0;
  /* bit-exact check first: 100 steps of every ship against the model's
   * literal rk4se (its minv = 1/m is the let the host computes) */
  for (size_t i = 0; i < n; i++) {
    const float *in = sc.in + i * m->nparam, *y0 = sc.y0 + i * m->nstate;
    a.T[i] = in[iT], a.C[i] = in[iC], a.minv[i] = 1.0f / in[im], a.h[i] = in[0];
    a.v[i] = y0[iv], a.s[i] = y0[is];
  }
  cpu_ship_steps_array(&a, 100);
  for (size_t i = 0; i < n; i++) {
    float y[2 * FP3_MODEL_MAX_VARS];
    const float *in = sc.in + i * m->nparam;
    memcpy(y, sc.y0 + i * m->nstate, m->nstate * sizeof *y);
    fp3_model_start_literal(m, "rk4se", in, y);
    for (int k = 0; k < 100; k++) fp3_model_step_literal(m, "rk4se", in, y);
    if (memcmp(&a.v[i], &y[iv], sizeof(float)) || memcmp(&a.s[i], &y[is], sizeof(float))) {
      fprintf(stderr, "bench_chip: the CPU reference differs from the golden model (ship %zu)\n",
              i);
      rc = -1;
    }
  }
  double t_arr[5], t_one[5];
  const uint32_t one_steps = steps * 100;
  for (int r = 0; r < 5; r++) {
    double t0 = now_s();
    cpu_ship_steps_array(&a, steps);
    t_arr[r] = (now_s() - t0) * 1e9 / ((double)n * steps);
    t0 = now_s();
    cpu_ship_steps_scalar(&a, 0, one_steps);
    t_one[r] = (now_s() - t0) * 1e9 / one_steps;
  }
  qsort(t_arr, 5, sizeof t_arr[0], cmp_double);
  qsort(t_one, 5, sizeof t_one[0], cmp_double);
  *array_ns = t_arr[2];
  *scalar_ns = t_one[2];
  /* keep the results live */
  volatile float sink = a.v[0] + a.s[n - 1];
  (void)sink;
  free(mem);
  fp3_mscene_free(&sc);
  return rc;
}

/* The ns table's row of spatial chip r (program prog): its cycles per
 * object-step at fmax_mhz, or the cycles alone (fmax_mhz 0: not given
 * with option opt); nothing if r did not run. */
static void spatial_ns_row(const row *r, const char *prog, double fmax_mhz, const char *opt) {
  if (!(r->cpos > 0.0)) return;
  if (fmax_mhz > 0.0)
    printf("| FP3 spatial chip (%u pipelines), %s RK4: %.3f cycles at %.1f MHz | %.2f |\n",
           r->lanes, prog, r->cpos, fmax_mhz, r->cpos * 1e3 / fmax_mhz);
  else
    printf("| FP3 spatial chip (%u pipelines), %s RK4: %.3f cycles; give %s for ns | |\n",
           r->lanes, prog, r->cpos, opt);
}

int main(int argc, char **argv) {
  uint32_t steps = 200;
  double fmax_mhz = 0.0, spatial_fmax_mhz = 0.0, spatial_lit_fmax_mhz = 0.0;
  int spatial = 1;
  const char *csv_path = "build/bench/chip.csv";
  for (int i = 1; i < argc; i++) {
    if (strcmp(argv[i], "--steps") == 0 && i + 1 < argc) {
      steps = (uint32_t)strtoul(argv[++i], NULL, 10);
    } else if (strcmp(argv[i], "--fmax-mhz") == 0 && i + 1 < argc) {
      fmax_mhz = strtod(argv[++i], NULL);
    } else if (strcmp(argv[i], "--spatial-fmax-mhz") == 0 && i + 1 < argc) {
      spatial_fmax_mhz = strtod(argv[++i], NULL);
    } else if (strcmp(argv[i], "--spatial-literal-fmax-mhz") == 0 && i + 1 < argc) {
      spatial_lit_fmax_mhz = strtod(argv[++i], NULL);
    } else if (strcmp(argv[i], "--no-spatial") == 0) {
      spatial = 0;
    } else if (strcmp(argv[i], "--csv") == 0 && i + 1 < argc) {
      csv_path = argv[++i];
    } else {
      fprintf(stderr, "usage: bench_chip [--steps N] [--fmax-mhz F] [--spatial-fmax-mhz F] "
                      "[--spatial-literal-fmax-mhz F] [--csv FILE] [--no-spatial]\n");
      return strcmp(argv[i], "--help") == 0 ? 0 : 2;
    }
  }
  if (steps == 0 || !(fmax_mhz >= 0.0) || !(spatial_fmax_mhz >= 0.0) ||
      !(spatial_lit_fmax_mhz >= 0.0)) {
    fprintf(stderr, "bench_chip: --steps must be >= 1, the --*fmax-mhz values >= 0\n");
    return 2;
  }
  const struct {
    const char *name;
    const fp3_model_ops *ops; /* NULL: the default build (or not linked) */
    int is_default;
  } builds[] = {{"l1", NULL, 1},           {"l2", &fp3_model_l2, 0},
                {"l4", &fp3_model_l4, 0},   {"l8", &fp3_model_l8, 0},
                {"l16", &fp3_model_l16, 0}, {"fmax", &fp3_model_fmax, 0},
                {"f16", &fp3_model_f16, 0},  {"chip", &fp3_model_chip, 0}};
  const size_t nbuilds = sizeof builds / sizeof builds[0];
  fp3_model ship;
  char msg[512];
  if (fp3_model_load(SHIP_MODEL, &ship, msg, sizeof msg)) {
    fprintf(stderr, "bench_chip: %s\n", msg);
    return 2;
  }
  char tmp[4200];
  FILE *csv = fp3_bench_csv_open(csv_path, tmp, sizeof tmp);
  if (!csv) return 1;
  fprintf(csv, "build,num_contexts,num_lanes,fmax_pipe,program,objects,steps,cycles,"
               "cycles_per_object_step,issued_per_object_step,ratio,host_object_steps_per_s,"
               "golden_mismatches\n");
  printf("%-5s %4s %5s %4s %-9s %7s %15s %12s %6s %14s\n", "build", "ctx", "lanes", "fmax",
         "program", "objects", "cycles/obj-step", "issue bound", "ratio", "host obj-st/s");
  int rc = 0;
  row chip_lit = {0}, chip_comp = {0};
  double host_l1_64 = 0.0, host_big_256 = 0.0;
  const char *host_big = NULL;   /* the chip build, else the most lanes linked */
  unsigned host_big_lanes = 1;
  for (size_t b = 0; b < nbuilds; b++) {
    if (!builds[b].is_default && !builds[b].ops) {
      printf("%-5s (not linked: make bench-chip BENCH_CHIP_MODELS)\n", builds[b].name);
      continue;
    }
    fp3_engine *e = builds[b].ops ? fp3_engine_rtl_new_model(builds[b].ops, NULL)
                                  : fp3_engine_rtl_new(NULL);
    if (!e) {
      fprintf(stderr, "bench_chip: cannot create build %s\n", builds[b].name);
      rc = 1;
      continue;
    }
    const size_t n = fp3_config_slots(&e->config);
    /* the programs, for this build's latencies and pipeline */
    fp3_compiled *lit = NULL, *comp = NULL;
    if (ship_programs(&ship, e, &lit, &comp)) {
      fp3_compiled_free(lit);
      fp3_compiled_free(comp);
      fp3_engine_free(e);
      rc = 1;
      continue;
    }
    for (int p = 0; p < 2; p++) {
      row r;
      if (measure(e, builds[b].name, p ? "compiled" : "literal", p ? comp : lit, n, steps, &r)) {
        rc = 1;
        continue;
      }
      const double ratio = r.cpos / r.bound;
      printf("%-5s %4u %5u %4u %-9s %7zu %15.3f %12.3f %6.3f %14.0f%s\n", r.build, r.contexts,
             r.lanes, r.fmax_pipe, r.program, r.objects, r.cpos, r.bound, ratio, r.host_osps,
             r.mismatches || r.error ? "  GOLDEN MISMATCH OR ERROR" : "");
      fprintf(csv, "%s,%u,%u,%u,%s,%zu,%" PRIu32 ",%" PRIu64 ",%.4f,%.4f,%.4f,%.0f,%" PRIu64 "\n",
              r.build, r.contexts, r.lanes, r.fmax_pipe, r.program, r.objects, steps, r.cycles,
              r.cpos, r.bound, ratio, r.host_osps, r.mismatches);
      if (r.mismatches || r.error) rc = 1;
      if (strcmp(r.build, "chip") == 0) *(p ? &chip_comp : &chip_lit) = r;
    }
    /* host speed of the Verilated models: the 8-context build on 64
     * ships against the chip build on 256 (fp3 run --objects) */
    row h;
    if (strcmp(builds[b].name, "l1") == 0 && measure(e, "l1", "literal", lit, 64, steps, &h) == 0)
      host_l1_64 = h.host_osps;
    /* (the chip build comes last: it replaces any other) */
    if ((strcmp(builds[b].name, "chip") == 0 || e->config.num_lanes > host_big_lanes) &&
        measure(e, builds[b].name, "literal", lit, 256, steps, &h) == 0) {
      host_big_256 = h.host_osps;
      host_big = builds[b].name;
      host_big_lanes = e->config.num_lanes;
    }
    fp3_compiled_free(lit);
    fp3_compiled_free(comp);
    fp3_engine_free(e);
  }
  /* the spatial chip: the same table's columns (ctx = slots, lanes =
   * pipelines, bound = 1 / pipelines) */
  row sp_fold = {0}, sp_lit = {0};
  unsigned sp_lat[2] = {0, 0};
  for (int p = 0; spatial && p < 2; p++) {
    row r;
    if (spatial_row(&ship, !p, steps, &r, &sp_lat[p])) {
      rc = 1;
      continue;
    }
    const double ratio = r.cpos / r.bound;
    printf("%-5s %4u %5u %4u %-9s %7zu %15.3f %12.3f %6.3f %14.0f%s\n", "spat", r.contexts,
           r.lanes, 0u, r.program, r.objects, r.cpos, r.bound, ratio, r.host_osps,
           r.mismatches || r.error ? "  GOLDEN MISMATCH OR ERROR" : "");
    fprintf(csv, "spatial,%u,%u,0,%s,%zu,%" PRIu32 ",%" PRIu64 ",%.4f,%.4f,%.4f,%.0f,%" PRIu64 "\n",
            r.contexts, r.lanes, r.program, r.objects, steps, r.cycles, r.cpos, r.bound, ratio,
            r.host_osps, r.mismatches);
    if (r.mismatches || r.error) rc = 1;
    *(p ? &sp_fold : &sp_lit) = r;
  }
  if (spatial)
    printf("(spat: the spatial chip, ctx = object slots, lanes = pipelines, latency L = %u "
           "literal, %u folded; bound 1/pipelines)\n", sp_lat[0], sp_lat[1]);
  if (fp3_bench_csv_close(csv, tmp, csv_path)) return 1;
  if (host_l1_64 > 0.0 && host_big)
    printf("\nVerilated model speed on this host (object-steps per CPU second): the "
           "8-context build, 64 ships: %.0f; %s (%u lanes), 256 ships: %.0f; ratio %.2f\n",
           host_l1_64, host_big, host_big_lanes, host_big_256, host_big_256 / host_l1_64);
  /* the spatial engine's model, the same run: the folded chip on all its
   * slots against the lanes' largest build linked */
  if (sp_fold.host_osps > 0.0 && host_l1_64 > 0.0) {
    printf("Verilated spatial chip (%u pipelines, folded), %zu ships: %.0f object-steps per CPU "
           "second; ratio to the 8-context build %.2f", sp_fold.lanes, sp_fold.objects,
           sp_fold.host_osps, sp_fold.host_osps / host_l1_64);
    if (host_big) printf(", to %s %.2f", host_big, sp_fold.host_osps / host_big_256);
    printf("\n");
  }

  double cpu_arr = 0.0, cpu_one = 0.0;
  if (cpu_reference(1024, 2000, &cpu_arr, &cpu_one)) rc = 1;
  printf("\nCPU reference (cpu_ship.c, %s), the same binary32 step, bit-exact with the golden "
         "model (rk4se):\n  one ship alone:      %.3f ns per object-step\n  1,024 ships, arrays: %.3f ns "
         "per object-step\n", cpu_ship_flags(), cpu_one, cpu_arr);

  printf("\n| machine | ns per object-step |\n| --- | ---: |\n");
  printf("| paper: FPGA (XC2V6000-4, one ship, 8.888 ns clock) | %.2f |\n", PAPER_FPGA_NS);
  printf("| paper: Pentium 4 | %.2f |\n", PAPER_P4_NS);
  printf("| this machine's CPU, one core, 1,024 ships | %.3f |\n", cpu_arr);
  printf("| this machine's CPU, one ship | %.3f |\n", cpu_one);
  if (fmax_mhz > 0.0 && chip_lit.cpos > 0.0) {
    printf("| FP3 chip build (%u x %u), literal RK4: %.3f cycles at %.1f MHz | %.2f |\n",
           chip_lit.contexts, chip_lit.lanes, chip_lit.cpos, fmax_mhz,
           chip_lit.cpos * 1e3 / fmax_mhz);
    printf("| FP3 chip build (%u x %u), compiled RK4: %.3f cycles at %.1f MHz | %.2f |\n",
           chip_comp.contexts, chip_comp.lanes, chip_comp.cpos, fmax_mhz,
           chip_comp.cpos * 1e3 / fmax_mhz);
  } else if (chip_lit.cpos > 0.0) {
    printf("| FP3 chip build (%u x %u): %.3f (literal), %.3f (compiled) cycles; give "
           "--fmax-mhz for ns | |\n", chip_lit.contexts, chip_lit.lanes, chip_lit.cpos,
           chip_comp.cpos);
  }
  spatial_ns_row(&sp_fold, "folded", spatial_fmax_mhz, "--spatial-fmax-mhz");
  spatial_ns_row(&sp_lit, "literal", spatial_lit_fmax_mhz, "--spatial-literal-fmax-mhz");
  printf("CSV: %s\n", csv_path);
  return rc;
}
