/*
 * cmd_run.c -- `fp3 run`: a program on an engine, every integration
 * checked against the golden model bit for bit and compared with the
 * exact solution (cmd_run.h).  The many-objects form is cmd_objects.c,
 * the model form cmd_model.c.
 */
#include "cmd_run.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "analytic.h"
#include "asm.h"
#include "cliopt.h"
#include "cmd_asm.h"
#include "cmd_model.h"
#include "cmd_objects.h"
#include "compile.h"
#include "engine.h"
#include "fp3_isa.h"
#include "fpenv.h"
#include "golden.h"
#include "image.h"
#include "report.h"
#include "traceopt.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2

#define DEFAULT_PROGRAM "programs/ship_rk4.s"
#define DEFAULT_STEPS 10000u
#define MAX_OBJECTS 1000000u /* --objects */
#define TABLE_ROWS 5     /* first integrations shown in the table   */
#define PAPER_FIRST 445  /* cycles of the first integration (paper) */
#define PAPER_LATER 418  /* cycles of each later integration        */
/* The run's cycles for the trace's size estimate (--trace-limit): each
 * integration this many cycles per instruction word of the program, an
 * upper bound for the shipped programs on the default build (2.2 to 4
 * cycles a word; rk4, 34 words: 121 cycles for the first integration, 113
 * for each later one, estimated as 136).  A program of long dependency
 * chains can take more. */
#define TRACE_CYCLES_PER_WORD 4u

/* ---- fp3 run: observing and checking ------------------------------------ */

enum { OV = 0, OS = 1 }; /* the two checked results */

typedef struct checker {
  fp3_track t;            /* v and s after every integration (t.last: integrations requested) */
  /* golden values of integrations base .. base+count-1 */
  fp3_istate gst;                 /* golden state of the integrator */
  const fp3_integrator *integ;    /* --integrator (default rk4)     */
  fp3_diverge div;                /* run-time divergence watch      */
  float *gv, *gs;
  size_t cap, count;
  uint32_t base;
  int oom;
  fp3_ship_params p;
  fpref_mode mode;        /* core options the golden model follows */
  /* comparison */
  uint64_t mismatches;
  uint32_t first_k;
  int first_which;
  uint32_t first_got, first_want;
  int64_t max_ulp;
  /* error against the exact solution */
  double max_abs[2], max_rel[2];
  double final_abs[2], final_rel[2];
  /* table rows */
  uint32_t row[2][TABLE_ROWS];
  uint32_t last[2];
  uint32_t last_k[2];
  /* endi */
  uint32_t endis;
  uint64_t cyc_first, cyc_last;
} checker;

/* Golden (v, s) after integration k >= 1, computed on demand. */
static int golden_at(checker *c, uint32_t k, float *v, float *s) {
  uint32_t lo = c->t.next_k[OV] < c->t.next_k[OS] ? c->t.next_k[OV] : c->t.next_k[OS];
  if (k < c->base) return -1; /* cannot happen: finalised in order */
  while (k >= c->base + c->count) {
    if (c->count == c->cap) {
      /* drop integrations both results are past */
      size_t drop = lo > c->base ? lo - c->base : 0;
      if (drop > c->count) drop = c->count;
      if (drop) {
        memmove(c->gv, c->gv + drop, (c->count - drop) * sizeof *c->gv);
        memmove(c->gs, c->gs + drop, (c->count - drop) * sizeof *c->gs);
        c->count -= drop;
        c->base += (uint32_t)drop;
      }
      if (c->count == c->cap) {
        size_t cap = c->cap ? c->cap * 2 : 256;
        float *nv = realloc(c->gv, cap * sizeof *nv);
        if (!nv) return -1;
        c->gv = nv;
        float *ns = realloc(c->gs, cap * sizeof *ns);
        if (!ns) return -1;
        c->gs = ns;
        c->cap = cap;
      }
    }
    fpenv_saved env;
    if (fpenv_enter(c->mode, &env) != 0) return -1; /* checked before the run */
    c->integ->step(&c->gst);
    fpenv_leave(&env);
    c->gv[c->count] = c->gst.v;
    c->gs[c->count] = c->gst.s;
    c->count++;
  }
  *v = c->gv[k - c->base];
  *s = c->gs[k - c->base];
  return 0;
}

