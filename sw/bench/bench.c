/*
 * bench.c -- integrators on the engines and in their golden models:
 * bit-exact runs, error against the exact solution, stability bounds, and
 * `fp3 bench` (see bench.h).
 *
 * The work-precision sweep measures cost without running long programs on
 * the RTL: the pipeline's timing does not depend on the data, so one short
 * RTL run of each program gives its exact cycles for the first and every
 * later integration (checked periodic), and the cost of n integrations is
 * first + (n - 1) * later.  The errors come from the golden model, which
 * the RTL and the ISS equal bit for bit (checked here on short runs, and
 * on long runs: 10^5 integrations on the RTL, 10^7 on the ISS).
 */
#include "bench.h"

#include <errno.h>
#include <float.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "analytic.h"
#include "asm.h"
#include "fpref.h"
#include "gslref.h"
#include "objects.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2

/* The paper's clock period on the XC2V6000-4 [ns]: cost in time where our
 * own Fmax is not measured. */
#define PAPER_CLOCK_NS 8.888

/* ---- one program on one engine, checked against its golden model ------- */

enum { RV = 0, RS = 1 };

typedef struct irun_ctx {
  const fp3_integrator *ig;
  fp3_istate g[2]; /* golden state advanced for v and for s separately */
  fp3_track t;     /* v and s after every integration */
  fp3_irun *r;
  uint64_t first_cyc, prev_cyc, per0;
  uint32_t endis;
} irun_ctx;

static void irun_final(void *ctx, int which, uint32_t k, uint32_t bits) {
  irun_ctx *c = ctx;
  c->ig->step(&c->g[which]);
  float want = which == RV ? c->g[which].v : c->g[which].s;
  if (bits != fpref_bits(want)) {
    if (!c->r->mismatches) c->r->first_mismatch = k;
    c->r->mismatches++;
  }
  float got = fpref_float(bits);
  if (which == RV) {
    fp3_diverge_update(&c->r->div, k, got, 0.0f);
    c->r->v = got;
  } else {
    if (!isfinite(got) && (!c->r->div.nonfinite || k < c->r->div.nonfinite))
      c->r->div.nonfinite = k;
    c->r->s = got;
  }
}

static void irun_write(void *ctx, unsigned reg, uint32_t value,
                       uint32_t integration) {
  fp3_track_write(&((irun_ctx *)ctx)->t, reg, value, integration);
}

static void irun_endi(void *ctx, uint32_t integration, uint64_t cycle) {
  irun_ctx *c = ctx;
  if (integration == 1) c->first_cyc = cycle;
  if (integration == 2) c->per0 = cycle - c->prev_cyc;
  if (integration > 2 && cycle - c->prev_cyc != c->per0) c->r->periodic = 0;
  c->prev_cyc = cycle;
  c->endis = integration;
}

int fp3_irun_program(fp3_engine *e, const fp3_integrator *ig,
                     const fp3_image *img, const fp3_ship_params *p,
                     uint32_t steps, fp3_irun *r, char *msg, size_t n) {
  memset(r, 0, sizeof *r);
  r->periodic = 1;
  r->cycles_per = NAN;
  if (img->out_reg[FP3_OUT_V] < 0 || img->out_reg[FP3_OUT_S] < 0) {
    snprintf(msg, n, "the program binds no '.out v' or '.out s'");
    return -1;
  }
  irun_ctx c;
  memset(&c, 0, sizeof c);
  c.ig = ig;
  c.r = r;
  c.t.last = steps;
  c.t.final = irun_final;
  c.t.ctx = &c;
  ig->init(&c.g[RV], p);
  ig->init(&c.g[RS], p);
  fp3_diverge_init(&r->div, p);
  float inval[FP3_IN_COUNT];
  fp3_in_values(p, inval);
  int erc = fp3_engine_load(e, img->words, img->n);
  for (int i = 0; i < FP3_IN_COUNT && erc == 0; i++)
    if (img->in_reg[i] >= 0)
      erc = fp3_engine_write_reg(e, (unsigned)img->in_reg[i],
                                 fpref_bits(inval[i]));
  c.t.reg[RV] = img->out_reg[FP3_OUT_V];
  c.t.reg[RS] = img->out_reg[FP3_OUT_S];
  for (int w = 0; w < 2 && erc == 0; w++) {
    c.t.next_k[w] = 1;
    erc = fp3_engine_read_reg(e, (unsigned)c.t.reg[w], &c.t.cur[w]);
  }
  if (erc == 0) {
    fp3_observer obs = {.ctx = &c, .on_write = irun_write, .on_endi = irun_endi};
    erc = fp3_engine_run(e, steps, &obs, &r->st);
  }
  if (erc != 0) {
    snprintf(msg, n, "%s engine: %s", e->ops->name, fp3_engine_error(e));
    return -1;
  }
  uint32_t done = r->st.steps_done < steps ? r->st.steps_done : steps;
  for (int w = 0; w < 2; w++) fp3_track_advance(&c.t, w, done + 1);
  r->steps_done = done;
  if (c.endis >= 1) r->cycles_first = (double)c.first_cyc + 1.0;
  if (c.endis >= 2)
    r->cycles_per =
        (double)(c.prev_cyc - c.first_cyc) / (double)(c.endis - 1);
  return 0;
}

