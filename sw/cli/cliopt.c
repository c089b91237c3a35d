/*
 * cliopt.c -- option parsing shared by the fp3 subcommands (cliopt.h).
 */
#include "cliopt.h"

#include <errno.h>
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

int fp3_parse_count(const char *v, unsigned long long lo, unsigned long long hi,
                    unsigned long long *out) {
  char *end;
  errno = 0;
  unsigned long long x = strtoull(v, &end, 10);
  if (v[0] < '0' || v[0] > '9' || *end || errno || x < lo || x > hi) return -1;
  *out = x;
  return 0;
}

int fp3_is_help(const char *a) { return strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0; }
