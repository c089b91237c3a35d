/*
 * integrators.c -- golden models of the ship integrators (integrators.h).
 *
 * Compiled with -ffp-contract=off and never with -ffast-math: every
 * variable is a float and every expression one binary32 operation, the
 * same operation on the same operands as one instruction of
 * programs/ship_<name>.s.  The programs may issue independent operations
 * in another order, and may compute a value one integration later when
 * no result depends on it (rk4comp), which changes no value.
 */
#include "integrators.h"

#include <float.h>
#include <math.h>
#include <string.h>

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "the golden models need float expressions evaluated in float"
#endif

/* f(v) as the paper computes it: (T - C v) * (1/m). */
static float accel(const fp3_istate *st, float v) {
  float cv = st->C * v;
  float F = st->T - cv;
  return F * st->minv;
}

static void init_common(fp3_istate *st, const fp3_ship_params *p) {
  memset(st, 0, sizeof *st);
  st->T = p->T;
  st->C = p->C;
  st->minv = fp3_ship_minv(p->m);
  st->h = p->h;
  st->v = p->v0;
  st->s = p->s0;
}

/* ---- explicit Euler ------------------------------------------------------ */

static void euler_step(fp3_istate *st) {
  float a = accel(st, st->v);
  float hv = st->h * st->v; /* old v */
  float dv = st->h * a;
  st->s = st->s + hv;
  st->v = st->v + dv;
}

/* ---- semi-implicit (symplectic) Euler ------------------------------------ */

static void symeuler_step(fp3_istate *st) {
  float a = accel(st, st->v);
  float dv = st->h * a;
  st->v = st->v + dv;
  float hv = st->h * st->v; /* new v */
  st->s = st->s + hv;
}

/* ---- velocity Verlet ----------------------------------------------------- */

static void verlet_init(fp3_istate *st, const fp3_ship_params *p) {
  init_common(st, p);
  const float half = 0.5f;
  float hsq = st->h * st->h;
  st->hh = half * st->h;
  st->hh2 = half * hsq;
  st->a = accel(st, st->v);
}

static void verlet_step(fp3_istate *st) {
  /* s += h v + h^2/2 a */
  float hv = st->h * st->v;
  float q = st->hh2 * st->a;
  float ds = hv + q;
  st->s = st->s + ds;
  /* predicted velocity, its acceleration, the trapezoid */
  float ea = st->h * st->a;
  float vp = st->v + ea;
  float ap = accel(st, vp);
  float sa = st->a + ap;
  float dv = st->hh * sa;
  st->v = st->v + dv;
  /* the next integration's acceleration */
  st->a = accel(st, st->v);
}

/* ---- midpoint RK2 on (v, s) ---------------------------------------------- */

static void rk2_init(fp3_istate *st, const fp3_ship_params *p) {
  init_common(st, p);
  const float half = 0.5f;
  st->hh = half * st->h;
}

static void rk2_step(fp3_istate *st) {
  float a = accel(st, st->v);
  float hk = st->hh * a;
  float vm = st->v + hk;
  float hv = st->h * vm;
  st->s = st->s + hv;
  float a2 = accel(st, vm);
  float k2 = st->h * a2;
  st->v = st->v + k2;
}

/* ---- RK4, the paper's program (sw/ref/golden.c) ------------------------------ */

static void rk4_step(fp3_istate *st) {
  fp3_ship_state g = {st->T, st->C, st->minv, st->h, st->v, st->s};
  fp3_golden_step(&g);
  st->v = g.v;
  st->s = g.s;
}

/* The four RK4 stages of the velocity: trial velocities vt2..vt4 and
 * dv = 0.16666667 (k1 + 2 k2 + 2 k3 + k4), as in sw/ref/golden.c. */
static float rk4_stages(const fp3_istate *st, float *vt2, float *vt3,
                        float *vt4) {
  const float half = FP3_GOLDEN_HALF, two = FP3_GOLDEN_TWO,
              sixth = FP3_GOLDEN_SIXTH;
  const float v = st->v, h = st->h;
  float a, hk, t2, t3, sum;
  a = accel(st, v);
  float k1 = h * a;
  hk = half * k1;
  *vt2 = v + hk;
  a = accel(st, *vt2);
  float k2 = h * a;
  hk = half * k2;
  *vt3 = v + hk;
  a = accel(st, *vt3);
  float k3 = h * a;
  *vt4 = v + k3;
  a = accel(st, *vt4);
  float k4 = h * a;
  t2 = two * k2;
  t3 = two * k3;
  sum = k1 + t2;
  sum = sum + t3;
  sum = sum + k4;
  return sixth * sum;
}

/* ---- RK4 on (v, s) -------------------------------------------------------- */

static void rk4vs_init(fp3_istate *st, const fp3_ship_params *p) {
  init_common(st, p);
  const float sixth = FP3_GOLDEN_SIXTH;
  st->h6 = st->h * sixth;
}

static void rk4vs_step(fp3_istate *st) {
  const float two = FP3_GOLDEN_TWO;
  float vt2, vt3, vt4;
  float dv = rk4_stages(st, &vt2, &vt3, &vt4);
  /* s1 = s + h/6 (v + 2 vt2 + 2 vt3 + vt4): the s-stages of RK4 on s' = v */
  float w = vt2 + vt3;
  float w2 = two * w;
  float u = st->v + w2;
  u = u + vt4;
  float ds = st->h6 * u;
  st->s = st->s + ds;
  st->v = st->v + dv;
}

