/*
 * objects.c -- ship scenes: the five-column file, the generated ones, and
 * a ship's host values (objects.h).
 */
#include "objects.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fpenv.h"
#include "fpref.h"
#include "mscene.h"
#include "progress.h"

/* ---- a ship ------------------------------------------------------------------ */

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

/* ---- scene files --------------------------------------------------------- */

/* Next whitespace-separated binary32 number of *p; -1 if none or bad. */
static int next_float(char **p, float *out) {
  char *s = *p;
  while (*s == ' ' || *s == '\t') s++;
  if (*s == '\0') return -1;
  char *end;
  errno = 0;
  *out = strtof(s, &end);
  if (end == s || (*end != '\0' && *end != ' ' && *end != '\t')) return -1;
  *p = end;
  return 0;
}

static int rest_is_blank(const char *s) {
  while (*s == ' ' || *s == '\t') s++;
  return *s == '\0';
}

int fp3_scene_h_line(char *p, const char *path, int lineno, size_t nobj, int *h_line,
                     float *h, char *msg, size_t n) {
  int rc = 0;
  if (nobj > 0) {
    snprintf(msg, n, "%s:%d: 'h' must come before the objects", path, lineno);
    rc = -1;
  } else if (*h_line) {
    snprintf(msg, n, "%s:%d: a second 'h' line (the first is line %d): the time step "
             "comes once", path, lineno, *h_line);
    rc = -1;
  } else if (next_float(&p, h) || !rest_is_blank(p)) {
    snprintf(msg, n, "%s:%d: 'h' wants one number", path, lineno);
    rc = -1;
  } else if (!(*h > 0.0f) || !isfinite(*h)) {
    snprintf(msg, n, "%s:%d: h = %g: the time step must be finite and > 0", path, lineno,
             (double)*h);
    rc = -1;
  }
  *h_line = lineno;
  return rc;
}

int fp3_scene_read(const char *path, float h, fp3_scene *sc, char *msg, size_t n) {
  memset(sc, 0, sizeof *sc);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(msg, n, "%s: %s", path, strerror(errno));
    return -1;
  }
  size_t cap = 0;
  char line[1024];
  int lineno = 0, rc = 0;
  int h_line = 0;       /* the line of the `h STEP` line, 0 before it */
  int first_obj = 0;    /* the line of the first object */
  while (rc == 0 && fgets(line, sizeof line, f)) {
    lineno++;
    size_t len = strlen(line);
    if (len == sizeof line - 1 && line[len - 1] != '\n') {
      snprintf(msg, n, "%s:%d: line too long", path, lineno);
      rc = -1;
      break;
    }
    char *hash = strchr(line, '#');
    if (hash) *hash = '\0';
    line[strcspn(line, "\r\n")] = '\0';
    char *p = line;
    while (*p == ' ' || *p == '\t') p++;
    if (*p == '\0') continue;
    if (p[0] == 'h' && (p[1] == ' ' || p[1] == '\t')) {
      rc = fp3_scene_h_line(p + 1, path, lineno, sc->n, &h_line, &h, msg, n);
      continue;
    }
    float v[5];
    for (int i = 0; i < 5 && rc == 0; i++) {
      if (next_float(&p, &v[i])) {
        snprintf(msg, n, "%s:%d: expected 5 numbers 'T C m v0 s0', %s", path, lineno,
                 i == 0 ? "found none" : "found fewer or a bad one");
        rc = -1;
      }
    }
    if (rc == 0 && !rest_is_blank(p)) {
      snprintf(msg, n, "%s:%d: more than 5 numbers", path, lineno);
      rc = -1;
    }
    if (rc) break;
    fp3_ship_params o = {v[0], v[1], v[2], h, v[3], v[4]};
    char why[200];
    if (fp3_ship_validate(&o, why, sizeof why)) {
      snprintf(msg, n, "%s:%d: %s", path, lineno, why);
      rc = -1;
      break;
    }
    if (sc->n == cap) {
      cap = cap ? 2 * cap : 16;
      fp3_ship_params *g = realloc(sc->objs, cap * sizeof *g);
      if (!g) {
        snprintf(msg, n, "%s: out of memory", path);
        rc = -1;
        break;
      }
      sc->objs = g;
    }
    sc->objs[sc->n++] = o;
    if (!first_obj) first_obj = lineno;
  }
  if (rc == 0 && ferror(f)) {
    snprintf(msg, n, "%s: read error", path);
    rc = -1;
  }
  fclose(f);
  if (rc == 0 && sc->n == 0) {
    snprintf(msg, n, "%s: no objects in the scene", path);
    rc = -1;
  }
  if (rc == 0 && !h_line) {
    snprintf(msg, n, "%s:%d: no 'h STEP' line before the first object: the scene format "
             "wants the time step once, before the objects (e.g. 'h 0.0166666675')",
             path, first_obj);
    rc = -1;
  }
  if (rc == 0) return 0;
  fp3_scene_free(sc);
  return -1;
}

