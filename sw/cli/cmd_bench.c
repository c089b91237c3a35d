/*
 * cmd_bench.c -- `fp3 bench` (cmd_bench.h): the benchmark of a model's
 * integrators, models/ship.fp3m unless --model names another model.
 *
 * The options are those of the model commands (fp3_parse_model); the
 * parts are
 *
 *   sweep      each integrator that applies: one short engine run of its
 *              compiled program (cycles per integration, checked bit for
 *              bit against the golden model), then the golden model with
 *              h = H, H/2, ... H/2^(K-1) to t_end against GSL's rk8pd:
 *              the work-precision CSV and, with --out, the Pareto table
 *              (the cheapest integrator and step for each error target);
 *   stability  the largest stable h of each integrator (bisection on the
 *              golden model), then the engine just below (0.98) and just
 *              above (1.02) it: stable or diverges, bit-exact;
 *   long       N integrations on the engine, every one checked, with the
 *              binary32 stagnation of each state variable (the last
 *              integration that changed it; the integrations that left it
 *              unchanged although its derivative was not zero).
 *
 * The pipeline's timing does not depend on the data, so one short engine
 * run gives a program's cycles per integration; the errors come from the
 * golden model, which the engines equal bit for bit (checked on every
 * engine run here).
 */
#include "cmd_bench.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "cliopt.h"
#include "cmd_model.h"
#include "compile.h"
#include "engine.h"
#include "fpref.h"
#include "model.h"
#include "modelref.h"
#include "report.h"
#include "runsetup.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2

#define SHIP_MODEL "models/ship.fp3m" /* the model of `fp3 bench` without --model */
#define BENCH_RTL_STEPS 16u   /* integrations of the timed, checked engine run  */
#define STAB_STEPS 20000u     /* golden integrations of one stability trial     */
#define STAB_GROWTH FP3_GROWTH_BOUND /* a trial is unstable when a state
                                 exceeds STAB_GROWTH (1 + max |initial state|) */
#define STAB_ENGINE_STEPS STAB_STEPS /* engine integrations at 0.98 and 1.02 of it */
#define MAX_ROWS 1024         /* sweep rows kept for the Pareto table           */

static void usage(FILE *f) {
  fprintf(f,
          "usage: fp3 bench [--model FILE] [--set NAME=VALUE ...] [--integrator I[,I...]]\n"
          "                 [--out DIR [--only sweep|stability|long]] [--h-max H] [--points K]\n"
          "                 [--t-end T] [--long-steps N] [--engine rtl|iss] [--literal]\n"
          "                 [-o FILE.csv] [--stability FILE.csv] [--long FILE.csv]\n"
          "\n"
          "The integrators of a model (default models/ship.fp3m, Bourg's ship: T = 50 kN,\n"
          "C = 5000 kg/s, m = 10 t, h = 1/60 s, v = s = 0; tau = m/C = 2 s):\n"
          "\n"
          "  sweep      the golden model with h = H, H/2, ... H/2^(K-1) to the end time,\n"
          "             its largest |state - GSL rk8pd| there, and the engine's cycles\n"
          "             per integration (one short run, bit-exact) -> DIR/sweep.csv and\n"
          "             DIR/pareto.md (the cheapest integrator and h for each error\n"
          "             target 1e-2 .. 1e-7); CSV on stdout (or -o) without --out\n"
          "  stability  the largest stable h (bisection, %u golden integrations; a state\n"
          "             beyond %g (1 + max |initial state|) diverges, positions aside\n"
          "             when the model has velocities), then %u engine integrations\n"
          "             at 0.98 and 1.02 of it -> DIR/stability.{csv,md}\n"
          "  long       N engine integrations, every one checked, and the binary32\n"
          "             stagnation of each state variable -> DIR/longrun.{csv,md}\n"
          "\n"
          "  --model FILE      a model file (.fp3m, docs/models.md; default %s)\n"
          "  --set NAME=VALUE  h, a param or a state's initial value over the file's\n"
          "                    default (the ship far out: --set s=16777216)\n"
          "  --integrator I    one integrator or a comma-separated list (default: every\n"
          "                    one that applies, of:\n"
          "                    %s)\n"
          "  --out DIR         every part's CSV and Markdown into DIR (created)\n"
          "  --only PART       with --out: sweep, stability or long (default all three)\n"
          "  --h-max H         the sweep's largest h [s] (default the model's h)\n"
          "  --points K        sweep steps, each half the one before (default 6)\n"
          "  --t-end T         the sweep's end time (default 600 h)\n"
          "  --long-steps N    integrations of a long run (default 100000)\n"
          "  --engine E        rtl (default) or iss\n"
          "  --literal         the integrators exactly as docs/models.md writes them\n"
          "  -o FILE.csv, --stability FILE.csv, --long FILE.csv: one part's CSV alone\n"
          "\n"
          "Exit status: 0 done and every engine run bit-exact; 1 a check failed;\n"
          "2 bad arguments or model.\n",
          STAB_STEPS, STAB_GROWTH, STAB_ENGINE_STEPS, SHIP_MODEL, fp3_model_integrators());
}

