/*
 * mscene.c -- model scenes and their runs on the contexts of an engine
 * (mscene.h).
 */
#include "mscene.h"

#include <ctype.h>
#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fp3_isa.h"
#include "fpenv.h"
#include "objects.h"
#include "progress.h"

/* Skip blanks. */
static char *skip_blank(char *p) {
  while (*p == ' ' || *p == '\t') p++;
  return p;
}

/* Next blank-separated token of *p into tok (NUL-terminated, cut at n-1);
 * 0, or -1 at the end of the line. */
static int next_token(char **p, char *tok, size_t n) {
  char *s = skip_blank(*p);
  if (*s == '\0') return -1;
  size_t k = 0;
  while (*s && *s != ' ' && *s != '\t') {
    if (k + 1 < n) tok[k++] = *s;
    s++;
  }
  tok[k] = '\0';
  *p = s;
  return 0;
}

/* Read one line of f into buf without its comment and line end; returns
 * the line with leading blanks skipped, or NULL at the end of the file or
 * for a line longer than the buffer (*too_long set). */
static char *read_line(FILE *f, char *buf, size_t n, int *too_long) {
  *too_long = 0;
  if (!fgets(buf, (int)n, f)) return NULL;
  size_t len = strlen(buf);
  if (len == n - 1 && buf[len - 1] != '\n' && !feof(f)) {
    *too_long = 1;
    return NULL;
  }
  char *hash = strchr(buf, '#');
  if (hash) *hash = '\0';
  buf[strcspn(buf, "\r\n")] = '\0';
  return skip_blank(buf);
}

/* 1 if p starts with keyword kw followed by a blank. */
static int keyword(const char *p, const char *kw) {
  size_t k = strlen(kw);
  return strncmp(p, kw, k) == 0 && (p[k] == ' ' || p[k] == '\t');
}

int fp3_scene_is_model(const char *path) {
  FILE *f = fopen(path, "r");
  if (!f) return 0;
  char buf[1024];
  char *p;
  int too_long, r = 0;
  while ((p = read_line(f, buf, sizeof buf, &too_long)) != NULL)
    if (*p) {
      r = keyword(p, "model");
      break;
    }
  fclose(f);
  return r;
}

/* The model path: relative paths are taken from the scene file's folder. */
static int resolve(const char *scene, const char *rel, char *out, size_t n) {
  const char *slash = strrchr(scene, '/');
  int w;
  if (rel[0] == '/' || !slash) w = snprintf(out, n, "%s", rel);
  else w = snprintf(out, n, "%.*s/%s", (int)(slash - scene), scene, rel);
  return w < 0 || (size_t)w >= n ? -1 : 0;
}

/* Grow the object arrays of s to hold `need` objects. */
static int grow(fp3_mscene *s, size_t need, size_t *cap) {
  if (need <= *cap) return 0;
  size_t c = *cap ? 2 * *cap : 16;
  while (c < need) c *= 2;
  const fp3_model *m = s->model;
  float *in = realloc(s->in, c * m->nparam * sizeof *in);
  if (!in) return -1;
  s->in = in;
  float *y0 = realloc(s->y0, c * (m->nstate ? m->nstate : 1) * sizeof *y0);
  if (!y0) return -1;
  s->y0 = y0;
  int *line = realloc(s->line, c * sizeof *line);
  if (!line) return -1;
  s->line = line;
  *cap = c;
  return 0;
}

