/*
 * cmd_spatial.h -- `fp3 spatial`: a model's integration step as one fully
 * pipelined Verilog module (spatial.h, docs/spatial.md).
 */
#ifndef FP3_CMD_SPATIAL_H
#define FP3_CMD_SPATIAL_H

#include <stddef.h>
#include <stdint.h>

#include "compile.h"
#include "spatial.h"

/* `fp3 spatial MODEL.fp3m | --scene FILE`'s options (fp3 spatial --help). */
typedef struct fp3_spatial_args {
  const char *model;       /* the model file (NULL: the scene's)            */
  const char *scene;       /* --scene FILE: drop the terms of params zero in
                              every object (NULL: none)                     */
  const char *dir;         /* -o DIR: the folder written                    */
  const char *integ;       /* --integrator (default rk4)                    */
  int literal;             /* --literal: the integrator's literal operations */
  size_t vec_objects;      /* --vectors N: test vectors for N objects (0: none) */
  unsigned vec_steps;      /* --steps K: of K integrations each             */
  uint64_t seed;           /* --seed: the vectors' objects                  */
  unsigned pipelines;      /* --pipelines N: also the chip top (0: none)    */
  unsigned objects;        /* --objects M: its objects (0: the default)     */
  fp3_spatial_opts opts;   /* the cores' latencies and rounding             */
  int no_fit_check;        /* --no-fit-check: write a pipeline that does not
                              fit the LFE5U-85F (for simulation)            */
} fp3_spatial_args;

/* The parse step (cliopt.h): FP3_ARGS_RUN with *a filled, FP3_ARGS_HELP,
 * or FP3_ARGS_BAD with the message on stderr. */
int fp3_parse_spatial(int argc, char **argv, fp3_spatial_args *a);

/* argv[0] is "spatial".  Returns the exit status: 0 written, 1 the files
 * could not be written, 2 bad arguments, model or integrator, or a pipeline
 * that does not fit the LFE5U-85F even once (a message on stderr; no file
 * is left). */
int fp3_cmd_spatial(int argc, char **argv);

#endif /* FP3_CMD_SPATIAL_H */