/* ---- golden runs ---------------------------------------------------------- */

void fp3_golden_errors(const fp3_integrator *ig, const fp3_ship_params *p,
                       uint32_t n, fp3_gerr *e) {
  memset(e, 0, sizeof *e);
  fp3_istate st;
  ig->init(&st, p);
  fp3_diverge_init(&e->div, p);
  double vmax = 0.0, smax = 0.0;
  for (uint32_t k = 1; k <= n; k++) {
    float v0 = st.v, s0 = st.s;
    ig->step(&st);
    if (st.v != v0) e->v_last_change = k;
    if (st.s == s0 && st.v != 0.0f) e->s_unmoved++;
    double ve, se;
    fp3_ship_exact(p->T, p->C, p->m, p->v0, p->s0, (double)k * (double)p->h,
                   &ve, &se);
    double dv = fabs((double)st.v - ve), ds = fabs((double)st.s - se);
    if (!(dv <= e->v_max_abs)) e->v_max_abs = dv;
    if (!(ds <= e->s_max_abs)) e->s_max_abs = ds;
    if (fabs(ve) > vmax) vmax = fabs(ve);
    if (fabs(se) > smax) smax = fabs(se);
    e->v_final_abs = dv;
    e->s_final_abs = ds;
    e->v_final_rel = ve != 0.0 ? dv / fabs(ve) : dv;
    e->s_final_rel = se != 0.0 ? ds / fabs(se) : ds;
    fp3_diverge_update(&e->div, k, st.v, st.s);
  }
  e->v = st.v;
  e->s = st.s;
  double ev = vmax > 0.0 ? e->v_max_abs / vmax : e->v_max_abs;
  double es = smax > 0.0 ? e->s_max_abs / smax : e->s_max_abs;
  e->err_norm = ev > es || isnan(ev) ? ev : es;
}

int fp3_golden_diverges(const fp3_integrator *ig, const fp3_ship_params *p,
                        uint32_t n, uint32_t *began) {
  fp3_istate st;
  fp3_diverge d;
  ig->init(&st, p);
  fp3_diverge_init(&d, p);
  for (uint32_t k = 1; k <= n; k++) {
    ig->step(&st);
    if (fp3_diverge_update(&d, k, st.v, st.s)) break;
  }
  if (began) *began = d.detected ? d.began : d.nonfinite;
  return d.detected || d.nonfinite;
}

static int diverges_at(const fp3_integrator *ig, const fp3_ship_params *p,
                       uint32_t n, double x) {
  fp3_ship_params q = *p;
  q.h = (float)(x * (double)p->m / (double)p->C);
  return fp3_golden_diverges(ig, &q, n, NULL);
}

double fp3_measure_bound(const fp3_integrator *ig, const fp3_ship_params *p,
                         uint32_t n, double lo, double hi) {
  if (!(p->C > 0.0f) || diverges_at(ig, p, n, lo) || !diverges_at(ig, p, n, hi))
    return NAN;
  while (hi - lo > 1e-6 * hi) {
    double mid = 0.5 * (lo + hi);
    if (diverges_at(ig, p, n, mid))
      hi = mid;
    else
      lo = mid;
  }
  return lo;
}

/* ---- timing ------------------------------------------------------------------ */

static double now_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec * 1e9 + (double)ts.tv_nsec;
}

