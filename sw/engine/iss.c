/*
 * iss.c -- the FP3 instruction-set simulator: the architectural model of
 * the processor, one instruction at a time, as an engine (engine.h).
 *
 * Registers hold binary32 bit patterns, NUM_REGS per object slot (32, or
 * the build's: fp3_engine_iss_new_config); add/sub/mul/div/sqrt are
 * fpref_add/sub/mul/div/sqrt in the engine's core configuration (default
 * RNE with subnormals; RTZ and FTZ as the RTL's ROUND and FTZ parameters),
 * abs/neg/min/max are fpref_abs/neg/min/max (exact, never flushed); their
 * flags accumulate into the run's sticky FLAGS.  The ISS has every unit
 * (HAS_DIV, HAS_SQRT, HAS_SIGN all 1).  There is no timing: every instruction
 * takes one "cycle", so cycles = issued = instructions executed and
 * stalls = 0.
 *
 * Contexts are independent (their own registers, the same program), so a
 * run of several contexts runs them one after another; the ISS has
 * FP3_MAX_CONTEXTS of them, or the contexts and lanes of a build
 * (fp3_engine_iss_new_config).  The lanes of a context run in lock step:
 * each instruction executes on every lane before the next, and a beq is
 * taken only if ra and rb are bit-identical in every lane (fp3_isa.h).
 * Object slot s is lane s / num_contexts of context s % num_contexts
 * (engine.h); "cycles" and "issued" count a context's instruction once,
 * whatever its lanes.  A run of N integrations starts at PC 0.  endi counts an integration,
 * reports it, and stops the run if it was the N-th, else jumps to its imm.
 * halt stops the run.  beq continues at its imm if ra and rb hold the same
 * bit pattern.  Errors end the run with status.error set (the
 * engine call itself succeeds, as on the RTL engine):
 *   N == 0                         BAD_STEPS
 *   a word the ISA table rejects   ILLEGAL_INSN, fault_pc = its PC
 *   PC past the last entry         PC_OVERFLOW, fault_pc = IMEM_DEPTH - 1
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "engine.h"
#include "fp3_isa.h"
#include "fpref.h"
#include "image.h"

typedef struct iss_engine {
  fp3_engine base;
  uint64_t imem[FP3_DEFAULT_IMEM_DEPTH];
  uint32_t *regs; /* slot s's register r: regs[s * num_regs + r] */
  fp3_ctx_status cs[FP3_MAX_CONTEXTS * FP3_MAX_LANES]; /* [slot], of the last run */
} iss_engine;

static int iss_load_program(fp3_engine *e, const uint64_t *words, size_t n) {
  iss_engine *s = (iss_engine *)e;
  if (n > e->config.imem_depth) {
    snprintf(e->error, sizeof e->error,
             "program of %zu instructions does not fit the instruction memory "
             "(%u entries)", n, e->config.imem_depth);
    return -1;
  }
  memset(s->imem, 0, sizeof s->imem);
  if (n) memcpy(s->imem, words, n * sizeof *words);
  return 0;
}

static int check_reg(fp3_engine *e, unsigned context, unsigned reg) {
  if (context >= fp3_config_slots(&e->config)) {
    snprintf(e->error, sizeof e->error,
             "object slot %u out of range (the ISS has %u contexts x %u lanes)", context,
             e->config.num_contexts, e->config.num_lanes);
    return -1;
  }
  if (reg >= e->config.num_regs) {
    snprintf(e->error, sizeof e->error,
             "register r%u out of range (the ISS has %u)", reg,
             e->config.num_regs);
    return -1;
  }
  return 0;
}

static int iss_write_reg(fp3_engine *e, unsigned context, unsigned reg,
                         uint32_t value) {
  if (check_reg(e, context, reg)) return -1;
  ((iss_engine *)e)->regs[(size_t)context * e->config.num_regs + reg] = value;
  return 0;
}

static int iss_read_reg(fp3_engine *e, unsigned context, unsigned reg,
                        uint32_t *value) {
  if (check_reg(e, context, reg)) return -1;
  *value = ((iss_engine *)e)->regs[(size_t)context * e->config.num_regs + reg];
  return 0;
}

static void fail(fp3_engine *e, fp3_ctx_status *cs, unsigned err, uint32_t pc,
                 const char *why) {
  cs->error = err;
  cs->fault_pc = pc;
  snprintf(e->error, sizeof e->error, "%s", why);
}

