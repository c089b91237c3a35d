/*
 * cmd_bench.h -- `fp3 bench`: the benchmark of a model's integrators
 * (models/ship.fp3m unless --model names another): the work-precision
 * sweep and its Pareto table, the stability bounds checked on the
 * engine, the long runs and their binary32 stagnation (cmd_bench.c,
 * fp3 bench --help, docs/numerics.md).
 */
#ifndef FP3_CMD_BENCH_H
#define FP3_CMD_BENCH_H

/* `fp3 bench [options]` (fp3 bench --help).  Exit status 0 done and every
 * engine run bit-exact, 1 a check failed or a file not written, 2 bad
 * arguments or model. */
int fp3_cmd_bench(int argc, char **argv);

#endif /* FP3_CMD_BENCH_H */
