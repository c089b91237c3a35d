/*
 * cmd_testfloat.h -- `fp3 testfloat [--round rne|rtz] [--ftz] [--ref] OP
 * FILE`: Berkeley TestFloat vectors through a Verilated FP core or the C
 * reference (testfloat.h) on the command line.
 */
#ifndef FP3_CMD_TESTFLOAT_H
#define FP3_CMD_TESTFLOAT_H

#include "fpref.h"
#include "testfloat.h"

/* `fp3 testfloat`'s options. */
typedef struct fp3_testfloat_args {
  testfloat_op op;  /* the operation (OP: add, sub, mul, div, sqrt)          */
  const char *path; /* the vector file, gzip or plain (FILE)                 */
  fpref_mode mode;  /* --round and --ftz: which core, or the reference's mode */
  int use_ref;      /* --ref: check sw/fpref instead of a core               */
} fp3_testfloat_args;

/* The parse step of `fp3 testfloat`: FP3_ARGS_RUN with *a filled,
 * FP3_ARGS_HELP, or FP3_ARGS_BAD with the message on stderr ("fp3
 * testfloat: unknown operation 'fma' (add, sub, mul, div or sqrt)", an
 * unknown option, a missing or extra argument; cliopt.h). */
int fp3_parse_testfloat(int argc, char **argv, fp3_testfloat_args *a);

/* argv[0] is "testfloat".  Prints the first failures and a closing line
 * "N passed, M failed".  Returns the exit status: 0 all passed, 1 some
 * failed, 2 usage or input error (0 for --help). */
int fp3_cmd_testfloat(int argc, char **argv);

#endif /* FP3_CMD_TESTFLOAT_H */
