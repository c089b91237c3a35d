/*
 * integrators.h -- the ship integrators: one assembly program each
 * (programs/ship_<name>.s) and its golden model in plain C binary32, in
 * exactly the program's operations, so every engine equals it bit for bit
 * after every integration.
 *
 * The model is Bourg's ship, v' = f(v) = (T - C v) / m, s' = v, with
 * f evaluated as the paper does: F = T - C*v, a = F*minv (minv = 1.0f/m).
 * tau = m / C is the time constant; every explicit method here is stable
 * on it only for h/tau below a bound (the region of absolute stability of
 * its velocity update on the real axis):
 *
 *   name       velocity update               position update       h/tau
 *   euler      v += h f(v)                   s += h v_old          2
 *   symeuler   v += h f(v)                   s += h v_new          2
 *   verlet     v += h/2 (a + f(v + h a))     s += h v + h^2/2 a    2
 *              a = f(v) carried between steps (velocity Verlet with an
 *              Euler-predicted velocity for the velocity-dependent force)
 *   rk2        midpoint: vm = v + h/2 f(v),  s += h vm             2
 *              v += h f(vm)
 *   rk4        classic RK4 (the paper)       s += h v1 (1st order) 2.7853
 *   rk4vs      classic RK4 on (v, s)         s += h/6 (v + 2 vt2   2.7853
 *                                              + 2 vt3 + vt4)
 *   rk4comp    rk4 with Kahan-compensated    Kahan-compensated     2.7853
 *              v += dv                       s += h v1
 *   rk4vscomp  rk4vs with Kahan-compensated v and s updates          2.7853
 *
 * Bounds: |R(-x)| <= 1 with R the method's stability polynomial; 1 - x
 * (Euler), 1 - x + x^2/2 (Heun, midpoint), 1 - x + x^2/2 - x^3/6 + x^4/24
 * (RK4, real root of |R| = 1 at x = 2.785293563...; Hairer & Wanner,
 * Solving ODEs II, Sec. IV.2).
 */
#ifndef FP3_INTEGRATORS_H
#define FP3_INTEGRATORS_H

#include <stddef.h>
#include <stdint.h>

#include "golden.h"

/* State of one golden integration.  T, C, minv, h, v, s as in golden.h;
 * the rest is used by some integrators only (zero otherwise). */
typedef struct fp3_istate {
  float T, C, minv, h; /* scene; minv = 1.0f / m                         */
  float v, s;          /* results after the latest integration           */
  float a;             /* verlet: f(v) carried to the next integration   */
  float hh, hh2;       /* verlet, rk2: 0.5*h; verlet: 0.5*(h*h)           */
  float h6;            /* rk4vs, rk4vscomp: h * 0.16666667               */
  float cv, cs;        /* rk4comp, rk4vscomp: Kahan compensations       */
} fp3_istate;

/* One integrator: its program and golden model. */
typedef struct fp3_integrator {
  const char *name;    /* --integrator NAME                               */
  const char *program; /* path relative to the repository root            */
  const char *desc;    /* one line                                        */
  /* golden model: start (v = v0, s = s0, the program's prologue values)
   * and one integration */
  void (*init)(fp3_istate *st, const fp3_ship_params *p);
  void (*step)(fp3_istate *st);
  double bound;  /* stability bound on h/tau (theory, see above)          */
  int order_v;   /* global order of the velocity                          */
  int order_s;   /* global order of the displacement                      */
} fp3_integrator;

/* The table, in the order shown to users; *n gets the count. */
const fp3_integrator *fp3_integrators(size_t *n);

/* By name, or NULL for an unknown name. */
const fp3_integrator *fp3_integrator_find(const char *name);

/* Space-separated names, for messages ("euler symeuler ..."). */
const char *fp3_integrator_names(void);

/* h/tau = h C / m of a scene (0 when C = 0: no stiffness, no bound). */
double fp3_h_over_tau(const fp3_ship_params *p);

/*
 * Run-time divergence detection on a sequence of results.
 *
 * With drag (C > 0) every stable integrator makes the distance of v from
 * the terminal velocity T/C shrink (|R| <= 1); a distance above twice its
 * start (or above 16 ulp of T/C, whichever is larger) is a divergence.
 * The step where it began is the first of the uninterrupted run of
 * growing distances that led there.  A non-finite v or s is always
 * reported, with its first integration, with or without drag.
 */
typedef struct fp3_diverge {
  double vinf;          /* T/C, NAN when C = 0                             */
  double limit;         /* distance that counts as diverged                */
  double prev;          /* distance after the previous integration         */
  uint32_t run_start;   /* first integration of the current growing run    */
  uint32_t began;       /* 0, or where the detected divergence began       */
  uint32_t detected;    /* 0, or the integration that crossed the limit    */
  double detected_dist; /* |v - T/C| there                                 */
  uint32_t nonfinite;   /* 0, or the first integration with v or s not finite */
} fp3_diverge;

/* Start watching a run of scene p. */
void fp3_diverge_init(fp3_diverge *d, const fp3_ship_params *p);

/* v and s after integration k (k = 1, 2, ... in order).  Returns 1 once a
 * divergence or a non-finite value has been seen, else 0. */
int fp3_diverge_update(fp3_diverge *d, uint32_t k, float v, float s);

#endif /* FP3_INTEGRATORS_H */
