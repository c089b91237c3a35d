/*
 * cmd_compile.h -- `fp3 compile SCENE`: the scene compiler (compile.h) on
 * the command line.
 */
#ifndef FP3_CMD_COMPILE_H
#define FP3_CMD_COMPILE_H

#include "compile.h"

/* `fp3 compile SCENE`'s options (fp3 compile --help). */
typedef struct fp3_compile_args {
  const char *scene;      /* the scene file (required)                     */
  const char *out;        /* -o FILE, or NULL: standard output             */
  const char *integ;      /* --integrator (default rk4; the compiler checks
                             it, fp3_compile)                              */
  int json;               /* --json (needs -o)                             */
  fp3_compile_opts opts;  /* latencies, --fmax-pipe, folding               */
} fp3_compile_args;

/* The parse step of `fp3 compile SCENE` (not of a model, fp3_parse_model):
 * FP3_ARGS_RUN with *a filled, FP3_ARGS_HELP, or FP3_ARGS_BAD with the
 * message on stderr (cliopt.h). */
int fp3_parse_compile(int argc, char **argv, fp3_compile_args *a);

/* argv[0] is "compile".  Returns the exit status: 0 written, 1 the output
 * could not be written, 2 bad arguments, scene or integrator (a message on
 * stderr). */
int fp3_cmd_compile(int argc, char **argv);

#endif /* FP3_CMD_COMPILE_H */