static int cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static double median(double *x, int n) {
  qsort(x, (size_t)n, sizeof *x, cmp_double);
  return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

/* Keeps the compiler from dropping a timed loop. */
static volatile float sink_f;
static volatile double sink_d;

/* CPU ns per golden integration: median of `reps` runs of n steps. */
static double time_golden(const fp3_integrator *ig, const fp3_ship_params *p,
                          uint32_t n, int reps) {
  double t[64];
  if (reps > 64) reps = 64;
  for (int r = 0; r < reps; r++) {
    fp3_istate st;
    ig->init(&st, p);
    double t0 = now_ns();
    for (uint32_t k = 0; k < n; k++) ig->step(&st);
    t[r] = (now_ns() - t0) / (double)n;
    sink_f = st.v + st.s;
  }
  return median(t, reps);
}

static double time_gsl(const char *name, const fp3_ship_params *p, uint32_t n,
                       int reps) {
  double t[64];
  if (reps > 64) reps = 64;
  for (int r = 0; r < reps; r++) {
    double v, s;
    double t0 = now_ns();
    if (fp3_gsl_fixed(name, p, (double)p->h, n, NULL, NULL, &v, &s)) return NAN;
    t[r] = (now_ns() - t0) / (double)n;
    sink_d = v + s;
  }
  return median(t, reps);
}

/* ---- GSL errors at a fixed step ------------------------------------------ */

typedef struct gsl_err_ctx {
  const fp3_ship_params *p;
  double vmax, smax, v_max_abs, s_max_abs, v_fin, s_fin, v_rel, s_rel;
} gsl_err_ctx;

static void gsl_err_cb(void *ctx, uint32_t k, double v, double s) {
  gsl_err_ctx *g = ctx;
  const fp3_ship_params *p = g->p;
  double ve, se;
  fp3_ship_exact(p->T, p->C, p->m, p->v0, p->s0, (double)k * (double)p->h, &ve,
                 &se);
  double dv = fabs(v - ve), ds = fabs(s - se);
  if (!(dv <= g->v_max_abs)) g->v_max_abs = dv;
  if (!(ds <= g->s_max_abs)) g->s_max_abs = ds;
  if (fabs(ve) > g->vmax) g->vmax = fabs(ve);
  if (fabs(se) > g->smax) g->smax = fabs(se);
  g->v_fin = dv;
  g->s_fin = ds;
  g->v_rel = ve != 0.0 ? dv / fabs(ve) : dv;
  g->s_rel = se != 0.0 ? ds / fabs(se) : ds;
}

/* ---- the benchmark behind `fp3 bench` ----------------------------------------- */

/* The assembled program of each integrator, found from the working
 * directory or next to the executable (build/fp3 -> programs/). */
static int load_program(const fp3_integrator *ig, fp3_image *img) {
  char path[4200];
  snprintf(path, sizeof path, "%s", ig->program);
  if (access(path, R_OK) != 0) {
    char exe[4096];
    ssize_t k = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (k > 0) {
      exe[k] = '\0';
      char *slash = strrchr(exe, '/');
      if (slash) {
        *slash = '\0';
        snprintf(path, sizeof path, "%s/../%s", exe, ig->program);
      }
    }
  }
  char *errs = NULL;
  fp3_image_init(img);
  if (fp3_asm_file(path, img, &errs) != 0) {
    fprintf(stderr, "fp3 bench: %s: %s", path, errs ? errs : "assembly failed\n");
    free(errs);
    return -1;
  }
  free(errs);
  return 0;
}

static FILE *open_out(const char *dir, const char *name) {
  char path[4200];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *f = fopen(path, "w");
  if (!f) fprintf(stderr, "fp3 bench: cannot write %s: %s\n", path, strerror(errno));
  return f;
}

static void csv_num(FILE *f, double x) {
  if (isfinite(x))
    fprintf(f, ",%.6e", x);
  else
    fprintf(f, ",NaN");
}

typedef struct cost {
  double first, per; /* RTL cycles */
  double cpu_ns;     /* golden, per step */
} cost;

#define MAX_POINTS 128
#define GSL_STEPPERS 3
static const char *const gsl_names[GSL_STEPPERS] = {"rk4", "rkf45", "rk8pd"};

/* Sweep: CSV rows and the Pareto table. */
static int bench_sweep(const char *dir, const fp3_ship_params *scene,
                       const uint32_t *ns, int npts, double t_end,
                       const cost *costs, const double *gsl_ns) {
  size_t ni;
  const fp3_integrator *ig = fp3_integrators(&ni);
  FILE *f = open_out(dir, "sweep.csv");
  if (!f) return -1;
  const double tau = (double)scene->m / (double)scene->C;
  fprintf(f, "integrator,kind,h_over_tau,h,steps,t_end,cycles_first,"
             "cycles_per_integration,total_cycles,ns_at_paper_clock,"
             "cpu_ns_per_step,cpu_ns_total,v_final_abs,v_final_rel,v_max_abs,"
             "s_final_abs,s_final_rel,s_max_abs,err_norm,diverged\n");
  /* Pareto: best (fewest cycles) per error target */
  static const double targets[] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7};
  enum { NT = sizeof targets / sizeof targets[0] };
  struct {
    double cycles, hot, err;
    uint32_t steps;
    const char *name;
  } best[NT];
  for (int t = 0; t < NT; t++) best[t].name = NULL;
  for (int k = 0; k < npts; k++) {
    fp3_ship_params p = *scene;
    p.h = (float)(t_end / (double)ns[k]);
    double hot = (double)p.h / tau;
    for (size_t i = 0; i < ni; i++) {
      fp3_gerr e;
      fp3_golden_errors(&ig[i], &p, ns[k], &e);
      double total = costs[i].first + (double)(ns[k] - 1) * costs[i].per;
      int div = e.div.detected || e.div.nonfinite;
      fprintf(f, "%s,fp3,%.6e,%.9g,%" PRIu32 ",%.9g", ig[i].name, hot,
              (double)p.h, ns[k], (double)ns[k] * (double)p.h);
      csv_num(f, costs[i].first);
      csv_num(f, costs[i].per);
      csv_num(f, total);
      csv_num(f, total * PAPER_CLOCK_NS);
      csv_num(f, costs[i].cpu_ns);
      csv_num(f, costs[i].cpu_ns * (double)ns[k]);
      csv_num(f, e.v_final_abs);
      csv_num(f, e.v_final_rel);
      csv_num(f, e.v_max_abs);
      csv_num(f, e.s_final_abs);
      csv_num(f, e.s_final_rel);
      csv_num(f, e.s_max_abs);
      csv_num(f, e.err_norm);
      fprintf(f, ",%d\n", div);
      for (int t = 0; t < NT && !div; t++)
        if (e.err_norm <= targets[t] &&
            (!best[t].name || total < best[t].cycles)) {
          best[t].cycles = total;
          best[t].hot = hot;
          best[t].err = e.err_norm;
          best[t].steps = ns[k];
          best[t].name = ig[i].name;
        }
    }
    for (int g = 0; g < GSL_STEPPERS; g++) {
      gsl_err_ctx gc;
      memset(&gc, 0, sizeof gc);
      gc.p = &p;
      double v, s;
      if (fp3_gsl_fixed(gsl_names[g], &p, (double)p.h, ns[k], gsl_err_cb, &gc,
                        &v, &s))
        continue;
      double ev = gc.vmax > 0 ? gc.v_max_abs / gc.vmax : gc.v_max_abs;
      double es = gc.smax > 0 ? gc.s_max_abs / gc.smax : gc.s_max_abs;
      fprintf(f, "gsl_%s,gsl,%.6e,%.9g,%" PRIu32 ",%.9g,,,,", gsl_names[g],
              hot, (double)p.h, ns[k], (double)ns[k] * (double)p.h);
      csv_num(f, gsl_ns[g]);
      csv_num(f, gsl_ns[g] * (double)ns[k]);
      csv_num(f, gc.v_fin);
      csv_num(f, gc.v_rel);
      csv_num(f, gc.v_max_abs);
      csv_num(f, gc.s_fin);
      csv_num(f, gc.s_rel);
      csv_num(f, gc.s_max_abs);
      csv_num(f, ev > es ? ev : es);
      fprintf(f, ",%d\n", !isfinite(v) || !isfinite(s));
    }
  }
  fclose(f);
  FILE *m = open_out(dir, "pareto.md");
  if (!m) return -1;
  fprintf(m, "| error at most | cheapest integrator | h/τ | steps to %.3g s "
             "| RTL cycles | error reached |\n| --- | --- | --- | --- | --- | --- |\n",
          t_end);
  printf("\nPareto front (error = max over the run of |v - v(t)|/max|v| and "
         "the same for s):\n");
  for (int t = 0; t < NT; t++) {
    if (!best[t].name) {
      fprintf(m, "| %.0e | none in the sweep | | | | |\n", targets[t]);
      printf("  <= %.0e: none in the sweep\n", targets[t]);
      continue;
    }
    fprintf(m, "| %.0e | %s | %.3g | %" PRIu32 " | %.0f | %.2e |\n",
            targets[t], best[t].name, best[t].hot, best[t].steps,
            best[t].cycles, best[t].err);
    printf("  <= %.0e: %-8s h/tau %-9.3g %7" PRIu32 " steps %10.0f cycles "
           "(error %.2e)\n",
           targets[t], best[t].name, best[t].hot, best[t].steps, best[t].cycles,
           best[t].err);
  }
  fclose(m);
  return 0;
}

