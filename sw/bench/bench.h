/*
 * bench.h -- running the integrators (sw/ref/integrators.h) on an engine and
 * in their golden models, measuring their error against the exact
 * solution (sw/ref/analytic.h), their stability bound, and the `fp3 bench`
 * subcommand (work-precision sweep, stability, long runs).
 */
#ifndef FP3_BENCH_H
#define FP3_BENCH_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "engine.h"
#include "image.h"
#include "integrators.h"
#include "objects.h"

/* Result of one integrator program run on an engine. */
typedef struct fp3_irun {
  fp3_status st;           /* engine status and counters                  */
  uint32_t steps_done;     /* integrations whose v and s were compared    */
  uint64_t mismatches;     /* v or s != golden, bit for bit               */
  uint32_t first_mismatch; /* integration of the first one (0: none)      */
  double cycles_first;     /* cycles of integration 1 (RTL: exact)        */
  double cycles_per;       /* cycles per later integration (mean; NAN < 2)*/
  int periodic;            /* 1 if every later integration cost the same  */
  float v, s;              /* engine results after the last integration   */
  fp3_diverge div;         /* divergence watch on the engine's v and s    */
} fp3_irun;

/*
 * Load image `img` (the integrator's program) into engine e, write the
 * scene p into its .in registers, run `steps` integrations and compare v
 * and s after every integration with the golden model of `ig`, bit for
 * bit, while the machine runs freely (observer).  Cycle counts come from
 * the endi events.  Returns 0 if the run could be made (mismatches and
 * engine errors are in *r), -1 with a message in msg[0..n) if not.
 */
int fp3_irun_program(fp3_engine *e, const fp3_integrator *ig,
                     const fp3_image *img, const fp3_ship_params *p,
                     uint32_t steps, fp3_irun *r, char *msg, size_t n);

/* Error of a golden (binary32) integration against the exact solution. */
typedef struct fp3_gerr {
  float v, s;                 /* after the last integration                 */
  double v_final_abs, v_final_rel, v_max_abs;   /* [m/s], 1, [m/s]          */
  double s_final_abs, s_final_rel, s_max_abs;   /* [m], 1, [m]              */
  /* max_k |v_k - v(t_k)| / max_k |v(t_k)| and the same for s; the larger */
  double err_norm;
  fp3_diverge div;            /* divergence watch                           */
  uint32_t v_last_change;     /* last integration that changed v            */
  uint64_t s_unmoved;         /* integrations that left s unchanged although
                                 its increment was not zero (stagnation)    */
} fp3_gerr;

/* n integrations of the golden model of ig on scene p; the exact solution
 * at t = k h (h the binary32 step, in double) after every one.  Nothing
 * fails: non-finite results show as NaN/inf errors and in e->div. */
void fp3_golden_errors(const fp3_integrator *ig, const fp3_ship_params *p,
                       uint32_t n, fp3_gerr *e);

/* 1 if n golden integrations on scene p diverge (see fp3_diverge), with
 * the integration where the divergence began in *began (may be NULL). */
int fp3_golden_diverges(const fp3_integrator *ig, const fp3_ship_params *p,
                        uint32_t n, uint32_t *began);

/* The largest h/tau (scene p with h = x m / C, C > 0) for which n golden
 * integrations do not diverge, by bisection between lo and hi (diverging
 * at hi, not at lo) to a relative width of 1e-6.  Returns NAN when the
 * bracket is not one. */
double fp3_measure_bound(const fp3_integrator *ig, const fp3_ship_params *p,
                         uint32_t n, double lo, double hi);

/* What `fp3 bench` measures (fp3 bench --help says the same per option). */
typedef struct fp3_bench_opts {
  const char *dir;         /* output directory, created if missing */
  const char *only;        /* "sweep", "stability", "long" or NULL for all */
  double from, to;         /* sweep bounds in h/tau, 0 < from <= to */
  double t_end;            /* end time of the sweep's runs [s] */
  double single;           /* > 0: one point h/tau = single instead of a sweep */
  double per_decade;       /* sweep points per decade of h/tau */
  uint32_t long_steps;     /* ISS integrations of the long runs */
  uint32_t rtl_long_steps; /* RTL integrations of the long runs */
  uint32_t repeats;        /* timing repeats, the median taken (1..64) */
} fp3_bench_opts;

/* The integrator benchmark on the ship's default scene: the sweep
 * (DIR/sweep.csv, DIR/pareto.md), the stability bounds (DIR/stability.*)
 * and the long runs (DIR/longrun.*), with progress on stdout.  Returns 0
 * when every engine run was bit-exact with its golden model, 1 when a
 * check failed or a file could not be written, 2 when the options
 * describe no valid sweep (from > to, an end time that is not a whole
 * number of steps). */
int fp3_bench_run(const fp3_bench_opts *o);

/* A CSV file written whole under a temporary name, PATH.tmp (in tmp, n
 * bytes), renamed to PATH by fp3_bench_csv_close: a failed run leaves no
 * half-written PATH.  NULL (perror) if it cannot be opened. */
FILE *fp3_bench_csv_open(const char *path, char *tmp, size_t n);
/* Close and rename; 0, or -1 (perror, the temporary removed). */
int fp3_bench_csv_close(FILE *f, const char *tmp, const char *path);

#endif /* FP3_BENCH_H */
