/*
 * cmd_frames.c -- `fp3 frames` (cmd_frames.h): a scene run frame by frame,
 * as a game engine runs it, with sleeping objects (docs/skipping.md).
 *
 * The one path of `fp3 run` (runsetup.h: a model, a scene of it, a
 * program, an engine), run by fp3_run_state_frames: each frame one
 * integration of every awake object, the register banks kept by the host,
 * objects at rest skipped, every object compared with its golden model
 * after every frame.  Without a scene, the ship model's harbour of 1,000
 * ships and the paper's RK4 program that sleeps (programs/ship_rk4_sleep.s,
 * `beq` once v stops changing).
 */
#include "cmd_frames.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cliopt.h"
#include "cmd_model.h"
#include "compile.h"
#include "engine.h"
#include "fpref.h"
#include "mscene.h"
#include "report.h"
#include "runsetup.h"

/* fp3-mpi (-DFP3_MPI): each frame's batches sharded across the MPI ranks
 * (mpishard.h); build/fp3 runs them in one process. */
#ifdef FP3_MPI
#include "mpishard.h"
#define RUN_STATE_FRAMES fp3_mpi_run_state_frames
#else
#define RUN_STATE_FRAMES fp3_run_state_frames
#endif

#define EXIT_FAIL 1
#define EXIT_USAGE 2
#define DEFAULT_PROGRAM "programs/ship_rk4_sleep.s"

static void usage(FILE *f) {
  fprintf(f,
          "usage: fp3 frames [--scene FILE | --harbour N [--seed S] | --model FILE --objects N\n"
          "                  [--seed S]] [--frames F] [--program FILE.s | --integrator NAME\n"
          "                  [--literal]] [--no-rest-skip] [--wake F:K:NAME=VALUE[*PARAM]]\n"
          "                  [--engine rtl|iss|spatial [--pipelines N] [--clock-cores]|uart:DEV] [--round rne|rtz] [--ftz] [--fmax MHZ] [--json]\n"
          "\n"
          "Run a scene frame by frame, as a game engine does: each frame is one\n"
          "integration of every object that is awake, in batches of contexts x\n"
          "lanes (one START each); the host keeps every object's register bank\n"
          "between frames.  An object whose frame left its whole bank bit-identical\n"
          "is at rest and is not run again until woken.  Every object is compared\n"
          "after every frame, bit for bit, with its golden model, which runs every\n"
          "stage.  The model, the program and the engine are fp3 run's (fp3 run --help).\n"
          "\n"
          "  --scene FILE     a model scene, or a ship scene ('T C m v0 s0' a line) of\n"
          "                   models/ship.fp3m (or --model)\n"
          "  --harbour N      a generated harbour of N ships of the ship model (the\n"
          "                   default: 1000): 60 %% moored, 35 %% cruising at terminal\n"
          "                   velocity, 5 %% accelerating; h = 1/60 s; --seed S (1)\n"
          "  --objects N      N objects of --model FILE from its defaults and --set,\n"
          "                   each value (h excepted) times a factor in [0.75, 1.25]\n"
          "  --frames F       frames, 1..10000000 (default 600: 10 s)\n"
          "  --program FILE   a hand-written program of the model (default for the ship:\n"
          "                   %s, which also skips the velocity\n"
          "                   stages of settled objects); every value it carries from\n"
          "                   frame to frame must be bound (.out)\n"
          "  --integrator I   compile the model for I (%s)\n"
          "  --literal        the literal integrator (docs/models.md)\n"
          "  --no-rest-skip   run objects at rest too (to measure what skipping saves)\n"
          "  --wake F:K:NAME=VALUE[*PARAM]  before frame F, the first K objects whose\n"
          "                   param NAME is 0 get NAME = VALUE (or VALUE times their param\n"
          "                   PARAM, in binary32) and restart from where they are: the\n"
          "                   ship's harbour, --wake 300:100:T=4*C\n"
          "  --engine E       rtl (default), iss (no timing: cycles = instructions),\n"
          "                   spatial (the model's pipeline, docs/spatial.md), or a\n"
          "                   board: uart:DEVICE[@BAUD], uart:socket://HOST:PORT\n"
          "  --fmax MHZ       clock for frames per second (default 40.5, the default\n"
          "                   build's Fmax on LFE5U-85F-6, README)\n"
          "  --json           the report as JSON (docs/json.md)\n"
          "\n"
          "Exit status: 0 all bit-identical, 1 a mismatch or error, 2 bad usage.\n",
          DEFAULT_PROGRAM, fp3_model_integrators());
}

/* ---- fp3 frames -------------------------------------------------------------- */