/* Stability: theory, bisection on the golden model, RTL at 0.98/1.02. */
static int bench_stability(const char *dir, const fp3_ship_params *scene,
                           fp3_engine *rtl, const fp3_image *imgs) {
  size_t ni;
  const fp3_integrator *ig = fp3_integrators(&ni);
  FILE *f = open_out(dir, "stability.csv");
  FILE *m = open_out(dir, "stability.md");
  if (!f || !m) {
    if (f) fclose(f);
    if (m) fclose(m);
    return -1;
  }
  int bad = 0;
  fprintf(f, "integrator,bound_theory,bound_measured,rtl_0.98_diverged,"
             "rtl_1.02_diverged,rtl_1.02_began,bit_exact\n");
  fprintf(m, "| integrator | bound h/τ (theory) | measured (binary32, 20000 "
             "steps) | RTL at 0.98 bound | RTL at 1.02 bound |\n"
             "| --- | --- | --- | --- | --- |\n");
  printf("\nStability on the ship (h/tau = h C/m):\n");
  for (size_t i = 0; i < ni; i++) {
    double meas = fp3_measure_bound(&ig[i], scene, 20000, 0.5 * ig[i].bound,
                                    1.5 * ig[i].bound);
    int dv[2] = {0, 0};
    uint32_t began = 0;
    uint64_t mism = 0;
    for (int j = 0; j < 2; j++) {
      fp3_ship_params p = *scene;
      double x = (j ? 1.02 : 0.98) * ig[i].bound;
      p.h = (float)(x * (double)p.m / (double)p.C);
      fp3_irun r;
      char msg[300];
      if (fp3_irun_program(rtl, &ig[i], &imgs[i], &p, 3000, &r, msg, sizeof msg)) {
        fprintf(stderr, "fp3 bench: %s\n", msg);
        bad = 1;
        continue;
      }
      mism += r.mismatches;
      dv[j] = r.div.detected || r.div.nonfinite;
      if (j) began = r.div.detected ? r.div.began : r.div.nonfinite;
    }
    if (mism) bad = 1;
    fprintf(f, "%s,%.6f,%.6f,%d,%d,%" PRIu32 ",%d\n", ig[i].name, ig[i].bound,
            meas, dv[0], dv[1], began, mism == 0);
    fprintf(m, "| %s | %.6f | %.6f | %s | %s (from step %" PRIu32 ") |\n",
            ig[i].name, ig[i].bound, meas, dv[0] ? "diverges" : "stable",
            dv[1] ? "diverges" : "stable", began);
    printf("  %-8s bound %.6f, measured %.6f; RTL 3000 steps at 0.98: %s, at "
           "1.02: %s (from step %" PRIu32 ")%s\n",
           ig[i].name, ig[i].bound, meas, dv[0] ? "DIVERGES" : "stable",
           dv[1] ? "diverges" : "STABLE", began,
           mism ? "  NOT BIT-EXACT" : "");
  }
  fclose(f);
  fclose(m);
  return bad;
}