/* ---- generated scenes -------------------------------------------------- */

uint64_t fp3_scene_xorshift(uint64_t *s) {
  *s ^= *s << 13;
  *s ^= *s >> 7;
  *s ^= *s << 17;
  return *s;
}

/* Uniform in [lo, hi]. */
static double uniform(uint64_t *s, double lo, double hi) {
  return lo + (hi - lo) * (double)(fp3_scene_xorshift(s) >> 11) / 9007199254740992.0;
}

/* An empty scene with room for n objects, and the generator state of seed
 * in *s.  Returns 0 or -1 (out of memory). */
static int scene_start(uint64_t seed, size_t n, fp3_scene *sc, uint64_t *s) {
  memset(sc, 0, sizeof *sc);
  sc->objs = calloc(n ? n : 1, sizeof *sc->objs);
  if (!sc->objs) return -1;
  *s = seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
  if (*s == 0) *s = 1;
  return 0;
}

int fp3_scene_generate(uint64_t seed, size_t n, float h, fp3_scene *sc) {
  uint64_t s;
  if (scene_start(seed, n, sc, &s)) return -1;
  for (size_t i = 0; i < n; i++) {
    double m = pow(10.0, uniform(&s, 0.0, 6.0));
    double tau = uniform(&s, 0.5, 50.0);
    double vinf = uniform(&s, -5.0, 30.0);
    double C = (fp3_scene_xorshift(&s) % 8 == 0) ? 0.0 : m / tau;
    double T = C > 0.0 ? vinf * C : m * uniform(&s, -0.5, 0.5);
    fp3_ship_params *o = &sc->objs[i];
    o->T = (float)T;
    o->C = (float)C;
    o->m = (float)m;
    o->h = h;
    o->v0 = (float)uniform(&s, -10.0, 30.0);
    o->s0 = (float)uniform(&s, -100.0, 100.0);
  }
  sc->n = n;
  return 0;
}

int fp3_scene_harbour(uint64_t seed, size_t n, float h, fp3_scene *sc) {
  uint64_t s;
  if (scene_start(seed, n, sc, &s)) return -1;
  for (size_t i = 0; i < n; i++) {
    double m = pow(10.0, uniform(&s, 4.0, 6.5));
    double C = m / uniform(&s, 2.0, 20.0);
    double vinf = uniform(&s, 2.0, 12.0);
    unsigned kind = (unsigned)(fp3_scene_xorshift(&s) % 100); /* 60 / 35 / 5 */
    fp3_ship_params *o = &sc->objs[i];
    o->C = (float)C;
    o->m = (float)m;
    o->h = h;
    o->T = kind < 60 ? 0.0f : (float)(vinf * C);
    o->v0 = (kind < 60 || kind >= 95) ? 0.0f : o->T / o->C; /* cruising: T/C */
    o->s0 = (float)uniform(&s, -2000.0, 2000.0);
  }
  sc->n = n;
  return 0;
}

void fp3_scene_free(fp3_scene *sc) {
  free(sc->objs);
  memset(sc, 0, sizeof *sc);
}
