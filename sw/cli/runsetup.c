/*
 * runsetup.c -- what `fp3 run` and `fp3 frames` set up before they run
 * (runsetup.h): the program, the model and its objects, the engine, and
 * the parts of their reports they share.
 */
#define _DEFAULT_SOURCE /* realpath */
#include "runsetup.h"

#include <math.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "asm.h"
#include "cmd_asm.h"
#include "engine_spatial.h"
#include "fpenv.h"
#include "fpref.h"
#include "modelref.h"
#include "objects.h"
#include "report.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2

/* A generated harbour (--harbour N --seed S, objects.h) as a scene of
 * model file model_path, which must name params T, C, m and state
 * variables v, s.  0; -1 with the reason (another model); 1 out of
 * memory. */
static int harbour_scene(const fp3_model_args *a, const char *model_path, fp3_mscene *sc,
                         char *msg, size_t n) {
  fp3_scene ships;
  fp3_ship_params dflt;
  fp3_ship_default(&dflt);
  if (fp3_scene_harbour(a->seed, a->harbour, dflt.h, &ships)) {
    snprintf(msg, n, "out of memory for %llu ships", a->harbour);
    return 1;
  }
  int rc = fp3_mscene_from_ships(&ships, model_path, "harbour", sc, msg, n);
  fp3_scene_free(&ships);
  return rc;
}

/* The folder of the running executable (build/fp3: build) into dir[4096];
 * -1 if /proc/self/exe cannot say. */
static int exe_dir(char dir[4096]) {
  ssize_t k = readlink("/proc/self/exe", dir, 4096 - 1);
  if (k <= 0) return -1;
  dir[k] = '\0';
  char *slash = strrchr(dir, '/');
  if (!slash) return -1;
  *slash = '\0';
  return 0;
}

/* A shipped file (models/, programs/): relative to the working directory,
 * else to the executable (build/fp3 -> ../). */
void fp3_find_shipped(const char *rel, char *path, size_t n) {
  snprintf(path, n, "%s", rel);
  if (access(rel, R_OK) == 0) return;
  char exe[4096];
  if (exe_dir(exe)) return;
  char alt[8192];
  if ((size_t)snprintf(alt, sizeof alt, "%s/../%s", exe, rel) < n && access(alt, R_OK) == 0)
    memcpy(path, alt, strlen(alt) + 1);
}

int fp3_read_scene(const char *path, fp3_mscene *sc, char *msg, size_t n) {
  char ship[4096];
  fp3_find_shipped(FP3_DEFAULT_MODEL, ship, sizeof ship);
  return fp3_mscene_read_any(path, ship, sc, msg, n);
}

fp3_model *fp3_scene_model(const char *path, const char *ship_model, unsigned char *zero,
                           size_t *objects, char *msg, size_t n) {
  fp3_mscene sc;
  if (ship_model ? fp3_mscene_read_any(path, ship_model, &sc, msg, n)
                 : fp3_read_scene(path, &sc, msg, n))
    return NULL;
  fp3_mscene_zero(&sc, zero);
  *objects = sc.n;
  fp3_model *m = sc.model;
  sc.model = NULL;
  fp3_mscene_free(&sc);
  return m;
}

unsigned fp3_zero_params_list(const fp3_model *m, const unsigned char *zero, fp3_strbuf *b) {
  unsigned any = 0;
  for (unsigned k = 1; k < m->nparam; k++)
    if (zero[k]) fp3_strbuf_printf(b, "%s%s", any++ ? ", " : "", m->param[k]);
  return any;
}

