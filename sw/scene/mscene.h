/*
 * mscene.h -- scenes of many objects of one model (the model language,
 * docs/models.md), and running them on the contexts of an engine, every
 * object checked bit for bit against a golden model after every
 * integration.
 *
 * Scene file (text, `#` starts a comment):
 *
 *   model ../models/spring.fp3m     (the model, relative to this file)
 *   h 0.015625                      (time step [s], once, before objects)
 *   k    c    m    x     v          (header: the per-object columns)
 *   40   0.8  2    0.5   -0.25      (one object per line)
 *   10   0    1    1     0
 *
 * The header names every param of the model (h excepted: it is the `h`
 * line) and every state variable (its initial value), each once, in any
 * order.  Numbers are read as binary32 (strtof) and must be finite.
 */
#ifndef FP3_MSCENE_H
#define FP3_MSCENE_H

#include <stddef.h>
#include <stdint.h>

#include "engine.h"
#include "fpref.h"
#include "model.h"
#include "objects.h"

/* A model scene: n objects of one model. */
typedef struct fp3_mscene {
  fp3_model *model;      /* malloc'd; model->file is model_path           */
  char model_path[1024]; /* the model file, resolved against the scene's
                            folder                                         */
  int model_line;        /* line of the `model` line                       */
  int header_line;       /* line of the column header                      */
  size_t n;              /* objects                                         */
  float *in;             /* n x model->nparam: h, then the params          */
  float *y0;             /* n x model->nstate: initial states              */
  int *line;             /* source line of each object (0: generated)      */
} fp3_mscene;

/* 1 if the file's first line that is not blank or a comment is a `model`
 * line (a model scene), 0 otherwise (a ship scene, or unreadable: the ship
 * reader then gives the error). */
int fp3_scene_is_model(const char *path);

/* Read a model scene.  Returns 0, or -1 with "FILE:LINE: reason" in msg
 * (nothing allocated): no `model` line or two, the model's own errors
 * (its FILE:LINE:COL), no `h` line or two, h not finite and > 0, no
 * header before the first object, a header name that is neither a param
 * nor a state variable, named twice, or `h`; a param or state variable the
 * header leaves out (named with the model file and its declaring line); a
 * row with fewer or more numbers than columns, or a number that is bad or
 * not finite; no objects. */
int fp3_mscene_read(const char *path, fp3_mscene *s, char *msg, size_t n);

/* zero[k] = 1 for each param k of sc's model that is zero in every object
 * (a term the compiler may drop, fp3_compile_model's param_zero), else 0. */
void fp3_mscene_zero(const fp3_mscene *sc, unsigned char *zero);

/* A scene of ships (objects.h: T C m v0 s0 and h each) as a scene of
 * the model file model_path, which must have params T, C, m and state
 * variables v, s (models/ship.fp3m); what names the scene in messages.
 * Returns 0; -1 with the reason in msg (a bad model, or another one); 1
 * out of memory. */
int fp3_mscene_from_ships(const fp3_scene *ships, const char *model_path, const char *what,
                          fp3_mscene *s, char *msg, size_t n);

/* A scene file in either format: a model scene (fp3_mscene_read), or a
 * ship scene ('h STEP', then 'T C m v0 s0' a line, objects.h), read as a
 * scene of the model file ship_model (models/ship.fp3m: params T, C, m,
 * state variables v, s; the step 1/60 s until an `h` line).  Returns 0;
 * -1 with "FILE:LINE: reason" in msg; 1 out of memory. */
int fp3_mscene_read_any(const char *path, const char *ship_model, fp3_mscene *s, char *msg,
                        size_t n);

/* n objects of model m (loaded by the caller, owned by s afterwards), all
 * from base values in[] (h and params) and y0[] (states), each non-h value
 * of object i >= 1 scaled by its own factor uniform in [0.75, 1.25] from a
 * seeded xorshift (object 0 has the base values exactly; h is never
 * varied).  Returns 0 or -1 (out of memory; m is freed). */
int fp3_mscene_generate(fp3_model *m, const float *in, const float *y0, size_t n,
                        uint64_t seed, fp3_mscene *s);

void fp3_mscene_free(fp3_mscene *s);

/* Write regs[0..nregs) into the registers of context c of engine e.
 * Returns 0, or -1 with the engine's message. */
int fp3_ctx_write_bank(fp3_engine *e, unsigned c, const uint32_t *regs, unsigned nregs,
                       char *msg, size_t n);

/* The status of context c after a run (*cs), its object obj: the first
 * context error of a run is kept in *error (enum fp3_error, left alone
 * once set), *error_object and *error_pc.  Returns 0, or -1 with the
 * engine's message. */