/* The ship bench's options that have no meaning on the model path: each is
 * refused with its new form.  1 (message printed) or 0. */
static int gone_option(int argc, char **argv) {
  static const char *const gone[][2] = {
      {"--from", "the sweep is in h, in seconds: --h-max H --points K runs h = H, H/2, ... "
                 "H/2^(K-1) (the ship: h = h/tau x 2 s; --to 3 is --h-max 6)"},
      {"--to", "the sweep is in h, in seconds: --h-max H --points K runs h = H, H/2, ... "
               "H/2^(K-1) (the ship: h = h/tau x 2 s; --to 3 is --h-max 6)"},
      {"--per-decade", "--points K: K steps h = H, H/2, ... (3.3 a decade)"},
      {"--h-over-tau", "one step is --set h=H --points 1, h in seconds (the ship: "
                       "H = h/tau x 2 s, tau = m/C)"},
      {"--rtl-long-steps", "--long-steps N: N integrations on the --engine (rtl, or iss)"},
      {"--repeats", "the bench's cost is the engine's cycles per integration, not host time"},
  };
  for (int i = 1; i < argc; i++)
    for (size_t g = 0; g < sizeof gone / sizeof gone[0]; g++) {
      size_t n = strlen(gone[g][0]);
      if (strncmp(argv[i], gone[g][0], n) == 0 && (argv[i][n] == '\0' || argv[i][n] == '=')) {
        fprintf(stderr, "fp3 bench: %s is gone: %s\n", gone[g][0], gone[g][1]);
        return 1;
      }
    }
  return 0;
}

/* ---- divergence ------------------------------------------------------------ */

/* 1 if state variable i is watched for divergence: every state variable
 * but the positions of a model that has others.  A position integrates a
 * velocity and drifts without bound while the velocity stays bounded
 * (the ship's s = v t): no instability; an unstable mode of a second-order
 * model shows in its velocities. */
static int watched(const fp3_model *m, unsigned i) {
  int others = 0;
  for (unsigned k = 0; k < m->nstate; k++) others |= m->role[k] != FP3_MR_POSITION;
  return !others || m->role[i] != FP3_MR_POSITION;
}

/* The divergence bound of m from y0: STAB_GROWTH (1 + max |y0[i]|) over
 * the watched state variables. */
static double growth_bound(const fp3_model *m, const float *y0) {
  double b = 0.0;
  for (unsigned i = 0; i < m->nstate; i++)
    if (watched(m, i)) b = fmax(b, fabs((double)y0[i]));
  return STAB_GROWTH * (1.0 + b);
}

/* ---- one compiled program on the engine, checked ----------------------- */

/* What an engine run of one object gives. */
typedef struct bench_run {
  double cyc;        /* cycles per later integration (NAN: fewer than 2)     */
  uint64_t mism;     /* state values != golden (+1 if the run stopped short) */
  uint32_t diverged; /* first integration with a watched state variable not
                        finite or beyond growth_bound(); 0: none             */
  uint32_t last_change[FP3_MODEL_MAX_VARS]; /* last integration that changed
                                               state variable i (0: none)     */
  uint64_t unmoved[FP3_MODEL_MAX_VARS];     /* integrations that left it
                        unchanged although its derivative (double, at the
                        state before the integration) was not zero           */
  float y[FP3_MODEL_MAX_VARS];              /* the final golden state         */
} bench_run;

/* One object of compiled program c on engine e for `steps` integrations
 * with inputs in[] (in[0] = h) from y0[], compared with the golden model
 * after every integration.  0, or -1 (the engine's message; out of
 * memory: none). */
