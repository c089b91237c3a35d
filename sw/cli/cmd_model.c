/*
 * cmd_model.c -- what the model commands share (cmd_model.h): their options,
 * the --set values, compiling a model for an engine, watching state registers.
 */
#include "cmd_model.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cliopt.h"
#include "cmd_run.h"
#include "compile.h"
#include "engine.h"
#include "fpenv.h"
#include "fpref.h"
#include "model.h"
#include "modelref.h"
#include "mscene.h"
#include "report.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2
#define DEFAULT_STEPS 1000u  /* fp3 run --model: integrations          */
#define DEFAULT_FRAMES 600u  /* fp3 frames: 10 s at h = 1/60 s          */
#define DEFAULT_POINTS 6u    /* fp3 bench: sweep steps                   */
/* object-steps x state variables the bit-for-bit check keeps */
#define MAX_CHECKED (1u << 26)
#define MAX_MODEL_OBJECTS 1000000u /* --objects */
#define DEFAULT_HARBOUR 1000u /* fp3 frames: ships of the default harbour */
/* fp3 frames --fmax: MHz, the default build's Fmax on the LFE5U-85F-6
 * (README "Results", make pnr) */
#define DEFAULT_FMAX 40.5


/* --wake F:K:NAME=VALUE[*PARAM] into a (fp3_model_args).  0, or -1 with
 * the message on stderr. */
static int parse_wake(const char *v, fp3_model_args *a) {
  unsigned long long f, k;
  char pair[64], rule[128];
  const char *c2 = strchr(v, ':') ? strchr(strchr(v, ':') + 1, ':') : NULL;
  if (!c2) {
    fprintf(stderr, "fp3 frames: --wake '%s': want FRAME:COUNT:NAME=VALUE[*PARAM] (the ship's "
            "harbour: --wake 300:100:T=4*C, thrust T = 4 C for 100 moored ships)\n", v);
    return -1;
  }
  snprintf(pair, sizeof pair, "%.*s", (int)(c2 - v), v);
  snprintf(rule, sizeof rule, "%s", c2 + 1);
  if (fp3_parse_pair(pair, 1, 10000000u, 1, MAX_MODEL_OBJECTS, NULL, &f, &k)) {
    fprintf(stderr, "fp3 frames: --wake '%s': want FRAME:COUNT:..., FRAME 1..10000000, COUNT "
            "1..%u\n", v, MAX_MODEL_OBJECTS);
    return -1;
  }
  char *eq = strchr(rule, '='), *times = eq ? strchr(eq, '*') : NULL, *end;
  if (times) *times = '\0';
  if (eq) *eq = '\0';
  float val = eq ? strtof(eq + 1, &end) : 0.0f;
  if (!eq || eq == rule || strlen(rule) >= sizeof a->wake_param || !eq[1] || *end ||
      !isfinite(val) || (times && (!times[1] || strlen(times + 1) >= sizeof a->wake_times))) {
    fprintf(stderr, "fp3 frames: --wake '%s': the change is NAME=VALUE or NAME=VALUE*PARAM "
            "(a param of the model, a finite number)\n", v);
    return -1;
  }
  a->wake_frame = (uint32_t)f;
  a->wake_count = (size_t)k;
  snprintf(a->wake_param, sizeof a->wake_param, "%s", rule);
  snprintf(a->wake_times, sizeof a->wake_times, "%s", times ? times + 1 : "");
  a->wake_value = val;
  return 0;
}

