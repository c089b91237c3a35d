/*
 * runsetup.h -- what `fp3 run` and `fp3 frames` set up before they run: the
 * one path of a model (docs/models.md "Commands").
 *
 *   the program  --program FILE.s (hand-written, bound to the model by
 *                name, fp3_compile_bind), the command's default program,
 *                or none: compiled from the model for --integrator;
 *   the model    --model, a model scene's, the program's `.model`, or
 *                models/ship.fp3m;
 *   the objects  one (the model's defaults and --set), --objects N
 *                generated from them, a model scene, a ship scene
 *                ('T C m v0 s0' a line) or --harbour N of the ship model;
 *   the engine   rtl (with --trace) or iss, and the program for it.
 *
 * Each step returns 0, or the command's exit status (2 bad input, 1 a
 * failure) with the message on stderr naming the command.
 */
#ifndef FP3_RUNSETUP_H
#define FP3_RUNSETUP_H

#include <stddef.h>
#include <stdint.h>

#include "cmd_model.h"
#include "compile.h"
#include "engine.h"
#include "image.h"
#include "model.h"
#include "report.h"
#include "mscene.h"

#define FP3_DEFAULT_MODEL "models/ship.fp3m" /* the paper's Equations (1) */

typedef struct fp3_run_setup {
  char model_path[8192], program_path[8192];
  const char *program;   /* the hand-written program, or NULL: compiled      */
  fp3_image img;         /* its image                                        */
  fp3_model *m;          /* the model (the scene's own when many)            */
  fp3_mscene sc;         /* many objects: the scene (owns m)                 */
  int many;              /* 1: sc holds the objects                          */
  float in[FP3_MODEL_MAX_VARS], y0[FP3_MODEL_MAX_VARS]; /* one object: h and
                            the params, the initial state                   */
  fp3_engine *e;
  fp3_compiled *c;       /* the program, compiled or bound                   */
  const char *integ;     /* its integrator                                   */
  int literal;           /* 1: the literal integrator (a bound program is)   */
} fp3_run_setup;

/* A file shipped with FP3 (models/, programs/): path gets rel when it is
 * readable from the working directory, else rel beside the executable's
 * folder (build/fp3 -> ../rel) when that is, else rel. */
void fp3_find_shipped(const char *rel, char *path, size_t n);

/* A scene of any kind (fp3_mscene_read_any): a model scene, or a ship
 * scene read as a scene of the shipped ship model (FP3_DEFAULT_MODEL, as
 * fp3_find_shipped finds it).  0 and *sc, or non-zero with msg. */
int fp3_read_scene(const char *path, fp3_mscene *sc, char *msg, size_t n);

/* The model of scene `path` (fp3_read_scene; a ship scene as a scene of
 * ship_model, or of the shipped ship when it is NULL), for compiling the
 * scene's program: zero[k] = 1 for each param k zero in every object
 * (fp3_mscene_zero), *objects the scene's objects.  The model (the
 * caller frees it with free()), or NULL with "FILE:LINE: reason" in msg. */
fp3_model *fp3_scene_model(const char *path, const char *ship_model, unsigned char *zero,
                           size_t *objects, char *msg, size_t n);

/* Append to b the params whose terms a scene's program drops, those k
 * >= 1 (not h) with zero[k] set (fp3_scene_model), as "a, b, c"; returns
 * how many. */
unsigned fp3_zero_params_list(const fp3_model *m, const unsigned char *zero, fp3_strbuf *b);

/* The program: a->program, or default_program (NULL: none) when neither
 * --model, a model scene, --integrator nor --literal asks for a compiled
 * one; assembled into s->img, refused when it cannot end. */
int fp3_run_setup_program(const fp3_model_args *a, fp3_run_setup *s, const char *cmd,
                          const char *default_program);

/* The model and the objects (see above); a program's `.model`, when the
 * file is there, must be the model. */
int fp3_run_setup_model(const fp3_model_args *a, fp3_run_setup *s, const char *cmd);

/* The engine (its progress line unless --json, the trace of one object)
 * and s->c: the program bound to the model, or the model compiled for
 * the engine's build (the ISS reshaped to the registers it needs). */
int fp3_run_setup_engine(const fp3_model_args *a, fp3_run_setup *s, const char *cmd);

void fp3_run_setup_free(fp3_run_setup *s);

/* ---- the reports' common parts (docs/json.md) ------------------------------ */

/* The JSON members every run and frames object starts with: engine,
 * cycles_counted, model, model_file, program, scene (NULL: null),
 * integrator, literal, words, insns_per_step, registers_needed, num_regs,
 * est_cycles_per_step, round, ftz. */
void fp3_run_json_head(const fp3_model_args *a, const fp3_run_setup *s, const char *scene);

/* ", \"run_error\": " null, or the first context error, its object and pc. */
void fp3_run_json_error(unsigned error, size_t object, uint32_t pc);

/* One object's results: each state variable y[], its golden value (gold
 * NULL: none), GSL reference and exact solution (NAN: null). */
void fp3_run_json_object(const fp3_model *m, const uint32_t *y, const float *gold,
                         const double *ref, const double *ex);

/* The GSL reference (rk8pd, 1e-12; want_ref 0: none) and the exact
 * solution of an object (params in, initial state y0) after `steps`
 * integrations, NAN where there is none; rmsg the reference's failure. */
void fp3_run_references(const fp3_model *m, const float *in, const float *y0, uint32_t steps,
                        int want_ref, double *ref, double *ex, char *rmsg, size_t n);

#endif /* FP3_RUNSETUP_H */
