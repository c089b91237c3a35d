/*
 * bench.h -- what the benchmark programs (bench_parallel.c, bench_chip.c)
 * share: their CSV files, written whole (bench_csv.c).  `fp3 bench`, the
 * integrators' benchmark, is sw/cli/cmd_bench.c.
 */
#ifndef FP3_BENCH_H
#define FP3_BENCH_H

#include <stddef.h>
#include <stdio.h>

/* A CSV file written whole under a temporary name, PATH.tmp (in tmp, n
 * bytes), renamed to PATH by fp3_bench_csv_close: a failed run leaves no
 * half-written PATH.  NULL (perror) if it cannot be opened. */
FILE *fp3_bench_csv_open(const char *path, char *tmp, size_t n);
/* Close and rename; 0, or -1 (perror, the temporary removed). */
int fp3_bench_csv_close(FILE *f, const char *tmp, const char *path);

#endif /* FP3_BENCH_H */
