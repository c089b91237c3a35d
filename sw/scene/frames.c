/*
 * frames.c -- a scene run frame by frame with sleeping objects (frames.h).
 */
#include "frames.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fp3_isa.h"
#include "fpenv.h"
#include "fpref.h"
#include "progress.h"

typedef struct frames_run {
  fp3_engine *e;
  const fp3_image *img;
  const fp3_scene *sc;
  const fp3_integrator *ig;
  fpref_mode mode;
  unsigned nregs;
  uint32_t *bank;     /* [object * nregs + register]                      */
  uint32_t *fresh;    /* one batch's banks after its frame                */
  uint8_t *asleep;    /* [object]                                         */
  size_t *batch;      /* objects of the batch being run                   */
  fp3_istate *gold;   /* [object]                                         */
  fp3_ship_params *p; /* [object]: the scene, T changed by wakes          */
} frames_run;

static int engine_fail(const frames_run *r, char *msg, size_t n) {
  snprintf(msg, n, "%s", fp3_engine_error(r->e));
  return -1;
}

/* Run the k objects of r->batch for one frame; update banks and sleep. */
static int run_batch(frames_run *r, size_t k, const fp3_frames_opts *o, fp3_frames_result *res,
                     char *msg, size_t n) {
  const unsigned nr = r->nregs;
  for (size_t c = 0; c < k; c++)
    for (unsigned g = 0; g < nr; g++)
      if (fp3_engine_write_ctx_reg(r->e, (unsigned)c, g, r->bank[r->batch[c] * nr + g]))
        return engine_fail(r, msg, n);
  fp3_status st;
  if (fp3_engine_run_contexts(r->e, 1, (unsigned)k, NULL, &st)) return engine_fail(r, msg, n);
  res->batches++;
  res->cycles += st.cycles;
  res->issued += st.issued;
  res->object_frames += k;
  res->host_words += 2 * (uint64_t)k * nr;
  for (size_t c = 0; c < k; c++) {
    size_t obj = r->batch[c];
    fp3_ctx_status cs;
    if (fp3_engine_ctx_status(r->e, (unsigned)c, &cs)) return engine_fail(r, msg, n);
    if (cs.error != FP3_ERR_NONE && res->error == FP3_ERR_NONE) {
      res->error = cs.error;
      res->error_object = obj;
      res->error_pc = cs.fault_pc;
    }
    uint32_t *now = &r->fresh[c * nr];
    for (unsigned g = 0; g < nr; g++)
      if (fp3_engine_read_ctx_reg(r->e, (unsigned)c, g, &now[g])) return engine_fail(r, msg, n);
    uint32_t *was = &r->bank[obj * nr];
    if (o->rest_skip && cs.error == FP3_ERR_NONE && memcmp(now, was, nr * sizeof *now) == 0)
      r->asleep[obj] = 1;
    memcpy(was, now, nr * sizeof *now);
  }
  return 0;
}

/* Wake object i: thrust T = vinf * C, in its bank and its golden model. */
static void wake(frames_run *r, size_t i, float vinf) {
  uint32_t *b = &r->bank[i * r->nregs];
  fp3_ship_params q = r->p[i];
  q.T = vinf * q.C;
  /* The .in registers from the changed object at its current v and s:
   * T and the values folded from it change, v0 = v and s0 = s rewrite v
   * and s unchanged, nv0 = -v wakes a sleeping program. */
  q.v0 = fpref_float(b[r->img->out_reg[FP3_OUT_V]]);
  q.s0 = fpref_float(b[r->img->out_reg[FP3_OUT_S]]);
  fp3_in_registers(r->img, &q, b);
  r->p[i].T = q.T;
  r->gold[i].T = q.T;
  r->asleep[i] = 0;
}

