/*
 * bench_csv.c -- the CSV files of the benchmark programs (bench.h),
 * written whole under a temporary name and renamed.
 */
#include "bench.h"

#include <stdio.h>

FILE *fp3_bench_csv_open(const char *path, char *tmp, size_t n) {
  snprintf(tmp, n, "%s.tmp", path);
  FILE *f = fopen(tmp, "w");
  if (!f) perror(tmp);
  return f;
}

int fp3_bench_csv_close(FILE *f, const char *tmp, const char *path) {
  if (fclose(f) || rename(tmp, path)) {
    perror(path);
    remove(tmp);
    return -1;
  }
  return 0;
}
