/*
 * gslref.c -- GSL gsl_odeiv2 peers of the integrators (see gslref.h).
 */
#include "gslref.h"

#include <stdio.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

typedef struct ship_dp {
  double T, C, m;
} ship_dp;

/* y = (v, s): y' = ((T - C v)/m, v) */
static int ship_rhs(double t, const double y[], double dydt[], void *params) {
  (void)t;
  const ship_dp *q = params;
  dydt[0] = (q->T - q->C * y[0]) / q->m;
  dydt[1] = y[0];
  return GSL_SUCCESS;
}

/* The Jacobian (needed by implicit steppers only; given for completeness). */
static int ship_jac(double t, const double y[], double *dfdy, double dfdt[],
                    void *params) {
  (void)t;
  (void)y;
  const ship_dp *q = params;
  dfdy[0] = -q->C / q->m;
  dfdy[1] = 0.0;
  dfdy[2] = 1.0;
  dfdy[3] = 0.0;
  dfdt[0] = 0.0;
  dfdt[1] = 0.0;
  return GSL_SUCCESS;
}

static const gsl_odeiv2_step_type *stepper(const char *name) {
  if (strcmp(name, "rk4") == 0) return gsl_odeiv2_step_rk4;
  if (strcmp(name, "rkf45") == 0) return gsl_odeiv2_step_rkf45;
  if (strcmp(name, "rk8pd") == 0) return gsl_odeiv2_step_rk8pd;
  return NULL;
}

int fp3_gsl_known(const char *name) { return stepper(name) != NULL; }

int fp3_gsl_fixed(const char *name, const fp3_ship_params *p, double h,
                  uint32_t n, fp3_gsl_cb cb, void *ctx, double *v, double *s) {
  const gsl_odeiv2_step_type *type = stepper(name);
  if (!type) return -1;
  gsl_set_error_handler_off();
  ship_dp q = {p->T, p->C, p->m};
  gsl_odeiv2_system sys = {ship_rhs, ship_jac, 2, &q};
  /* the stepper alone: no step-size control, every step of size h */
  gsl_odeiv2_step *st = gsl_odeiv2_step_alloc(type, 2);
  if (!st) return -1;
  double t = 0.0, y[2] = {p->v0, p->s0}, yerr[2];
  int rc = GSL_SUCCESS;
  for (uint32_t k = 1; k <= n && rc == GSL_SUCCESS; k++) {
    rc = gsl_odeiv2_step_apply(st, t, h, y, yerr, NULL, NULL, &sys);
    t = (double)k * h;
    if (rc == GSL_SUCCESS && cb) cb(ctx, k, y[0], y[1]);
  }
  gsl_odeiv2_step_free(st);
  if (rc != GSL_SUCCESS) {
    fprintf(stderr, "gsl %s: fixed step failed: %s\n", name, gsl_strerror(rc));
    return -1;
  }
  *v = y[0];
  *s = y[1];
  return 0;
}

int fp3_gsl_adaptive(const char *name, const fp3_ship_params *p, double t1,
                     double eps, double *v, double *s, unsigned long *nsteps) {
  const gsl_odeiv2_step_type *type = stepper(name);
  if (!type) return -1;
  gsl_set_error_handler_off();
  ship_dp q = {p->T, p->C, p->m};
  gsl_odeiv2_system sys = {ship_rhs, ship_jac, 2, &q};
  gsl_odeiv2_driver *d =
      gsl_odeiv2_driver_alloc_y_new(&sys, type, 1e-3 * t1, eps, eps);
  if (!d) return -1;
  gsl_odeiv2_driver_set_nmax(d, 0); /* no limit */
  double t = 0.0, y[2] = {p->v0, p->s0};
  int rc = gsl_odeiv2_driver_apply(d, &t, t1, y);
  if (nsteps) *nsteps = d->n;
  gsl_odeiv2_driver_free(d);
  if (rc != GSL_SUCCESS) {
    fprintf(stderr, "gsl %s: adaptive integration failed: %s\n", name,
            gsl_strerror(rc));
    return -1;
  }
  *v = y[0];
  *s = y[1];
  return 0;
}
