/*
 * analytic.h -- the exact solution of the ship ODE, in double.
 *
 *   v' = (T - C v) / m,  s' = v,  v(0) = v0, s(0) = s0
 *
 * With x = C t / m:
 *   v(t) = v0 + (T - C v0) t / m * phi1(x)
 *   s(t) = s0 + v0 t phi1(x) + T t^2 / m * phi2(x)
 * where phi1(x) = (1 - e^-x) / x and phi2(x) = (x - 1 + e^-x) / x^2, the
 * same as v_inf + (v0 - v_inf) e^(-t/tau) etc. (DESIGN.md) but without
 * cancellation for small C and exact for C = 0 (phi1 = 1, phi2 = 1/2).
 */
#ifndef FP3_ANALYTIC_H
#define FP3_ANALYTIC_H

/* v(t), s(t) for the given parameters (C >= 0, m > 0, t >= 0). */
void fp3_ship_exact(double T, double C, double m, double v0, double s0,
                    double t, double *v, double *s);

#endif /* FP3_ANALYTIC_H */