static void exact_at(const checker *c, uint32_t k, double *v, double *s) {
  fp3_ship_exact(c->p.T, c->p.C, c->p.m, c->p.v0, c->p.s0,
                 (double)k * (double)c->p.h, v, s);
}

/* Result `which` after integration k is `bits`. */
static void finalise(void *ctx, int which, uint32_t k, uint32_t bits) {
  checker *c = ctx;
  float gv, gs;
  if (golden_at(c, k, &gv, &gs)) {
    c->oom = 1;
    return;
  }
  uint32_t want = fpref_bits(which == OV ? gv : gs);
  if (bits != want) {
    if (c->mismatches == 0) {
      c->first_k = k;
      c->first_which = which;
      c->first_got = bits;
      c->first_want = want;
    }
    c->mismatches++;
    int64_t d = fp3_ulp_distance(bits, want);
    if (d > c->max_ulp) c->max_ulp = d;
  }
  double ev, es;
  exact_at(c, k, &ev, &es);
  double exact = which == OV ? ev : es;
  double got = (double)fpref_float(bits);
  double abs_err = fabs(got - exact);
  double rel_err = exact != 0.0 ? abs_err / fabs(exact) : (abs_err == 0 ? 0 : INFINITY);
  if (!(abs_err <= c->max_abs[which])) c->max_abs[which] = abs_err;
  if (!(rel_err <= c->max_rel[which])) c->max_rel[which] = rel_err;
  c->final_abs[which] = abs_err;
  c->final_rel[which] = rel_err;
  if (which == OV)
    fp3_diverge_update(&c->div, k, fpref_float(bits), 0.0f);
  else if (!isfinite(fpref_float(bits)) &&
           (!c->div.nonfinite || k < c->div.nonfinite))
    c->div.nonfinite = k;
  if (k <= TABLE_ROWS) c->row[which][k - 1] = bits;
  c->last[which] = bits;
  c->last_k[which] = k;
}

static void obs_write(void *ctx, unsigned reg, uint32_t value,
                      uint32_t integration) {
  fp3_track_write(&((checker *)ctx)->t, reg, value, integration);
}

static void obs_endi(void *ctx, uint32_t integration, uint64_t cycle) {
  checker *c = ctx;
  c->endis = integration;
  if (integration == 1) c->cyc_first = cycle;
  c->cyc_last = cycle;
}

/* ---- fp3 run ------------------------------------------------------------ */

