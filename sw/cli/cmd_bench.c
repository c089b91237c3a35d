/*
 * cmd_bench.c -- `fp3 bench`: the command line of the integrator benchmark
 * (bench.h): options parsed and checked here (fp3_parse_bench), the work
 * done by fp3_bench_run().
 */
#include "cmd_bench.h"

#include "bench.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cliopt.h"
#include "cmd_model.h"

static void usage_bench(FILE *f) {
  fprintf(f,
          "usage: fp3 bench [--out DIR] [--from X] [--to Y] [--per-decade K]\n"
          "                 [--t-end T] [--h-over-tau X] [--only PART]\n"
          "                 [--long-steps N] [--rtl-long-steps N] [--repeats R]\n"
          "\n"
          "The integrators (fp3 run --integrator) on Bourg's ship, default scene\n"
          "(T = 50 kN, C = 5000 kg/s, m = 10 t: tau = m/C = 2 s, T/C = 10 m/s,\n"
          "v0 = s0 = 0), against the exact solution and GSL's gsl_odeiv2\n"
          "steppers rk4, rkf45, rk8pd in double:\n"
          "\n"
          "  sweep      h/tau from X to Y, K points a decade, each integrated to\n"
          "             the end time T: RTL cycles (one short RTL run of each\n"
          "             program, bit-exact, gives the exact per-integration\n"
          "             cost), CPU ns per step of the golden model and of GSL\n"
          "             (median of R runs), final and maximum error of v and s\n"
          "             -> DIR/sweep.csv, DIR/pareto.md\n"
          "  stability  measured stability bound in h/tau of each integrator\n"
          "             (bisection, 20000 golden integrations) and RTL runs at\n"
          "             0.98 and 1.02 of the theoretical bound -> DIR/stability.*\n"
          "  long       binary32 stagnation: N integrations on the ISS, M on\n"
          "             the RTL, bit-exact, plain RK4 against the compensated\n"
          "             programs (others in the golden model) -> DIR/longrun.*\n"
          "\n"
          "  --out DIR          output directory (default build/bench)\n"
          "  --from X, --to Y   sweep bounds in h/tau, 0 < X <= Y (1e-4, 3)\n"
          "  --per-decade K     sweep points per decade (default 4)\n"
          "  --t-end T          end time [s] (default 12 = 6 tau)\n"
          "  --h-over-tau X     one point instead of the sweep; T must then be\n"
          "                     a whole number of steps h = X tau\n"
          "  --only PART        sweep, stability or long (default: all three)\n"
          "  --long-steps N     ISS integrations of the long runs (10000000)\n"
          "  --rtl-long-steps M RTL integrations of the long runs (100000)\n"
          "  --repeats R        timing repeats, median taken (default 7)\n"
          "\n"
          "fp3 bench --model FILE [--set NAME=VALUE ...] [--integrator I] [--t-end T]\n"
          "          [--points K] [--engine rtl|iss] [-o FILE.csv]: a model's\n"
          "  work-precision sweep (fp3 bench --model x --help, docs/models.md)\n"
          "\n"
          "Exit status: 0 done and every engine run bit-exact; 1 a check\n"
          "failed; 2 bad arguments.\n");
}


static int parse_pos(const char *opt, const char *s, double *x) {
  char *end;
  errno = 0;
  double d = strtod(s, &end);
  if (end == s || *end != '\0' || errno || !isfinite(d)) {
    fprintf(stderr, "fp3 bench: %s '%s' is not a number\n", opt, s);
    return -1;
  }
  if (!(d > 0.0)) {
    fprintf(stderr, "fp3 bench: %s %s: must be > 0\n", opt, s);
    return -1;
  }
  *x = d;
  return 0;
}


int fp3_parse_bench(int argc, char **argv, fp3_bench_opts *o) {
  *o = (fp3_bench_opts){.dir = "build/bench", .only = NULL, .from = 1e-4, .to = 3.0,
                        .t_end = 12.0, .single = 0.0, .per_decade = 4.0,
                        .long_steps = 10000000u, .rtl_long_steps = 100000u, .repeats = 7};
  for (int i = 1; i < argc; i++) {
    const char *v;
    unsigned long long k;
    int r;
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    if ((r = fp3_opt_value(argc, argv, &i, "bench", "--out", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->dir = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, "bench", "--from", &v)) != 0) {
      if (r < 0 || parse_pos("--from", v, &o->from)) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_value(argc, argv, &i, "bench", "--to", &v)) != 0) {
      if (r < 0 || parse_pos("--to", v, &o->to)) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_value(argc, argv, &i, "bench", "--per-decade", &v)) != 0) {
      if (r < 0 || parse_pos("--per-decade", v, &o->per_decade)) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_value(argc, argv, &i, "bench", "--t-end", &v)) != 0) {
      if (r < 0 || parse_pos("--t-end", v, &o->t_end)) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_value(argc, argv, &i, "bench", "--h-over-tau", &v)) != 0) {
      if (r < 0 || parse_pos("--h-over-tau", v, &o->single)) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_value(argc, argv, &i, "bench", "--only", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      if (strcmp(v, "sweep") && strcmp(v, "stability") && strcmp(v, "long")) {
        fprintf(stderr, "fp3 bench: --only '%s': sweep, stability or long\n", v);
        return FP3_ARGS_BAD;
      }
      o->only = v;
    } else if ((r = fp3_opt_count(argc, argv, &i, "bench", "--long-steps", 1, UINT32_MAX,
                                  "integrations", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->long_steps = (uint32_t)k;
    } else if ((r = fp3_opt_count(argc, argv, &i, "bench", "--rtl-long-steps", 1, UINT32_MAX,
                                  "integrations", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->rtl_long_steps = (uint32_t)k;
    } else if ((r = fp3_opt_count(argc, argv, &i, "bench", "--repeats", 1, 64, "", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->repeats = (uint32_t)k;
    } else {
      fprintf(stderr, "fp3 bench: unknown argument '%s' (see fp3 bench --help)\n",
              argv[i]);
      return FP3_ARGS_BAD;
    }
  }
  return FP3_ARGS_RUN;
}

/* 1 if argv names a model (--model FILE, --model=FILE): the model's bench
 * (cmd_model.h); the ship's bench of h/tau sweeps otherwise. */
static int names_model(int argc, char **argv) {
  for (int i = 1; i < argc; i++)
    if (strcmp(argv[i], "--model") == 0 || strncmp(argv[i], "--model=", 8) == 0) return 1;
  return 0;
}

int fp3_cmd_bench(int argc, char **argv) {
  if (names_model(argc, argv)) return fp3_cmd_bench_model(argc, argv);
  fp3_bench_opts o;
  int r = fp3_parse_bench(argc, argv, &o);
  return r == FP3_ARGS_RUN ? fp3_bench_run(&o) : fp3_args_exit(r, usage_bench);
}