static int bench_engine(fp3_engine *e, fp3_compiled *c, const fp3_model *m, const float *in,
                        const float *y0, uint32_t steps, bench_run *r) {
  unsigned regs[512];
  uint32_t vals[512];
  const size_t cells = (size_t)steps * m->nstate;
  fp3_state_obs ob;
  memset(&ob, 0, sizeof ob);
  memset(r, 0, sizeof *r);
  ob.nstate = m->nstate;
  ob.steps = steps;
  ob.v = malloc(cells * sizeof *ob.v);
  ob.seen = calloc(cells, 1);
  double *val = malloc((m->nn + 1) * sizeof *val);
  int rc = -1;
  if (!ob.v || !ob.seen || !val) goto done;
  for (unsigned i = 0; i < m->nstate; i++) ob.reg[i] = fp3_compiled_state_reg(c, i);
  size_t nw = fp3_compiled_model_start(c, in, y0, regs, vals, 512);
  const fp3_image *img = fp3_compiled_image(c);
  int erc = fp3_engine_load(e, img->words, img->n);
  for (size_t w = 0; w < nw && erc == 0; w++) erc = fp3_engine_write_reg(e, regs[w], vals[w]);
  fp3_status st;
  fp3_observer obs = {.ctx = &ob, .on_write = fp3_state_obs_write, .on_endi = fp3_state_obs_endi};
  if (erc || fp3_engine_run(e, steps, &obs, &st)) goto done;
  uint32_t cur[FP3_MODEL_MAX_VARS];
  double din[FP3_MODEL_MAX_VARS], dy[FP3_MODEL_MAX_VARS], f[FP3_MODEL_MAX_VARS];
  const double bound = growth_bound(m, y0);
  for (unsigned k = 0; k < m->nparam; k++) din[k] = in[k];
  for (unsigned i = 0; i < m->nstate; i++) cur[i] = fpref_bits(y0[i]), r->y[i] = y0[i];
  r->mism = st.steps_done == steps && st.error == FP3_ERR_NONE ? 0 : 1;
  for (uint32_t k = 1; k <= st.steps_done && k <= steps; k++) {
    float prev[FP3_MODEL_MAX_VARS];
    for (unsigned i = 0; i < m->nstate; i++) prev[i] = r->y[i], dy[i] = r->y[i];
    fp3_model_eval_f_double(m, din, dy, f, val);
    fp3_compiled_model_step(c, r->y);
    for (unsigned i = 0; i < m->nstate; i++) {
      size_t q = (size_t)(k - 1) * m->nstate + i;
      if (ob.seen[q]) cur[i] = ob.v[q];
      r->mism += cur[i] != fpref_bits(r->y[i]);
      if (fpref_bits(r->y[i]) != fpref_bits(prev[i])) r->last_change[i] = k;
      else if (f[i] != 0.0) r->unmoved[i]++;
      if (!r->diverged && watched(m, i) && !(fabs((double)r->y[i]) <= bound)) r->diverged = k;
    }
  }
  r->cyc = ob.endis >= 2 ? (double)(ob.cyc_last - ob.cyc_first) / (ob.endis - 1) : NAN;
  rc = 0;
done:
  free(ob.v);
  free(ob.seen);
  free(val);
  return rc;
}

/* ---- stability ------------------------------------------------------------ */

/* 1 if the golden model of c stays finite and within growth_bound() (its
 * watched state variables) for STAB_STEPS integrations of step h (the
 * other inputs in[]). */
static int stable_at(fp3_compiled *c, const fp3_model *m, const float *in, const float *y0,
                     float h) {
  float hin[FP3_MODEL_MAX_VARS], y[FP3_MODEL_MAX_VARS];
  unsigned wr[512];
  uint32_t wv[512];
  const double bound = growth_bound(m, y0);
  memcpy(hin, in, sizeof hin);
  hin[0] = h;
  fp3_compiled_model_start(c, hin, y0, wr, wv, 512);
  for (uint32_t t = 0; t < STAB_STEPS; t++) {
    fp3_compiled_model_step(c, y);
    for (unsigned k = 0; k < m->nstate; k++)
      if (watched(m, k) && !(fabs((double)y[k]) <= bound)) return 0;
  }
  return 1;
}

/* The largest stable step of c near in[0]: a bracket by doubling or
 * halving h, then 40 bisections.  Returns it, or NAN when no bracket is
 * found within 2^+-60 of in[0]. */
static double stability_bound(fp3_compiled *c, const fp3_model *m, const float *in,
                              const float *y0) {
  double lo = in[0], hi = in[0];
  int k;
  if (stable_at(c, m, in, y0, in[0])) {
    for (k = 0; k < 60 && stable_at(c, m, in, y0, (float)hi); k++) lo = hi, hi *= 2.0;
  } else {
    for (k = 0; k < 60 && !stable_at(c, m, in, y0, (float)lo); k++) hi = lo, lo *= 0.5;
  }
  if (k == 60) return NAN;
  for (int i = 0; i < 40; i++) {
    double mid = 0.5 * (lo + hi);
    if ((float)mid == (float)lo || (float)mid == (float)hi) break;
    if (stable_at(c, m, in, y0, (float)mid)) lo = mid;
    else hi = mid;
  }
  return (float)lo;
}

/* ---- the Pareto table ------------------------------------------------------ */

