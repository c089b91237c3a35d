/*
 * gslref.h -- software peers of the FP3 integrators: the ship ODE
 *   v' = (T - C v) / m,  s' = v
 * integrated in double precision by the GNU Scientific Library's
 * gsl_odeiv2 steppers (rk4, rkf45, rk8pd), at a fixed step or adaptively.
 */
#ifndef FP3_GSLREF_H
#define FP3_GSLREF_H

#include <stdint.h>

#include "golden.h"

/* Called after fixed step k (1-based) with the state at t = k h. */
typedef void (*fp3_gsl_cb)(void *ctx, uint32_t k, double v, double s);

/* Names of the steppers offered: "rk4", "rkf45", "rk8pd".  Returns 1 if
 * `name` is one of them. */
int fp3_gsl_known(const char *name);

/*
 * n fixed steps of size h [s] with stepper `name` from (p->v0, p->s0);
 * T, C, m of p are converted to double (not rounded to binary32 beyond
 * what p already holds).  cb (may be NULL) sees every step.  *v, *s: the
 * state at t = n h.  Returns 0, or -1 for an unknown stepper or a GSL
 * failure (message on stderr).  GSL: gsl_odeiv2_step_apply, no step
 * control.
 */
int fp3_gsl_fixed(const char *name, const fp3_ship_params *p, double h,
                  uint32_t n, fp3_gsl_cb cb, void *ctx, double *v, double *s);

/*
 * Adaptive integration from 0 to t [s] with stepper `name`, absolute and
 * relative tolerance eps (gsl_odeiv2_driver_apply, initial step 1e-3 t).
 * Returns 0 or -1 as above; *nsteps (may be NULL) gets the steps taken.
 */
int fp3_gsl_adaptive(const char *name, const fp3_ship_params *p, double t,
                     double eps, double *v, double *s, unsigned long *nsteps);

#endif /* FP3_GSLREF_H */
