/*
 * cmd_frames.c -- `fp3 frames` (cmd_frames.h): the sleeping-objects
 * benchmark's command line.
 */
#include "cmd_frames.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asm.h"
#include "cliopt.h"
#include "cmd_model.h"
#include "frames.h"
#include "report.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2
#define DEFAULT_PROGRAM "programs/ship_rk4_sleep.s"
#define DEFAULT_FMAX 40.5 /* MHz: README "Results" Fmax row, make pnr, default build on LFE5U-85F-6 */
#define MAX_FRAMES 10000000u
#define MAX_SHIPS 1000000u

static void usage(FILE *f) {
  fprintf(f,
          "usage: fp3 frames [--scene FILE | --harbour N [--seed S]] [--frames F]\n"
          "                  [--program FILE.s] [--integrator NAME] [--no-rest-skip]\n"
          "                  [--wake FRAME:COUNT [--wake-vinf V]] [--engine rtl|iss]\n"
          "                  [--fmax MHZ] [--json]\n"
          "\n"
          "Run a scene frame by frame, as a game engine does: each frame is one\n"
          "integration of every object that is awake, in batches of NUM_CONTEXTS\n"
          "(one START each); the host keeps every object's register bank between\n"
          "frames.  An object whose frame left its whole bank bit-identical is at\n"
          "rest and is not run again until woken.  Every object is compared after\n"
          "every frame, bit for bit, with its golden model, which runs every stage.\n"
          "\n"
          "  --scene FILE     scene file (fp3 run --help); a model scene (docs/models.md)\n"
          "                   runs its compiled model, options --frames, --integrator,\n"
          "                   --literal, --no-rest-skip, --engine, --json; or\n"
          "  --harbour N      a generated harbour of N ships (default 1000): 60 %%\n"
          "                   moored, 35 %% cruising at terminal velocity, 5 %%\n"
          "                   accelerating; h = 1/60 s\n"
          "  --seed S         harbour seed (default 1)\n"
          "  --frames F       frames, 1..%u (default 600: 10 s)\n"
          "  --program FILE   program (default %s, which also\n"
          "                   skips the velocity stages of settled objects)\n"
          "  --integrator I   golden model (default rk4): %s\n"
          "  --no-rest-skip   run objects at rest too (to measure what skipping saves)\n"
          "  --wake F:K       before frame F, give K moored ships (T = 0, C > 0)\n"
          "                   thrust T = V * C (--wake-vinf V, default 4 m/s)\n"
          "  --engine E       rtl (default) or iss (no timing: cycles = instructions)\n"
          "  --fmax MHZ       clock for frames per second (default %.1f, the default\n"
          "                   build's Fmax on LFE5U-85F-6, README)\n"
          "  --json           the report as JSON\n"
          "\n"
          "Exit status: 0 all bit-identical, 1 a mismatch or error, 2 bad usage.\n",
          MAX_FRAMES, DEFAULT_PROGRAM, fp3_integrator_names(), DEFAULT_FMAX);
}

