/*
 * cmd_objects.h -- the many-objects form of `fp3 run` (--objects, --scene).
 */
#ifndef FP3_CMD_OBJECTS_H
#define FP3_CMD_OBJECTS_H

#include <stddef.h>
#include <stdint.h>

#include "engine.h"
#include "image.h"
#include "integrators.h"
#include "compile.h"
#include "objects.h"

/* Everything `fp3 run` parsed for a multi-object run. */
typedef struct fp3_objects_cmd {
  fp3_engine *engine;
  const fp3_image *img;
  const char *program;           /* path, for the report               */
  const char *integ_name;        /* integrator                          */
  const fp3_golden_ref *golden;  /* golden model of img                 */
  int compile;                   /* 1: run the scene compiler's program
                                    for integ_name (compile.h) and its
                                    golden model instead of img, golden */
  const fp3_compile_opts *copts; /* its options (NULL: defaults with the
                                    engine's latencies, registers and
                                    FMAX_PIPE)                          */
  const char *scene_path;        /* scene file, or NULL: generate        */
  size_t objects;                /* --objects (0: all of the scene)      */
  uint64_t seed;                 /* generator seed                       */
  float h;                       /* time step (scene files may set it)   */
  uint32_t steps;
  fpref_mode mode;
  int json;
} fp3_objects_cmd;

/* Run and report.  Returns the exit status: 0 all objects bit-exact and
 * no error, 1 otherwise, 2 a bad scene (message on stderr). */
int fp3_cmd_run_objects(const fp3_objects_cmd *c);

#endif /* FP3_CMD_OBJECTS_H */
