/*
 * cpu_ship.c -- the ship's RK4 step on the CPU (cpu_ship.h): Equations
 * (1) of the paper with the operations, operands and order of
 * the ship model's literal rk4se (models/ship.fp3m, fp3_model_step_literal;
 * programs/ship_rk4.s), so that every result is bit-identical to
 * the golden model's (bench_chip checks it) and the timing is of the same
 * 18 multiplies and 12 adds or subtracts per step.
 */
#include "cpu_ship.h"

#include <float.h>

#include "model.h"

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "the CPU reference needs float expressions evaluated in float"
#endif

#ifndef CPU_SHIP_FLAGS
#define CPU_SHIP_FLAGS "(unknown)"
#endif

const char *cpu_ship_flags(void) { return CPU_SHIP_FLAGS; }

/* One RK4 step of one ship: rk4se's operations, in its order. */
static inline void step(float T, float C, float minv, float h, float *vp, float *sp) {
  const float half = FP3_RK4_HALF, two = FP3_RK4_TWO, sixth = FP3_RK4_SIXTH;
  float v = *vp, s = *sp;
  float k1 = h * ((T - C * v) * minv);
  float k2 = h * ((T - C * (v + half * k1)) * minv);
  float k3 = h * ((T - C * (v + half * k2)) * minv);
  float k4 = h * ((T - C * (v + k3)) * minv);
  float sum = ((k1 + two * k2) + two * k3) + k4;
  v = v + sixth * sum;
  s = s + h * v;
  *vp = v;
  *sp = s;
}

void cpu_ship_steps_array(cpu_ships *a, uint32_t steps) {
  float *restrict T = a->T, *restrict C = a->C, *restrict minv = a->minv, *restrict h = a->h,
                  *restrict v = a->v, *restrict s = a->s;
  const size_t n = a->n;
  for (uint32_t k = 0; k < steps; k++)
    for (size_t i = 0; i < n; i++) step(T[i], C[i], minv[i], h[i], &v[i], &s[i]);
}

void cpu_ship_steps_scalar(cpu_ships *a, size_t i, uint32_t steps) {
  float v = a->v[i], s = a->s[i];
  const float T = a->T[i], C = a->C[i], minv = a->minv[i], h = a->h[i];
  for (uint32_t k = 0; k < steps; k++) step(T, C, minv, h, &v, &s);
  a->v[i] = v;
  a->s[i] = s;
}