int fp3_parse_frames(int argc, char **argv, fp3_frames_args *a) {
  a->scene_path = NULL;
  a->program = DEFAULT_PROGRAM;
  a->engine_name = "rtl";
  a->ships = 1000;
  a->seed = 1;
  a->fmax = DEFAULT_FMAX;
  a->json = 0;
  a->ig = fp3_integrator_find("rk4");
  a->opts = (fp3_frames_opts){.frames = 600, .rest_skip = 1, .wake_frame = 0, .wake_count = 0,
                              .wake_vinf = 4.0f};
  fp3_frames_opts *o = &a->opts;
  unsigned long long frames = 600;
  for (int i = 1; i < argc; i++) {
    const char *arg = argv[i], *v = NULL;
    int r;
    char *end;
    if (fp3_is_help(arg)) {
      return FP3_ARGS_HELP;
    } else if ((r = fp3_opt_value(argc, argv, &i, "frames", "--scene", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->scene_path = v;
    } else if ((r = fp3_opt_count(argc, argv, &i, "frames", "--harbour", 1, MAX_SHIPS,
                                  "ships", &a->ships)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_seed(argc, argv, &i, "frames", &a->seed)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_count(argc, argv, &i, "frames", "--frames", 1, MAX_FRAMES,
                                  "frames", &frames)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_value(argc, argv, &i, "frames", "--program", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->program = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, "frames", "--integrator", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      if (!(a->ig = fp3_integrator_find(v))) {
        fprintf(stderr, "fp3 frames: unknown integrator '%s' (%s)\n", v, fp3_integrator_names());
        return FP3_ARGS_BAD;
      }
    } else if (strcmp(arg, "--no-rest-skip") == 0) {
      o->rest_skip = 0;
    } else if ((r = fp3_opt_value(argc, argv, &i, "frames", "--wake", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      unsigned long long wf, wk;
      if (fp3_parse_pair(v, 1, MAX_FRAMES, 1, MAX_SHIPS, NULL, &wf, &wk)) {
        fprintf(stderr, "fp3 frames: --wake '%s': want FRAME:COUNT, FRAME 1..%u, COUNT 1..%u\n",
                v, MAX_FRAMES, MAX_SHIPS);
        return FP3_ARGS_BAD;
      }
      o->wake_frame = (uint32_t)wf;
      o->wake_count = wk;
    } else if ((r = fp3_opt_value(argc, argv, &i, "frames", "--wake-vinf", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->wake_vinf = strtof(v, &end);
      if (*end || !isfinite(o->wake_vinf)) {
        fprintf(stderr, "fp3 frames: --wake-vinf '%s': not a finite number\n", v);
        return FP3_ARGS_BAD;
      }
    } else if ((r = fp3_opt_value(argc, argv, &i, "frames", "--engine", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      if (strcmp(v, "rtl") && strcmp(v, "iss")) {
        fprintf(stderr, "fp3 frames: --engine '%s': rtl or iss\n", v);
        return FP3_ARGS_BAD;
      }
      a->engine_name = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, "frames", "--fmax", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->fmax = strtod(v, &end);
      if (*end || !(a->fmax > 0.0) || !isfinite(a->fmax)) {
        fprintf(stderr, "fp3 frames: --fmax '%s': a positive clock in MHz\n", v);
        return FP3_ARGS_BAD;
      }
    } else if (strcmp(arg, "--json") == 0) {
      a->json = 1;
    } else {
      fprintf(stderr, "fp3 frames: unknown argument '%s' (see --help)\n", arg);
      return FP3_ARGS_BAD;
    }
  }
  o->frames = (uint32_t)frames;
  /* Every frame is a START, which runs the program's prologue again; the
   * compensated ship programs' prologue sets the Kahan compensations to
   * 0 (programs/ship_rk4comp.s), so frame by frame they integrate
   * another recurrence than their golden model, which carries them.  A
   * model scene's compiled rk4comp keeps them in the bank. */
  if (strstr(a->ig->name, "comp")) {
    fprintf(stderr, "fp3 frames: integrator %s on a ship program: the program's prologue, "
            "which every frame's START runs, restarts its Kahan compensations at 0, so frame "
            "by frame it is not the integration its golden model carries on; a model scene "
            "keeps the compensations in the register bank (fp3 frames --scene "
            "scenes/fleet.scene --integrator rk4comp)\n", a->ig->name);
    return FP3_ARGS_BAD;
  }
  return FP3_ARGS_RUN;
}

/* The run step: the scene, the program, the engine, the frames, the report. */
static int run_frames(const fp3_frames_args *a) {
  const char *scene_path = a->scene_path, *program = a->program, *engine_name = a->engine_name;
  const unsigned long long ships = a->ships;
  const uint64_t seed = a->seed;
  const double fmax = a->fmax;
  const int json = a->json;
  const fp3_integrator *ig = a->ig;
  const fp3_frames_opts o = a->opts;

  fp3_scene sc;
  char msg[512];
  if (scene_path) {
    if (fp3_scene_read(scene_path, 1.0f / 60.0f, &sc, msg, sizeof msg)) {
      fprintf(stderr, "fp3 frames: %s\n", msg);
      return EXIT_USAGE;
    }
  } else if (fp3_scene_harbour(seed, ships, 1.0f / 60.0f, &sc)) {
    fprintf(stderr, "fp3 frames: out of memory for %llu ships\n", ships);
    return EXIT_FAIL;
  }
  fp3_image img;
  char *errors = NULL;
  fp3_image_init(&img);
  if (fp3_asm_file(program, &img, &errors)) {
    fprintf(stderr, "%s", errors ? errors : "fp3 frames: assembly failed\n");
    free(errors);
    fp3_scene_free(&sc);
    return EXIT_USAGE;
  }
  fp3_engine *e = fp3_engine_new(engine_name);
  if (!e) {
    fprintf(stderr, "fp3 frames: cannot create the %s engine\n", engine_name);
    fp3_scene_free(&sc);
    return EXIT_FAIL;
  }
  fp3_engine_show_progress(e, json ? NULL : "fp3 frames");
  fp3_frames_result res;
  int rc = fp3_run_frames(e, &img, &sc, ig, (fpref_mode){FPREF_RNE, 0}, &o, &res, msg, sizeof msg);
  fp3_engine_free(e);
  fp3_scene_free(&sc);
  if (rc) {
    fprintf(stderr, "fp3 frames: %s\n", msg);
    return EXIT_FAIL;
  }
  const double per = (double)res.cycles / res.frames;
  const double fps = fmax * 1e6 / per;
  const uint64_t all = (uint64_t)res.objects * res.frames;
  const int pass = res.mismatches == 0 && res.error == FP3_ERR_NONE;
  if (json) {
    printf("{\"program\": ");
    fp3_json_string(stdout, program);
    printf(", \"scene\": ");
    fp3_json_string(stdout, scene_path ? scene_path : "harbour");
    printf(", \"seed\": %" PRIu64 ", \"objects\": %zu, \"frames\": %u, \"contexts\": %u, "
           "\"lanes\": %u, \"rest_skip\": %s, \"batches\": %" PRIu64 ", \"cycles\": %" PRIu64 ", "
           "\"cycles_per_frame\": %.2f, \"issued_per_frame\": %.2f, "
           "\"object_frames_run\": %" PRIu64 ", \"object_frames_skipped\": %" PRIu64 ", "
           "\"asleep_at_end\": %zu, \"woken\": %zu, \"host_words_per_frame\": %.1f, "
           "\"fmax_mhz\": %.1f, \"frames_per_second\": %.1f, \"golden_mismatches\": %" PRIu64
           ", \"error\": \"%s\", \"pass\": %s}\n",
           seed, res.objects, res.frames, res.contexts, res.lanes, o.rest_skip ? "true" : "false",
           res.batches, res.cycles, per, (double)res.issued / res.frames, res.object_frames,
           res.skipped, res.asleep_last, res.woken, (double)res.host_words / res.frames, fmax,
           fps, res.mismatches, fp3_error_name(res.error), pass ? "true" : "false");
  } else {
    printf("fp3 frames: %zu objects (%s), %u frames, %s, %s engine, %u contexts x %u lanes%s\n",
           res.objects, scene_path ? scene_path : "harbour", res.frames, program, engine_name,
           res.contexts, res.lanes, o.rest_skip ? "" : ", no rest skip");
    printf("  cycles per frame          %.2f (START to DONE of %" PRIu64 " batches)\n", per,
           res.batches);
    printf("  instructions per frame    %.2f\n", (double)res.issued / res.frames);
    printf("  object-frames run         %" PRIu64 " of %" PRIu64 " (%" PRIu64
           " skipped at rest); %zu at rest at the end, %zu woken\n",
           res.object_frames, all, res.skipped, res.asleep_last, res.woken);
    printf("  host words per frame      %.1f (register banks written and read)\n",
           (double)res.host_words / res.frames);
    printf("  frames per second         %.0f at %.1f MHz\n", fps, fmax);
    if (res.error != FP3_ERR_NONE)
      printf("  ERROR %s in object %zu at pc %u\n", fp3_error_name(res.error), res.error_object,
             res.error_pc);
    if (res.mismatches)
      printf("  FAIL: %" PRIu64 " mismatches against the golden model, first object %zu "
             "frame %u\n", res.mismatches, res.first_object, res.first_frame);
    else
      printf("  golden model: bit-identical, v and s of every object after every frame\n");
  }
  return pass ? 0 : EXIT_FAIL;
}

int fp3_cmd_frames(int argc, char **argv) {
  if (fp3_args_have_model(argc, argv)) return fp3_cmd_frames_model(argc, argv);
  fp3_frames_args a;
  int r = fp3_parse_frames(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_frames(&a) : fp3_args_exit(r, usage);
}