/* ---- RK4 with compensated (Kahan) updates -------------------------------- */

static void rk4comp_step(fp3_istate *st) {
  float vt2, vt3, vt4;
  float dv = rk4_stages(st, &vt2, &vt3, &vt4);
  /* v += dv, compensated: cv holds -(the part of the sum lost so far) */
  float yv = dv - st->cv;
  float tv = st->v + yv;
  float zv = tv - st->v;
  st->cv = zv - yv;
  st->v = tv;
  /* s += h v1, compensated */
  float hv = st->h * st->v;
  float ys = hv - st->cs;
  float ts = st->s + ys;
  float zs = ts - st->s;
  st->cs = zs - ys;
  st->s = ts;
}

/* ---- RK4 on (v, s) with compensated (Kahan) updates ---------------------- */

static void rk4vscomp_step(fp3_istate *st) {
  const float two = FP3_GOLDEN_TWO;
  float vt2, vt3, vt4;
  float dv = rk4_stages(st, &vt2, &vt3, &vt4);
  float w = vt2 + vt3;
  float w2 = two * w;
  float u = st->v + w2;
  u = u + vt4;
  float ds = st->h6 * u;
  /* s += ds, compensated */
  float ys = ds - st->cs;
  float ts = st->s + ys;
  float zs = ts - st->s;
  st->cs = zs - ys;
  st->s = ts;
  /* v += dv, compensated */
  float yv = dv - st->cv;
  float tv = st->v + yv;
  float zv = tv - st->v;
  st->cv = zv - yv;
  st->v = tv;
}

/* ---- the table ------------------------------------------------------------ */

#define RK4_BOUND 2.785293563405282

static const fp3_integrator table[] = {
    {"euler", "programs/ship_euler.s",
     "explicit Euler: v += h f(v), s += h v (old v)", init_common, euler_step,
     2.0, 1, 1},
    {"symeuler", "programs/ship_symeuler.s",
     "semi-implicit (symplectic) Euler: v += h f(v), s += h v (new v)",
     init_common, symeuler_step, 2.0, 1, 1},
    {"verlet", "programs/ship_verlet.s",
     "velocity Verlet: s += h v + h^2/2 a, v += h/2 (a + f(v + h a))",
     verlet_init, verlet_step, 2.0, 2, 2},
    {"rk2", "programs/ship_rk2.s",
     "midpoint RK2 on (v, s): vm = v + h/2 f(v), v += h f(vm), s += h vm",
     rk2_init, rk2_step, 2.0, 2, 2},
    {"rk4", "programs/ship_rk4.s",
     "classic RK4 on v, s += h v1 (the paper's program)", init_common,
     rk4_step, RK4_BOUND, 4, 1},
    {"rk4vs", "programs/ship_rk4vs.s",
     "classic RK4 on (v, s) together", rk4vs_init, rk4vs_step, RK4_BOUND, 4,
     4},
    {"rk4comp", "programs/ship_rk4comp.s",
     "the paper's RK4 with Kahan-compensated v and s updates", init_common,
     rk4comp_step, RK4_BOUND, 4, 1},
    {"rk4vscomp", "programs/ship_rk4vscomp.s",
     "RK4 on (v, s) with Kahan-compensated v and s updates", rk4vs_init,
     rk4vscomp_step, RK4_BOUND, 4, 4},
};

const fp3_integrator *fp3_integrators(size_t *n) {
  *n = sizeof table / sizeof table[0];
  return table;
}

const fp3_integrator *fp3_integrator_find(const char *name) {
  for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
    if (strcmp(table[i].name, name) == 0) return &table[i];
  return NULL;
}

const char *fp3_integrator_names(void) {
  return "euler symeuler verlet rk2 rk4 rk4vs rk4comp rk4vscomp";
}

double fp3_h_over_tau(const fp3_ship_params *p) {
  return (double)p->h * (double)p->C / (double)p->m;
}

/* ---- divergence ------------------------------------------------------------ */

void fp3_diverge_init(fp3_diverge *d, const fp3_ship_params *p) {
  memset(d, 0, sizeof *d);
  if (p->C > 0.0f) {
    d->vinf = (double)p->T / (double)p->C;
    double start = fabs((double)p->v0 - d->vinf);
    double floor16 = 16.0 * (double)FLT_EPSILON * fabs(d->vinf);
    if (!(floor16 > 0.0)) floor16 = (double)FLT_MIN;
    d->limit = 2.0 * (start > floor16 ? start : floor16);
    d->prev = start;
  } else {
    d->vinf = NAN;
  }
  d->run_start = 1;
}

int fp3_diverge_update(fp3_diverge *d, uint32_t k, float v, float s) {
  if (!d->nonfinite && (!isfinite(v) || !isfinite(s))) d->nonfinite = k;
  if (!isnan(d->vinf) && !d->detected) {
    double dist = fabs((double)v - d->vinf);
    if (!(dist > d->prev)) d->run_start = k + 1; /* not growing: restart */
    if (!(dist <= d->limit)) {               /* also NaN */
      d->detected = k;
      d->began = d->run_start <= k ? d->run_start : k;
      d->detected_dist = dist;
    }
    d->prev = dist;
  }
  return d->detected || d->nonfinite;
}