/* The column header: col[j] = param index (>= 1) or -(1 + state index). */
static int read_header(fp3_mscene *s, char *p, const char *path, int lineno, int *col,
                       unsigned *ncol, char *msg, size_t n) {
  const fp3_model *m = s->model;
  unsigned char named[2 * FP3_MODEL_MAX_VARS] = {0};
  char tok[64];
  *ncol = 0;
  while (next_token(&p, tok, sizeof tok) == 0) {
    int k = fp3_model_param(m, tok), slot;
    if (strcmp(tok, "h") == 0) {
      snprintf(msg, n, "%s:%d: 'h' is not a column: the time step is the 'h' line", path,
               lineno);
      return -1;
    }
    if (k >= 1) {
      col[*ncol] = k;
      slot = k;
    } else if ((k = fp3_model_state(m, tok)) >= 0) {
      col[*ncol] = -(1 + k);
      slot = (int)m->nparam + k;
    } else {
      snprintf(msg, n, "%s:%d: column '%s' is neither a param nor a state variable of model "
               "%s (%s)", path, lineno, tok, m->name, m->file);
      return -1;
    }
    if (named[slot]) {
      snprintf(msg, n, "%s:%d: column '%s' named twice", path, lineno, tok);
      return -1;
    }
    named[slot] = 1;
    if (++*ncol > 2 * FP3_MODEL_MAX_VARS) return -1; /* unreachable: named[] */
  }
  for (unsigned k = 1; k < m->nparam + m->nstate; k++) {
    if (named[k]) continue;
    int st = k >= m->nparam;
    snprintf(msg, n, "%s:%d: the header does not give %s '%s' of model %s (declared at "
             "%s:%d): every param and state variable needs a column", path, lineno,
             st ? "state variable" : "param", st ? m->state[k - m->nparam] : m->param[k],
             m->name, m->file, st ? m->state_line[k - m->nparam] : m->param_line[k]);
    return -1;
  }
  return 0;
}

int fp3_mscene_read(const char *path, fp3_mscene *s, char *msg, size_t n) {
  memset(s, 0, sizeof *s);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(msg, n, "%s: %s", path, strerror(errno));
    return -1;
  }
  char buf[4096], tok[1024];
  char *p;
  int lineno = 0, too_long = 0, rc = 0, h_line = 0;
  float h = 0.0f;
  int col[2 * FP3_MODEL_MAX_VARS];
  unsigned ncol = 0;
  size_t cap = 0;
  while (rc == 0 && (p = read_line(f, buf, sizeof buf, &too_long)) != NULL) {
    lineno++;
    if (*p == '\0') continue;
    if (keyword(p, "model")) {
      if (s->model_line) {
        snprintf(msg, n, "%s:%d: a second 'model' line (the first is line %d)", path, lineno,
                 s->model_line);
        rc = -1;
        break;
      }
      p += 5;
      if (next_token(&p, tok, sizeof tok) || *skip_blank(p)) {
        snprintf(msg, n, "%s:%d: 'model' wants one file name", path, lineno);
        rc = -1;
        break;
      }
      s->model_line = lineno;
      if (resolve(path, tok, s->model_path, sizeof s->model_path)) {
        snprintf(msg, n, "%s:%d: model path too long", path, lineno);
        rc = -1;
        break;
      }
      s->model = malloc(sizeof *s->model);
      char mm[512];
      if (!s->model) {
        snprintf(msg, n, "%s: out of memory", path);
        rc = -1;
      } else if (fp3_model_load(s->model_path, s->model, mm, sizeof mm)) {
        snprintf(msg, n, "%s:%d: model: %s", path, lineno, mm);
        rc = -1;
      }
      continue;
    }
    if (!s->model_line) {
      snprintf(msg, n, "%s:%d: a model scene starts with 'model FILE'", path, lineno);
      rc = -1;
      break;
    }
    if (p[0] == 'h' && (p[1] == ' ' || p[1] == '\t' || p[1] == '\0')) {
      rc = fp3_scene_h_line(p + 1, path, lineno, s->n, &h_line, &h, msg, n);
      continue;
    }
    if (!s->header_line) {
      if (!(isalpha((unsigned char)*p) || *p == '_')) {
        snprintf(msg, n, "%s:%d: an object before the column header (a line naming the "
                 "params and state variables of model %s, in the order of the columns)",
                 path, lineno, s->model->name);
        rc = -1;
      } else if (read_header(s, p, path, lineno, col, &ncol, msg, n) == 0) {
        s->header_line = lineno;
      } else {
        rc = -1;
      }
      continue;
    }
    if (grow(s, s->n + 1, &cap)) {
      snprintf(msg, n, "%s: out of memory", path);
      rc = -1;
      break;
    }
    const fp3_model *m = s->model;
    float *in = s->in + s->n * m->nparam, *y0 = s->y0 + s->n * m->nstate;
    for (unsigned j = 0; j < ncol && rc == 0; j++) {
      char *end;
      const char *name = col[j] > 0 ? m->param[col[j]] : m->state[-col[j] - 1];
      if (next_token(&p, tok, sizeof tok)) {
        snprintf(msg, n, "%s:%d: %u numbers, the header (line %d) has %u columns: no value "
                 "for '%s'", path, lineno, j, s->header_line, ncol, name);
        rc = -1;
        break;
      }
      float v = strtof(tok, &end);
      if (*end != '\0' || !isfinite(v)) {
        snprintf(msg, n, "%s:%d: %s = '%s' is not a finite number", path, lineno, name, tok);
        rc = -1;
        break;
      }
      if (col[j] > 0) in[col[j]] = v;
      else y0[-col[j] - 1] = v;
    }
    if (rc == 0 && *skip_blank(p)) {
      snprintf(msg, n, "%s:%d: more numbers than the %u columns of the header (line %d)",
               path, lineno, ncol, s->header_line);
      rc = -1;
    }
    if (rc) break;
    in[0] = h;
    s->line[s->n++] = lineno;
  }
  if (too_long) {
    snprintf(msg, n, "%s:%d: line too long", path, lineno + 1);
    rc = -1;
  }
  if (rc == 0 && ferror(f)) {
    snprintf(msg, n, "%s: read error", path);
    rc = -1;
  }
  fclose(f);
  if (rc == 0 && !s->model_line) {
    snprintf(msg, n, "%s: no 'model FILE' line", path);
    rc = -1;
  } else if (rc == 0 && s->n == 0) {
    snprintf(msg, n, "%s: no objects in the scene", path);
    rc = -1;
  } else if (rc == 0 && !h_line) {
    snprintf(msg, n, "%s:%d: no 'h STEP' line before the first object: the scene format "
             "wants the time step once, before the objects", path, s->line[0]);
    rc = -1;
  }
  if (rc == 0) return 0;
  fp3_mscene_free(s);
  return -1;
}