/* Run context ctx, every lane in lock step, to its end; slots below
 * `report` are reported to obs; *n counts the instructions executed. */
static void run_context(iss_engine *s, unsigned ctx, uint32_t steps, unsigned report,
                        const fp3_observer *obs, fp3_ctx_status *cs,
                        unsigned *flags, uint64_t *n, uint64_t *unit_issued) {
  fp3_engine *e = &s->base;
  const uint32_t depth = e->config.imem_depth;
  const fpref_mode mode = e->config.mode;
  const unsigned nc = e->config.num_contexts, nl = e->config.num_lanes;
  uint32_t pc = 0, integ = 0;
  char why[200];
  for (;;) {
    uint64_t w = s->imem[pc];
    if (fp3_insn_check_at(w, pc, e->config.num_regs, depth, why, sizeof why)) {
      char msg[240];
      snprintf(msg, sizeof msg, "illegal instruction at pc %u: %s", pc, why);
      fail(e, cs, FP3_ERR_ILLEGAL_INSN, pc, msg);
      break;
    }
    unsigned opc = fp3_insn_opc(w), rd = fp3_insn_rd(w);
    uint32_t imm = fp3_insn_imm(w);
    int stop = 0, all_equal = 1;
    uint32_t next = pc + 1;
    for (unsigned l = 0; l < nl; l++) {
      const unsigned slot = l * nc + ctx;
      uint32_t *regs = s->regs + (size_t)slot * e->config.num_regs;
      uint32_t a = regs[fp3_insn_ra(w)], b = regs[fp3_insn_rb(w)];
      int writes = 1;
      uint32_t result = 0;
      switch ((enum fp3_opcode)opc) {
      case FP3_OP_ADD: result = fpref_add(a, b, mode, &flags[l]); break;
      case FP3_OP_SUB: result = fpref_sub(a, b, mode, &flags[l]); break;
      case FP3_OP_MUL: result = fpref_mul(a, b, mode, &flags[l]); break;
      case FP3_OP_DIV: result = fpref_div(a, b, mode, &flags[l]); break;
      case FP3_OP_SQRT: result = fpref_sqrt(a, mode, &flags[l]); break;
      case FP3_OP_ABS: result = fpref_abs(a); break;
      case FP3_OP_NEG: result = fpref_neg(a); break;
      case FP3_OP_MIN: result = fpref_min(a, b, &flags[l]); break;
      case FP3_OP_MAX: result = fpref_max(a, b, &flags[l]); break;
      case FP3_OP_LI: result = imm; break;
      case FP3_OP_MOV: result = a; break;
      case FP3_OP_BEQ: writes = 0; all_equal &= a == b; break;
      case FP3_OP_NOP: case FP3_OP_HALT: case FP3_OP_ENDI: writes = 0; break;
      }
      if (writes) {
        regs[rd] = result;
        if (slot < report) fp3_observe_write(obs, slot, rd, result, integ + 1);
      }
    }
    switch ((enum fp3_opcode)opc) {
    case FP3_OP_BEQ: /* the target is checked above: ahead, inside memory */
      if (all_equal) next = imm;
      break;
    case FP3_OP_HALT: stop = 1; break;
    case FP3_OP_ENDI:
      integ++;
      for (unsigned l = 0; l < nl; l++)
        if (l * nc + ctx < report) fp3_observe_endi(obs, l * nc + ctx, integ, *n);
      if (integ == steps) stop = 1;
      else next = imm;
      break;
    default: break;
    }
    (*n)++;
    unit_issued[fp3_opc_unit(opc)]++;
    if (stop) break;
    if (next >= depth) { /* endi and beq targets are checked above */
      fail(e, cs, FP3_ERR_PC_OVERFLOW, depth - 1,
           "PC ran past the end of instruction memory");
      break;
    }
    pc = next;
  }
  cs->steps_done = integ;
}

