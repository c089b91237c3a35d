/*
 * cmd_bench.h -- `fp3 bench`: the integrator benchmark (bench.h) on the
 * command line.
 */
#ifndef FP3_CMD_BENCH_H
#define FP3_CMD_BENCH_H

#include "bench.h"

/* The parse step of `fp3 bench` (not of `fp3 bench --model`,
 * fp3_parse_model): the options into *o, defaults for those not given
 * (fp3 bench --help).  FP3_ARGS_RUN, FP3_ARGS_HELP, or FP3_ARGS_BAD with
 * the message on stderr (cliopt.h). */
int fp3_parse_bench(int argc, char **argv, fp3_bench_opts *o);

/* `fp3 bench [options]` (fp3 bench --help).  Exit status 0, 1 when a
 * check failed (an engine not bit-exact), 2 for bad arguments. */
int fp3_cmd_bench(int argc, char **argv);

#endif /* FP3_CMD_BENCH_H */