int fp3_mscene_generate(fp3_model *m, const float *in, const float *y0, size_t n,
                        uint64_t seed, fp3_mscene *s) {
  memset(s, 0, sizeof *s);
  s->model = m;
  snprintf(s->model_path, sizeof s->model_path, "%s", m->file);
  size_t cap = 0;
  if (grow(s, n ? n : 1, &cap)) {
    fp3_mscene_free(s);
    return -1;
  }
  uint64_t x = seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull;
  if (x == 0) x = 1;
  for (size_t i = 0; i < n; i++) {
    float *oi = s->in + i * m->nparam, *oy = s->y0 + i * m->nstate;
    for (unsigned k = 0; k < m->nparam + m->nstate; k++) {
      double f = 0.75 + 0.5 * (double)(fp3_scene_xorshift(&x) >> 11) / 9007199254740992.0;
      int st = k >= m->nparam;
      float base = st ? y0[k - m->nparam] : in[k];
      float v = (i == 0 || k == 0) ? base : (float)((double)base * f);
      if (st) oy[k - m->nparam] = v;
      else oi[k] = v;
    }
    s->line[i] = 0;
  }
  s->n = n;
  return 0;
}

void fp3_mscene_zero(const fp3_mscene *sc, unsigned char *zero) {
  const fp3_model *m = sc->model;
  for (unsigned k = 0; k < m->nparam; k++) {
    zero[k] = sc->n > 0;
    for (size_t i = 0; i < sc->n && zero[k]; i++) zero[k] = sc->in[i * m->nparam + k] == 0.0f;
  }
}