int fp3_ctx_check(fp3_engine *e, unsigned c, size_t obj, fp3_ctx_status *cs, unsigned *error,
                  size_t *error_object, uint32_t *error_pc, char *msg, size_t n);

/* Run contexts 0..k-1 of engine e for `steps` integrations (observer obs,
 * may be NULL).  Returns 0, or -1 with the engine's message, or when
 * *bad_tag (if not NULL) was set by the observer: a write tagged with an
 * integration past the run (an engine fault). */
int fp3_ctx_run_batch(fp3_engine *e, uint32_t steps, unsigned k, const fp3_observer *obs,
                      const int *bad_tag, fp3_status *st, char *msg, size_t n);

/* A golden model of a program with nstate state registers, one object at
 * a time.  start() sets object `obj` and gives the register writes the
 * host makes before the run (at most max: returns how many); step() runs
 * one integration and gives the new state.  Both run inside the cores' FP
 * environment (fpenv_enter(mode)). */
typedef struct fp3_state_golden {
  void *ctx;
  unsigned nstate;
  const unsigned *reg; /* nstate registers holding the state            */
  size_t (*start)(void *ctx, size_t obj, unsigned *reg, uint32_t *val, size_t max);
  void (*step)(void *ctx, float *y);
} fp3_state_golden;

/* Outcome of fp3_run_state_objects. */
typedef struct fp3_state_result {
  size_t objects;
  unsigned contexts;       /* contexts per batch                           */
  unsigned lanes;          /* lanes per context: a batch holds contexts x
                              lanes objects (engine.h slots)              */
  size_t batches;
  uint64_t cycles, issued, stalls;
  uint64_t unit_issued[FP3_NUM_UNITS]; /* issued per unit, FP3_UNIT_*       */
  uint32_t flags;          /* sticky exception flags, all batches          */
  unsigned error;          /* first context error (enum fp3_error)         */
  size_t error_object;
  uint32_t error_pc;
  uint64_t mismatches;     /* (object, integration, variable) != golden   */
  size_t first_object;     /* first mismatch: object, integration, variable */
  uint32_t first_step;
  unsigned first_var;
  uint32_t first_got, first_want;
  size_t nonfinite_object; /* first object whose golden state is not finite
                              (SIZE_MAX: none), its integration, variable */
  uint32_t nonfinite_step;
  unsigned nonfinite_var;
  uint32_t *y;             /* final state, objects x nstate (malloc'd)     */
  int final_only;          /* 1: the engine reports no write-backs (a
                              board, fp3_engine_untraced): only the final
                              state was compared, not every integration   */
} fp3_state_result;

/* Run `nobj` objects for `steps` integrations on engine e with the
 * program words[0..nwords) (assembled, image.h), in batches of
 * fp3_config_slots(&e->config) objects (contexts x lanes; object slot s is
 * lane s / NUM_CONTEXTS of context s % NUM_CONTEXTS, engine.h): each
 * slot's registers zeroed, then golden->start's writes; after the batch, every
 * state register of every object after every integration compared bit for
 * bit with golden->step (run in `mode`); on an engine that reports no
 * write-backs (fp3_engine_untraced: a board) the state after the run.  Returns 0 when the runs took
 * place (mismatches, errors and non-finite states are in *res), or -1 with
 * a message (engine failure, out of memory, a register beyond NUM_REGS,
 * too much to record).  The object-steps count on the engine's progress line
 * (fp3_engine_show_progress). */
int fp3_run_state_objects(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                          uint32_t steps, fpref_mode mode, const fp3_state_golden *golden,
                          fp3_state_result *res, char *msg, size_t n);

void fp3_state_result_free(fp3_state_result *res);

/* ---- frame by frame, with rest skipping --------------------------------- */

/* A golden model that steps any object from any state: step_from() runs
 * one integration of object `obj` from state y (nstate values, at most
 * FP3_STEPPER_MAX_VARS) into ynew, in the cores' FP environment; start()
 * as in fp3_state_golden gives the host's register writes of the object's
 * first frame.  The state is every value the program carries from one
 * integration to the next (a model's state variables, then rk4comp's
 * compensations), each in its register reg[i]. */
#define FP3_STEPPER_MAX_VARS (2 * FP3_MODEL_MAX_VARS)
typedef struct fp3_state_stepper {
  void *ctx;
  unsigned nstate;
  const unsigned *reg;
  size_t (*start)(void *ctx, size_t obj, unsigned *reg, uint32_t *val, size_t max);
  void (*step_from)(void *ctx, size_t obj, const float *y, float *ynew);
} fp3_state_stepper;

