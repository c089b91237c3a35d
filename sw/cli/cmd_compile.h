/*
 * cmd_compile.h -- `fp3 compile`: a model (--model FILE, a scene of it:
 * a model scene, or a ship scene of models/ship.fp3m) compiled for an
 * integrator (fp3_compile_model), on the command line (compile.h).
 */
#ifndef FP3_CMD_COMPILE_H
#define FP3_CMD_COMPILE_H

#include "compile.h"

/* `fp3 compile SCENE`'s options (fp3 compile --help). */
typedef struct fp3_compile_args {
  const char *scene;      /* the scene file (a model scene or a ship scene) */
  const char *model;      /* --model FILE (instead of a scene)             */
  const char *out;        /* -o FILE, or NULL: standard output             */
  const char *integ;      /* --integrator (default rk4, a ship scene's
                             rk4se; fp3_compile_model checks it)          */
  int json;               /* --json (needs -o)                             */
  fp3_compile_opts opts;  /* latencies, --fmax-pipe, folding               */
} fp3_compile_args;

/* The parse step of `fp3 compile`:
 * FP3_ARGS_RUN with *a filled, FP3_ARGS_HELP, or FP3_ARGS_BAD with the
 * message on stderr (cliopt.h). */
int fp3_parse_compile(int argc, char **argv, fp3_compile_args *a);

/* argv[0] is "compile".  Returns the exit status: 0 written, 1 the output
 * could not be written, 2 bad arguments, scene or integrator (a message on
 * stderr). */
int fp3_cmd_compile(int argc, char **argv);

#endif /* FP3_CMD_COMPILE_H */