int fp3_mscene_from_ships(const fp3_scene *ships, const char *model_path, const char *what,
                          fp3_mscene *s, char *msg, size_t n) {
  static const char *const cols[5] = {"T", "C", "m", "v", "s"};
  int at[5];
  memset(s, 0, sizeof *s);
  fp3_model *m = malloc(sizeof *m);
  if (!m) {
    snprintf(msg, n, "out of memory");
    return 1;
  }
  if (fp3_model_load(model_path, m, msg, n)) {
    free(m);
    return -1;
  }
  for (int k = 0; k < 5; k++) {
    at[k] = k < 3 ? fp3_model_param(m, cols[k]) : fp3_model_state(m, cols[k]);
    if (at[k] < 0 || m->nparam != 4 || m->nstate != 2) {
      snprintf(msg, n, "%s: a ship scene ('T C m v0 s0' a line) is a scene of a model with "
               "params T, C, m and state variables v, s; %s (%s) is not", what, m->name,
               m->file);
      free(m);
      return -1;
    }
  }
  s->model = m;
  snprintf(s->model_path, sizeof s->model_path, "%s", m->file);
  size_t cap = 0;
  if (grow(s, ships->n ? ships->n : 1, &cap)) {
    snprintf(msg, n, "out of memory for %zu objects", ships->n);
    fp3_mscene_free(s);
    return 1;
  }
  for (size_t i = 0; i < ships->n; i++) {
    const fp3_ship_params *p = &ships->objs[i];
    const float v[5] = {p->T, p->C, p->m, p->v0, p->s0};
    float *in = s->in + i * m->nparam, *y0 = s->y0 + i * m->nstate;
    in[0] = p->h;
    for (int k = 0; k < 5; k++) {
      if (k < 3) in[at[k]] = v[k];
      else y0[at[k]] = v[k];
    }
    s->line[i] = 0;
  }
  s->n = ships->n;
  return 0;
}

int fp3_mscene_read_any(const char *path, const char *ship_model, fp3_mscene *s, char *msg,
                        size_t n) {
  if (fp3_scene_is_model(path)) return fp3_mscene_read(path, s, msg, n);
  fp3_scene ships;
  fp3_ship_params dflt; /* the step until the scene's `h` line */
  fp3_ship_default(&dflt);
  if (fp3_scene_read(path, dflt.h, &ships, msg, n)) return -1;
  int rc = fp3_mscene_from_ships(&ships, ship_model, path, s, msg, n);
  fp3_scene_free(&ships);
  return rc;
}

void fp3_mscene_free(fp3_mscene *s) {
  free(s->model);
  free(s->in);
  free(s->y0);
  free(s->line);
  memset(s, 0, sizeof *s);
}

/* ---- running ---------------------------------------------------------------- */

#define MAX_WRITES 512 /* register writes of one object's start */

int fp3_ctx_write_bank(fp3_engine *e, unsigned c, const uint32_t *regs, unsigned nregs,
                       char *msg, size_t n) {
  for (unsigned r = 0; r < nregs; r++)
    if (fp3_engine_write_ctx_reg(e, c, r, regs[r])) {
      snprintf(msg, n, "%s", fp3_engine_error(e));
      return -1;
    }
  return 0;
}

int fp3_ctx_check(fp3_engine *e, unsigned c, size_t obj, fp3_ctx_status *cs, unsigned *error,
                  size_t *error_object, uint32_t *error_pc, char *msg, size_t n) {
  if (fp3_engine_ctx_status(e, c, cs)) {
    snprintf(msg, n, "%s", fp3_engine_error(e));
    return -1;
  }
  if (cs->error != FP3_ERR_NONE && *error == FP3_ERR_NONE) {
    *error = cs->error;
    *error_object = obj;
    *error_pc = cs->fault_pc;
  }
  return 0;
}

