/*
 * cmd_bench.h -- `fp3 bench`: the benchmark of a model's integrators
 * (models/ship.fp3m unless --model names another): the work-precision
 * sweep and its Pareto table, the stability bounds checked on the
 * engine, the long runs and their binary32 stagnation (cmd_bench.c,
 * fp3 bench --help, docs/numerics.md).
 */
#ifndef FP3_CMD_BENCH_H
#define FP3_CMD_BENCH_H

#include "cmd_model.h"

/* The options of `fp3 bench`: the model commands' (fp3_parse_model) and
 * the bench's own. */
typedef struct fp3_bench_args {
  fp3_model_args a;  /* --model (default: ship below), --set, --integrator,
                        --points, --t-end, --long-steps, -o, ...          */
  const char *dir;   /* --out DIR: every part's files (NULL: none)        */
  const char *only;  /* --only sweep|stability|long (with --out; NULL: all) */
  double hmax;       /* --h-max: the sweep's largest h (0: the model's)   */
  char ship[4096];   /* models/ship.fp3m as found (fp3_find_shipped)      */
} fp3_bench_args;

/* The parse step of `fp3 bench`: argv into *b, models/ship.fp3m when no
 * --model is given; the ship-only options that have no meaning on the
 * model path (--from, --h-over-tau, ...) refused with their new form.
 * FP3_ARGS_RUN, FP3_ARGS_HELP, or FP3_ARGS_BAD with the message on stderr
 * (cliopt.h). */
int fp3_parse_bench(int argc, char **argv, fp3_bench_args *b);

/* `fp3 bench [options]` (fp3 bench --help).  Exit status 0 done and every
 * engine run bit-exact, 1 a check failed or a file not written, 2 bad
 * arguments or model. */
int fp3_cmd_bench(int argc, char **argv);

#endif /* FP3_CMD_BENCH_H */
