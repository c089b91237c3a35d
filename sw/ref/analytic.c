/*
 * analytic.c -- the exact solution of the ship ODE (see analytic.h).
 */
#include "analytic.h"

#include <math.h>

/* (1 - e^-x) / x, x >= 0 */
static double phi1(double x) {
  if (x == 0.0) return 1.0;
  return -expm1(-x) / x;
}

/* (x - 1 + e^-x) / x^2, x >= 0.  Below 0.5 the direct form cancels, so
 * sum the series  sum_k (-x)^k / (k+2)!  instead. */
static double phi2(double x) {
  if (x < 0.5) {
    double term = 0.5, sum = 0.0; /* k = 0: 1/2! */
    for (int k = 0; k < 40 && term != 0.0; k++) {
      sum += term;
      term *= -x / (double)(k + 3);
    }
    return sum;
  }
  return (x + expm1(-x)) / (x * x);
}

void fp3_ship_exact(double T, double C, double m, double v0, double s0,
                    double t, double *v, double *s) {
  double x = C * t / m;
  double p1 = phi1(x);
  *v = v0 + (T - C * v0) * t / m * p1;
  *s = s0 + v0 * t * p1 + T * t * t / m * phi2(x);
}