int fp3_ctx_run_batch(fp3_engine *e, uint32_t steps, unsigned k, const fp3_observer *obs,
                      const int *bad_tag, fp3_status *st, char *msg, size_t n) {
  if (fp3_engine_run_contexts(e, steps, k, obs, st)) {
    snprintf(msg, n, "%s", fp3_engine_error(e));
    return -1;
  }
  if (bad_tag && *bad_tag) {
    snprintf(msg, n, "engine fault: a write tagged with an integration past the run");
    return -1;
  }
  return 0;
}

/* The registers of object obj before its run: zero, then the writes of
 * start() (in the cores' mode).  0, or -1 for a write beyond nregs. */
static int start_bank(size_t (*start)(void *, size_t, unsigned *, uint32_t *, size_t),
                      void *ctx, size_t obj, fpref_mode mode, uint32_t *bank, unsigned nregs,
                      char *msg, size_t n) {
  unsigned wreg[MAX_WRITES];
  uint32_t wval[MAX_WRITES];
  fpenv_saved env;
  memset(bank, 0, nregs * sizeof *bank);
  fpenv_enter(mode, &env);
  size_t nw = start(ctx, obj, wreg, wval, MAX_WRITES);
  fpenv_leave(&env);
  for (size_t w = 0; w < nw; w++) {
    if (wreg[w] >= nregs) {
      snprintf(msg, n, "register r%u is beyond this hardware's %u registers per context",
               wreg[w], nregs);
      return -1;
    }
    bank[wreg[w]] = wval[w];
  }
  return 0;
}

/* What both runners need of the golden model and the host: the mode, and
 * the state registers inside NUM_REGS.  0, or -1 with the reason. */
static int golden_fits(fpref_mode mode, unsigned ns, const unsigned *reg, unsigned nregs,
                       char *msg, size_t n) {
  if (!fpenv_supported(mode)) {
    snprintf(msg, n, "this host cannot run the golden model in that mode");
    return -1;
  }
  for (unsigned i = 0; i < ns; i++)
    if (reg[i] >= nregs) {
      snprintf(msg, n, "state register r%u is beyond this hardware's %u registers per context",
               reg[i], nregs);
      return -1;
    }
  return 0;
}

/* Per context, integration and state variable: the last value written. */
typedef struct srec {
  const fp3_state_golden *g;
  uint32_t steps;
  uint32_t *val;  /* [(ctx * (steps + 1) + k) * nstate + i] */
  uint8_t *seen;
  int bad_tag;
  fp3_progress *progress; /* object-steps of the whole run */
  uint64_t done;          /* object-steps ended (endi of any slot) so far */
} srec;

static void srec_write(void *ctx, unsigned context, unsigned reg, uint32_t value,
                       uint32_t integ) {
  srec *b = ctx;
  for (unsigned i = 0; i < b->g->nstate; i++) {
    if (reg != b->g->reg[i]) continue;
    if (integ > b->steps + 1) {
      b->bad_tag = 1;
      continue;
    }
    uint32_t k = integ > b->steps ? b->steps : integ;
    size_t at = ((size_t)context * (b->steps + 1) + k) * b->g->nstate + i;
    b->val[at] = value;
    b->seen[at] = 1;
  }
}

/* An integration of one object ended: one object-step more. */
static void srec_endi(void *ctx, unsigned context, uint32_t integ, uint64_t cycle) {
  srec *b = ctx;
  (void)context, (void)integ, (void)cycle;
  fp3_progress_update(b->progress, ++b->done);
}

