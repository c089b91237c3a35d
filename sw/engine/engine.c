/*
 * engine.c -- the engine dispatchers of engine.h and the constructor by
 * name.  The engines themselves live in iss.c and engine_rtl.c.
 */
#include <stdio.h>
#include <string.h>

#include "engine.h"
#include "fp3_isa.h"
#include "image.h"

fp3_engine *fp3_engine_new(const char *name) {
  if (!name) return NULL;
  if (strcmp(name, "iss") == 0) return fp3_engine_iss_new();
  if (strcmp(name, "rtl") == 0) return fp3_engine_rtl_new(NULL);
  if (fp3_engine_is_uart(name)) {
    char err[512];
    fp3_engine *e = fp3_engine_uart_new(name + 5, err, sizeof err);
    if (!e) fprintf(stderr, "fp3: %s\n", err);
    return e;
  }
  return NULL;
}

int fp3_engine_is_uart(const char *name) {
  return name && strncmp(name, "uart:", 5) == 0 && name[5] != '\0';
}

int fp3_engine_untraced(const fp3_engine *e) {
  return e && e->ops->untraced;
}

uint64_t fp3_config_cycle_limit(const fp3_config *c, uint32_t steps, unsigned contexts) {
  const uint64_t extra = (c->fmax_pipe ? FP3_FMAX_PIPE_CYCLES : 0) +
                         (c->num_lanes > 1 ? FP3_LANES_BEQ_CYCLES : 0);
  unsigned longest = c->add_latency > c->mul_latency ? c->add_latency : c->mul_latency;
  if (c->div_latency > longest) longest = c->div_latency;
  uint64_t per_insn = (uint64_t)longest + 2 + extra;
  if (per_insn < FP3_BEQ_CYCLES + extra) per_insn = FP3_BEQ_CYCLES + extra;
  return ((uint64_t)steps + 1) * c->imem_depth * per_insn * (contexts ? contexts : 1) + 1000;
}

unsigned fp3_config_slots(const fp3_config *c) {
  return c->num_contexts * (c->num_lanes ? c->num_lanes : 1);
}

int fp3_config_check_program(const fp3_config *c, const uint64_t *words, size_t n,
                             char *msg, size_t len) {
  for (size_t pc = 0; pc < n; pc++) {
    const unsigned opc = fp3_insn_opc(words[pc]);
    const char *missing = NULL, *param = NULL;
    if ((opc == FP3_OP_ADD || opc == FP3_OP_SUB) && !c->has_add) {
      missing = "no adder";
      param = "HAS_ADD";
    } else if (opc == FP3_OP_SUB && !c->has_sub) {
      missing = "an adder that cannot subtract";
      param = "HAS_SUB";
    } else if (opc == FP3_OP_MUL && !c->has_mul) {
      missing = "no multiplier";
      param = "HAS_MUL";
    } else if (opc == FP3_OP_DIV && !c->has_div) {
      missing = "no divider";
      param = "HAS_DIV";
    } else if (opc == FP3_OP_SQRT && !c->has_sqrt) {
      missing = "no square root";
      param = "HAS_SQRT";
    } else if ((opc == FP3_OP_ABS || opc == FP3_OP_NEG || opc == FP3_OP_MIN ||
                opc == FP3_OP_MAX) && !c->has_sign) {
      missing = "no sign group";
      param = "HAS_SIGN";
    }
    if (missing) {
      snprintf(msg, len, "the program uses %s (pc %zu), but this hardware has %s "
               "(built with %s=0)", fp3_opc_mnemonic(opc), pc, missing, param);
      return -1;
    }
  }
  return 0;
}

int fp3_engine_load(fp3_engine *e, const uint64_t *words, size_t n) {
  if (fp3_config_check_program(&e->config, words, n, e->error, sizeof e->error)) return -1;
  return e->ops->load_program(e, words, n);
}

int fp3_engine_write_reg(fp3_engine *e, unsigned reg, uint32_t value) {
  return e->ops->write_reg(e, 0, reg, value);
}

int fp3_engine_read_reg(fp3_engine *e, unsigned reg, uint32_t *value) {
  return e->ops->read_reg(e, 0, reg, value);
}

