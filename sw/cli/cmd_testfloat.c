/*
 * cmd_testfloat.c -- `fp3 testfloat`: the TestFloat vector runner
 * (testfloat.h) on the command line (cmd_testfloat.h).
 */
#include "cmd_testfloat.h"

#include <stdio.h>
#include <string.h>

#include "../sim/fpu_model.h" /* relative: no -Isim needed */
#include "cliopt.h"

#define TF_MAX_PRINT 10
#define EXIT_USAGE 2

static void usage_testfloat(FILE *f) {
  fputs("usage: fp3 testfloat [--round rne|rtz] [--ftz] [--ref] OP FILE\n"
        "  Run Berkeley TestFloat vectors (lines \"A B RESULT FLAGS\" in hex,\n"
        "  \"A RESULT FLAGS\" for sqrt; gzip or plain) through the Verilated\n"
        "  FP core of that configuration and compare results (any NaN\n"
        "  matches any NaN) and flags exactly.\n"
        "  OP               add, sub, mul, div or sqrt\n"
        "  --round rne|rtz  rounding of the core (default rne)\n"
        "  --ftz            the flush-to-zero core\n"
        "  --ref            check the C reference (sw/fpref) instead\n"
        "  --help           this text\n"
        "Prints the first failures and \"N passed, M failed\"; exit status 0\n"
        "when all passed, 1 when some failed, 2 on a usage or input error.\n",
        f);
}

int fp3_parse_testfloat(int argc, char **argv, fp3_testfloat_args *a) {
  a->mode = FPREF_IEEE;
  a->use_ref = 0;
  a->path = NULL;
  a->op = TESTFLOAT_ADD;
  const char *opname = NULL;
  for (int i = 1; i < argc; i++) {
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    int r = fp3_opt_mode(argc, argv, &i, "testfloat", &a->mode);
    if (r < 0) return FP3_ARGS_BAD;
    if (r > 0) continue;
    if (strcmp(argv[i], "--ref") == 0) {
      a->use_ref = 1;
    } else if (!opname || (argv[i][0] == '-' && argv[i][1] != '\0')) {
      if (fp3_opt_positional("testfloat", "operation", argv[i], &opname)) return FP3_ARGS_BAD;
    } else if (fp3_opt_positional("testfloat", "vector file", argv[i], &a->path)) {
      return FP3_ARGS_BAD;
    }
  }
  if (!opname || !a->path) {
    fprintf(stderr, "fp3 testfloat: want an operation and a vector file (see fp3 testfloat --help)\n");
    return FP3_ARGS_BAD;
  }
  if (testfloat_op_parse(opname, &a->op) != 0) {
    fprintf(stderr, "fp3 testfloat: unknown operation '%s' (add, sub, mul, div or sqrt)\n",
            opname);
    return FP3_ARGS_BAD;
  }
  return FP3_ARGS_RUN;
}

/* The run step: the core of the chosen mode (or none for --ref), the
 * file, the report. */
static int run_testfloat(const fp3_testfloat_args *a) {
  struct fpu_model *model = NULL;
  if (!a->use_ref) {
    model = fpu_model_new((int)a->mode.round, a->mode.ftz, 0, 0);
    if (!model) {
      fprintf(stderr, "fp3 testfloat: no core built for --round %s%s\n",
              a->mode.round == FPREF_RTZ ? "rtz" : "rne", a->mode.ftz ? " --ftz" : "");
      return EXIT_USAGE;
    }
  }
  testfloat_stats st;
  int rc = testfloat_run(a->path, a->op, a->mode, model, stdout, TF_MAX_PRINT, stderr, &st);
  if (model) fpu_model_free(model);
  if (rc != 0) return EXIT_USAGE;
  if (st.failed > TF_MAX_PRINT)
    printf("... %lu more failures not shown\n", st.failed - TF_MAX_PRINT);
  printf("%lu passed, %lu failed\n", st.passed, st.failed);
  return st.failed ? 1 : 0;
}

int fp3_cmd_testfloat(int argc, char **argv) {
  fp3_testfloat_args a;
  int r = fp3_parse_testfloat(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_testfloat(&a) : fp3_args_exit(r, usage_testfloat);
}
