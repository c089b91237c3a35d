/*
 * cmd_configure.h -- `fp3 configure SCENE`: the RTL parameters a scene
 * needs (configure.h) on the command line.
 */
#ifndef FP3_CMD_CONFIGURE_H
#define FP3_CMD_CONFIGURE_H

#include "configure.h"

/* `fp3 configure SCENE`'s options (fp3 configure --help). */
typedef struct fp3_configure_args {
  const char *scene;         /* the scene file (required)                  */
  const char *out;           /* -o FILE, or NULL: standard output          */
  int json;                  /* --json                                     */
  fp3_configure_opts opts;   /* integrator (checked by the run step, which
                                knows whether the scene is a model's),
                                budget, steps, lanes                       */
} fp3_configure_args;

/* The parse step of `fp3 configure`: FP3_ARGS_RUN with *a filled,
 * FP3_ARGS_HELP, or FP3_ARGS_BAD with the message on stderr (cliopt.h). */
int fp3_parse_configure(int argc, char **argv, fp3_configure_args *a);

/* argv[0] is "configure".  Returns the exit status: 0 derived (and
 * written), 1 the output could not be written, 2 bad arguments, scene,
 * integrator or budget (a message on stderr). */
int fp3_cmd_configure(int argc, char **argv);

#endif /* FP3_CMD_CONFIGURE_H */