static int iss_run(fp3_engine *e, uint32_t steps, unsigned contexts,
                   const fp3_observer *obs, fp3_status *st) {
  iss_engine *s = (iss_engine *)e;
  const unsigned nc = e->config.num_contexts, nl = e->config.num_lanes;
  const unsigned slots = fp3_config_slots(&e->config);
  memset(st, 0, sizeof *st);
  memset(s->cs, 0, sizeof s->cs);
  e->error[0] = '\0';
  st->done = 1;
  if (steps == 0 || contexts == 0 || contexts > slots) {
    unsigned err = steps == 0 ? FP3_ERR_BAD_STEPS : FP3_ERR_BAD_CONTEXTS;
    for (unsigned c = 0; c < slots; c++)
      fail(e, &s->cs[c], err, 0,
           steps == 0 ? "run started with STEPS = 0"
                      : "run started with CONTEXTS = 0 or > NUM_CONTEXTS x NUM_LANES");
  } else {
    uint64_t n = 0; /* instructions executed */
    const unsigned hw = contexts < nc ? contexts : nc;   /* contexts started */
    for (unsigned c = 0; c < hw; c++) {
      unsigned flags[FP3_MAX_LANES] = {0};
      run_context(s, c, steps, contexts, obs, &s->cs[c], flags, &n, st->unit_issued);
      for (unsigned l = 0; l < nl; l++) {
        fp3_ctx_status *cs = &s->cs[l * nc + c];
        if (l) { /* the context's status, the lane's flags */
          cs->error = s->cs[c].error;
          cs->fault_pc = s->cs[c].fault_pc;
          cs->steps_done = s->cs[c].steps_done;
        }
        cs->flags = flags[l];
        if (l * nc + c < contexts) st->flags |= flags[l];
      }
    }
    st->cycles = n;
    st->issued = n;
  }
  for (unsigned c = 0; c < slots; c++)
    if (s->cs[c].error != FP3_ERR_NONE) st->any_error = 1;
  st->error = s->cs[0].error;
  st->fault_pc = s->cs[0].fault_pc;
  st->steps_done = s->cs[0].steps_done;
  st->stalls = 0;
  return 0;
}

static int iss_ctx_status(fp3_engine *e, unsigned context, fp3_ctx_status *cs) {
  if (check_reg(e, context, 0)) return -1;
  *cs = ((iss_engine *)e)->cs[context];
  return 0;
}

static void iss_destroy(fp3_engine *e) {
  free(((iss_engine *)e)->regs);
  free(e);
}

static const fp3_engine_ops iss_ops = {
    "iss",   iss_load_program, iss_write_reg,  iss_read_reg,
    iss_run, iss_ctx_status,   iss_destroy,
    0, /* traced: every write-back is reported */
};

fp3_engine *fp3_engine_iss_new_mode(fpref_mode mode) {
  iss_engine *s = calloc(1, sizeof *s);
  if (!s) return NULL;
  s->regs = calloc((size_t)FP3_MAX_CONTEXTS * FP3_DEFAULT_NUM_REGS, sizeof *s->regs);
  if (!s->regs) {
    free(s);
    return NULL;
  }
  s->base.ops = &iss_ops;
  s->base.config.num_contexts = FP3_MAX_CONTEXTS;
  s->base.config.num_lanes = 1;
  s->base.config.num_regs = FP3_DEFAULT_NUM_REGS;
  s->base.config.imem_depth = FP3_DEFAULT_IMEM_DEPTH;
  s->base.config.add_latency = 0; /* no timing model */
  s->base.config.mul_latency = 0;
  s->base.config.mode = mode;
  s->base.config.has_add = s->base.config.has_sub = s->base.config.has_mul = 1; /* every unit */
  s->base.config.has_div = s->base.config.has_sqrt = s->base.config.has_sign = 1;
  s->base.config.div_latency = 0;
  return &s->base;
}

fp3_engine *fp3_engine_iss_new(void) { return fp3_engine_iss_new_mode(FPREF_IEEE); }

fp3_engine *fp3_engine_iss_new_config(const fp3_config *c) {
  if (!c || c->num_contexts == 0 || c->num_contexts > FP3_MAX_CONTEXTS ||
      c->num_lanes > FP3_MAX_LANES || c->num_regs == 1 || c->num_regs > FP3_MAX_REGS)
    return NULL;
  fp3_engine *e = fp3_engine_iss_new_mode(c->mode);
  if (!e) return NULL;
  iss_engine *s = (iss_engine *)e;
  e->config.num_contexts = c->num_contexts;
  e->config.num_lanes = c->num_lanes ? c->num_lanes : 1;
  e->config.num_regs = c->num_regs ? c->num_regs : FP3_DEFAULT_NUM_REGS;
  free(s->regs);
  s->regs = calloc((size_t)fp3_config_slots(&e->config) * e->config.num_regs, sizeof *s->regs);
  if (!s->regs) {
    free(e);
    return NULL;
  }
  return e;
}