/* Outcome of fp3_run_state_frames. */
typedef struct fp3_state_frames_result {
  size_t objects;
  uint32_t frames;
  unsigned contexts, lanes; /* a batch: contexts x lanes objects          */
  uint64_t batches, cycles, issued;
  uint64_t object_frames;  /* object-frames run on the engine              */
  uint64_t skipped;        /* object-frames skipped at rest                 */
  size_t asleep_last;      /* objects at rest after the last frame          */
  unsigned error;
  size_t error_object;
  uint32_t error_pc;
  uint64_t mismatches;     /* (object, frame, carried value) != golden     */
  size_t first_object;
  uint32_t first_frame;
  unsigned first_var;      /* index into the stepper's carried values      */
  size_t woken;            /* objects woken (fp3_state_wake)               */
  uint64_t host_words;     /* register words the host wrote and read back  */
} fp3_state_frames_result;

/* Waking objects between two frames: before frame `frame` (1-based; 0:
 * never), wake(ctx, obj, bank, nregs) is asked for object 0, 1, ... until
 * `count` have been woken; it returns 1 when it changed object obj (its
 * params, and the registers of its bank the host writes, restarted from
 * the carried values the bank holds), which is then awake, else 0.  The
 * golden model steps it from the same values with its new params. */
typedef struct fp3_state_wake {
  uint32_t frame;
  size_t count;
  int (*wake)(void *ctx, size_t obj, uint32_t *bank, unsigned nregs);
  void *ctx;
} fp3_state_wake;

/* Run nobj objects frame by frame: each frame one integration (STEPS = 1)
 * of every awake object, in batches of contexts x lanes (fp3_config_slots,
 * as fp3_run_state_objects); the host keeps every
 * object's whole register bank between frames (written before, read after
 * each batch).  With rest_skip, an object whose frame left its whole bank
 * bit-identical is at a fixed point of the program (a frame reads nothing
 * but its bank and the instruction memory) and is not run again: every
 * later frame would leave it so.  Every object, awake or asleep, is
 * compared after every frame with golden->step_from, which steps it every
 * frame: the evidence that skipping changes no bit.  wake (NULL: none)
 * wakes objects between two frames.  The frames count on
 * the engine's progress line (fp3_engine_show_progress).  Returns 0 when
 * the frames ran (results in *res), or -1 with a message. */
int fp3_run_state_frames(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                         uint32_t frames, int rest_skip, const fp3_state_wake *wake,
                         fpref_mode mode,
                         const fp3_state_stepper *golden, fp3_state_frames_result *res,
                         char *msg, size_t n);

/* One frame of objects on engine e: one integration (STEPS = 1) of each
 * of k objects, in batches of contexts x lanes (the first batch the first
 * fp3_config_slots objects, and so on); object i's register bank, at
 * bank + at[i] * NUM_REGS, is written before its batch and read back
 * after it, and stay[i] = 1 when it came back bit-identical (at rest).
 * Adds the batches, cycles, issued, object_frames and host_words to *acc
 * and keeps its first context error (error_object: at[i]).  The engine
 * holds the program already.  Returns 0, or -1 with the engine's message. */
int fp3_frame_batches(fp3_engine *e, uint32_t *bank, const size_t *at, size_t k,
                      unsigned char *stay, fp3_state_frames_result *acc, char *msg, size_t n);

/* Where a frame's batches run, when not on the caller's engine alone (the
 * ranks of fp3-mpi, sw/cli/mpishard.h): run() has fp3_frame_batches'
 * contract for the frame's awake objects, at[i] being their indices into
 * the scene (bank holds every object's bank), and must give the same
 * results: the same batches, in the same order of the awake objects. */
typedef struct fp3_frames_farm {
  void *ctx;
  int (*run)(void *ctx, uint32_t *bank, const size_t *at, size_t k, unsigned char *stay,
             fp3_state_frames_result *acc, char *msg, size_t n);
} fp3_frames_farm;

/* fp3_run_state_frames with each frame's batches run by farm (NULL: on e
 * by fp3_frame_batches); e loads the program and gives the build's shape,
 * the rest-skipping, the waking and the golden check stay with the caller. */
int fp3_run_state_frames_farm(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                              uint32_t frames, int rest_skip, const fp3_state_wake *wake,
                              fpref_mode mode, const fp3_state_stepper *golden,
                              const fp3_frames_farm *farm, fp3_state_frames_result *res,
                              char *msg, size_t n);

#endif /* FP3_MSCENE_H */