int fp3_run_state_objects(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                          uint32_t steps, fpref_mode mode, const fp3_state_golden *golden,
                          fp3_state_result *res, char *msg, size_t n) {
  memset(res, 0, sizeof *res);
  const unsigned nctx = fp3_config_slots(&e->config); /* objects per batch */
  const unsigned ns = golden->nstate, nregs = e->config.num_regs;
  double bytes = 5.0 * nctx * ns * ((double)steps + 1.0);
  if (bytes > 2e9) {
    snprintf(msg, n, "%u contexts x %u state variables x %" PRIu32 " integrations is too "
             "much to record (%.0f MB)", nctx, ns, steps, bytes / 1e6);
    return -1;
  }
  if (golden_fits(mode, ns, golden->reg, nregs, msg, n)) return -1;
  const int untraced = fp3_engine_untraced(e);
  res->final_only = untraced;
  size_t slots = (size_t)nctx * (steps + 1) * ns;
  fp3_progress prog;
  srec b = {golden, steps, malloc(slots * sizeof(uint32_t)), malloc(slots), 0, &prog, 0};
  fp3_progress_start(&prog, e->progress, (uint64_t)nobj * steps, "object-steps",
                     e->progress != NULL);
  res->y = calloc(nobj * (ns ? ns : 1), sizeof *res->y);
  uint32_t *regs = calloc(nregs, sizeof *regs);
  float y[FP3_MODEL_MAX_VARS];
  int rc = -1;
  fpenv_saved env;
  if (!b.val || !b.seen || !res->y || !regs) {
    snprintf(msg, n, "out of memory");
    goto out;
  }
  if (fp3_engine_load(e, words, nwords)) {
    snprintf(msg, n, "%s", fp3_engine_error(e));
    goto out;
  }
  res->objects = nobj;
  res->contexts = e->config.num_contexts;
  res->lanes = e->config.num_lanes ? e->config.num_lanes : 1;
  res->first_object = res->error_object = res->nonfinite_object = SIZE_MAX;
  for (size_t first = 0; first < nobj; first += nctx) {
    unsigned k = (unsigned)(nobj - first < nctx ? nobj - first : nctx);
    for (unsigned c = 0; c < k; c++)
      if (start_bank(golden->start, golden->ctx, first + c, mode, regs, nregs, msg, n) ||
          fp3_ctx_write_bank(e, c, regs, nregs, msg, n))
        goto out;
    memset(b.seen, 0, slots);
    fp3_observer obs = {.ctx = &b, .on_ctx_write = srec_write,
                        .on_ctx_endi = prog.out ? srec_endi : NULL};
    fp3_status st;
    b.done = (uint64_t)first * steps; /* a batch ends with all its steps */
    if (fp3_ctx_run_batch(e, steps, k, &obs, &b.bad_tag, &st, msg, n)) goto out;
    res->batches++;
    res->cycles += st.cycles;
    res->issued += st.issued;
    res->stalls += st.stalls;
    for (int u = 0; u < FP3_NUM_UNITS; u++) res->unit_issued[u] += st.unit_issued[u];
    res->flags |= st.flags;
    for (unsigned c = 0; c < k; c++) {
      size_t obj = first + c;
      fp3_ctx_status cs;
      if (fp3_ctx_check(e, c, obj, &cs, &res->error, &res->error_object, &res->error_pc, msg,
                        n))
        goto out;
      /* the golden model restarted on this object; the state before the
       * first integration is what the host wrote into its registers */
      uint32_t cur[FP3_MODEL_MAX_VARS];
      if (start_bank(golden->start, golden->ctx, obj, mode, regs, nregs, msg, n)) goto out;
      for (unsigned i = 0; i < ns; i++) cur[i] = regs[golden->reg[i]];
      size_t base = (size_t)c * (steps + 1);
      /* an engine without events (a board): the state its registers hold
       * after the run is its last integration's, compared with the golden
       * model's there only */
      const uint32_t last = steps < cs.steps_done ? steps : cs.steps_done;
      if (untraced && last > 0)
        for (unsigned i = 0; i < ns; i++) {
          size_t at = (base + last) * ns + i;
          if (fp3_engine_read_ctx_reg(e, c, golden->reg[i], &b.val[at])) {
            snprintf(msg, n, "%s", fp3_engine_error(e));
            goto out;
          }
          b.seen[at] = 1;
        }
      for (uint32_t t = 1; t <= last; t++) {
        fpenv_enter(mode, &env);
        golden->step(golden->ctx, y);
        fpenv_leave(&env);
        for (unsigned i = 0; i < ns; i++) {
          size_t at = (base + t) * ns + i;
          if (b.seen[at]) cur[i] = b.val[at];
          uint32_t want = fpref_bits(y[i]);
          if ((!untraced || t == last) && cur[i] != want) {
            if (res->mismatches == 0) {
              res->first_object = obj;
              res->first_step = t;
              res->first_var = i;
              res->first_got = cur[i];
              res->first_want = want;
            }
            res->mismatches++;
          }
          if (res->nonfinite_object == SIZE_MAX && !isfinite(y[i])) {
            res->nonfinite_object = obj;
            res->nonfinite_step = t;
            res->nonfinite_var = i;
          }
        }
      }
      for (unsigned i = 0; i < ns; i++)
        if (fp3_engine_read_ctx_reg(e, c, golden->reg[i], &res->y[obj * ns + i])) {
          snprintf(msg, n, "%s", fp3_engine_error(e));
          goto out;
        }
    }
  }
  rc = 0;
out:
  fp3_progress_finish(&prog);
  free(b.val);
  free(b.seen);
  free(regs);
  if (rc) fp3_state_result_free(res);
  return rc;
}