static const double targets[] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
#define NTARGETS (sizeof targets / sizeof targets[0])

typedef struct sweep_row {
  char integ[32];
  double h, work, err;
  uint32_t steps;
} sweep_row;

/* The cheapest row (fewest engine cycles to t_end) of rows[0..n) whose
 * error is at most target, or NULL. */
static const sweep_row *cheapest(const sweep_row *rows, unsigned n, double target) {
  const sweep_row *best = NULL;
  for (unsigned i = 0; i < n; i++)
    if (rows[i].err <= target && isfinite(rows[i].work) && (!best || rows[i].work < best->work))
      best = &rows[i];
  return best;
}

/* The Pareto table as Markdown into f (and its lines on stdout). */
static void write_pareto(FILE *f, const fp3_model *m, const sweep_row *rows, unsigned n,
                         double t_end) {
  fprintf(f, "| error at most | cheapest integrator | h [s] | steps to %.6g s | engine cycles "
             "| error reached |\n| --- | --- | --- | --- | --- | --- |\n", t_end);
  printf("\nPareto front of %s (error: largest |state - GSL rk8pd| at t_end = %g):\n", m->name,
         t_end);
  for (size_t t = 0; t < NTARGETS; t++) {
    const sweep_row *b = cheapest(rows, n, targets[t]);
    if (!b) {
      fprintf(f, "| %.0e | none in the sweep | | | | |\n", targets[t]);
      printf("  <= %.0e: none in the sweep\n", targets[t]);
      continue;
    }
    fprintf(f, "| %.0e | %s | %.6g | %" PRIu32 " | %.0f | %.2e |\n", targets[t], b->integ, b->h,
            b->steps, b->work, b->err);
    printf("  <= %.0e: %-10s h %-12.6g %8" PRIu32 " steps %10.0f cycles (error %.2e)\n",
           targets[t], b->integ, b->h, b->steps, b->work, b->err);
  }
}

/* ---- fp3 bench ------------------------------------------------------------ */

/* DIR/NAME into p (n bytes); -1 if it does not fit. */
static int out_path(char *p, size_t n, const char *dir, const char *name) {
  if ((size_t)snprintf(p, n, "%s/%s", dir, name) < n) return 0;
  fprintf(stderr, "fp3 bench: %s/%s: path too long\n", dir, name);
  return -1;
}

/* text into path (atomic); 0 or -1 (message printed). */
static int write_out(const char *path, const char *text) {
  char msg[512];
  if (!fp3_write_text_atomic(path, text, msg, sizeof msg)) return 0;
  fprintf(stderr, "fp3 bench: %s\n", msg);
  return -1;
}

/* Close the memory stream *f (NULL: none) and write the text it gathered
 * (*text, which open_memstream sets when the stream closes) to path; 0 or
 * -1 (message printed). */
static int close_out(FILE **f, const char *path, char *const *text) {
  if (!*f) return 0;
  fclose(*f);
  *f = NULL;
  return write_out(path, *text);
}

/* dir and the directories above it (mkdir -p); 0 or -1 (message printed). */
static int make_dirs(const char *dir) {
  char p[4096];
  snprintf(p, sizeof p, "%s", dir);
  for (char *q = p + 1;; q++) {
    const int end = *q == '\0';
    if (*q == '/' || end) {
      *q = '\0';
      if (mkdir(p, 0777) != 0 && errno != EEXIST) {
        fprintf(stderr, "fp3 bench: cannot create %s: %s\n", p, strerror(errno));
        return -1;
      }
      if (end) return 0;
      *q = '/';
    }
  }
}

/* 1 if argv names a model (--model FILE, --model=FILE). */
static int names_model(int argc, char **argv) {
  for (int i = 1; i < argc; i++)
    if (strcmp(argv[i], "--model") == 0 || strncmp(argv[i], "--model=", 8) == 0) return 1;
  return 0;
}

/* The bench's own options (--out, --only, --h-max) taken out of argv into
 * *dir, *only, *hmax; the rest left for fp3_parse_model in argv, *argc
 * updated.  0, or -1 (message printed). */