int fp3_engine_run(fp3_engine *e, uint32_t steps, const fp3_observer *obs,
                   fp3_status *st) {
  fp3_progress p;
  fp3_progress_start(&p, e->progress, steps, "integrations", e->progress != NULL);
  if (!p.out) return e->ops->run(e, steps, 1, obs, st);
  /* the caller's observer, with the progress line fed by its endi events */
  fp3_observer w = {0};
  if (obs) w = *obs;
  w.progress = &p;
  int rc = e->ops->run(e, steps, 1, &w, st);
  fp3_progress_finish(&p);
  return rc;
}

/* The cycles of the first, the last but one and the last endi. */
typedef struct endi_at {
  uint32_t k;
  uint64_t first, prev, last;
} endi_at;

static void on_endi_at(void *ctx, uint32_t integration, uint64_t cycle) {
  endi_at *a = ctx;
  if (integration == 1) a->first = cycle;
  if (integration == a->k - 1) a->prev = cycle;
  if (integration == a->k) a->last = cycle;
}

int fp3_engine_endi_cycles(fp3_engine *e, const uint64_t *words, size_t n, uint32_t k,
                           unsigned *first, unsigned *later) {
  endi_at at = {k, 0, 0, 0};
  fp3_observer obs = {.ctx = &at, .on_endi = on_endi_at};
  fp3_status st;
  if (k < 2 || fp3_engine_load(e, words, n) || fp3_engine_run(e, k, &obs, &st) ||
      st.error != FP3_ERR_NONE || !at.last)
    return -1;
  *first = (unsigned)(at.first + 1);
  *later = (unsigned)(at.last - at.prev);
  return 0;
}

int fp3_engine_write_ctx_reg(fp3_engine *e, unsigned context, unsigned reg,
                             uint32_t value) {
  return e->ops->write_reg(e, context, reg, value);
}

int fp3_engine_read_ctx_reg(fp3_engine *e, unsigned context, unsigned reg,
                            uint32_t *value) {
  return e->ops->read_reg(e, context, reg, value);
}

int fp3_engine_run_contexts(fp3_engine *e, uint32_t steps, unsigned contexts,
                            const fp3_observer *obs, fp3_status *st) {
  return e->ops->run(e, steps, contexts, obs, st);
}

int fp3_engine_ctx_status(fp3_engine *e, unsigned context, fp3_ctx_status *cs) {
  return e->ops->ctx_status(e, context, cs);
}

void fp3_observe_write(const fp3_observer *obs, unsigned context, unsigned reg,
                       uint32_t value, uint32_t integration) {
  if (!obs) return;
  if (obs->on_ctx_write) obs->on_ctx_write(obs->ctx, context, reg, value, integration);
  if (context == 0 && obs->on_write) obs->on_write(obs->ctx, reg, value, integration);
}

void fp3_observe_endi(const fp3_observer *obs, unsigned context,
                      uint32_t integration, uint64_t cycle) {
  if (!obs) return;
  if (obs->on_ctx_endi) obs->on_ctx_endi(obs->ctx, context, integration, cycle);
  if (context == 0 && obs->on_endi) obs->on_endi(obs->ctx, integration, cycle);
  if (context == 0 && obs->progress) fp3_progress_update(obs->progress, integration);
}

void fp3_engine_free(fp3_engine *e) {
  if (e) e->ops->destroy(e);
}

const char *fp3_engine_error(const fp3_engine *e) {
  return e ? e->error : "no engine";
}

void fp3_engine_show_progress(fp3_engine *e, const char *label) {
  if (e) e->progress = label;
}

void fp3_track_advance(fp3_track *t, int which, uint32_t upto) {
  while (t->next_k[which] < upto && t->next_k[which] <= t->last) {
    t->final(t->ctx, which, t->next_k[which], t->cur[which]);
    t->next_k[which]++;
  }
}

void fp3_track_write(fp3_track *t, unsigned reg, uint32_t value, uint32_t integration) {
  for (int w = 0; w < 2; w++)
    if ((int)reg == t->reg[w]) {
      fp3_track_advance(t, w, integration); /* integrations before this one are over */
      t->cur[w] = value;
    }
}