void fp3_state_result_free(fp3_state_result *res) {
  free(res->y);
  res->y = NULL;
}

/* ---- frames ------------------------------------------------------------------ */

int fp3_frame_batches(fp3_engine *e, uint32_t *bank, const size_t *at, size_t k,
                      unsigned char *stay, fp3_state_frames_result *acc, char *msg, size_t n) {
  const unsigned nctx = fp3_config_slots(&e->config); /* objects per batch */
  const unsigned nregs = e->config.num_regs;
  for (size_t first = 0; first < k; first += nctx) {
    unsigned kb = (unsigned)(k - first < nctx ? k - first : nctx);
    for (unsigned c = 0; c < kb; c++)
      if (fp3_ctx_write_bank(e, c, bank + at[first + c] * nregs, nregs, msg, n)) return -1;
    fp3_status st;
    if (fp3_ctx_run_batch(e, 1, kb, NULL, NULL, &st, msg, n)) return -1;
    acc->batches++;
    acc->cycles += st.cycles;
    acc->issued += st.issued;
    acc->object_frames += kb;
    acc->host_words += 2u * kb * nregs; /* each bank written, then read back */
    for (unsigned c = 0; c < kb; c++) {
      size_t o = at[first + c];
      uint32_t *b = bank + o * nregs;
      fp3_ctx_status cs;
      if (fp3_ctx_check(e, c, o, &cs, &acc->error, &acc->error_object, &acc->error_pc, msg, n))
        return -1;
      int same = 1;
      for (unsigned r = 0; r < nregs; r++) {
        uint32_t v;
        if (fp3_engine_read_ctx_reg(e, c, r, &v)) {
          snprintf(msg, n, "%s", fp3_engine_error(e));
          return -1;
        }
        same &= v == b[r];
        b[r] = v;
      }
      stay[first + c] = (unsigned char)same;
    }
  }
  return 0;
}

int fp3_run_state_frames(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                         uint32_t frames, int rest_skip, const fp3_state_wake *wake,
                         fpref_mode mode,
                         const fp3_state_stepper *golden, fp3_state_frames_result *res,
                         char *msg, size_t n) {
  return fp3_run_state_frames_farm(e, words, nwords, nobj, frames, rest_skip, wake, mode, golden,
                                   NULL, res, msg, n);
}