static int take_options(int *argc, char **argv, const char **dir, const char **only,
                        double *hmax) {
  int o = 1;
  for (int i = 1; i < *argc; i++) {
    const char *v;
    int r;
    if (fp3_is_help(argv[i])) {
      argv[o++] = argv[i];
    } else if ((r = fp3_opt_value(*argc, argv, &i, "bench", "--out", &v)) != 0) {
      if (r < 0) return -1;
      *dir = v;
    } else if ((r = fp3_opt_value(*argc, argv, &i, "bench", "--only", &v)) != 0) {
      if (r < 0) return -1;
      if (strcmp(v, "sweep") && strcmp(v, "stability") && strcmp(v, "long")) {
        fprintf(stderr, "fp3 bench: --only '%s': sweep, stability or long\n", v);
        return -1;
      }
      *only = v;
    } else if ((r = fp3_opt_value(*argc, argv, &i, "bench", "--h-max", &v)) != 0) {
      char *end;
      if (r < 0) return -1;
      *hmax = strtod(v, &end);
      if (*end || !(*hmax > 0.0) || !isfinite(*hmax) || !((float)*hmax > 0.0f)) {
        fprintf(stderr, "fp3 bench: --h-max '%s': a positive step [s]\n", v);
        return -1;
      }
    } else {
      argv[o++] = argv[i];
    }
  }
  *argc = o;
  return 0;
}

static int bench(fp3_bench_args *b);

int fp3_parse_bench(int argc, char **argv, fp3_bench_args *b) {
  memset(b, 0, sizeof *b);
  if (gone_option(argc, argv)) return FP3_ARGS_BAD;
  /* argv with --model models/ship.fp3m when it names no model */
  char **av = malloc(((size_t)argc + 3) * sizeof *av);
  if (!av) return FP3_ARGS_BAD;
  int ac = 0;
  for (int i = 0; i < argc; i++) av[ac++] = argv[i];
  if (!names_model(argc, argv)) {
    fp3_find_shipped(SHIP_MODEL, b->ship, sizeof b->ship);
    av[ac++] = "--model";
    av[ac++] = b->ship;
  }
  av[ac] = NULL;
  int r = take_options(&ac, av, &b->dir, &b->only, &b->hmax)
              ? FP3_ARGS_BAD
              : fp3_parse_model(ac, av, "bench", &b->a);
  free(av);
  if (r != FP3_ARGS_RUN) return r;
  if (b->only && !b->dir) {
    fprintf(stderr, "fp3 bench: --only goes with --out DIR\n");
    return FP3_ARGS_BAD;
  }
  if (b->dir && (b->a.out || b->a.stab || b->a.long_out)) {
    fprintf(stderr, "fp3 bench: --out DIR writes every part's files; -o, --stability and "
            "--long name one part's CSV without it\n");
    return FP3_ARGS_BAD;
  }
  return FP3_ARGS_RUN;
}

int fp3_cmd_bench(int argc, char **argv) {
  fp3_bench_args *b = malloc(sizeof *b);
  if (!b) return EXIT_FAIL;
  int r = fp3_parse_bench(argc, argv, b);
  if (r != FP3_ARGS_RUN) {
    free(b);
    return fp3_args_exit(r, usage);
  }
  int rc = bench(b);
  free(b);
  return rc;
}