/* Long runs: stagnation of the plain programs, the compensated one.
 * Engine runs are checked bit for bit against the golden model after every
 * integration; "golden" rows run the golden model alone (equal to the
 * engines bit for bit, as those rows and tests/test_integrators show). */
static int bench_long(const char *dir, fp3_engine *iss, fp3_engine *rtl,
                      const fp3_image *imgs, uint32_t nlong, uint32_t nrtl) {
  static const struct {
    int scene;        /* 0 default, 1 s0 = 2^24 m */
    const char *name; /* integrator */
    int engine;       /* 0 golden, 1 ISS, 2 RTL */
  } rows[] = {
      {0, "rk4", 1},       {0, "rk4vscomp", 1}, {0, "rk4vs", 0},
      {0, "rk4comp", 0},   {0, "rk4", 2},       {0, "rk4vscomp", 2},
      {1, "rk4", 0},       {1, "rk4vs", 0},     {1, "rk4comp", 0},
      {1, "rk4vscomp", 0},
  };
  static const char *const labels[] = {"default (s0 = 0)", "far out (s0 = 2^24 m)"};
  static const char *const engines[] = {"golden", "iss", "rtl"};
  FILE *f = open_out(dir, "longrun.csv");
  FILE *m = open_out(dir, "longrun.md");
  if (!f || !m) {
    if (f) fclose(f);
    if (m) fclose(m);
    return -1;
  }
  int bad = 0;
  size_t nint;
  const fp3_integrator *all = fp3_integrators(&nint);
  fprintf(f, "scene,integrator,engine,steps,bit_exact,v,v_exact,v_rel_err,"
             "s,s_exact,s_rel_err,v_last_change,s_unmoved_steps,"
             "cycles_per_integration\n");
  fprintf(m, "| scene | integrator | run | v rel. error | s rel. error | v "
             "last changed at step | steps that left s unchanged | cycles "
             "per integration |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  printf("\nLong runs (binary32 stagnation; T = 50 kN, C = 5000 kg/s, m = 10 t, "
         "h = 1/60 s):\n");
  for (size_t i = 0; i < sizeof rows / sizeof rows[0]; i++) {
    const fp3_integrator *ig = fp3_integrator_find(rows[i].name);
    size_t idx = (size_t)(ig - all);
    fp3_ship_params p;
    fp3_ship_default(&p);
    if (rows[i].scene == 1) p.s0 = 16777216.0f;
    uint32_t n = rows[i].engine == 2 ? nrtl : nlong;
    if (n == 0) continue;
    double t0 = now_ns();
    fp3_gerr g;
    fp3_golden_errors(ig, &p, n, &g);
    float v = g.v, s = g.s;
    int exact = 1;
    double cyc = NAN;
    if (rows[i].engine) {
      fp3_engine *e = rows[i].engine == 1 ? iss : rtl;
      fp3_irun r;
      char msg[300];
      if (fp3_irun_program(e, ig, &imgs[idx], &p, n, &r, msg, sizeof msg)) {
        fprintf(stderr, "fp3 bench: %s\n", msg);
        bad = 1;
        continue;
      }
      exact = r.mismatches == 0 && r.steps_done == n &&
              fpref_bits(r.v) == fpref_bits(g.v) &&
              fpref_bits(r.s) == fpref_bits(g.s);
      v = r.v;
      s = r.s;
      if (rows[i].engine == 2) cyc = r.cycles_per;
    }
    if (!exact) bad = 1;
    double secs = (now_ns() - t0) * 1e-9;
    double ve, se;
    fp3_ship_exact(p.T, p.C, p.m, p.v0, p.s0, (double)n * (double)p.h, &ve, &se);
    double vr = fabs((double)v - ve) / fabs(ve);
    double sr = fabs((double)s - se) / fabs(se);
    const char *en = engines[rows[i].engine];
    fprintf(f, "%s,%s,%s,%" PRIu32 ",%d,%.9g,%.17g,%.6e,%.9g,%.17g,%.6e,%" PRIu32
               ",%" PRIu64,
            labels[rows[i].scene], ig->name, en, n, exact, (double)v, ve, vr,
            (double)s, se, sr, g.v_last_change, g.s_unmoved);
    csv_num(f, cyc);
    fputc('\n', f);
    fprintf(m, "| %s | %s | %s, %" PRIu32 " steps%s | %.2e | %.2e | %" PRIu32
               " | %" PRIu64 " |",
            labels[rows[i].scene], ig->name, en, n,
            rows[i].engine ? (exact ? ", bit-exact" : ", NOT BIT-EXACT") : "",
            vr, sr, g.v_last_change, g.s_unmoved);
    if (isfinite(cyc))
      fprintf(m, " %.0f |\n", cyc);
    else
      fprintf(m, " |\n");
    printf("  %-22s %-8s %-6s %9" PRIu32 " steps (%.1f s): v %.9g (exact "
           "%.9g, rel %.2e), s %.9g (exact %.9g, rel %.2e); v last changed at "
           "%" PRIu32 ", s unchanged in %" PRIu64 " steps%s\n",
           labels[rows[i].scene], ig->name, en, n, secs, (double)v, ve, vr,
           (double)s, se, sr, g.v_last_change, g.s_unmoved,
           exact ? "" : "  NOT BIT-EXACT");
    fflush(stdout);
  }
  fclose(f);
  fclose(m);
  return bad;
}

int fp3_bench_run(const fp3_bench_opts *o) {
  const char *dir = o->dir, *only = o->only;
  const double from = o->from, to = o->to, t_end = o->t_end, single = o->single,
               perdec = o->per_decade;
  const uint32_t nlong = o->long_steps, nrtl = o->rtl_long_steps, reps = o->repeats;
  setvbuf(stdout, NULL, _IOLBF, 0); /* progress through a pipe (tee) */
  if (from > to) {
    fprintf(stderr, "fp3 bench: --from %g > --to %g: empty sweep\n", from, to);
    return EXIT_USAGE;
  }
  fp3_ship_params scene;
  fp3_ship_default(&scene);
  const double tau = (double)scene.m / (double)scene.C;

  /* the step counts of the sweep */
  uint32_t ns[MAX_POINTS];
  int npts = 0;
  if (single > 0.0) {
    double h = (double)(float)(single * tau);
    double steps = t_end / h;
    if (!(steps >= 1.0) || steps > (double)UINT32_MAX ||
        fabs(steps - nearbyint(steps)) > 1e-6 * steps) {
      fprintf(stderr,
              "fp3 bench: end time %g s is not a whole number of steps h = "
              "%g tau = %.9g s (%.9g steps)\n",
              t_end, single, h, steps);
      return EXIT_USAGE;
    }
    ns[npts++] = (uint32_t)nearbyint(steps);
  } else {
    double dec = log10(to / from);
    int pts = (int)ceil(dec * perdec - 1e-9) + 1;
    if (pts > MAX_POINTS) pts = MAX_POINTS;
    for (int k = 0; k < pts; k++) {
      double x = pts > 1 ? from * pow(to / from, (double)k / (pts - 1)) : from;
      double steps = nearbyint(t_end / (x * tau));
      if (steps < 1.0) steps = 1.0;
      if (steps > (double)UINT32_MAX) {
        fprintf(stderr, "fp3 bench: h/tau %g needs more than 2^32 steps to %g s\n",
                x, t_end);
        return EXIT_USAGE;
      }
      uint32_t n = (uint32_t)steps;
      if (npts == 0 || ns[npts - 1] != n) ns[npts++] = n;
    }
  }
  if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
    fprintf(stderr, "fp3 bench: cannot create %s: %s\n", dir, strerror(errno));
    return EXIT_FAIL;
  }

  size_t ni;
  const fp3_integrator *ig = fp3_integrators(&ni);
  fp3_image *imgs = calloc(ni, sizeof *imgs);
  cost *costs = calloc(ni, sizeof *costs);
  if (!imgs || !costs) {
    free(imgs);
    free(costs);
    return EXIT_FAIL;
  }
  int rc = 0;
  fp3_engine *rtl = fp3_engine_rtl_new(NULL);
  fp3_engine *iss = fp3_engine_iss_new();
  if (!rtl || !iss || fp3_engine_error(rtl)[0]) {
    fprintf(stderr, "fp3 bench: cannot create the engines\n");
    rc = EXIT_FAIL;
    goto out;
  }
  /* a run longer than a few seconds (the long runs) shows its progress */
  fp3_engine_show_progress(rtl, "fp3 bench");
  fp3_engine_show_progress(iss, "fp3 bench");
  /* cost of each program: one short RTL run, bit-exact on RTL and ISS */
  printf("Integrators (RTL cycles, ADD_LATENCY %u, MUL_LATENCY %u; CPU ns per "
         "golden step, median of %" PRIu32 "):\n",
         rtl->config.add_latency, rtl->config.mul_latency, reps);
  for (size_t i = 0; i < ni; i++) {
    if (load_program(&ig[i], &imgs[i])) {
      rc = EXIT_FAIL;
      goto out;
    }
    fp3_irun r, q;
    char msg[300];
    if (fp3_irun_program(rtl, &ig[i], &imgs[i], &scene, 64, &r, msg, sizeof msg) ||
        fp3_irun_program(iss, &ig[i], &imgs[i], &scene, 64, &q, msg, sizeof msg)) {
      fprintf(stderr, "fp3 bench: %s\n", msg);
      rc = EXIT_FAIL;
      goto out;
    }
    if (r.mismatches || q.mismatches || !r.periodic || r.steps_done != 64) {
      fprintf(stderr, "fp3 bench: %s: RTL %" PRIu64 ", ISS %" PRIu64
              " golden mismatches, periodic %d\n",
              ig[i].name, r.mismatches, q.mismatches, r.periodic);
      rc = EXIT_FAIL;
    }
    costs[i].first = r.cycles_first;
    costs[i].per = r.cycles_per;
    time_golden(&ig[i], &scene, 20000, 1); /* warm-up */
    costs[i].cpu_ns = time_golden(&ig[i], &scene, 200000, (int)reps);
    printf("  %-8s %3.0f cycles first, %3.0f per integration (%.0f ns at the "
           "paper's 8.888 ns clock); golden %.2f ns/step; %s\n",
           ig[i].name, costs[i].first, costs[i].per, costs[i].per * PAPER_CLOCK_NS,
           costs[i].cpu_ns, ig[i].desc);
  }
  double gsl_ns[GSL_STEPPERS];
  for (int g = 0; g < GSL_STEPPERS; g++) {
    gsl_ns[g] = time_gsl(gsl_names[g], &scene, 200000, (int)reps);
    printf("  gsl_%-5s (double) %.2f ns/step\n", gsl_names[g], gsl_ns[g]);
  }
  {
    /* rk8pd at tolerance 1e-12 against the exact solution */
    double v, s, ve, se;
    unsigned long nst = 0;
    if (fp3_gsl_adaptive("rk8pd", &scene, t_end, 1e-12, &v, &s, &nst) == 0) {
      fp3_ship_exact(scene.T, scene.C, scene.m, scene.v0, scene.s0, t_end, &ve,
                     &se);
      printf("  exact solution cross-check: GSL rk8pd, tolerance 1e-12, %lu "
             "steps to %g s: |dv| = %.2e m/s, |ds| = %.2e m\n",
             nst, t_end, fabs(v - ve), fabs(s - se));
      if (!(fabs(v - ve) <= 1e-9 * fabs(ve) && fabs(s - se) <= 1e-9 * fabs(se))) {
        fprintf(stderr, "fp3 bench: rk8pd disagrees with the exact solution\n");
        rc = EXIT_FAIL;
      }
    }
  }
  if (!only || strcmp(only, "sweep") == 0) {
    printf("\nSweep: h/tau %g .. %g, %d step counts, end time %g s -> %s/sweep.csv\n",
           single > 0 ? single : from, single > 0 ? single : to, npts, t_end, dir);
    if (bench_sweep(dir, &scene, ns, npts, t_end, costs, gsl_ns)) rc = EXIT_FAIL;
  }
  if (!only || strcmp(only, "stability") == 0) {
    int b = bench_stability(dir, &scene, rtl, imgs);
    if (b) rc = EXIT_FAIL;
  }
  if (!only || strcmp(only, "long") == 0) {
    int b = bench_long(dir, iss, rtl, imgs, nlong, nrtl);
    if (b) rc = EXIT_FAIL;
  }
out:
  if (rtl) fp3_engine_free(rtl);
  if (iss) fp3_engine_free(iss);
  free(imgs);
  free(costs);
  return rc;
}


FILE *fp3_bench_csv_open(const char *path, char *tmp, size_t n) {
  snprintf(tmp, n, "%s.tmp", path);
  FILE *f = fopen(tmp, "w");
  if (!f) perror(tmp);
  return f;
}

int fp3_bench_csv_close(FILE *f, const char *tmp, const char *path) {
  if (fclose(f) || rename(tmp, path)) {
    perror(path);
    remove(tmp);
    return -1;
  }
  return 0;
}
