/*
 * modelref.h -- the double-precision references of a model (model.h):
 * the model's equations as a gsl_odeiv2_system integrated by GSL's rk8pd
 * (Prince-Dormand 8(9)) with step control at absolute and relative
 * tolerance 1e-12, and its `exact` lines where the file gives them.
 *
 * The references solve the model's mathematics, not its binary32
 * arithmetic: numbers are read in double (strtod), params and initial
 * values are the binary32 values the processor gets, converted exactly to
 * double.  Their difference from an FP3 run is the run's error.
 */
#ifndef FP3_MODELREF_H
#define FP3_MODELREF_H

#include <stdint.h>

#include "model.h"

/* The GSL tolerance of fp3_model_gsl (absolute and relative). */
#define FP3_MODEL_GSL_EPS 1e-12

/* Called with the reference state after fixed time k h (k = 1, 2, ...). */
typedef void (*fp3_model_ref_cb)(void *ctx, uint32_t k, const double *y);

/*
 * Integrate m from y0 (nstate values) with params in[] (in[0] = h) over
 * `steps` intervals of length h, with rk8pd at FP3_MODEL_GSL_EPS
 * (gsl_odeiv2_driver_apply to each t = k h, so the driver's own step is
 * free of the output grid).  cb (may be NULL) sees each k; y gets the
 * state at t = steps h.  Returns 0, or -1 with a message (a GSL failure,
 * e.g. a non-finite derivative: "gsl rk8pd: ... at t = 1.25").
 */
int fp3_model_gsl(const fp3_model *m, const double *in, const double *y0, uint32_t steps,
                  fp3_model_ref_cb cb, void *ctx, double *y, char *msg, size_t n);

#endif /* FP3_MODELREF_H */