int fp3_run_state_frames_farm(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                              uint32_t frames, int rest_skip, const fp3_state_wake *wake,
                              fpref_mode mode, const fp3_state_stepper *golden,
                              const fp3_frames_farm *farm, fp3_state_frames_result *res,
                              char *msg, size_t n) {
  memset(res, 0, sizeof *res);
  const unsigned nregs = e->config.num_regs, ns = golden->nstate;
  if (frames == 0) {
    snprintf(msg, n, "no frames to run");
    return -1;
  }
  if (ns > FP3_STEPPER_MAX_VARS) {
    snprintf(msg, n, "%u carried values; at most %d", ns, FP3_STEPPER_MAX_VARS);
    return -1;
  }
  if (golden_fits(mode, ns, golden->reg, nregs, msg, n)) return -1;
  uint32_t *bank = calloc(nobj * nregs, sizeof *bank);  /* every object's bank */
  unsigned char *stay = malloc(nobj ? nobj : 1); /* awake object i's bank unchanged */
  float *gy = malloc(nobj * (ns ? ns : 1) * sizeof *gy); /* golden state */
  unsigned char *asleep = calloc(nobj ? nobj : 1, 1);
  size_t *awake = malloc((nobj ? nobj : 1) * sizeof *awake);
  int rc = -1;
  fpenv_saved env;
  fp3_progress prog = {0}; /* off until the frames start */
  if (!bank || !stay || !gy || !asleep || !awake) {
    snprintf(msg, n, "out of memory");
    goto out;
  }
  for (size_t o = 0; o < nobj; o++) {
    if (start_bank(golden->start, golden->ctx, o, mode, bank + o * nregs, nregs, msg, n))
      goto out;
    for (unsigned i = 0; i < ns; i++) gy[o * ns + i] = fpref_float(bank[o * nregs + golden->reg[i]]);
  }
  if (fp3_engine_load(e, words, nwords)) {
    snprintf(msg, n, "%s", fp3_engine_error(e));
    goto out;
  }
  res->objects = nobj;
  res->frames = frames;
  res->contexts = e->config.num_contexts;
  res->lanes = e->config.num_lanes ? e->config.num_lanes : 1;
  res->first_object = res->error_object = SIZE_MAX;
  fp3_progress_start(&prog, e->progress, frames, "frames", e->progress != NULL);
  for (uint32_t f = 1; f <= frames; f++) {
    if (wake && wake->frame == f)
      for (size_t o = 0; o < nobj && res->woken < wake->count; o++)
        if (wake->wake(wake->ctx, o, bank + o * nregs, nregs)) {
          asleep[o] = 0;
          res->woken++;
        }
    size_t na = 0;
    for (size_t o = 0; o < nobj; o++)
      if (!asleep[o]) awake[na++] = o;
    res->skipped += nobj - na;
    if (farm ? farm->run(farm->ctx, bank, awake, na, stay, res, msg, n)
             : fp3_frame_batches(e, bank, awake, na, stay, res, msg, n))
      goto out;
    if (rest_skip)
      for (size_t i = 0; i < na; i++)
        if (stay[i]) asleep[awake[i]] = 1;
    /* the golden model steps every object, asleep or not */
    for (size_t o = 0; o < nobj; o++) {
      float y[FP3_STEPPER_MAX_VARS];
      fpenv_enter(mode, &env);
      golden->step_from(golden->ctx, o, gy + o * ns, y);
      fpenv_leave(&env);
      for (unsigned i = 0; i < ns; i++) {
        gy[o * ns + i] = y[i];
        if (bank[o * nregs + golden->reg[i]] != fpref_bits(y[i])) {
          if (res->mismatches++ == 0) {
            res->first_object = o;
            res->first_frame = f;
            res->first_var = i;
          }
        }
      }
    }
    fp3_progress_update(&prog, f);
  }
  for (size_t o = 0; o < nobj; o++) res->asleep_last += asleep[o];
  rc = 0;
out:
  fp3_progress_finish(&prog);
  free(bank);
  free(stay);
  free(gy);
  free(asleep);
  free(awake);
  return rc;
}
