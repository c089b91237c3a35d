/*
 * objects.h -- scenes of many ships, run on the contexts of an engine and
 * checked object by object against the golden model.
 *
 * Scene file: text, one object per line, `#` starts a comment:
 *
 *   # a harbour                       (comment)
 *   h 0.0166666675                    (time step [s], once, before objects)
 *   # T [N]   C [kg/s]   m [kg]   v0 [m/s]   s0 [m]
 *   50000     5000       10000    0          0
 *   0         300        5000     12.5       100
 *
 * Numbers are read as binary32 (strtof).  Every object must be physical:
 * m > 0, C >= 0, all values finite (fp3_ship_validate); h > 0.
 */
#ifndef FP3_OBJECTS_H
#define FP3_OBJECTS_H

#include <stddef.h>
#include <stdint.h>

#include "engine.h"
#include "golden.h"
#include "image.h"
#include "integrators.h"

/* A scene: n objects, all with the same h (objs[i].h). */
typedef struct fp3_scene {
  fp3_ship_params *objs; /* malloc'd */
  size_t n;
} fp3_scene;

/* Read a scene file: one `h STEP` line (the time step, finite and > 0)
 * before the objects, then one object per line, `T C m v0 s0`; `#` starts
 * a comment.  A file without the `h` line, or with two, is refused: the
 * step is never guessed.  h: unused (the step comes from the file; kept so
 * that callers need not change).  Returns 0, or -1 with "FILE:LINE:
 * reason" in msg (nothing allocated). */
int fp3_scene_read(const char *path, float h, fp3_scene *sc, char *msg, size_t n);

/* The `h STEP` line of a scene file (ship or model scene): p is the text
 * after the `h`, nobj the objects read so far, *h_line the line of an
 * earlier `h` (0: none; set to lineno).  Returns 0 with the step in *h, or
 * -1 with "FILE:LINE: reason": after an object, a second `h`, not one
 * number, not finite and > 0. */
int fp3_scene_h_line(char *p, const char *path, int lineno, size_t nobj, int *h_line,
                     float *h, char *msg, size_t n);

/* A reproducible random scene of n ships (seeded xorshift): masses
 * log-uniform in [1, 1e6] kg, time constants m/C in [0.5, 50] s (one ship
 * in eight without drag), terminal velocities in [-5, 30] m/s, v0 in
 * [-10, 30] m/s, s0 in [-100, 100] m.  Returns 0 or -1 (out of memory). */
int fp3_scene_generate(uint64_t seed, size_t n, float h, fp3_scene *sc);

/* A reproducible harbour of n ships (seeded xorshift), the scene of the
 * sleeping benchmark (docs/skipping.md "Sleeping objects"): masses log-uniform in
 * [1e4, 3.2e6] kg, time constants m/C in [2, 20] s, terminal velocities
 * T/C in [2, 12] m/s, s0 in [-2000, 2000] m; 60 % moored (T = 0, v0 = 0),
 * 35 % cruising (v0 = T/C in binary32), 5 % accelerating from rest.
 * Returns 0 or -1 (out of memory). */
int fp3_scene_harbour(uint64_t seed, size_t n, float h, fp3_scene *sc);

void fp3_scene_free(fp3_scene *sc);

/* The scene generators' xorshift64 (Marsaglia 2003, shifts 13, 7, 17):
 * advances *s (never 0) and returns it. */
uint64_t fp3_scene_xorshift(uint64_t *s);

/* The value of every `.in` parameter (enum fp3_in_param) for object p:
 * the scene values, minv = 1.0f/m, and the folded inputs hm = h*minv,
 * hmT = hm*T, hmC = hm*C, and nv0 = -v0.  Each derived value is one binary32 operation in
 * round-to-nearest-even with subnormals, whatever the caller's FP
 * environment (fpenv.h): the values the host writes, and the values the
 * golden models must start from. */
void fp3_in_values(const fp3_ship_params *p, float val[FP3_IN_COUNT]);

/* Write the `.in` registers of img for object p into regs[] (registers the
 * image does not bind are left alone). */
void fp3_in_registers(const fp3_image *img, const fp3_ship_params *p, uint32_t *regs);

/* A golden model of one object, as fp3_run_objects() uses it: start() sets
 * the object (v = v0, s = s0, and any prologue arithmetic), step() runs
 * one integration and returns v and s.  Both run inside the cores' FP mode
 * (fpenv_enter).  The state lives in *ctx: one object at a time. */
typedef struct fp3_golden_ref {
  void *ctx;
  void (*start)(void *ctx, const fp3_ship_params *p);
  void (*step)(void *ctx, float *v, float *s);
} fp3_golden_ref;

/* Storage of the golden model of an integrator (integrators.h). */
typedef struct fp3_integ_golden {
  const fp3_integrator *integ;
  fp3_istate st;
} fp3_integ_golden;

/* The golden model of integrator ig, its state in *storage (which must
 * outlive the returned reference). */
fp3_golden_ref fp3_golden_of_integrator(fp3_integ_golden *storage,
                                        const fp3_integrator *ig);

/* Outcome of a multi-object run. */
typedef struct fp3_objects_result {
  size_t objects;
  unsigned contexts;       /* contexts per batch (the engine's)            */
  unsigned lanes;          /* lanes per context (the engine's): a batch is
                              contexts x lanes objects (engine.h slots)    */
  size_t batches;
  uint64_t cycles;         /* sum over batches                             */
  uint64_t issued, stalls;
  uint64_t unit_issued[FP3_NUM_UNITS]; /* per unit, FP3_UNIT_*              */
  uint32_t flags;          /* sticky exception flags, all batches          */
  unsigned error;          /* first context error (enum fp3_error)         */
  size_t error_object;     /* ... of this object                           */
  uint32_t error_pc;
  uint64_t mismatches;     /* (object, integration, v or s) != golden      */
  size_t first_object;     /* first mismatch                               */
  uint32_t first_step;
  uint32_t *v, *s;         /* final v and s of each object (malloc'd)       */
} fp3_objects_result;

/* What running objects of program img on engine e needs: `.out v` and
 * `.out s`, every `.in` register inside the engine's NUM_REGS, and a host
 * that can run the golden model in core options `mode`.  Returns 0, or -1
 * with the reason in msg. */
int fp3_objects_check(const fp3_engine *e, const fp3_image *img, fpref_mode mode, char *msg,
                      size_t n);

/* Run every object of the scene for `steps` integrations on the engine, in
 * batches of fp3_config_slots(&e->config) objects (contexts x lanes), writing each object's `.in`
 * registers (fp3_in_registers), and compare v and s of every object after
 * every integration with the golden model (run in core options `mode`).
 * The object-steps count on the engine's progress line
 * (fp3_engine_show_progress).
 * Returns 0 when the runs took place (mismatches and errors are in *res),
 * or -1 with a message (engine failure, out of memory, program without
 * .out v/s). */
int fp3_run_objects(fp3_engine *e, const fp3_image *img, const fp3_scene *sc,
                    uint32_t steps, fpref_mode mode, const fp3_golden_ref *golden,
                    fp3_objects_result *res, char *msg, size_t n);

void fp3_objects_result_free(fp3_objects_result *res);

#endif /* FP3_OBJECTS_H */