/* Step every golden model one frame and compare with the banks. */
static void check_frame(frames_run *r, uint32_t f, fp3_frames_result *res) {
  const unsigned nr = r->nregs;
  const int vreg = r->img->out_reg[FP3_OUT_V], sreg = r->img->out_reg[FP3_OUT_S];
  fpenv_saved env;
  fpenv_enter(r->mode, &env);
  for (size_t i = 0; i < r->sc->n; i++) r->ig->step(&r->gold[i]);
  fpenv_leave(&env);
  for (size_t i = 0; i < r->sc->n; i++) {
    const uint32_t got[2] = {r->bank[i * nr + (unsigned)vreg], r->bank[i * nr + (unsigned)sreg]};
    const uint32_t want[2] = {fpref_bits(r->gold[i].v), fpref_bits(r->gold[i].s)};
    for (int w = 0; w < 2; w++) {
      if (got[w] == want[w]) continue;
      if (res->mismatches == 0) {
        res->first_object = i;
        res->first_frame = f;
      }
      res->mismatches++;
    }
  }
}

static void run_free(frames_run *r) {
  free(r->bank);
  free(r->fresh);
  free(r->asleep);
  free(r->batch);
  free(r->gold);
  free(r->p);
}

int fp3_run_frames(fp3_engine *e, const fp3_image *img, const fp3_scene *sc,
                   const fp3_integrator *ig, fpref_mode mode, const fp3_frames_opts *o,
                   fp3_frames_result *res, char *msg, size_t n) {
  memset(res, 0, sizeof *res);
  if (fp3_objects_check(e, img, mode, msg, n)) return -1;
  if (o->frames == 0 || sc->n == 0) {
    snprintf(msg, n, "nothing to run: %u frames of %zu objects", o->frames, sc->n);
    return -1;
  }
  frames_run r = {e, img, sc, ig, mode, e->config.num_regs, NULL, NULL, NULL, NULL, NULL, NULL};
  const unsigned nctx = fp3_config_slots(&e->config);   /* objects per batch */
  r.bank = calloc(sc->n * r.nregs, sizeof *r.bank);
  r.fresh = calloc((size_t)nctx * r.nregs, sizeof *r.fresh);
  r.asleep = calloc(sc->n, 1);
  r.batch = calloc(nctx, sizeof *r.batch);
  r.gold = calloc(sc->n, sizeof *r.gold);
  r.p = malloc(sc->n * sizeof *r.p);
  if (!r.bank || !r.fresh || !r.asleep || !r.batch || !r.gold || !r.p) {
    run_free(&r);
    snprintf(msg, n, "out of memory for %zu objects", sc->n);
    return -1;
  }
  if (fp3_engine_load(e, img->words, img->n)) {
    run_free(&r);
    return engine_fail(&r, msg, n);
  }
  memcpy(r.p, sc->objs, sc->n * sizeof *r.p);
  fpenv_saved env;
  fpenv_enter(mode, &env); /* prologue arithmetic of the models in the cores' mode */
  for (size_t i = 0; i < sc->n; i++) ig->init(&r.gold[i], &r.p[i]);
  fpenv_leave(&env);
  for (size_t i = 0; i < sc->n; i++) fp3_in_registers(img, &r.p[i], &r.bank[i * r.nregs]);

  res->objects = sc->n;
  res->frames = o->frames;
  res->contexts = e->config.num_contexts;
  res->lanes = e->config.num_lanes ? e->config.num_lanes : 1;
  res->first_object = SIZE_MAX;
  res->error_object = SIZE_MAX;
  int rc = 0;
  fp3_progress prog;
  fp3_progress_start(&prog, e->progress, o->frames, "frames", e->progress != NULL);
  for (uint32_t f = 1; f <= o->frames && rc == 0; f++) {
    if (f == o->wake_frame) {
      for (size_t i = 0; i < sc->n && res->woken < o->wake_count; i++)
        if (r.p[i].T == 0.0f && r.p[i].C > 0.0f) {
          wake(&r, i, o->wake_vinf);
          res->woken++;
        }
    }
    size_t k = 0;
    for (size_t i = 0; i < sc->n && rc == 0; i++) {
      if (r.asleep[i]) {
        res->skipped++;
        continue;
      }
      r.batch[k++] = i;
      if (k == nctx) {
        rc = run_batch(&r, k, o, res, msg, n);
        k = 0;
      }
    }
    if (k && rc == 0) rc = run_batch(&r, k, o, res, msg, n);
    if (rc == 0) check_frame(&r, f, res);
    fp3_progress_update(&prog, f);
  }
  fp3_progress_finish(&prog);
  for (size_t i = 0; i < sc->n; i++) res->asleep_last += r.asleep[i];
  run_free(&r);
  return rc;
}
