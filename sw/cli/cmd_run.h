/*
 * cmd_run.h -- `fp3 run`: a program on the RTL or the ISS, checked bit for
 * bit against the golden model after every integration (fp3 run --help).
 */
#ifndef FP3_CMD_RUN_H
#define FP3_CMD_RUN_H

#include <stddef.h>
#include <stdint.h>

#include "fpref.h"
#include "golden.h"
#include "integrators.h"
#include "traceopt.h"

/* `fp3 run`'s options (not those of `fp3 run --model`, fp3_model_args). */
typedef struct fp3_run_args {
  const char *engine_name;     /* --engine: "rtl" (default) or "iss"        */
  const char *program;         /* --program, or NULL: programs/ship_I.s     */
  fp3_trace_opts trace;        /* --trace, --trace-window, --trace-limit    */
  uint32_t steps;              /* --steps, integrations (default 10000)     */
  int json, strict;            /* --json, --strict                          */
  int literal, compile;        /* --literal; --compile, or a scene file
                                  without --literal or --program            */
  size_t objects;              /* --objects N (0: one object)               */
  const char *scene;           /* --scene FILE, or NULL                     */
  uint64_t seed;               /* --seed (with --objects)                   */
  int seeded;                  /* --seed given                              */
  const fp3_integrator *integ; /* --integrator (default rk4)                */
  fpref_mode mode;             /* --round, --ftz                            */
  fp3_ship_params p;           /* the scene, --set values applied and
                                  validated                                 */
} fp3_run_args;

/* The parse step of `fp3 run`: FP3_ARGS_RUN with *a filled and checked
 * (the combinations of options, the scene values, the integrator the
 * compiler needs; h/tau above the integrator's stability bound is a
 * warning on stderr, with --strict an error), FP3_ARGS_HELP, or
 * FP3_ARGS_BAD with the message on stderr (cliopt.h). */
int fp3_parse_run(int argc, char **argv, fp3_run_args *a);

/* argv[0] is "run"; a model (--model, a model scene) goes to
 * fp3_cmd_run_model.  Exit status: 0 the run finished without error and
 * bit-exact with the golden model, 1 it did not, 2 bad arguments or
 * program (a message on stderr). */
int fp3_cmd_run(int argc, char **argv);

#endif /* FP3_CMD_RUN_H */