static int run_frames(const fp3_model_args *a, fp3_run_setup *s) {
  const fp3_model *m = s->m;
  const unsigned carried = fp3_compiled_carried(s->c);
  for (unsigned i = 0; i < carried; i++) /* the bank must hold what the golden carries */
    if (fp3_compiled_state_reg(s->c, i) >= s->e->config.num_regs) {
      fprintf(stderr, "fp3 frames: %s carries %u values from one integration to the next "
              "(%s), but binds no register for value %u: frame by frame the host restarts "
              "each object from its bank; a compiled program keeps them there (--integrator "
              "%s)\n", s->program ? s->program : m->file, carried, s->integ, i, s->integ);
      return EXIT_USAGE;
    }
  fp3_scene_waker w;
  char msg[512];
  if (a->wake_frame &&
      fp3_scene_waker_init(&w, s->c, &s->sc, a->wake_frame, a->wake_count, a->wake_param,
                           a->wake_value, a->wake_times, msg, sizeof msg)) {
    fprintf(stderr, "fp3 frames: --wake: %s\n", msg);
    return EXIT_USAGE;
  }
  fp3_scene_gold sg;
  fp3_scene_gold_init(&sg, s->c, &s->sc);
  const fp3_image *img = fp3_compiled_image(s->c);
  fp3_state_frames_result res;
  if (RUN_STATE_FRAMES(s->e, img->words, img->n, s->sc.n, a->steps, !a->no_rest_skip,
                       a->wake_frame ? &w.wake : NULL, a->mode, &sg.stepper, &res, msg,
                       sizeof msg)) {
    fprintf(stderr, "fp3 frames: %s\n", msg);
    return EXIT_FAIL;
  }
  const int pass = res.mismatches == 0 && res.error == FP3_ERR_NONE;
  const double per = (double)res.cycles / res.frames;
  const double fps = a->fmax * 1e6 / per;
  const uint64_t all = (uint64_t)res.objects * res.frames;
  const char *scene = a->scene ? a->scene : a->harbour ? "harbour" : "generated (--objects, --seed)";
  if (a->json) {
    fp3_run_json_head(a, s, scene);
    printf(", \"seed\": ");
    if (a->scene) printf("null");
    else printf("%" PRIu64, a->seed);
    printf(", \"objects\": %zu, \"frames\": %" PRIu32 ", \"contexts\": %u, \"lanes\": %u"
           ", \"rest_skip\": %s, \"batches\": %" PRIu64 ", \"cycles\": %" PRIu64
           ", \"cycles_per_frame\": %.9g, \"issued_per_frame\": %.9g"
           ", \"object_frames_run\": %" PRIu64 ", \"object_frames_skipped\": %" PRIu64
           ", \"asleep_at_end\": %zu, \"woken\": %zu, \"host_words_per_frame\": %.9g"
           ", \"fmax_mhz\": %.9g, \"frames_per_second\": %.9g, \"golden_mismatches\": %" PRIu64,
           res.objects, res.frames, res.contexts, res.lanes, a->no_rest_skip ? "false" : "true",
           res.batches, res.cycles, per, (double)res.issued / res.frames, res.object_frames,
           res.skipped, res.asleep_last, res.woken, (double)res.host_words / res.frames,
           a->fmax, fps, res.mismatches);
    printf(", \"first_mismatch\": ");
    if (res.mismatches)
      printf("{\"object\": %zu, \"frame\": %" PRIu32 ", \"variable\": \"%s%s\"}",
             res.first_object, res.first_frame, res.first_var < m->nstate ? "" : "carried ",
             m->state[res.first_var % m->nstate]);
    else
      printf("null");
    fp3_run_json_error(res.error, res.error_object, res.error_pc);
    printf(", \"pass\": %s}\n", pass ? "true" : "false");
  } else {
    printf("fp3 frames: %zu objects of model %s (%s), %" PRIu32 " frames, ", res.objects,
           m->name, scene, res.frames);
    if (s->program) printf("program %s (%s)", s->program, s->integ);
    else printf("integrator %s %s", s->integ, s->literal ? "literal" : "folded");
    printf(", %s engine, %u contexts x %u lanes%s\n", a->engine, res.contexts, res.lanes,
           a->no_rest_skip ? ", no rest skip" : "");
    printf("  cycles per frame          %.2f (START to DONE of %" PRIu64 " batches)\n", per,
           res.batches);
    printf("  instructions per frame    %.2f\n", (double)res.issued / res.frames);
    printf("  object-frames run         %" PRIu64 " of %" PRIu64 " (%" PRIu64
           " skipped at rest); %zu at rest at the end, %zu woken\n", res.object_frames, all,
           res.skipped, res.asleep_last, res.woken);
    printf("  host words per frame      %.1f (register banks written and read)\n",
           (double)res.host_words / res.frames);
    printf("  frames per second         %.0f at %.1f MHz\n", fps, a->fmax);
    if (res.error != FP3_ERR_NONE)
      printf("  ERROR %s in object %zu at pc %" PRIu32 "\n", fp3_error_name(res.error),
             res.error_object, res.error_pc);
    if (res.mismatches)
      printf("  FAIL: %" PRIu64 " mismatches against the golden model, first object %zu frame "
             "%" PRIu32 " %s %s\n", res.mismatches, res.first_object, res.first_frame,
             res.first_var < m->nstate ? "variable" : "the carried value beside",
             m->state[res.first_var % m->nstate]);
    else
      printf("  golden model: bit-identical, every value carried by every object after every "
             "frame\n");
  }
  return pass ? 0 : EXIT_FAIL;
}

int fp3_cmd_frames(int argc, char **argv) {
  fp3_model_args a;
  int r = fp3_parse_model(argc, argv, "frames", &a);
  if (r != FP3_ARGS_RUN) return fp3_args_exit(r, usage);
  fp3_run_setup s;
  memset(&s, 0, sizeof s);
  fp3_image_init(&s.img);
  int rc = fp3_run_setup_program(&a, &s, "frames", DEFAULT_PROGRAM);
  if (!rc) rc = fp3_run_setup_model(&a, &s, "frames");
  /* fp3_parse_model leaves frames a scene, --objects or a harbour: many objects */
  if (!rc) rc = fp3_run_setup_engine(&a, &s, "frames");
  if (!rc) rc = run_frames(&a, &s);
  fp3_run_setup_free(&s);
  return rc;
}
