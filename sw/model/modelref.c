/*
 * modelref.c -- GSL reference of a model (modelref.h).
 */
#include "modelref.h"

#include <stdio.h>
#include <stdlib.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

typedef struct sysdata {
  const fp3_model *m;
  const double *in;
  double *val; /* scratch of m->nn doubles */
} sysdata;

/* y' = f(y): the model's equations in double. */
static int rhs(double t, const double y[], double dydt[], void *params) {
  (void)t;
  const sysdata *d = params;
  fp3_model_eval_f_double(d->m, d->in, y, dydt, d->val);
  for (unsigned i = 0; i < d->m->nstate; i++)
    if (dydt[i] != dydt[i] || dydt[i] - dydt[i] != 0.0) return GSL_EBADFUNC;
  return GSL_SUCCESS;
}

int fp3_model_gsl(const fp3_model *m, const double *in, const double *y0, uint32_t steps,
                  fp3_model_ref_cb cb, void *ctx, double *y, char *msg, size_t n) {
  gsl_set_error_handler_off();
  sysdata d = {m, in, malloc((m->nn ? m->nn : 1) * sizeof(double))};
  if (!d.val) {
    snprintf(msg, n, "out of memory");
    return -1;
  }
  /* rk8pd is explicit: no Jacobian */
  gsl_odeiv2_system sys = {rhs, NULL, m->nstate, &d};
  const double h = in[0];
  gsl_odeiv2_driver *drv = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, h,
                                                         FP3_MODEL_GSL_EPS, FP3_MODEL_GSL_EPS);
  if (!drv) {
    free(d.val);
    snprintf(msg, n, "gsl rk8pd: cannot allocate the driver");
    return -1;
  }
  gsl_odeiv2_driver_set_nmax(drv, 0);
  for (unsigned i = 0; i < m->nstate; i++) y[i] = y0[i];
  double t = 0.0;
  int rc = GSL_SUCCESS;
  uint32_t k;
  for (k = 1; k <= steps && rc == GSL_SUCCESS; k++) {
    rc = gsl_odeiv2_driver_apply(drv, &t, (double)k * h, y);
    if (rc == GSL_SUCCESS && cb) cb(ctx, k, y);
  }
  gsl_odeiv2_driver_free(drv);
  free(d.val);
  if (rc != GSL_SUCCESS) {
    snprintf(msg, n, "gsl rk8pd: %s at t = %.9g (step %u)", gsl_strerror(rc), t, k - 1);
    return -1;
  }
  return 0;
}