static void usage_run(FILE *f) {
  fprintf(f,
          "usage: fp3 run [--engine rtl|iss] [--integrator NAME] [--strict]\n"
          "               [--objects N [--seed S] | --scene FILE]\n"
          "               [--literal | --compile]\n"
          "               [--program FILE.s] [--steps N]\n"
          "               [--set NAME=VALUE ...] [--round rne|rtz] [--ftz]\n"
          "               [--json] [--trace FILE.vcd [--trace-window FIRST:COUNT]\n"
          "               [--trace-limit SIZE]]\n"
          "       fp3 run --model FILE.fp3m ...   a model file (fp3 run --model x --help,\n"
          "                                       docs/models.md)\n"
          "\n"
          "Assemble the program, write its .in registers, run N integrations\n"
          "on the engine and compare the .out results v and s after every\n"
          "integration with the golden model (sw/ref/golden.c), bit for bit, and\n"
          "with the exact solution of the ship ODE.\n"
          "\n"
          "  --engine E       rtl (Verilated RTL, default) or iss (simulator)\n"
          "  --integrator I   integrator: program programs/ship_I.s and its\n"
          "                   golden model (sw/ref/integrators.c): euler, symeuler,\n"
          "                   verlet, rk2, rk4 (default, the paper's), rk4vs,\n"
          "                   rk4comp, rk4vscomp.  A warning when h/tau =\n"
          "                   h C/m exceeds its stability bound; divergence\n"
          "                   (non-finite v or s, |v - T/C| growing past\n"
          "                   twice its start) is reported with the\n"
          "                   integration it began\n"
          "  --strict         the bound warning is an error (exit 2), and a\n"
          "                   divergence fails the run (exit 1)\n"
          "  --program FILE   assembly program (default %s, or that of\n"
          "                   --integrator; checked against its golden model)\n"
          "  --steps N        integrations, 1..4294967295 (default %u)\n"
          "  --set NAME=VALUE scene parameter, binary32 (repeatable):\n"
          "                   T thrust [N] (default 50000), C drag [kg/s]\n"
          "                   (5000), m mass [kg] (10000), h step [s] (1/60),\n"
          "                   v0 [m/s] (0), s0 [m] (0).  m > 0, h > 0, C >= 0,\n"
          "                   all finite.  minv = 1.0f/m is derived.\n"
          "  --round R        FP core rounding: rne (default) or rtz\n"
          "  --ftz            FP cores flush subnormals to zero\n"
          "                   (the ISS and the golden model follow; the RTL\n"
          "                   model of that configuration is chosen)\n"
          "  --objects N      many ships at once on the contexts (in batches of\n"
          "                   NUM_CONTEXTS): a scene generated from --seed S\n"
          "                   (default 1), or all of --scene FILE; every object\n"
          "                   is checked against its golden model\n"
          "  --scene FILE     scene file: 'h STEP' once, then one object per\n"
          "                   line 'T C m v0 s0' ('#' comments; docs/skipping.md);\n"
          "                   runs the scene compiler's program for the scene\n"
          "                   (fp3 compile --help; integrators euler, symeuler,\n"
          "                   rk2, rk4), checked against the IR's golden model;\n"
          "                   a model scene ('model FILE' first, docs/models.md)\n"
          "                   runs its model (fp3 run --model x --help)\n"
          "  --literal        with --scene: the integrator's literal program\n"
          "                   programs/ship_I.s and its golden model instead\n"
          "  --compile        with --objects N: the compiled program too\n"
          "  --json           one JSON object instead of the report\n"
          "  --trace FILE     waveform of the run (rtl engine only): a VCD of\n"
          "                   every signal, cycles FIRST .. FIRST+COUNT-1 of the\n"
          "                   run (cycle 0 is the first after START)\n"
          "  --trace-window FIRST:COUNT  cycles to write (default 0:%u; COUNT\n"
          "                   'all': to the end of the run)\n"
          "  --trace-limit SIZE  refuse (exit 2) a trace estimated above SIZE\n"
          "                   bytes (K, M, G, T: KiB .. TiB; default 1G; 'none':\n"
          "                   no limit); about 24 KB a cycle; a warning above\n"
          "                   100M.  FILE appears when the run has finished:\n"
          "                   until then it is FILE.tmp.PID, removed if the run\n"
          "                   fails and on SIGINT or SIGTERM\n"
          "\n"
          "Exit status: 0 the run finished without error and bit-exact with\n"
          "the golden model; 1 it did not; 2 bad arguments or program.\n",
          DEFAULT_PROGRAM, DEFAULT_STEPS, FP3_TRACE_WINDOW_DEFAULT);
}

/* The default program: relative to the working directory, else to the
 * executable (build/fp3 -> programs/). */
static int open_default(const char *rel, char *path, size_t n) {
  if (access(rel, R_OK) == 0) {
    snprintf(path, n, "%s", rel);
    return 0;
  }
  char exe[4096];
  ssize_t k = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (k > 0) {
    exe[k] = '\0';
    char *slash = strrchr(exe, '/');
    if (slash) {
      *slash = '\0';
      snprintf(path, n, "%s/../%s", exe, rel);
      if (access(path, R_OK) == 0) return 0;
    }
  }
  snprintf(path, n, "%s", rel);
  return -1;
}

