/*
 * cmd_frames.h -- `fp3 frames`: a scene run frame by frame with sleeping
 * objects (frames.h), and its report.
 */
#ifndef FP3_CMD_FRAMES_H
#define FP3_CMD_FRAMES_H

#include <stdint.h>

#include "frames.h"
#include "integrators.h"

/* `fp3 frames`'s options (fp3 frames --help). */
typedef struct fp3_frames_args {
  const char *scene_path;      /* --scene FILE, or NULL: a harbour          */
  const char *program;         /* --program (default programs/ship_rk4_sleep.s) */
  const char *engine_name;     /* --engine: "rtl" or "iss"                   */
  unsigned long long ships;    /* --harbour N                                */
  uint64_t seed;               /* --seed                                     */
  double fmax;                 /* --fmax [MHz], > 0                          */
  int json;                    /* --json                                     */
  const fp3_integrator *ig;    /* --integrator's golden model                */
  fp3_frames_opts opts;        /* frames, rest skipping, waking              */
} fp3_frames_args;

/* The parse step of `fp3 frames` (not of a model scene, fp3_parse_model):
 * FP3_ARGS_RUN with *a filled, FP3_ARGS_HELP, or FP3_ARGS_BAD with the
 * message on stderr (cliopt.h). */
int fp3_parse_frames(int argc, char **argv, fp3_frames_args *a);

/* argv[0] is "frames".  Returns the exit status: 0 every object equals
 * its golden model after every frame, 1 a mismatch, a context error or an
 * engine failure, 2 bad arguments or scene (a message on stderr). */
int fp3_cmd_frames(int argc, char **argv);

#endif /* FP3_CMD_FRAMES_H */
