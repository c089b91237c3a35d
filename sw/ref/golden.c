/*
 * golden.c -- RK4 on the ship in binary32, Equations (1) of the paper.
 *
 * Compiled with -ffp-contract=off (no fused multiply-add) and never with
 * -ffast-math; every variable is a float and every expression has one
 * operation, so each line is exactly one binary32 operation rounded to
 * nearest even, as the program's instructions are.
 */
#include "golden.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "the golden model needs float expressions evaluated in float"
#endif

void fp3_ship_default(fp3_ship_params *p) {
  p->T = 50000.0f;
  p->C = 5000.0f;
  p->m = 10000.0f;
  p->h = 1.0f / 60.0f; /* 0.016666668f */
  p->v0 = 0.0f;
  p->s0 = 0.0f;
}

int fp3_ship_validate(const fp3_ship_params *p, char *msg, size_t n) {
  const struct {
    const char *name;
    float v;
  } all[] = {{"T", p->T}, {"C", p->C},   {"m", p->m},
             {"h", p->h}, {"v0", p->v0}, {"s0", p->s0}};
  for (size_t i = 0; i < sizeof all / sizeof all[0]; i++)
    if (!isfinite(all[i].v)) {
      snprintf(msg, n, "parameter %s = %g is not a finite number", all[i].name,
               (double)all[i].v);
      return -1;
    }
  if (!(p->m > 0.0f)) {
    snprintf(msg, n, "parameter m = %g: the mass must be > 0", (double)p->m);
    return -1;
  }
  if (!(p->h > 0.0f)) {
    snprintf(msg, n, "parameter h = %g: the time step must be > 0",
             (double)p->h);
    return -1;
  }
  if (p->C < 0.0f) {
    snprintf(msg, n, "parameter C = %g: the drag coefficient must be >= 0",
             (double)p->C);
    return -1;
  }
  return 0;
}

float fp3_ship_minv(float m) { return 1.0f / m; }

void fp3_golden_init(fp3_ship_state *st, const fp3_ship_params *p) {
  st->T = p->T;
  st->C = p->C;
  st->minv = fp3_ship_minv(p->m);
  st->h = p->h;
  st->v = p->v0;
  st->s = p->s0;
}

void fp3_golden_step(fp3_ship_state *st) {
  const float T = st->T, C = st->C, minv = st->minv, h = st->h;
  const float half = FP3_GOLDEN_HALF, two = FP3_GOLDEN_TWO,
              sixth = FP3_GOLDEN_SIXTH;
  float v = st->v, s = st->s;
  float cv, F, a, hk, vt, k1, k2, k3, k4, t2, t3, sum, dv, hv;

  /* k1 = h f(v0),          f(v) = (T - C v) / m */
  cv = C * v;
  F = T - cv;
  a = F * minv;
  k1 = h * a;
  /* k2 = h f(v0 + k1/2) */
  hk = half * k1;
  vt = v + hk;
  cv = C * vt;
  F = T - cv;
  a = F * minv;
  k2 = h * a;
  /* k3 = h f(v0 + k2/2) */
  hk = half * k2;
  vt = v + hk;
  cv = C * vt;
  F = T - cv;
  a = F * minv;
  k3 = h * a;
  /* k4 = h f(v0 + k3) */
  vt = v + k3;
  cv = C * vt;
  F = T - cv;
  a = F * minv;
  k4 = h * a;
  /* v1 = v0 + (k1 + 2 k2 + 2 k3 + k4) / 6 */
  t2 = two * k2;
  t3 = two * k3;
  sum = k1 + t2;
  sum = sum + t3;
  sum = sum + k4;
  dv = sixth * sum;
  v = v + dv;
  /* s = s + h v1 */
  hv = h * v;
  s = s + hv;

  st->v = v;
  st->s = s;
}
