/*
 * golden.h -- the golden model of the ship program: RK4 on Bourg's ship,
 * Equations (1) of the paper, in plain C binary32 arithmetic, in exactly
 * the order the program computes it.  The engines must equal it bit for
 * bit after every integration.
 */
#ifndef FP3_GOLDEN_H
#define FP3_GOLDEN_H

#include <stddef.h>

/* Scene parameters of one ship (binary32, SI units). */
typedef struct fp3_ship_params {
  float T;  /* thrust [N]              */
  float C;  /* drag coefficient [kg/s] */
  float m;  /* mass [kg]               */
  float h;  /* time step [s]           */
  float v0; /* initial velocity [m/s]  */
  float s0; /* initial displacement [m]*/
} fp3_ship_params;

/* State of the golden integration. */
typedef struct fp3_ship_state {
  float T, C, minv, h; /* minv = 1.0f / m */
  float v, s;
} fp3_ship_state;

/* The constants the program loads (`li`). */
#define FP3_GOLDEN_HALF  0.5f
#define FP3_GOLDEN_TWO   2.0f
#define FP3_GOLDEN_SIXTH 0.16666667f

/* The default scene: a 10 t patrol boat, 50 kN thrust, C = 5000 kg/s:
 * terminal velocity 10 m/s, time constant 2 s, h = 1/60 s. */
void fp3_ship_default(fp3_ship_params *p);

/* 0 if the parameters are usable, else -1 and a message naming the
 * parameter (m <= 0, h <= 0, C < 0, any non-finite value). */
int fp3_ship_validate(const fp3_ship_params *p, char *msg, size_t n);

/* minv as the host computes it: 1.0f / m, correctly rounded binary32. */
float fp3_ship_minv(float m);

/* Start a golden run (v = v0, s = s0). */
void fp3_golden_init(fp3_ship_state *st, const fp3_ship_params *p);

/* One integration: Equations (1), then s = s + h*v. */
void fp3_golden_step(fp3_ship_state *st);

#endif /* FP3_GOLDEN_H */
