/*
 * frames.h -- a scene run frame by frame, as a game engine runs it, with
 * sleeping objects (docs/skipping.md "Sleeping objects").
 *
 * Each frame is one integration (step h) of every object.  The host keeps
 * every object's whole register bank (NUM_REGS words) between frames and
 * runs the objects that are awake in batches of the engine's contexts, one
 * START per batch with STEPS = 1: write the banks, run, read them back.
 *
 * Two kinds of sleeping, both bit-exact:
 *   - in the program: a sleeping program (programs/ship_rk4_sleep.s) skips
 *     the velocity stages with `beq v, vp` once v stopped changing;
 *   - on the host (rest_skip): an object whose frame left its whole
 *     register bank bit-identical is at a fixed point of the program (a
 *     frame reads nothing but its bank and the instruction memory), so
 *     every later frame would leave it so again: it is not run until it is
 *     woken.  Its flags too would repeat those already raised.
 * A wake (fp3_frames_opts.wake_*) changes an object's thrust T between two
 * frames, in its bank (with nv0 = -v, so that a sleeping program runs its
 * velocity stages again) and in its golden model.
 *
 * Every object (awake or asleep) is compared after every frame with the
 * golden model of its integrator, which runs every stage of every frame:
 * that is the evidence that sleeping changes no bit.
 */
#ifndef FP3_FRAMES_H
#define FP3_FRAMES_H

#include <stddef.h>
#include <stdint.h>

#include "engine.h"
#include "image.h"
#include "integrators.h"
#include "objects.h"

typedef struct fp3_frames_opts {
  uint32_t frames;     /* frames to run, >= 1                               */
  int rest_skip;       /* host skips objects at a fixed point (see above)   */
  uint32_t wake_frame; /* before this frame (1-based; 0: never) ...         */
  size_t wake_count;   /* ... the first wake_count objects with T = 0 ...   */
  float wake_vinf;     /* ... get thrust T = wake_vinf * C (C > 0 ones) [m/s] */
} fp3_frames_opts;

typedef struct fp3_frames_result {
  size_t objects;
  uint32_t frames;
  unsigned contexts;       /* contexts per batch (the engine's)              */
  unsigned lanes;          /* lanes per context: a batch packs the awake
                              objects into contexts x lanes slots          */
  uint64_t batches;        /* STARTs                                         */
  uint64_t cycles;         /* START to DONE, summed over batches             */
  uint64_t issued;
  uint64_t object_frames;  /* object-frames run on the engine                */
  uint64_t skipped;        /* object-frames skipped at rest by the host      */
  uint64_t host_words;     /* register words written and read by the host    */
  size_t asleep_last;      /* objects at rest after the last frame           */
  size_t woken;            /* objects woken                                  */
  unsigned error;          /* first context error (enum fp3_error)           */
  size_t error_object;
  uint32_t error_pc;
  uint64_t mismatches;     /* (object, frame, v or s) != golden              */
  size_t first_object;     /* first mismatch                                 */
  uint32_t first_frame;
} fp3_frames_result;

/* Run scene sc for o->frames frames on engine e with program img (its
 * `.in` registers written from each object, fp3_in_registers), checked
 * against the golden model of integrator ig in core options `mode`; the
 * frames count on the engine's progress line (fp3_engine_show_progress).
 * Returns 0 when the frames ran (mismatches and errors are in *res), -1
 * with a message (engine failure, out of memory, program without .out v
 * and s, bad options). */
int fp3_run_frames(fp3_engine *e, const fp3_image *img, const fp3_scene *sc,
                   const fp3_integrator *ig, fpref_mode mode, const fp3_frames_opts *o,
                   fp3_frames_result *res, char *msg, size_t n);

#endif /* FP3_FRAMES_H */