static void print_row(const checker *c, uint32_t k, uint32_t vb, uint32_t sb) {
  double ev, es;
  exact_at(c, k, &ev, &es);
  printf("%10" PRIu32 "  %10.4f  %15.9g %15.9g  %15.9g %15.9g\n", k,
         (double)k * (double)c->p.h, (double)fpref_float(vb), ev,
         (double)fpref_float(sb), es);
}

int fp3_parse_run(int argc, char **argv, fp3_run_args *a) {
  memset(a, 0, sizeof *a);
  a->engine_name = "rtl";
  fp3_trace_opts_init(&a->trace);
  a->steps = DEFAULT_STEPS;
  a->seed = 1;
  a->mode = FPREF_IEEE;
  fp3_ship_default(&a->p);
  for (int i = 1; i < argc; i++) {
    const char *v;
    unsigned long long k;
    int r;
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    if ((r = fp3_opt_value(argc, argv, &i, "run", "--engine", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      if (strcmp(v, "rtl") != 0 && strcmp(v, "iss") != 0) {
        fprintf(stderr, "fp3 run: unknown engine '%s' (rtl or iss)\n", v);
        return FP3_ARGS_BAD;
      }
      a->engine_name = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, "run", "--program", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->program = v;
    } else if ((r = fp3_opt_count(argc, argv, &i, "run", "--steps", 1, UINT32_MAX,
                                  "integrations", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->steps = (uint32_t)k;
    } else if ((r = fp3_opt_value(argc, argv, &i, "run", "--set", &v)) != 0) {
      if (r < 0 || fp3_ship_set("run", &a->p, v)) return FP3_ARGS_BAD;
    } else if ((r = fp3_trace_opt(argc, argv, &i, "run", &a->trace)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_mode(argc, argv, &i, "run", &a->mode)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
    } else if (strcmp(argv[i], "--json") == 0) {
      a->json = 1;
    } else if ((r = fp3_opt_value(argc, argv, &i, "run", "--integrator", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->integ = fp3_integrator_find(v);
      if (!a->integ) {
        fprintf(stderr, "fp3 run: unknown integrator '%s' (%s)\n", v,
                fp3_integrator_names());
        return FP3_ARGS_BAD;
      }
    } else if (strcmp(argv[i], "--strict") == 0) {
      a->strict = 1;
    } else if (strcmp(argv[i], "--literal") == 0) {
      a->literal = 1;
    } else if (strcmp(argv[i], "--compile") == 0) {
      a->compile = 1;
    } else if ((r = fp3_opt_count(argc, argv, &i, "run", "--objects", 1, MAX_OBJECTS,
                                  "objects", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->objects = (size_t)k;
    } else if ((r = fp3_opt_value(argc, argv, &i, "run", "--scene", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->scene = v;
    } else if ((r = fp3_opt_seed(argc, argv, &i, "run", &a->seed)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->seeded = 1;
    } else {
      fprintf(stderr, "fp3 run: unknown argument '%s' (see fp3 run --help)\n",
              argv[i]);
      return FP3_ARGS_BAD;
    }
  }
  if (a->seeded && (!a->objects || a->scene)) {
    fprintf(stderr, "fp3 run: --seed goes with --objects N (a generated scene)\n");
    return FP3_ARGS_BAD;
  }
  if (a->literal && a->compile) {
    fprintf(stderr, "fp3 run: --literal or --compile, not both\n");
    return FP3_ARGS_BAD;
  }
  if (a->compile && (a->program || !(a->objects || a->scene))) {
    fprintf(stderr, "fp3 run: --compile goes with --scene FILE or --objects N, "
                    "without --program\n");
    return FP3_ARGS_BAD;
  }
  /* a scene file runs the scene compiler's program unless told otherwise */
  if (a->scene && !a->literal && !a->program) a->compile = 1;
  if (fp3_trace_check(&a->trace, "run", a->engine_name, a->objects || a->scene))
    return FP3_ARGS_BAD;
  char msg[512];
  if (fp3_ship_validate(&a->p, msg, sizeof msg)) {
    fprintf(stderr, "fp3 run: %s\n", msg);
    return FP3_ARGS_BAD;
  }
  if (!fpenv_supported(a->mode)) {
    fprintf(stderr, "fp3 run: --ftz: this host cannot run the golden model with "
                    "flush-to-zero (needs x86 SSE)\n");
    return FP3_ARGS_BAD;
  }
  if (!a->integ) a->integ = fp3_integrator_find("rk4");
  if (a->compile && !fp3_compile_knows(a->integ->name)) {
    fprintf(stderr, "fp3 run: the scene compiler does not know integrator '%s' (%s); "
                    "--literal runs programs/ship_%s.s\n",
            a->integ->name, fp3_compile_integrators(), a->integ->name);
    return FP3_ARGS_BAD;
  }
  {
    double hot = fp3_h_over_tau(&a->p);
    if (a->p.C > 0.0f && hot > a->integ->bound) {
      fprintf(stderr,
              "fp3 run: %s: h/tau = h C/m = %.6g exceeds the stability bound "
              "%.6g of integrator %s: the integration will diverge\n",
              a->strict ? "error" : "warning", hot, a->integ->bound, a->integ->name);
      if (a->strict) return FP3_ARGS_BAD;
    }
  }
  return FP3_ARGS_RUN;
}

/* The run step: assemble, create the engine, run, check and report. */
static int run_run(const fp3_run_args *a) {
  const char *engine_name = a->engine_name, *program = a->program, *trace = a->trace.path;
  const uint32_t steps = a->steps;
  const int json = a->json, strict = a->strict;
  const size_t objects = a->objects;
  const char *scene = a->scene;
  const uint64_t seed = a->seed;
  const int compile = a->compile;
  const fp3_integrator *integ = a->integ;
  const fpref_mode mode = a->mode;
  const fp3_ship_params p = a->p;
  char defpath[4200];
  if (!program) {
    open_default(integ->program, defpath, sizeof defpath);
    program = defpath;
  }

  /* assemble */
  fp3_image img;
  char *errs = NULL;
  if (fp3_asm_file(program, &img, &errs) != 0) {
    fp3_print_asm_errors(errs);
    free(errs);
    return EXIT_USAGE;
  }
  free(errs);
  if (fp3_refuse_endless("run", program, &img)) return EXIT_USAGE;
  for (int w = 0; w < FP3_OUT_COUNT; w++)
    if (img.out_reg[w] < 0) {
      fprintf(stderr,
              "fp3 run: %s has no '.out %s, rN': nothing to check against "
              "the golden model\n",
              program, fp3_out_name(w));
      return EXIT_USAGE;
    }

  /* engine */
  if (fp3_trace_writable(&a->trace, "run")) return EXIT_USAGE;
  fp3_engine *e = strcmp(engine_name, "iss") == 0 ? fp3_engine_iss_new_mode(mode)
                                                  : fp3_engine_rtl_new_mode(mode, trace);
  if (!e) {
    fprintf(stderr, "fp3 run: cannot create the %s engine\n", engine_name);
    return EXIT_FAIL;
  }
  if (fp3_engine_error(e)[0]) {
    fprintf(stderr, "fp3 run: %s engine: %s\n", engine_name,
            fp3_engine_error(e));
    fp3_engine_free(e);
    return EXIT_FAIL;
  }
  if (fp3_trace_prepare(&a->trace, "run", e,
                        fp3_trace_run_cycles(steps, TRACE_CYCLES_PER_WORD * (uint64_t)img.n,
                                             TRACE_CYCLES_PER_WORD * (uint64_t)img.n),
                        "at 4 cycles an integration per word of the program")) {
    fp3_engine_free(e);
    return EXIT_USAGE;
  }
  if (objects || scene) {
    fp3_integ_golden gstore;
    const fp3_golden_ref golden = fp3_golden_of_integrator(&gstore, integ);
    fp3_objects_cmd oc = {e, &img, program, integ->name, &golden, compile, NULL, scene,
                          objects, seed, p.h, steps, mode, json};
    int orc = fp3_cmd_run_objects(&oc);
    fp3_engine_free(e);
    return orc;
  }
  int rc = EXIT_FAIL;
  checker c;
  memset(&c, 0, sizeof c);
  c.p = p;
  c.mode = mode;
  c.t.last = steps;
  c.t.final = finalise;
  c.t.ctx = &c;
  c.base = 1;
  c.integ = integ;
  fp3_diverge_init(&c.div, &p);
  {
    fpenv_saved env;
    if (fpenv_enter(mode, &env) == 0) {
      integ->init(&c.gst, &p); /* prologue arithmetic in the cores' mode */
      fpenv_leave(&env);
    } else {
      integ->init(&c.gst, &p);
    }
  }
  const float minv = fp3_ship_minv(p.m);
  float inval[FP3_IN_COUNT];
  fp3_in_values(&p, inval);
  fp3_status st;
  memset(&st, 0, sizeof st);
  int erc = fp3_engine_load(e, img.words, img.n);
  if (erc != 0) { /* the program does not fit this build: name it */
    fprintf(stderr, "fp3 run: %s: refused by the %s engine: %s\n", program, engine_name,
            fp3_engine_error(e));
    fprintf(stderr, "FAIL: the %s engine failed\n", engine_name);
    goto out;
  }
  for (int i = 0; i < FP3_IN_COUNT && erc == 0; i++)
    if (img.in_reg[i] >= 0)
      erc = fp3_engine_write_reg(e, (unsigned)img.in_reg[i],
                                 fpref_bits(inval[i]));
  for (int w = 0; w < 2 && erc == 0; w++) {
    c.t.reg[w] = img.out_reg[w];
    c.t.next_k[w] = 1;
    erc = fp3_engine_read_reg(e, (unsigned)c.t.reg[w], &c.t.cur[w]);
  }
  if (erc == 0) {
    fp3_observer obs = {.ctx = &c, .on_write = obs_write, .on_endi = obs_endi};
    erc = fp3_engine_run(e, steps, &obs, &st);
  }
  if (erc != 0) {
    fprintf(stderr, "fp3 run: %s engine: %s\n", engine_name,
            fp3_engine_error(e));
    fprintf(stderr, "FAIL: the %s engine failed\n", engine_name);
    goto out;
  }
  fp3_trace_note(&a->trace, "run", st.cycles);
  /* the results of the last integrations are the values left at the end */
  uint32_t done = st.steps_done < steps ? st.steps_done : steps;
  for (int w = 0; w < 2; w++) fp3_track_advance(&c.t, w, done + 1);
  if (c.oom) {
    fprintf(stderr, "fp3 run: out of memory\n");
    goto out;
  }

  double cyc_first = (double)c.cyc_first + 1.0;
  double cyc_per = c.endis >= 2 ? (double)(c.cyc_last - c.cyc_first) /
                                      (double)(c.endis - 1)
                                : NAN;
  int ok = st.error == FP3_ERR_NONE && done == steps && c.mismatches == 0;
  char flags[96];
  fp3_flags_text(st.flags, flags, sizeof flags);
  double fin_v = NAN, fin_s = NAN;
  if (done > 0) exact_at(&c, done, &fin_v, &fin_s);
  float gv = 0, gs = 0;
  if (done > 0) golden_at(&c, done, &gv, &gs);

  if (json) {
    printf("{\"engine\": ");
    fp3_json_string(stdout, engine_name);
    printf(", \"program\": ");
    fp3_json_string(stdout, program);
    printf(", \"words\": %zu", img.n);
    printf(", \"steps\": %" PRIu32 ", \"steps_done\": %" PRIu32, steps,
           st.steps_done);
    printf(", \"error\": \"%s\", \"fault_pc\": %" PRIu32, fp3_error_name(st.error),
           st.fault_pc);
    printf(", \"cycles\": %" PRIu64 ", \"issued\": %" PRIu64
           ", \"stalls\": %" PRIu64,
           st.cycles, st.issued, st.stalls);
    printf(", \"cycles_first_step\": ");
    if (c.endis >= 1) printf("%.9g", cyc_first); else printf("null");
    printf(", \"cycles_per_step\": ");
    if (c.endis >= 2) printf("%.9g", cyc_per); else printf("null");
    printf(", \"paper_cycles_first_step\": %d, \"paper_cycles_per_step\": %d",
           PAPER_FIRST, PAPER_LATER);
    printf(", \"golden_mismatches\": %" PRIu64, c.mismatches);
    if (c.mismatches)
      printf(", \"first_mismatch\": {\"integration\": %" PRIu32
             ", \"result\": \"%s\", \"got\": \"0x%08" PRIX32
             "\", \"want\": \"0x%08" PRIX32 "\", \"ulp\": %" PRId64 "}",
             c.first_k, c.first_which == OV ? "v" : "s", c.first_got,
             c.first_want, fp3_ulp_distance(c.first_got, c.first_want));
    else
      printf(", \"first_mismatch\": null");
    printf(", \"flags\": \"%s\", \"flags_bits\": %" PRIu32, flags, st.flags);
    printf(", \"round\": \"%s\", \"ftz\": %s", fpenv_round_name(mode),
           mode.ftz ? "true" : "false");
    printf(", \"params\": {\"T\": ");
    fp3_json_float(stdout, p.T);
    fp3_json_member_float(stdout, "C", p.C);
    fp3_json_member_float(stdout, "m", p.m);
    fp3_json_member_float(stdout, "minv", minv);
    fp3_json_member_float(stdout, "h", p.h);
    fp3_json_member_float(stdout, "v0", p.v0);
    fp3_json_member_float(stdout, "s0", p.s0);
    printf("}, \"results\": [{\"v\": ");
    fp3_json_float(stdout, fpref_float(c.last[OV]));
    fp3_json_member_float(stdout, "s", fpref_float(c.last[OS]));
    fp3_json_member_float(stdout, "v_golden", gv);
    fp3_json_member_float(stdout, "s_golden", gs);
    fp3_json_member_double(stdout, "v_exact", fin_v);
    fp3_json_member_double(stdout, "s_exact", fin_s);
    fp3_json_member_double(stdout, "v_max_abs_err", c.max_abs[OV]);
    fp3_json_member_double(stdout, "s_max_abs_err", c.max_abs[OS]);
    printf("}], \"integrator\": ");
    fp3_json_string(stdout, integ->name);
    fp3_json_member_double(stdout, "h_over_tau", fp3_h_over_tau(&p));
    printf(", \"stability_bound\": %.9g", integ->bound);
    printf(", \"diverged_from\": ");
    if (c.div.detected) printf("%" PRIu32, c.div.began); else printf("null");
    printf(", \"nonfinite_from\": ");
    if (c.div.nonfinite) printf("%" PRIu32, c.div.nonfinite); else printf("null");
    printf(", \"pass\": %s}\n", ok ? "true" : "false");
  } else {
    printf("FP3 run: engine %s, program %s (%zu words), %" PRIu32
           " integrations\n",
           engine_name, program, img.n, steps);
    printf("scene: T = %.9g N, C = %.9g kg/s, m = %.9g kg (1/m = %.9g), "
           "h = %.9g s, v0 = %.9g m/s, s0 = %.9g m\n",
           (double)p.T, (double)p.C, (double)p.m, (double)minv, (double)p.h,
           (double)p.v0, (double)p.s0);
    if (p.C > 0)
      printf("       tau = m/C = %.6g s, terminal velocity T/C = %.6g m/s\n",
             (double)p.m / (double)p.C, (double)p.T / (double)p.C);
    if (done > 0) {
      printf("\n%10s  %10s  %15s %15s  %15s %15s\n", "step", "t [s]",
             "v [m/s]", "v exact", "s [m]", "s exact");
      for (uint32_t k = 1; k <= done && k <= TABLE_ROWS; k++)
        print_row(&c, k, c.row[OV][k - 1], c.row[OS][k - 1]);
      if (done > TABLE_ROWS + 1) printf("%10s\n", "...");
      if (done > TABLE_ROWS) print_row(&c, done, c.last[OV], c.last[OS]);
      printf("\n");
    }
    printf("golden model: %" PRIu64 " mismatches in %" PRIu32
           " integrations (v and s, bit for bit)\n",
           c.mismatches, done);
    if (c.mismatches)
      printf("  first at integration %" PRIu32 ": %s = 0x%08" PRIX32
             " (%.9g), golden 0x%08" PRIX32 " (%.9g), %" PRId64
             " ulp; worst %" PRId64 " ulp\n",
             c.first_k, c.first_which == OV ? "v" : "s", c.first_got,
             (double)fpref_float(c.first_got), c.first_want,
             (double)fpref_float(c.first_want),
             fp3_ulp_distance(c.first_got, c.first_want), c.max_ulp);
    if (c.endis >= 1) {
      printf("cycles: first integration %.0f (paper %d)", cyc_first,
             PAPER_FIRST);
      if (c.endis >= 2)
        printf(", later %.2f per integration (paper %d)", cyc_per,
               PAPER_LATER);
      printf("\n");
    }
    printf("        total %" PRIu64 " cycles, %" PRIu64 " issued, %" PRIu64
           " stalls\n",
           st.cycles, st.issued, st.stalls);
    printf("flags: %s\n", flags);
    if (done > 0) {
      printf("error vs exact solution:  final abs      final rel      "
             "max abs        max rel\n");
      for (int w = 0; w < 2; w++)
        printf("  %s %*s %14.6g %14.6g %14.6g %14.6g\n", w == OV ? "v" : "s",
               20, "", c.final_abs[w], c.final_rel[w], c.max_abs[w],
               c.max_rel[w]);
      printf("  (integrator %s: %s)\n", integ->name, integ->desc);
    }
    if (c.div.detected)
      printf("DIVERGED: |v - T/C| grows from integration %" PRIu32
             " on and reached %.6g at integration %" PRIu32
             " (twice its start, h/tau = %.6g, bound %.6g)\n",
             c.div.began, c.div.detected_dist, c.div.detected,
             fp3_h_over_tau(&p), integ->bound);
    if (c.div.nonfinite)
      printf("DIVERGED: v or s not finite from integration %" PRIu32
             " on (flags: %s)\n",
             c.div.nonfinite, flags);
    if (st.error != FP3_ERR_NONE)
      printf("run error: %s at pc %" PRIu32 ": %s\n", fp3_error_name(st.error),
             st.fault_pc,
             fp3_engine_error(e)[0] ? fp3_engine_error(e) : fp3_error_text(st.error));
    if (ok)
      printf("PASS: %" PRIu32 " integrations on %s bit-exact with the golden "
             "model\n",
             steps, engine_name);
    else if (st.error != FP3_ERR_NONE)
      printf("FAIL: run error %s after %" PRIu32 " of %" PRIu32
             " integrations\n",
             fp3_error_name(st.error), st.steps_done, steps);
    else if (done != steps)
      printf("FAIL: the run ended after %" PRIu32 " of %" PRIu32
             " integrations\n",
             done, steps);
    else
      printf("FAIL: %" PRIu64 " golden mismatches, first at integration %" PRIu32
             "\n",
             c.mismatches, c.first_k);
  }
  if (ok && strict && (c.div.detected || c.div.nonfinite)) {
    fprintf(stderr, "fp3 run: --strict: the integration diverged\n");
    ok = 0;
  }
  rc = ok ? 0 : EXIT_FAIL;
out:
  free(c.gv);
  free(c.gs);
  fp3_engine_free(e);
  return rc;
}

int fp3_cmd_run(int argc, char **argv) {
  if (fp3_args_have_model(argc, argv)) return fp3_cmd_run_model(argc, argv);
  fp3_run_args a;
  int r = fp3_parse_run(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_run(&a) : fp3_args_exit(r, usage_run);
}
