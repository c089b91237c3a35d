/*
 * objects.h -- scenes of ships in the paper's five columns, read and
 * generated; every command reads them as scenes of models/ship.fp3m
 * (mscene.h fp3_mscene_read_any, fp3_mscene_from_ships).
 *
 * Scene file: text, one object per line, `#` starts a comment:
 *
 *   # a harbour                       (comment)
 *   h 0.0166666675                    (time step [s], once, before objects)
 *   # T [N]   C [kg/s]   m [kg]   v0 [m/s]   s0 [m]
 *   50000     5000       10000    0          0
 *   0         300        5000     12.5       100
 *
 * Numbers are read as binary32 (strtof).  Every object must be physical:
 * m > 0, C >= 0, all values finite (fp3_ship_validate); h > 0.
 */
#ifndef FP3_OBJECTS_H
#define FP3_OBJECTS_H

#include <stddef.h>
#include <stdint.h>

#include "image.h"

/* One ship of a scene (binary32, SI units): Bourg's ship, the paper's
 * Equations (1), as the five columns give it. */
typedef struct fp3_ship_params {
  float T;  /* thrust [N]              */
  float C;  /* drag coefficient [kg/s] */
  float m;  /* mass [kg]               */
  float h;  /* time step [s]           */
  float v0; /* initial velocity [m/s]  */
  float s0; /* initial displacement [m]*/
} fp3_ship_params;

/* The default ship: a 10 t patrol boat, 50 kN thrust, C = 5000 kg/s:
 * terminal velocity 10 m/s, time constant 2 s, h = 1/60 s (the defaults
 * of models/ship.fp3m). */
void fp3_ship_default(fp3_ship_params *p);

/* 0 if the parameters are usable, else -1 and a message naming the
 * parameter (m <= 0, h <= 0, C < 0, any non-finite value). */
int fp3_ship_validate(const fp3_ship_params *p, char *msg, size_t n);

/* minv as the host computes it: 1.0f / m, correctly rounded binary32. */
float fp3_ship_minv(float m);

/* A scene: n objects, all with the same h (objs[i].h). */
typedef struct fp3_scene {
  fp3_ship_params *objs; /* malloc'd */
  size_t n;
} fp3_scene;

/* Read a scene file: one `h STEP` line (the time step, finite and > 0)
 * before the objects, then one object per line, `T C m v0 s0`; `#` starts
 * a comment.  A file without the `h` line, or with two, is refused: the
 * step is never guessed.  h: unused (the step comes from the file; kept so
 * that callers need not change).  Returns 0, or -1 with "FILE:LINE:
 * reason" in msg (nothing allocated). */
int fp3_scene_read(const char *path, float h, fp3_scene *sc, char *msg, size_t n);

/* The `h STEP` line of a scene file (ship or model scene): p is the text
 * after the `h`, nobj the objects read so far, *h_line the line of an
 * earlier `h` (0: none; set to lineno).  Returns 0 with the step in *h, or
 * -1 with "FILE:LINE: reason": after an object, a second `h`, not one
 * number, not finite and > 0. */
int fp3_scene_h_line(char *p, const char *path, int lineno, size_t nobj, int *h_line,
                     float *h, char *msg, size_t n);

/* A reproducible random scene of n ships (seeded xorshift): masses
 * log-uniform in [1, 1e6] kg, time constants m/C in [0.5, 50] s (one ship
 * in eight without drag), terminal velocities in [-5, 30] m/s, v0 in
 * [-10, 30] m/s, s0 in [-100, 100] m.  Returns 0 or -1 (out of memory). */
int fp3_scene_generate(uint64_t seed, size_t n, float h, fp3_scene *sc);

/* A reproducible harbour of n ships (seeded xorshift), the scene of the
 * sleeping benchmark (docs/skipping.md "Sleeping objects"): masses log-uniform in
 * [1e4, 3.2e6] kg, time constants m/C in [2, 20] s, terminal velocities
 * T/C in [2, 12] m/s, s0 in [-2000, 2000] m; 60 % moored (T = 0, v0 = 0),
 * 35 % cruising (v0 = T/C in binary32), 5 % accelerating from rest.
 * Returns 0 or -1 (out of memory). */
int fp3_scene_harbour(uint64_t seed, size_t n, float h, fp3_scene *sc);

void fp3_scene_free(fp3_scene *sc);

/* The scene generators' xorshift64 (Marsaglia 2003, shifts 13, 7, 17):
 * advances *s (never 0) and returns it. */
uint64_t fp3_scene_xorshift(uint64_t *s);

#endif /* FP3_OBJECTS_H */