int fp3_parse_model(int argc, char **argv, const char *cmd, fp3_model_args *a) {
  memset(a, 0, sizeof *a);
  a->cmd = cmd;
  a->integ = "rk4";
  a->engine = "rtl";
  a->steps = strcmp(cmd, "frames") == 0 ? DEFAULT_FRAMES
             : strcmp(cmd, "run") == 0   ? FP3_RUN_DEFAULT_STEPS
                                         : DEFAULT_STEPS;
  a->points = DEFAULT_POINTS;
  a->seed = 1;
  a->mode = FPREF_IEEE;
  a->long_steps = 100000u;
  a->fmax = DEFAULT_FMAX;
  const int runlike = strcmp(cmd, "run") == 0 || strcmp(cmd, "frames") == 0;
  fp3_trace_opts_init(&a->trace);
  for (int i = 1; i < argc; i++) {
    const char *v;
    unsigned long long k;
    int r;
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    if ((r = fp3_opt_value(argc, argv, &i, cmd, "--model", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->file = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, cmd, "--integrator", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->integ = v;
      a->integ_given = 1;
    } else if ((r = fp3_opt_value(argc, argv, &i, cmd, "--engine", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      /* a board behind a serial line (engine_uart.c) for the commands
       * that compare the state after a run: run and frames */
      const int board = (strcmp(cmd, "run") == 0 || strcmp(cmd, "frames") == 0) &&
                        fp3_engine_is_uart(v);
      /* the spatial pipeline of the model (engine_spatial.h) for the
       * commands that run a model's objects: run and frames */
      const int spatial = (strcmp(cmd, "run") == 0 || strcmp(cmd, "frames") == 0) &&
                          strcmp(v, "spatial") == 0;
      if (strcmp(v, "rtl") != 0 && strcmp(v, "iss") != 0 && !board && !spatial) {
        fprintf(stderr, "fp3 %s: unknown engine '%s' (rtl or iss%s)\n", cmd, v,
                strcmp(cmd, "run") == 0 || strcmp(cmd, "frames") == 0
                    ? ", spatial, or uart:DEVICE[@BAUD], uart:socket://HOST:PORT"
                    : "");
        return FP3_ARGS_BAD;
      }
      a->engine = v;
    } else if (strcmp(cmd, "run") == 0 &&
               (r = fp3_opt_count(argc, argv, &i, cmd, "--steps", 1, UINT32_MAX,
                                  "integrations", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->steps = (uint32_t)k;
    } else if ((r = fp3_opt_value(argc, argv, &i, cmd, "--set", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      if (a->nset == (int)(sizeof a->set / sizeof a->set[0])) {
        fprintf(stderr, "fp3 %s: too many --set\n", cmd);
        return FP3_ARGS_BAD;
      }
      a->set[a->nset++] = v;
    } else if (!runlike && (r = fp3_opt_output(argc, argv, &i, cmd, &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->out = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, cmd, "--scene", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->scene = v;
    } else if (runlike &&
               (r = fp3_opt_count(argc, argv, &i, cmd, "--objects", 1, MAX_MODEL_OBJECTS,
                                  "objects", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->objects = (size_t)k;
    } else if (runlike &&
               (r = fp3_opt_count(argc, argv, &i, cmd, "--pipelines", 1, 255, "pipelines",
                                  &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->pipelines = (unsigned)k;
    } else if (runlike && strcmp(argv[i], "--clock-cores") == 0) {
      a->clock_cores = 1;
    } else if (runlike && (r = fp3_opt_seed(argc, argv, &i, cmd, &a->seed)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->seeded = 1;
    } else if (runlike && (r = fp3_opt_mode(argc, argv, &i, cmd, &a->mode)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
    } else if (strcmp(cmd, "frames") == 0 &&
               (r = fp3_opt_count(argc, argv, &i, cmd, "--frames", 1, 10000000u, "frames",
                                  &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->steps = (uint32_t)k;
    } else if (strcmp(cmd, "bench") == 0 &&
               (r = fp3_opt_value(argc, argv, &i, cmd, "--t-end", &v)) != 0) {
      char *end;
      if (r < 0) return FP3_ARGS_BAD;
      a->t_end = strtod(v, &end);
      if (*end || !(a->t_end > 0.0) || !isfinite(a->t_end)) {
        fprintf(stderr, "fp3 %s: --t-end '%s': a positive time\n", cmd, v);
        return FP3_ARGS_BAD;
      }
    } else if (strcmp(cmd, "bench") == 0 &&
               (r = fp3_opt_count(argc, argv, &i, cmd, "--long-steps", 2, 10000000u,
                                  "integrations", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->long_steps = (uint32_t)k;
    } else if (strcmp(cmd, "bench") == 0 &&
               (r = fp3_opt_value(argc, argv, &i, cmd, "--long", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->long_out = v;
    } else if (strcmp(cmd, "bench") == 0 &&
               (r = fp3_opt_value(argc, argv, &i, cmd, "--stability", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->stab = v;
    } else if (strcmp(cmd, "bench") == 0 &&
               (r = fp3_opt_count(argc, argv, &i, cmd, "--points", 1, 24, "step sizes",
                                  &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->points = (unsigned)k;
    } else if (runlike && (r = fp3_opt_value(argc, argv, &i, cmd, "--program", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->program = v;
    } else if (strcmp(cmd, "run") == 0 && strcmp(argv[i], "--compile") == 0) {
      fprintf(stderr, "fp3 run: --compile is gone: a model's program is compiled unless "
                      "--program FILE.s names a hand-written one\n");
      return FP3_ARGS_BAD;
    } else if (strcmp(cmd, "run") == 0 && strcmp(argv[i], "--strict") == 0) {
      fprintf(stderr, "fp3 run: --strict is gone: fp3 run reports a divergence of any model "
                      "(DIVERGED, diverged_from), a state that is not finite fails the run, and "
                      "a model's stability bound is fp3 bench --model FILE --stability "
                      "FILE.csv\n");
      return FP3_ARGS_BAD;
    } else if (strcmp(cmd, "frames") == 0 &&
               (r = fp3_opt_count(argc, argv, &i, cmd, "--harbour", 1, MAX_MODEL_OBJECTS, "ships",
                                  &a->harbour)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
    } else if (strcmp(cmd, "frames") == 0 &&
               (r = fp3_opt_value(argc, argv, &i, cmd, "--fmax", &v)) != 0) {
      char *end;
      if (r < 0) return FP3_ARGS_BAD;
      a->fmax = strtod(v, &end);
      if (*end || !(a->fmax > 0.0) || !isfinite(a->fmax)) {
        fprintf(stderr, "fp3 frames: --fmax '%s': a positive clock in MHz\n", v);
        return FP3_ARGS_BAD;
      }
    } else if (strcmp(cmd, "frames") == 0 &&
               (r = fp3_opt_value(argc, argv, &i, cmd, "--wake", &v)) != 0) {
      if (r < 0 || parse_wake(v, a)) return FP3_ARGS_BAD;
    } else if (strcmp(cmd, "frames") == 0 && strcmp(argv[i], "--wake-vinf") == 0) {
      fprintf(stderr, "fp3 frames: --wake-vinf is gone: --wake F:K:T=V*C gives K moored "
                      "ships thrust T = V C\n");
      return FP3_ARGS_BAD;
    } else if (strcmp(cmd, "frames") == 0 && strcmp(argv[i], "--no-rest-skip") == 0) {
      a->no_rest_skip = 1;
    } else if (strcmp(cmd, "frames") == 0 && strcmp(argv[i], "--json") == 0) {
      a->json = 1;
    } else if (strcmp(argv[i], "--literal") == 0) {
      a->literal = 1;
    } else if (strcmp(cmd, "run") == 0 && strcmp(argv[i], "--json") == 0) {
      a->json = 1;
    } else if (strcmp(cmd, "run") == 0 &&
               (r = fp3_trace_opt(argc, argv, &i, cmd, &a->trace)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
    } else {
      if (strcmp(cmd, "run") == 0)
        fprintf(stderr, "fp3 run: unknown argument '%s' (see fp3 run --help)\n", argv[i]);
      else
        fprintf(stderr, "fp3 %s: unknown argument '%s' for a model or a model scene (see "
                "fp3 %s --model x --help)\n", cmd, argv[i], cmd);
      return FP3_ARGS_BAD;
    }
  }
  if (strcmp(cmd, "frames") == 0 && !a->scene && !a->file && !a->objects && !a->harbour)
    a->harbour = DEFAULT_HARBOUR; /* the sleeping benchmark's scene */
  if (strcmp(cmd, "frames") == 0 && !!a->scene + !!a->objects + !!a->harbour > 1) {
    fprintf(stderr, "fp3 frames: one of --scene FILE, --objects N, --harbour N\n");
    return FP3_ARGS_BAD;
  }
  if (strcmp(cmd, "frames") == 0 && a->file && !a->objects && !a->harbour) {
    fprintf(stderr, "fp3 frames: --model FILE goes with --objects N (or --harbour N)\n");
    return FP3_ARGS_BAD;
  }
  if ((!runlike && !a->scene && !a->file) || (a->file && !a->file[0])) {
    fprintf(stderr, "fp3 %s: --model needs a file\n", cmd);
    return FP3_ARGS_BAD;
  }
  if (a->seeded && ((!a->objects && !a->harbour) || a->scene)) {
    fprintf(stderr, "fp3 %s: --seed goes with --objects N%s\n", cmd,
            strcmp(cmd, "frames") == 0 ? " or --harbour N" : "");
    return FP3_ARGS_BAD;
  }
  if ((a->mode.round != FPREF_RNE || a->mode.ftz) && !runlike) {
    fprintf(stderr, "fp3 %s: --round and --ftz go with fp3 run and fp3 frames\n", cmd);
    return FP3_ARGS_BAD;
  }
  if (a->program && a->literal && !a->scene) {
    fprintf(stderr, "fp3 %s: --literal goes with --integrator (a compiled program); "
            "--program runs the program as written\n", cmd);
    return FP3_ARGS_BAD;
  }
  if (!fpenv_supported(a->mode)) {
    fprintf(stderr, "fp3 %s: this host cannot run the golden model in that mode\n", cmd);
    return FP3_ARGS_BAD;
  }
  if ((a->scene || a->harbour) && a->nset) {
    fprintf(stderr, "fp3 %s: --set does not go with a scene: its objects give the values\n",
            cmd);
    return FP3_ARGS_BAD;
  }
  if (a->pipelines && strcmp(a->engine, "spatial") != 0) {
    fprintf(stderr, "fp3 %s: --pipelines goes with --engine spatial\n", cmd);
    return FP3_ARGS_BAD;
  }
  if (a->clock_cores && strcmp(a->engine, "spatial") != 0) {
    fprintf(stderr, "fp3 %s: --clock-cores goes with --engine spatial\n", cmd);
    return FP3_ARGS_BAD;
  }
  if (fp3_trace_check(&a->trace, cmd, a->engine, a->scene || a->objects)) return FP3_ARGS_BAD;
  if (strcmp(cmd, "bench") == 0 && a->scene) {
    fprintf(stderr, "fp3 bench: --model FILE with --set values (one object), not a scene\n");
    return FP3_ARGS_BAD;
  }
  if (fp3_ship_scene_integrator(a->scene, a->integ_given, &a->integ, cmd)) return FP3_ARGS_BAD;
  return FP3_ARGS_RUN;
}

/* A ship scene (five columns) is a scene of models/ship.fp3m whose
 * integrator is the paper's RK4 unless --integrator says otherwise: rk4se
 * (docs/models.md).  The ship's own names that
 * mean another integrator of a model are refused with the model's name. */
int fp3_ship_scene_integrator(const char *scene, int given, const char **integ,
                              const char *cmd) {
  if (!scene || fp3_scene_is_model(scene)) return 0;
  static const char *const renamed[][2] = {
      {"rk4", "rk4se"}, {"rk4comp", "rk4secomp"}, {"verlet", "verletp"}};
  if (!given) {
    *integ = "rk4se";
    return 0;
  }
  for (size_t i = 0; i < sizeof renamed / sizeof renamed[0]; i++)
    if (strcmp(*integ, renamed[i][0]) == 0) {
      fprintf(stderr, "fp3 %s: %s is a ship scene, whose %s is the model integrator %s: "
              "--integrator %s (the model's %s is another integrator; it runs on a model "
              "scene, such as scenes/fleet.scene)\n", cmd, scene, renamed[i][0],
              renamed[i][1], renamed[i][1], renamed[i][0]);
      return -1;
    }
  return 0;
}

/* Compile the model for a's integrator (folded: params zero in this
 * object, zero[], removed) for the build hw (NULL: the default build).
 * grow: the build may have more registers (the ISS, a model of any build,
 * and `fp3 compile`): a program that needs more than hw's NUM_REGS is
 * compiled for the fewest that run it (fp3_compile_opts.max_regs); else
 * it is refused with the numbers. */
fp3_compiled *fp3_model_compile_for(const fp3_model *m, const fp3_model_args *a,
                                 const unsigned char *zero, const fp3_config *hw, int grow,
                                 const char *cmd) {
  fp3_compile_opts o;
  if (hw) fp3_compile_opts_for(&o, hw); /* the engine's build */
  else fp3_compile_defaults(&o);
  if (grow) o.max_regs = FP3_MAX_REGS;
  o.fold = o.drop_zero = !a->literal;
  fp3_compiled *c = NULL;
  char msg[512];
  if (!fp3_model_integrator_known(a->integ)) {
    fprintf(stderr, "fp3 %s: unknown integrator '%s' for a model (%s)\n", cmd, a->integ,
            fp3_model_integrators());
    return NULL;
  }
  if (fp3_compile_model(m, a->integ, &o, zero, &c, msg, sizeof msg)) {
    fprintf(stderr, "fp3 %s: %s: %s%s\n", cmd, m->file, msg,
            strstr(msg, "NUM_REGS is") && hw && !grow
                ? "; --engine iss models such a build, `make build/fp3 NUM_REGS=N BUILD=DIR` "
                  "builds the RTL"
                : "");
    return NULL;
  }
  return c;
}

/* The ISS reshaped for program c when c was compiled for more registers
 * than it has (compile_for with grow): same contexts, lanes and mode,
 * NUM_REGS the program's, said on stderr.  0, or -1 (message printed). */
int fp3_model_fit_engine(fp3_engine **e, const fp3_compiled *c, const char *cmd) {
  const unsigned need = fp3_compiled_stats(c)->num_regs;
  if (need <= (*e)->config.num_regs) return 0;
  fp3_config cfg = (*e)->config;
  cfg.num_regs = need;
  fp3_engine *ne = fp3_engine_iss_new_config(&cfg);
  if (!ne) {
    fprintf(stderr, "fp3 %s: out of memory for an ISS of %u registers per context\n", cmd, need);
    return -1;
  }
  fprintf(stderr, "fp3 %s: the program needs %u registers (NUM_REGS is %u): the ISS runs it as "
          "a build with NUM_REGS=%u\n", cmd, fp3_compiled_stats(c)->regs_needed,
          (*e)->config.num_regs, need);
  fp3_engine_show_progress(ne, (*e)->progress);
  fp3_engine_free(*e);
  *e = ne;
  return 0;
}

/* ---- run ------------------------------------------------------------------ */

void fp3_state_obs_write(void *ctx, unsigned reg, uint32_t value, uint32_t k) {
  fp3_state_obs *o = ctx;
  if (!o->v || k < 1 || k > o->steps) return;
  for (unsigned i = 0; i < o->nstate; i++)
    if (o->reg[i] == reg) {
      o->v[(size_t)(k - 1) * o->nstate + i] = value;
      o->seen[(size_t)(k - 1) * o->nstate + i] = 1;
    }
}

void fp3_state_obs_endi(void *ctx, uint32_t k, uint64_t cycle) {
  fp3_state_obs *o = ctx;
  if (k == 1) o->cyc_first = cycle;
  o->cyc_last = cycle;
  o->endis = k;
}

/* --set NAME=VALUE into in[] (params) or y0[] (states), marking given[]
 * (params, then states).  NAME0 names state variable NAME's initial value
 * where the model has no param or state called NAME0 (the ship program's
 * --set v0 and s0). */
static int apply_set(const char *cmd, const fp3_model *m, const char *arg, float *in,
                     float *y0, unsigned char *given) {
  const char *eq = strchr(arg, '=');
  if (!eq || eq == arg) {
    fprintf(stderr, "fp3 %s: --set wants NAME=VALUE, got '%s'\n", cmd, arg);
    return -1;
  }
  char name[FP3_MODEL_NAME_LEN];
  size_t len = (size_t)(eq - arg);
  if (len >= sizeof name) len = sizeof name - 1;
  memcpy(name, arg, len);
  name[len] = '\0';
  char *end;
  float v = strtof(eq + 1, &end);
  if (!eq[1] || *end || !isfinite(v)) {
    fprintf(stderr, "fp3 %s: --set %s: '%s' is not a finite number\n", cmd, name, eq + 1);
    return -1;
  }
  int k = fp3_model_param(m, name);
  if (k >= 0) {
    in[k] = v;
    given[k] = 1;
    return 0;
  }
  k = fp3_model_state(m, name);
  if (k < 0 && len > 1 && name[len - 1] == '0') { /* NAME0: NAME's initial value */
    name[len - 1] = '\0';
    k = fp3_model_state(m, name);
    name[len - 1] = '0';
  }
  if (k >= 0) {
    y0[k] = v;
    given[m->nparam + (unsigned)k] = 1;
    return 0;
  }
  fprintf(stderr, "fp3 %s: --set %s: model %s (%s) has no param or state '%s'\n", cmd, name,
          m->name, m->file, name);
  return -1;
}

/* The declaration keyword of state variable i (for "a default in the
 * model file (position x = VALUE)"). */
static const char *state_keyword(const fp3_model *m, unsigned i) {
  return m->role[i] == FP3_MR_POSITION ? "position"
         : m->role[i] == FP3_MR_VELOCITY ? "velocity"
                                         : "state";
}

/* The model's defaults into in[] and y0[], then every --set over them;
 * whatever is still without a value is named, all of it in one message
 * (each with its declaring line), h > 0.  0 or -1. */
int fp3_model_args_values(const fp3_model *m, const fp3_model_args *a, float *in, float *y0) {
  const char *cmd = a->cmd ? a->cmd : "run";
  unsigned char given[2 * FP3_MODEL_MAX_VARS] = {0};
  for (unsigned k = 0; k < m->nparam; k++)
    if (m->param_has_def[k]) {
      in[k] = m->param_def[k];
      given[k] = 1;
    }
  for (unsigned k = 0; k < m->nstate; k++)
    if (m->state_has_def[k]) {
      y0[k] = m->state_def[k];
      given[m->nparam + k] = 1;
    }
  for (int i = 0; i < a->nset; i++)
    if (apply_set(cmd, m, a->set[i], in, y0, given)) return -1;
  char *text = NULL;
  size_t tlen = 0;
  FILE *f = NULL;
  unsigned missing = 0, first = 0;
  for (unsigned k = 0; k < m->nparam + m->nstate; k++) {
    if (given[k]) continue;
    if (!f && !(f = open_memstream(&text, &tlen))) {
      fprintf(stderr, "fp3 %s: out of memory\n", cmd);
      return -1;
    }
    if (!missing++) first = k;
    const int st = k >= m->nparam;
    const unsigned i = st ? k - m->nparam : k;
    if (k == 0)
      fprintf(f, "%sthe step h", missing > 1 ? ", " : "");
    else
      fprintf(f, "%s%s %s (line %d)", missing > 1 ? ", " : "",
              st ? "state variable" : "param", st ? m->state[i] : m->param[i],
              st ? m->state_line[i] : m->param_line[i]);
  }
  if (missing) {
    fprintf(f, ": give");
    for (unsigned k = 0; k < m->nparam + m->nstate; k++)
      if (!given[k])
        fprintf(f, " --set %s=VALUE", k >= m->nparam ? m->state[k - m->nparam] : m->param[k]);
    const int st = first >= m->nparam;
    fprintf(f, ", or a default in the model file (%s %s = VALUE)",
            st ? state_keyword(m, first - m->nparam) : "param",
            st ? m->state[first - m->nparam] : m->param[first]);
    fclose(f);
    fprintf(stderr, "fp3 %s: %s: no value for %s\n", cmd, m->file, text);
    free(text);
    return -1;
  }
  if (!(in[0] > 0.0f)) {
    fprintf(stderr, "fp3 %s: --set h=%g: the step must be above 0\n", cmd, (double)in[0]);
    return -1;
  }
  return 0;
}