/* 1 if paths a and b name the same file. */
static int same_file(const char *a, const char *b) {
  struct stat sa, sb;
  if (stat(a, &sa) != 0 || stat(b, &sb) != 0) return strcmp(a, b) == 0;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

/* ---- what runs: the model, its program, the engine -------------------------- */


void fp3_run_setup_free(fp3_run_setup *s) {
  fp3_compiled_free(s->c);
  fp3_engine_free(s->e);
  if (s->many) fp3_mscene_free(&s->sc);
  else free(s->m);
}

/* The program (runsetup.h). */
int fp3_run_setup_program(const fp3_model_args *a, fp3_run_setup *s, const char *cmd,
                          const char *default_program) {
  const char *p = a->program;
  const int spatial = strcmp(a->engine, "spatial") == 0;
  if (p && spatial) {
    fprintf(stderr, "fp3 %s: --program does not go with --engine spatial: the spatial engine "
            "runs a model's compiled step as a pipeline (--model, --integrator), not a "
            "program for the processor\n", cmd);
    return EXIT_USAGE;
  }
  if (!p) {
    if (!default_program || spatial || a->file || (a->scene && fp3_scene_is_model(a->scene)) ||
        a->integ_given || a->literal)
      return 0;
    fp3_find_shipped(default_program, s->program_path, sizeof s->program_path);
    p = s->program_path;
  }
  char *errs = NULL;
  if (fp3_asm_file(p, &s->img, &errs) != 0) {
    fp3_print_asm_errors(errs);
    free(errs);
    return EXIT_USAGE;
  }
  free(errs);
  if (fp3_refuse_endless(cmd, p, &s->img)) return EXIT_USAGE;
  s->program = p;
  return 0;
}

/* The model: --model, the scene's, the program's `.model`, or the ship;
 * a program's `.model` must be the same file.  Many objects: the scene
 * (read, or generated from the values). */
int fp3_run_setup_model(const fp3_model_args *a, fp3_run_setup *s, const char *cmd) {
  char msg[512];
  const char *mp = a->file;
  if (!mp && s->program && s->img.model[0]) mp = s->img.model;
  if (!mp) {
    fp3_find_shipped(FP3_DEFAULT_MODEL, s->model_path, sizeof s->model_path);
    mp = s->model_path;
  }
  if (a->scene && fp3_scene_is_model(a->scene) && a->file) {
    fprintf(stderr, "fp3 %s: --model or a model scene (it names its model), not both\n", cmd);
    return EXIT_USAGE;
  }
  if (a->scene || a->harbour) {
    int bad = a->scene ? fp3_mscene_read_any(a->scene, mp, &s->sc, msg, sizeof msg)
                       : harbour_scene(a, mp, &s->sc, msg, sizeof msg);
    if (bad) {
      fprintf(stderr, "fp3 %s: %s\n", cmd, msg);
      return bad < 0 ? EXIT_USAGE : EXIT_FAIL;
    }
    s->many = 1;
    s->m = s->sc.model;
    if (a->objects && a->scene && a->objects != s->sc.n) {
      fprintf(stderr, "fp3 %s: --objects %zu, but %s has %zu objects\n", cmd, a->objects, a->scene,
              s->sc.n);
      return EXIT_USAGE;
    }
    mp = s->sc.model_path;
  } else {
    if (!(s->m = malloc(sizeof *s->m))) return EXIT_FAIL;
    if (fp3_model_load(mp, s->m, msg, sizeof msg)) {
      if (mp == s->img.model)
        fprintf(stderr, "fp3 %s: %s: its .model line names %s: %s (--model FILE names "
                "the model)\n", cmd, s->program, mp, msg);
      else
        fprintf(stderr, "fp3 %s: %s\n", cmd, msg);
      return EXIT_USAGE;
    }
    if (fp3_model_args_values(s->m, a, s->in, s->y0)) return EXIT_USAGE;
    if (a->objects) {
      fp3_model *m = s->m;
      s->m = NULL;
      if (fp3_mscene_generate(m, s->in, s->y0, a->objects, a->seed, &s->sc)) {
        fprintf(stderr, "fp3 %s: out of memory for %zu objects\n", cmd, a->objects);
        return EXIT_FAIL;
      }
      s->many = 1;
      s->m = s->sc.model;
    }
  }
  /* a program's .model must be the model of the run, when it is there */
  if (s->program && s->img.model[0] && access(s->img.model, R_OK) == 0 &&
      !same_file(s->img.model, mp)) {
    fprintf(stderr, "fp3 %s: %s is a program of %s (its .model line), not of %s\n", cmd, s->program,
            s->img.model, mp);
    return EXIT_USAGE;
  }
  return 0;
}

/* The folder of a shipped file's folder: ROOT of ROOT/rel (rel found by
 * fp3_find_shipped), absolute.  -1 if it is not there. */
static int shipped_root(const char *rel, char *root, size_t n) {
  char path[8192];
  fp3_find_shipped(rel, path, sizeof path);
  char *abs = realpath(path, NULL);
  if (!abs) return -1;
  size_t k = strlen(abs), r = strlen(rel);
  int rc = -1;
  if (k > r && abs[k - r - 1] == '/') {
    abs[k - r - 1] = '\0';
    snprintf(root, n, "%s", abs);
    rc = 0;
  }
  free(abs);
  return rc;
}

/* The folder of the spatial engine's cache: $FP3_SPATIAL_CACHE, else
 * spatial-cache beside the executable (build/fp3: build/spatial-cache). */
static void spatial_cache(char *dir, size_t n) {
  if (n < 4096 + 16) return; /* callers pass a path's room */
  const char *env = getenv("FP3_SPATIAL_CACHE");
  if (env && env[0]) {
    snprintf(dir, n, "%s", env);
    return;
  }
  char exe[4096];
  snprintf(dir, n, "%s/spatial-cache", exe_dir(exe) ? "build" : exe);
}

/* The engine's progress line, "fp3 CMD", unless --json. */
static void show_progress(const fp3_model_args *a, fp3_run_setup *s, const char *cmd) {
  static char label[32]; /* the engine keeps it: one command a process */
  snprintf(label, sizeof label, "fp3 %s", cmd);
  fp3_engine_show_progress(s->e, a->json ? NULL : label);
}

/* The spatial engine: the model compiled (for the registers it needs:
 * the engine's banks are the program's), then its pipeline built or
 * found in the cache and loaded (engine_spatial.h). */
static int setup_spatial(const fp3_model_args *a, fp3_run_setup *s, const unsigned char *zero,
                         const char *cmd) {
  char root[4096], cache[4112], msg[4096], label[64];
  if (!(s->c = fp3_model_compile_for(s->m, a, zero, NULL, 1, cmd))) return EXIT_USAGE;
  s->integ = a->integ;
  s->literal = a->literal;
  if (shipped_root("sim/spatial_shim.cpp", root, sizeof root)) {
    fprintf(stderr, "fp3 %s: --engine spatial needs the FP3 tree (rtl/, sim/spatial_shim.cpp) "
            "beside the working directory or the executable\n", cmd);
    return EXIT_FAIL;
  }
  spatial_cache(cache, sizeof cache);
  snprintf(label, sizeof label, "fp3 %s: spatial", cmd);
  /* --clock-cores: the latencies of the chip make pnr-spatial places
   * (the engine takes the rounding and FTZ from the run's mode) */
  static fp3_spatial_opts clock; /* the engine keeps it: one command a process */
  fp3_spatial_defaults(&clock);
  fp3_spatial_clock_cores(&clock);
  fp3_spatial_env env = {.root = root, .cache = cache, .verilator = getenv("VERILATOR"),
                         .cxx = getenv("FP3_SPATIAL_CXX"), .label = label,
                         .pipelines = a->pipelines, .cores = a->clock_cores ? &clock : NULL};
  s->e = fp3_engine_spatial_new(s->c, s->m, s->integ, a->mode, &env, msg, sizeof msg);
  if (!s->e) {
    fprintf(stderr, "fp3 %s: spatial engine: %s\n", cmd, msg);
    return EXIT_FAIL;
  }
  show_progress(a, s, cmd);
  return 0;
}

/* The engine (with the trace of one object) and the program for it. */
int fp3_run_setup_engine(const fp3_model_args *a, fp3_run_setup *s, const char *cmd) {
  char msg[512];
  const int iss = strcmp(a->engine, "iss") == 0;
  if (fp3_trace_writable(&a->trace, cmd)) return EXIT_USAGE;
  /* the params zero in every object: terms a compiled program drops */
  unsigned char zero[FP3_MODEL_MAX_VARS] = {0};
  if (s->many) fp3_mscene_zero(&s->sc, zero);
  else
    for (unsigned k = 0; k < s->m->nparam; k++) zero[k] = s->in[k] == 0.0f;
  if (strcmp(a->engine, "spatial") == 0) return setup_spatial(a, s, zero, cmd);
  if (fp3_engine_is_uart(a->engine)) {
    /* a board: its build is what it is; the options must agree with it */
    s->e = fp3_engine_uart_new(a->engine + 5, msg, sizeof msg);
    if (!s->e) {
      fprintf(stderr, "fp3 %s: %s\n", cmd, msg);
      return EXIT_FAIL;
    }
    if (s->e->config.mode.round != a->mode.round || s->e->config.mode.ftz != a->mode.ftz) {
      fprintf(stderr, "fp3 %s: %s: the board is built with --round %s%s, not as asked\n", cmd,
              a->engine, fpenv_round_name(s->e->config.mode), s->e->config.mode.ftz ? " --ftz" : "");
      return EXIT_USAGE;
    }
  } else {
    s->e = iss ? fp3_engine_iss_new_mode(a->mode) : fp3_engine_rtl_new_mode(a->mode, a->trace.path);
  }
  if (!s->e || fp3_engine_error(s->e)[0]) {
    fprintf(stderr, "fp3 %s: cannot create the %s engine%s%s\n", cmd, a->engine, s->e ? ": " : "",
            s->e ? fp3_engine_error(s->e) : "");
    return EXIT_FAIL;
  }
  show_progress(a, s, cmd);
  if (s->program) {
    fp3_compile_opts o;
    fp3_compile_opts_for(&o, &s->e->config);
    if (a->integ_given && strcmp(a->integ, s->img.integrator) != 0) {
      fprintf(stderr, "fp3 %s: --integrator %s, but %s computes %s (its .integrator line)\n", cmd,
              a->integ, s->program, s->img.integrator[0] ? s->img.integrator : "nothing named");
      return EXIT_USAGE;
    }
    if (fp3_compile_bind(s->m, &s->img, s->program, &o, &s->c, msg, sizeof msg)) {
      fprintf(stderr, "fp3 %s: %s\n", cmd, msg);
      return EXIT_USAGE;
    }
    s->integ = s->img.integrator;
    s->literal = 1;
  } else {
    if (!(s->c = fp3_model_compile_for(s->m, a, zero, &s->e->config, iss, cmd)))
      return EXIT_USAGE;
    if (iss && fp3_model_fit_engine(&s->e, s->c, cmd)) return EXIT_FAIL;
    s->integ = a->integ;
    s->literal = a->literal;
  }
  /* the waveform's size, from the program's cycles, against --trace-limit */
  const fp3_compile_stats *cs = fp3_compiled_stats(s->c);
  if (!s->many && fp3_trace_prepare(&a->trace, cmd, s->e,
                                    fp3_trace_run_cycles(a->steps, cs->est_cycles_first,
                                                         cs->est_cycles_later),
                                    "by the scheduler's estimate of the program"))
    return EXIT_USAGE;
  return 0;
}

/* ---- the report's common parts ------------------------------------------------ */

/* The JSON members every `fp3 run` object starts with. */
void fp3_run_json_head(const fp3_model_args *a, const fp3_run_setup *s, const char *scene) {
  const fp3_compile_stats *cs = fp3_compiled_stats(s->c);
  printf("{\"engine\": ");
  fp3_json_string(stdout, a->engine);
  if (fp3_engine_spatial_is(s->e))
    printf(", \"pipeline_latency\": %u", fp3_engine_spatial_latency(s->e));
  printf(", \"cycles_counted\": \"%s\"",
         strcmp(a->engine, "iss") == 0 ? "instructions issued (the ISS issues one a cycle)"
                                       : "clock cycles");
  printf(", \"model\": ");
  fp3_json_string(stdout, s->m->name);
  printf(", \"model_file\": ");
  fp3_json_string(stdout, s->m->file);
  printf(", \"program\": ");
  if (s->program) fp3_json_string(stdout, s->program);
  else printf("null");
  printf(", \"scene\": ");
  if (scene) fp3_json_string(stdout, scene);
  else printf("null");
  printf(", \"integrator\": ");
  fp3_json_string(stdout, s->integ);
  printf(", \"literal\": %s, \"words\": %zu, \"insns_per_step\": %u", s->literal ? "true" : "false",
         fp3_compiled_image(s->c)->n, cs->body_insns);
  if (!s->literal) printf(", \"literal_insns_per_step\": %u", cs->literal_body_insns);
  printf(", \"registers_needed\": %u, \"num_regs\": %u, \"est_cycles_per_step\": %u",
         cs->regs_needed, s->e->config.num_regs, cs->est_cycles_later);
  printf(", \"round\": \"%s\", \"ftz\": %s", fpenv_round_name(a->mode),
         a->mode.ftz ? "true" : "false");
}

/* "run_error": null, or the first context error with its object and pc. */
void fp3_run_json_error(unsigned error, size_t object, uint32_t pc) {
  printf(", \"run_error\": ");
  if (error == FP3_ERR_NONE) printf("null");
  else printf("{\"error\": \"%s\", \"object\": %zu, \"pc\": %" PRIu32 "}", fp3_error_name(error),
              object, pc);
}

/* One object's results: each state variable, its golden value (gold,
 * or NULL), GSL reference (NAN: none) and exact solution (NAN: none). */
void fp3_run_json_object(const fp3_model *m, const uint32_t *y, const float *gold,
                        const double *ref, const double *ex) {
  printf("{");
  for (unsigned k = 0; k < m->nstate; k++) {
    printf("%s\"%s\": ", k ? ", " : "", m->state[k]);
    fp3_json_float(stdout, fpref_float(y[k]));
    if (gold) {
      printf(", \"%s_golden\": ", m->state[k]);
      fp3_json_float(stdout, gold[k]);
    }
    printf(", \"%s_ref\": ", m->state[k]);
    fp3_json_double(stdout, ref[k]);
    printf(", \"%s_exact\": ", m->state[k]);
    fp3_json_double(stdout, ex[k]);
  }
  printf("}");
}

/* The GSL reference (rk8pd, 1e-12) and the exact solution after `steps`
 * integrations of an object (params in, initial state y0): 0 with ref[]
 * and ex[] (NAN where there is none), rmsg the reason of a missing
 * reference. */
void fp3_run_references(const fp3_model *m, const float *in, const float *y0, uint32_t steps,
                       int want_ref, double *ref, double *ex, char *rmsg, size_t n) {
  double din[FP3_MODEL_MAX_VARS], dy0[FP3_MODEL_MAX_VARS];
  for (unsigned k = 0; k < m->nparam; k++) din[k] = in[k];
  for (unsigned k = 0; k < m->nstate; k++) dy0[k] = y0[k], ref[k] = ex[k] = NAN;
  if (want_ref && steps > 0 && fp3_model_gsl(m, din, dy0, steps, NULL, NULL, ref, rmsg, n))
    for (unsigned k = 0; k < m->nstate; k++) ref[k] = NAN;
  for (unsigned k = 0; k < m->nstate; k++)
    if (fp3_model_exact(m, k, din, dy0, (double)steps * din[0], &ex[k])) ex[k] = NAN;
}