/* fp3 bench with the options b (fp3_parse_bench's). */
static int bench(fp3_bench_args *b) {
  fp3_model_args a = b->a;
  const char *dir = b->dir, *only = b->only;
  const double hmax = b->hmax;
  int want_sweep = 1;
  char p_sweep[4200], p_pareto[4200], p_stab[4200], p_stabmd[4200], p_long[4200], p_longmd[4200];
  const char *pareto = NULL, *stabmd = NULL, *longmd = NULL;
  if (dir) {
    if (out_path(p_sweep, sizeof p_sweep, dir, "sweep.csv") ||
        out_path(p_pareto, sizeof p_pareto, dir, "pareto.md") ||
        out_path(p_stab, sizeof p_stab, dir, "stability.csv") ||
        out_path(p_stabmd, sizeof p_stabmd, dir, "stability.md") ||
        out_path(p_long, sizeof p_long, dir, "longrun.csv") ||
        out_path(p_longmd, sizeof p_longmd, dir, "longrun.md"))
      return EXIT_USAGE;
    want_sweep = !only || strcmp(only, "sweep") == 0;
    if (want_sweep) a.out = p_sweep, pareto = p_pareto;
    if (!only || strcmp(only, "stability") == 0) a.stab = p_stab, stabmd = p_stabmd;
    if (!only || strcmp(only, "long") == 0) a.long_out = p_long, longmd = p_longmd;
    if (make_dirs(dir)) return EXIT_FAIL;
    setvbuf(stdout, NULL, _IOLBF, 0); /* progress through a pipe (tee) */
  }

  fp3_model *m = malloc(sizeof *m);
  char msg[512];
  if (!m) return EXIT_FAIL;
  int rc = EXIT_USAGE;
  fp3_engine *e = NULL;
  FILE *csv = NULL, *scsv = NULL, *lcsv = NULL, *smd = NULL, *lmd = NULL;
  char *text = NULL, *stext = NULL, *ltext = NULL, *smtext = NULL, *lmtext = NULL;
  size_t tlen = 0, slen = 0, llen = 0, smlen = 0, lmlen = 0;
  sweep_row *rows = calloc(MAX_ROWS, sizeof *rows);
  float in[FP3_MODEL_MAX_VARS] = {0}, y0[FP3_MODEL_MAX_VARS] = {0};
  if (!rows) goto out;
  if (fp3_model_load(a.file, m, msg, sizeof msg)) {
    fprintf(stderr, "fp3 bench: %s\n", msg);
    goto out;
  }
  if (fp3_model_args_values(m, &a, in, y0)) goto out;
  const double t_end = a.t_end > 0.0 ? a.t_end : 600.0 * (double)in[0];
  const float h0 = hmax > 0.0 ? (float)hmax : in[0];
  rc = EXIT_FAIL;
  e = fp3_engine_new(a.engine);
  csv = open_memstream(&text, &tlen);
  if (!e || fp3_engine_error(e)[0] || !csv) {
    fprintf(stderr, "fp3 bench: cannot create the %s engine\n", a.engine);
    goto out;
  }
  fp3_engine_show_progress(e, "fp3 bench");
  if (a.stab && !(scsv = open_memstream(&stext, &slen))) goto out;
  if (stabmd && !(smd = open_memstream(&smtext, &smlen))) goto out;
  if (a.long_out && !(lcsv = open_memstream(&ltext, &llen))) goto out;
  if (longmd && !(lmd = open_memstream(&lmtext, &lmlen))) goto out;
  if (scsv)
    fprintf(scsv, "model,integrator,h_stable,trial_steps,growth_bound,engine,engine_steps,"
                  "below_diverged,above_diverged,above_diverged_from,bit_exact\n");
  if (smd)
    fprintf(smd, "| integrator | largest stable h [s] (%u golden integrations) | %s at 0.98 h "
                 "| %s at 1.02 h | bit-exact |\n| --- | --- | --- | --- | --- |\n",
            STAB_STEPS, a.engine, a.engine);
  if (lcsv) {
    fprintf(lcsv, "model,integrator,engine,steps,cycles_per_step,engine_mismatches,error_max");
    for (unsigned k = 0; k < m->nstate; k++)
      fprintf(lcsv, ",%s,%s_ref", m->state[k], m->state[k]);
    for (unsigned k = 0; k < m->nstate; k++)
      fprintf(lcsv, ",%s_last_change,%s_unchanged", m->state[k], m->state[k]);
    fprintf(lcsv, "\n");
  }
  if (lmd) {
    fprintf(lmd, "| integrator | run | largest error at the end |");
    for (unsigned k = 0; k < m->nstate; k++)
      fprintf(lmd, " %s last changed at | integrations that left %s unchanged |", m->state[k],
              m->state[k]);
    fprintf(lmd, "\n| --- | --- | --- |");
    for (unsigned k = 0; k < m->nstate; k++) fprintf(lmd, " --- | --- |");
    fprintf(lmd, "\n");
  }
  fprintf(csv, "model,integrator,h,steps,t_end,insns_per_step,cycles_per_step,work_cycles,"
               "engine_mismatches,error_max");
  for (unsigned k = 0; k < m->nstate; k++) fprintf(csv, ",%s,%s_ref", m->state[k], m->state[k]);
  fprintf(csv, "\n");
  unsigned char zero[FP3_MODEL_MAX_VARS] = {0};
  for (unsigned k = 0; k < m->nparam; k++) zero[k] = in[k] == 0.0f;
  char names[512];
  snprintf(names, sizeof names, "%s", a.integ_given ? a.integ : fp3_model_integrators());
  if (dir)
    printf("fp3 bench: model %s (%s), engine %s, h = %.9g s, t_end %g s -> %s/\n", m->name,
           m->file, a.engine, (double)in[0], t_end, dir);
  uint64_t bad = 0;
  unsigned nrows = 0;
  for (char *save = NULL, *ig = strtok_r(names, " ,", &save); ig;
       ig = strtok_r(NULL, " ,", &save)) {
    if (!a.integ_given && !fp3_model_integrator_applies(m, ig)) continue;
    fp3_model_args ai = a;
    ai.integ = ig;
    const int iss = strcmp(a.engine, "iss") == 0;
    fp3_compiled *c = fp3_model_compile_for(m, &ai, zero, &e->config, iss, "bench");
    if (!c) {
      rc = EXIT_USAGE;
      goto out;
    }
    if (iss && fp3_model_fit_engine(&e, c, "bench")) {
      fp3_compiled_free(c);
      goto out;
    }
    const unsigned insns = fp3_compiled_stats(c)->body_insns;
    bench_run br;
    if (bench_engine(e, c, m, in, y0, BENCH_RTL_STEPS, &br)) {
      fprintf(stderr, "fp3 bench: %s engine: %s\n", a.engine, fp3_engine_error(e));
      fp3_compiled_free(c);
      goto out;
    }
    const double cyc = br.cyc;
    const uint64_t mism = br.mism;
    bad += mism;
    if (dir)
      printf("  %-10s %3u instructions, %6.2f %s cycles per integration%s\n", ig, insns, cyc,
             a.engine, mism ? ", NOT BIT-EXACT" : "");
    if (scsv) { /* the bound, then the engine just below and above it */
      const double hs = stability_bound(c, m, in, y0);
      int dv[2] = {0, 0}, ok = isfinite(hs);
      uint32_t from = 0;
      for (int j = 0; j < 2 && ok; j++) {
        float hin[FP3_MODEL_MAX_VARS];
        memcpy(hin, in, sizeof hin);
        hin[0] = (float)((j ? 1.02 : 0.98) * hs);
        bench_run sr;
        if (bench_engine(e, c, m, hin, y0, STAB_ENGINE_STEPS, &sr)) {
          fprintf(stderr, "fp3 bench: %s engine: %s\n", a.engine, fp3_engine_error(e));
          fp3_compiled_free(c);
          goto out;
        }
        bad += sr.mism;
        ok = sr.mism == 0;
        dv[j] = sr.diverged != 0;
        if (j) from = sr.diverged;
      }
      fprintf(scsv, "%s,%s,%.9g,%u,%g,%s,%u,%d,%d,%" PRIu32 ",%d\n", m->name, ig, hs, STAB_STEPS,
              STAB_GROWTH, a.engine, STAB_ENGINE_STEPS, dv[0], dv[1], from, ok);
      char above[64];
      snprintf(above, sizeof above, "%s", dv[1] ? "diverges" : "stable");
      if (dv[1]) snprintf(above, sizeof above, "diverges from integration %" PRIu32, from);
      if (smd)
        fprintf(smd, "| %s | %.6g | %s | %s | %s |\n", ig, hs, dv[0] ? "diverges" : "stable",
                above, ok ? "yes" : "NO");
      if (dir)
        printf("  %-10s largest stable h %.6g s; %u %s integrations at 0.98 h: %s, at 1.02 h: "
               "%s%s\n", ig, hs, STAB_ENGINE_STEPS, a.engine, dv[0] ? "DIVERGES" : "stable",
               dv[1] ? above : "STABLE", ok ? "" : ", NOT BIT-EXACT");
    }
    if (lcsv) { /* the long run: on the engine, every integration checked */
      double din[FP3_MODEL_MAX_VARS], dy0[FP3_MODEL_MAX_VARS], ref[FP3_MODEL_MAX_VARS];
      bench_run lr;
      if (bench_engine(e, c, m, in, y0, a.long_steps, &lr)) {
        fprintf(stderr, "fp3 bench: %s engine: %s\n", a.engine, fp3_engine_error(e));
        fp3_compiled_free(c);
        goto out;
      }
      bad += lr.mism;
      for (unsigned k = 0; k < m->nparam; k++) din[k] = in[k];
      for (unsigned k = 0; k < m->nstate; k++) dy0[k] = y0[k];
      char rmsg[256];
      int have = fp3_model_gsl(m, din, dy0, a.long_steps, NULL, NULL, ref, rmsg, sizeof rmsg) == 0;
      double emax = have ? 0.0 : NAN;
      for (unsigned k = 0; have && k < m->nstate; k++)
        if (!(fabs((double)lr.y[k] - ref[k]) <= emax)) emax = fabs((double)lr.y[k] - ref[k]);
      fprintf(lcsv, "%s,%s,%s,%" PRIu32 ",%.2f,%" PRIu64 ",%.6g", m->name, ig, a.engine,
              a.long_steps, lr.cyc, lr.mism, emax);
      for (unsigned k = 0; k < m->nstate; k++)
        fprintf(lcsv, ",%.9g,%.15g", (double)lr.y[k], have ? ref[k] : NAN);
      for (unsigned k = 0; k < m->nstate; k++)
        fprintf(lcsv, ",%" PRIu32 ",%" PRIu64, lr.last_change[k], lr.unmoved[k]);
      fprintf(lcsv, "\n");
      if (lmd) {
        fprintf(lmd, "| %s | %s, %" PRIu32 " integrations, %s | %.2e |", ig, a.engine,
                a.long_steps, lr.mism ? "NOT BIT-EXACT" : "bit-exact", emax);
        for (unsigned k = 0; k < m->nstate; k++)
          fprintf(lmd, " %" PRIu32 " | %" PRIu64 " |", lr.last_change[k], lr.unmoved[k]);
        fprintf(lmd, "\n");
      }
      if (dir) {
        printf("  %-10s %" PRIu32 " %s integrations%s: largest error %.3g;", ig, a.long_steps,
               a.engine, lr.mism ? " NOT BIT-EXACT" : "", emax);
        for (unsigned k = 0; k < m->nstate; k++)
          printf(" %s %.9g last changed at %" PRIu32 ", unchanged in %" PRIu64 ";", m->state[k],
                 (double)lr.y[k], lr.last_change[k], lr.unmoved[k]);
        printf("\n");
      }
    }
    for (unsigned p = 0; want_sweep && p < a.points; p++) {
      float hin[FP3_MODEL_MAX_VARS];
      memcpy(hin, in, sizeof hin);
      hin[0] = (float)ldexp((double)h0, -(int)p); /* H, H/2, H/4, ...: exact */
      double steps_d = floor(t_end / (double)hin[0] + 0.5);
      if (steps_d < 1 || steps_d > 1e8) continue;
      uint32_t steps = (uint32_t)steps_d;
      unsigned wr[512];
      uint32_t wv[512];
      float y[FP3_MODEL_MAX_VARS];
      fp3_compiled_model_start(c, hin, y0, wr, wv, 512);
      for (uint32_t k = 0; k < steps; k++) fp3_compiled_model_step(c, y);
      double din[FP3_MODEL_MAX_VARS], dy0[FP3_MODEL_MAX_VARS], ref[FP3_MODEL_MAX_VARS];
      for (unsigned k = 0; k < m->nparam; k++) din[k] = hin[k];
      for (unsigned k = 0; k < m->nstate; k++) dy0[k] = y0[k];
      char rmsg[256];
      int have = fp3_model_gsl(m, din, dy0, steps, NULL, NULL, ref, rmsg, sizeof rmsg) == 0;
      double emax = 0.0;
      for (unsigned k = 0; k < m->nstate; k++) {
        double d = fabs((double)y[k] - ref[k]);
        if (!have || !(d <= emax)) emax = have ? d : NAN;
      }
      fprintf(csv, "%s,%s,%.9g,%" PRIu32 ",%.9g,%u,%.2f,%.0f,%" PRIu64 ",%.6g", m->name, ig,
              (double)hin[0], steps, (double)steps * hin[0], insns, cyc, cyc * steps, mism,
              emax);
      for (unsigned k = 0; k < m->nstate; k++)
        fprintf(csv, ",%.9g,%.15g", (double)y[k], have ? ref[k] : NAN);
      fprintf(csv, "\n");
      if (nrows < MAX_ROWS) {
        sweep_row *w = &rows[nrows];
        snprintf(w->integ, sizeof w->integ, "%s", ig);
        w->h = hin[0];
        w->steps = steps;
        w->work = cyc * steps;
        w->err = emax;
      }
      nrows++;
    }
    fp3_compiled_free(c);
  }
  fclose(csv);
  csv = NULL;
  if (close_out(&scsv, a.stab, &stext) || close_out(&smd, stabmd, &smtext) ||
      close_out(&lcsv, a.long_out, &ltext) || close_out(&lmd, longmd, &lmtext))
    goto out;
  if (want_sweep && a.out) {
    if (write_out(a.out, text)) goto out;
    fprintf(stderr, "fp3 bench: %s: %u rows (model %s, t_end %.6g)\n", a.out, nrows, m->name,
            t_end);
  } else if (want_sweep) {
    fputs(text, stdout);
  }
  if (pareto) {
    char *ptext = NULL;
    size_t plen = 0;
    FILE *pf = open_memstream(&ptext, &plen);
    if (!pf) goto out;
    write_pareto(pf, m, rows, nrows < MAX_ROWS ? nrows : MAX_ROWS, t_end);
    fclose(pf);
    int w = write_out(pareto, ptext);
    free(ptext);
    if (w) goto out;
  }
  if (bad)
    fprintf(stderr, "fp3 bench: FAIL: %" PRIu64 " state values of the %s runs differ from the "
            "golden model\n", bad, a.engine);
  rc = bad ? EXIT_FAIL : 0;
out:
  if (csv) fclose(csv);
  if (scsv) fclose(scsv);
  if (lcsv) fclose(lcsv);
  if (smd) fclose(smd);
  if (lmd) fclose(lmd);
  free(text);
  free(stext);
  free(ltext);
  free(smtext);
  free(lmtext);
  free(rows);
  fp3_engine_free(e);
  free(m);
  return rc;
}
