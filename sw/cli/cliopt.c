/*
 * cliopt.c -- option parsing shared by the fp3 subcommands (cliopt.h).
 */
#include "cliopt.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fp3_opt_value(int argc, char **argv, int *i, const char *cmd, const char *name,
                  const char **val) {
  const char *a = argv[*i];
  size_t n = strlen(name);
  if (strncmp(a, name, n) != 0) return 0;
  if (a[n] == '=') {
    *val = a + n + 1;
    return 1;
  }
  if (a[n] != '\0') return 0;
  if (*i + 1 >= argc) {
    fprintf(stderr, "fp3 %s: option %s needs a value\n", cmd, name);
    return -1;
  }
  *val = argv[++*i];
  return 1;
}

int fp3_opt_output(int argc, char **argv, int *i, const char *cmd, const char **val) {
  int r = fp3_opt_value(argc, argv, i, cmd, "-o", val);
  return r != 0 ? r : fp3_opt_value(argc, argv, i, cmd, "--output", val);
}

int fp3_opt_positional(const char *cmd, const char *what, const char *arg, const char **one) {
  if (arg[0] == '-' && arg[1] != '\0') {
    fprintf(stderr, "fp3 %s: unknown option '%s' (see fp3 %s --help)\n", cmd, arg, cmd);
    return -1;
  }
  if (*one) {
    fprintf(stderr, "fp3 %s: more than one %s ('%s')\n", cmd, what, arg);
    return -1;
  }
  *one = arg;
  return 0;
}

/* v as an unsigned integer in strtoull base `base` (10, or 0: decimal,
 * 0x hexadecimal, 0 octal) in lo..hi, starting with a digit (no sign, no
 * blank) and nothing after it.  0 and *out, else -1. */
static int parse_ull(const char *v, int base, unsigned long long lo, unsigned long long hi,
                     unsigned long long *out) {
  char *end;
  errno = 0;
  unsigned long long x = strtoull(v, &end, base);
  if (v[0] < '0' || v[0] > '9' || *end || errno || x < lo || x > hi) return -1;
  *out = x;
  return 0;
}

int fp3_parse_count(const char *v, unsigned long long lo, unsigned long long hi,
                    unsigned long long *out) {
  return parse_ull(v, 10, lo, hi, out);
}

/* Option `name` with an unsigned integer value (parse_ull); a bad value
 * is reported as "fp3 CMD: NAME 'V': want WANT".  1, 0, -1 as
 * fp3_opt_count. */
static int opt_number(int argc, char **argv, int *i, const char *cmd, const char *name,
                      int base, unsigned long long lo, unsigned long long hi, const char *want,
                      unsigned long long *out) {
  const char *v;
  int r = fp3_opt_value(argc, argv, i, cmd, name, &v);
  if (r <= 0) return r;
  if (parse_ull(v, base, lo, hi, out)) {
    fprintf(stderr, "fp3 %s: %s '%s': want %s\n", cmd, name, v, want);
    return -1;
  }
  return 1;
}

int fp3_opt_count(int argc, char **argv, int *i, const char *cmd, const char *name,
                  unsigned long long lo, unsigned long long hi, const char *unit,
                  unsigned long long *out) {
  char want[96];
  snprintf(want, sizeof want, "%llu..%llu%s%s", lo, hi, unit[0] ? " " : "", unit);
  return opt_number(argc, argv, i, cmd, name, 10, lo, hi, want, out);
}

int fp3_opt_seed(int argc, char **argv, int *i, const char *cmd, uint64_t *out) {
  unsigned long long x;
  int r = opt_number(argc, argv, i, cmd, "--seed", 0, 0, UINT64_MAX,
                     "an unsigned 64-bit integer (decimal, or 0x and hexadecimal digits)", &x);
  if (r > 0) *out = x;
  return r;
}

int fp3_opt_mode(int argc, char **argv, int *i, const char *cmd, fpref_mode *mode) {
  if (strcmp(argv[*i], "--ftz") == 0) {
    mode->ftz = 1;
    return 1;
  }
  const char *v;
  int r = fp3_opt_value(argc, argv, i, cmd, "--round", &v);
  if (r <= 0) return r;
  if (strcmp(v, "rne") == 0) mode->round = FPREF_RNE;
  else if (strcmp(v, "rtz") == 0) mode->round = FPREF_RTZ;
  else {
    fprintf(stderr, "fp3 %s: unknown rounding '%s' (rne or rtz)\n", cmd, v);
    return -1;
  }
  return 1;
}

int fp3_parse_pair(const char *v, unsigned long long lo1, unsigned long long hi1,
                   unsigned long long lo2, unsigned long long hi2, const char *all,
                   unsigned long long *a, unsigned long long *b) {
  const char *colon = strchr(v, ':');
  char first[24];
  if (!colon || (size_t)(colon - v) >= sizeof first) return -1;
  memcpy(first, v, (size_t)(colon - v));
  first[colon - v] = '\0';
  if (fp3_parse_count(first, lo1, hi1, a)) return -1;
  if (all && strcmp(colon + 1, all) == 0) {
    *b = ULLONG_MAX;
    return 0;
  }
  return fp3_parse_count(colon + 1, lo2, hi2, b);
}


int fp3_is_help(const char *a) { return strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0; }

int fp3_args_exit(int r, void (*usage)(FILE *)) {
  if (r == FP3_ARGS_HELP) {
    usage(stdout);
    return 0;
  }
  return 2;
}
