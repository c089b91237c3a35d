/*
 * cmd_bench.h -- `fp3 bench`: the integrator benchmark (bench.h) on the
 * command line.
 */
#ifndef FP3_CMD_BENCH_H
#define FP3_CMD_BENCH_H

/* `fp3 bench [options]` (fp3 bench --help).  Exit status 0, 1 when a
 * check failed (an engine not bit-exact), 2 for bad arguments. */
int fp3_cmd_bench(int argc, char **argv);

#endif /* FP3_CMD_BENCH_H */
