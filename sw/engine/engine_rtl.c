/*
 * engine_rtl.c -- the Verilated RTL (rtl/fp3_top.v) as an FP3 engine.
 *
 * Talks to the model only through its host port (sim/fp3_model.h), exactly
 * as a driver would talk to the FPGA, and watches the trace port while the
 * machine runs freely.  Each unit's write-backs leave in the order the unit
 * accepted operations, so a FIFO of (context, integration) tags per unit,
 * pushed at issue and popped at write-back, tags every result with the
 * integration it belongs to without any help from the hardware.  A
 * write-back with an empty FIFO or for another context than the FIFO
 * says, or a FIFO not empty when the run ends, is a hardware fault and
 * fails the run.  A write-back carries every lane's value (fp3_top trace
 * port); each lane's is reported as its object slot's (engine.h).
 */
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "engine.h"
#include "fp3_isa.h"
#include "../sim/fp3_model.h"

_Static_assert(FP3_MODEL_MAX_LANES == FP3_MAX_LANES, "fp3_model_out holds every lane");

#define TAG_FIFO 64 /* > deepest unit latency + 1 */

typedef struct tag_fifo {
  uint32_t integ[TAG_FIFO];
  uint8_t ctx[TAG_FIFO];
  unsigned head, count;
} tag_fifo;

typedef struct rtl_engine {
  fp3_engine base;
  const fp3_model_ops *mops; /* the model of the configuration */
  fp3_model *model;
  fp3_ctx_status cs[FP3_MAX_CONTEXTS * FP3_MAX_LANES]; /* [slot], of the last run */
  unsigned ctx_sel;              /* CTX as last written (UINT_MAX: unknown) */
  unsigned lane_sel;             /* LANE as last written (UINT_MAX: unknown) */
  unsigned read_cycles;          /* host-port read latency, 1 + 3 FMAX_PIPE (+ 1 with lanes) */
  int win_set;                   /* waveform window, in cycles of a run */
  uint64_t win_first, win_count;
  char *trace_path;              /* the waveform's final name (NULL: none) */
  int trace_slot;                /* its temporary's slot of trace_tmp[] (-1: none) */
  int run_ok, run_failed;        /* a run returned 0; a run returned -1 */
} rtl_engine;

/* ---- the waveform file -----------------------------------------------------
 *
 * A traced engine's model writes its VCD to a temporary beside the trace
 * file, PATH.tmp.PID; rtl_destroy closes it (the model's destroy flushes
 * the VCD writer) and renames it to PATH if a run completed and none
 * failed, else removes it.  So PATH is never a cut-off waveform: it is
 * either the whole window of finished runs or absent.
 *
 * While any temporary is open, SIGINT, SIGTERM and SIGHUP run
 * trace_on_signal, which removes every open temporary (unlink is
 * async-signal-safe, the names are in static buffers, each written before
 * its slot is marked live), puts back the signal's default action and
 * raises the signal again, so the process ends with the signal's status
 * as it would have without the handler.  A signal the process ignored
 * when the first temporary opened stays ignored (a background job's
 * SIGINT); the earlier actions come back when the last temporary closes.
 * A process can hold TRACE_SLOTS traced engines at once. */
#define TRACE_SLOTS 4
#define TRACE_NAME_MAX (4096 + 32) /* PATH_MAX and ".tmp." and a pid */

static char trace_tmp[TRACE_SLOTS][TRACE_NAME_MAX];
static volatile sig_atomic_t trace_live[TRACE_SLOTS];
static const int trace_signals[] = {SIGINT, SIGTERM, SIGHUP};
#define TRACE_NSIG (sizeof trace_signals / sizeof trace_signals[0])
static struct sigaction trace_old[TRACE_NSIG]; /* actions before the handler */
static int trace_hooked[TRACE_NSIG];           /* the handler is installed   */
static int trace_open;                         /* live slots                 */

static void trace_on_signal(int sig) {
  for (int k = 0; k < TRACE_SLOTS; k++)
    if (trace_live[k]) unlink(trace_tmp[k]);
  struct sigaction dfl;
  memset(&dfl, 0, sizeof dfl);
  dfl.sa_handler = SIG_DFL;
  sigemptyset(&dfl.sa_mask);
  sigaction(sig, &dfl, NULL);
  sigset_t one;
  sigemptyset(&one);
  sigaddset(&one, sig);
  sigprocmask(SIG_UNBLOCK, &one, NULL); /* the handler runs with sig blocked */
  raise(sig);
}

/* Claim a slot for the temporary of `path` (its name into trace_tmp[k]),
 * installing the handler with the first.  k, or -1 with a message on
 * stderr (the name too long, every slot taken). */
static int trace_claim(const char *path) {
  int k = 0;
  while (k < TRACE_SLOTS && trace_live[k]) k++;
  if (k == TRACE_SLOTS) {
    fprintf(stderr, "fp3: cannot trace to %s: %d waveforms are being written already\n", path,
            TRACE_SLOTS);
    return -1;
  }
  int n = snprintf(trace_tmp[k], sizeof trace_tmp[k], "%s.tmp.%ld", path, (long)getpid());
  if (n < 0 || (size_t)n >= sizeof trace_tmp[k]) {
    fprintf(stderr, "fp3: cannot trace to %s: the name is too long\n", path);
    return -1;
  }
  atomic_signal_fence(memory_order_seq_cst); /* the name before the mark */
  trace_live[k] = 1;
  if (trace_open++ == 0) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = trace_on_signal;
    sigemptyset(&sa.sa_mask);
    for (size_t i = 0; i < TRACE_NSIG; i++) sigaddset(&sa.sa_mask, trace_signals[i]);
    for (size_t i = 0; i < TRACE_NSIG; i++) {
      trace_hooked[i] = 0;
      if (sigaction(trace_signals[i], NULL, &trace_old[i]) != 0 ||
          trace_old[i].sa_handler == SIG_IGN)
        continue;
      trace_hooked[i] = sigaction(trace_signals[i], &sa, NULL) == 0;
    }
  }
  return k;
}

/* Give slot k back (its file renamed or removed); the last one restores
 * the signals' earlier actions. */
static void trace_release(int k) {
  trace_live[k] = 0;
  if (--trace_open == 0)
    for (size_t i = 0; i < TRACE_NSIG; i++)
      if (trace_hooked[i]) sigaction(trace_signals[i], &trace_old[i], NULL);
}

/* The model is closed: keep the temporary as the trace file or remove it. */
static void trace_finish(rtl_engine *r) {
  if (r->trace_slot < 0) return;
  const char *tmp = trace_tmp[r->trace_slot];
  if (r->run_ok && !r->run_failed) {
    if (rename(tmp, r->trace_path) != 0) {
      fprintf(stderr, "fp3: cannot rename the trace %s to %s: %s\n", tmp, r->trace_path,
              strerror(errno));
      unlink(tmp);
    }
  } else {
    unlink(tmp);
  }
  trace_release(r->trace_slot);
  r->trace_slot = -1;
}

static void host_write(const rtl_engine *m, unsigned addr, uint32_t value) {
  fp3_model_in in = {1, (uint16_t)addr, value};
  m->mops->cycle(m->model, &in, NULL);
}

/* The host port answers a read read_cycles cycles after its address (fp3_top
 * "Host port"); the address is held that long. */
static uint32_t host_read(const rtl_engine *m, unsigned addr) {
  fp3_model_in in = {0, (uint16_t)addr, 0};
  fp3_model_out out;
  for (unsigned k = 0; k < m->read_cycles; k++) m->mops->cycle(m->model, &in, &out);
  return out.rdata;
}

/* Select context c for the per-context host registers; CTX is written only
 * when it changes (a register bank is moved in a cycle per word). */
static void select_ctx(rtl_engine *m, unsigned c) {
  if (m->ctx_sel == c) return;
  host_write(m, FP3_HR_CTX, c);
  m->ctx_sel = c;
}

/* Select lane l for the register window and FLAGS (written when it changes). */
static void select_lane(rtl_engine *m, unsigned l) {
  if (m->lane_sel == l) return;
  host_write(m, FP3_HR_LANE, l);
  m->lane_sel = l;
}

/* Select the context and lane of object slot s (engine.h). */
static void select_slot(rtl_engine *m, unsigned s) {
  select_ctx(m, s % m->base.config.num_contexts);
  select_lane(m, s / m->base.config.num_contexts);
}

static uint64_t host_read64(const rtl_engine *m, unsigned lo_addr) {
  uint64_t lo = host_read(m, lo_addr);
  uint64_t hi = host_read(m, lo_addr + 1);
  return lo | (hi << 32);
}

static int rtl_load_program(fp3_engine *e, const uint64_t *words, size_t n) {
  rtl_engine *r = (rtl_engine *)e;
  if (n > e->config.imem_depth) {
    snprintf(e->error, sizeof e->error,
             "program of %zu instructions does not fit the instruction memory "
             "(%u entries)", n, e->config.imem_depth);
    return -1;
  }
  /* Every entry is written, so a shorter program leaves no stale words. */
  for (size_t i = 0; i < e->config.imem_depth; i++) {
    uint64_t w = i < n ? words[i] : 0;
    host_write(r, FP3_HR_IMEM_BASE + 2 * (unsigned)i, (uint32_t)w);
    host_write(r, FP3_HR_IMEM_BASE + 2 * (unsigned)i + 1, (uint32_t)(w >> 32));
  }
  return 0;
}

static int check_reg(fp3_engine *e, unsigned context, unsigned reg) {
  if (context >= fp3_config_slots(&e->config)) {
    snprintf(e->error, sizeof e->error,
             "object slot %u out of range (the model has %u contexts x %u lanes)", context,
             e->config.num_contexts, e->config.num_lanes);
    return -1;
  }
  if (reg >= e->config.num_regs) {
    snprintf(e->error, sizeof e->error, "register r%u out of range (the model has %u)",
             reg, e->config.num_regs);
    return -1;
  }
  return 0;
}

static int rtl_write_reg(fp3_engine *e, unsigned context, unsigned reg, uint32_t value) {
  if (check_reg(e, context, reg)) return -1;
  select_slot((rtl_engine *)e, context);
  host_write((rtl_engine *)e, FP3_HR_REG_BASE + reg, value);
  return 0;
}

static int rtl_read_reg(fp3_engine *e, unsigned context, unsigned reg, uint32_t *value) {
  if (check_reg(e, context, reg)) return -1;
  select_slot((rtl_engine *)e, context);
  *value = host_read((rtl_engine *)e, FP3_HR_REG_BASE + reg);
  return 0;
}

static int rtl_ctx_status(fp3_engine *e, unsigned context, fp3_ctx_status *cs) {
  if (check_reg(e, context, 0)) return -1;
  *cs = ((rtl_engine *)e)->cs[context];
  return 0;
}

static int rtl_run_once(fp3_engine *e, uint32_t steps, unsigned contexts,
                        const fp3_observer *obs, fp3_status *st) {
  rtl_engine *r = (rtl_engine *)e;
  tag_fifo fifo[FP3_NUM_UNITS];   /* [unit]: write-back port u is unit u + 1 */
  memset(fifo, 0, sizeof fifo);
  memset(st, 0, sizeof *st);
  memset(r->cs, 0, sizeof r->cs);
  const unsigned nc = e->config.num_contexts, nl = e->config.num_lanes;
  /* Contexts started: every lane of each; a count beyond the slots is
   * given as it is, for the RTL to refuse (BAD_CONTEXTS). */
  const unsigned hw = contexts <= nc || contexts > nc * nl ? contexts : nc;

  host_write(r, FP3_HR_STEPS, steps);
  host_write(r, FP3_HR_CONTEXTS, hw);
  /* run cycle 0 is the one after the START write */
  if (r->win_set)
    r->mops->trace_window(r->model,
                          r->win_first == UINT64_MAX ? UINT64_MAX : r->win_first + 1,
                          r->win_count);
  host_write(r, FP3_HR_CTRL, FP3_CTRL_START);

  uint32_t endis[FP3_MAX_CONTEXTS] = {0};
  uint64_t limit = fp3_config_cycle_limit(&e->config, steps, hw);
  fp3_model_out out;
  for (uint64_t cycle = 0;; cycle++) {
    r->mops->cycle(r->model, NULL, &out);
    if (!out.running) break; /* START refused (STEPS = 0) or run over */
    if (cycle > limit) {
      snprintf(e->error, sizeof e->error, "RTL hung: no DONE after %llu cycles",
               (unsigned long long)cycle);
      return -1;
    }
    /* Write-backs of this cycle belong to instructions issued earlier. */
    for (unsigned u = 0; u < FP3_MODEL_WB_PORTS; u++) {
      if (!out.wb_valid[u]) continue;
      tag_fifo *f = &fifo[u + 1];
      if (f->count == 0) {
        snprintf(e->error, sizeof e->error,
                 "RTL fault: write-back on port %u in cycle %llu without an issue", u,
                 (unsigned long long)cycle);
        return -1;
      }
      unsigned ctx = f->ctx[f->head];
      uint32_t integ = f->integ[f->head];
      f->head = (f->head + 1) % TAG_FIFO;
      f->count--;
      if (ctx != out.wb_ctx[u]) {
        snprintf(e->error, sizeof e->error,
                 "RTL fault: write-back on port %u in cycle %llu for context %u, "
                 "issued by context %u", u, (unsigned long long)cycle, out.wb_ctx[u], ctx);
        return -1;
      }
      for (unsigned l = 0, s = ctx; l < nl && s < contexts; l++, s += nc)
        fp3_observe_write(obs, s, out.wb_reg[u], out.wb_data[u][l], integ);
    }
    if (out.issue && out.issue_unit >= FP3_NUM_UNITS) {
      snprintf(e->error, sizeof e->error, "RTL fault: issue to unit %u in cycle %llu",
               out.issue_unit, (unsigned long long)cycle);
      return -1;
    }
    if (out.issue) st->unit_issued[out.issue_unit]++;
    if (out.issue && out.issue_unit != FP3_UNIT_NONE) {
      tag_fifo *f = &fifo[out.issue_unit];
      if (f->count == TAG_FIFO) {
        snprintf(e->error, sizeof e->error, "RTL fault: unit %u has more than %d operations in flight",
                 out.issue_unit, TAG_FIFO);
        return -1;
      }
      unsigned slot = (f->head + f->count) % TAG_FIFO;
      f->ctx[slot] = (uint8_t)out.issue_ctx;
      f->integ[slot] = endis[out.issue_ctx % FP3_MAX_CONTEXTS] + 1;
      f->count++;
    }
    if (out.endi) {
      unsigned ctx = out.issue_ctx % FP3_MAX_CONTEXTS;
      endis[ctx]++;
      for (unsigned l = 0, s = ctx; l < nl && s < contexts; l++, s += nc)
        fp3_observe_endi(obs, s, endis[ctx], cycle);
    }
  }
  for (unsigned u = 1; u < FP3_NUM_UNITS; u++) {
    if (fifo[u].count) {
      snprintf(e->error, sizeof e->error, "RTL fault: run ended with %u results of unit %u missing",
               fifo[u].count, u);
      return -1;
    }
  }

  for (unsigned c = 0; c < nc; c++) {
    select_ctx(r, c);
    fp3_ctx_status cs;
    cs.error = (host_read(r, FP3_HR_STATUS) >> FP3_STATUS_ERROR_LSB) & 0xF;
    cs.fault_pc = host_read(r, FP3_HR_FAULT_PC);
    cs.steps_done = host_read(r, FP3_HR_STEPS_DONE);
    for (unsigned l = 0; l < nl; l++) {
      select_lane(r, l);
      cs.flags = host_read(r, FP3_HR_FLAGS);
      r->cs[l * nc + c] = cs;
      if (l * nc + c < contexts) st->flags |= cs.flags;
    }
  }
  select_ctx(r, 0);
  uint32_t status = host_read(r, FP3_HR_STATUS);
  st->done = (status & FP3_STATUS_DONE) != 0;
  st->any_error = (status & FP3_STATUS_ANY_ERROR) != 0;
  st->error = r->cs[0].error;
  st->fault_pc = r->cs[0].fault_pc;
  st->steps_done = r->cs[0].steps_done;
  st->cycles = host_read64(r, FP3_HR_CYCLES_LO);
  st->issued = host_read64(r, FP3_HR_ISSUED_LO);
  st->stalls = host_read64(r, FP3_HR_STALLS_LO);
  host_write(r, FP3_HR_CTRL, FP3_CTRL_CLEAR);
  return 0;
}

/* A run, remembered for the waveform (trace_finish). */
static int rtl_run(fp3_engine *e, uint32_t steps, unsigned contexts,
                   const fp3_observer *obs, fp3_status *st) {
  rtl_engine *r = (rtl_engine *)e;
  int rc = rtl_run_once(e, steps, contexts, obs, st);
  if (rc == 0) r->run_ok = 1;
  else r->run_failed = 1;
  return rc;
}

static void rtl_destroy(fp3_engine *e) {
  rtl_engine *r = (rtl_engine *)e;
  r->mops->destroy(r->model);
  trace_finish(r);
  free(r->trace_path);
  free(r);
}

static const fp3_engine_ops rtl_ops = {
    "rtl", rtl_load_program, rtl_write_reg, rtl_read_reg, rtl_run, rtl_ctx_status, rtl_destroy,
    0, /* traced: the trace port reports every write-back */
};

/* The Verilated builds, one per core configuration. */
static const fp3_model_ops *model_of(fpref_mode mode) {
#define X(name, rtz, ftz_on)                                                   \
  if ((mode.round == FPREF_RTZ) == (rtz) && (mode.ftz != 0) == (ftz_on))       \
    return &fp3_model_##name;
  FP3_MODEL_CONFIGS(X)
#undef X
  return NULL;
}

fp3_engine *fp3_engine_rtl_new_mode(fpref_mode mode, const char *trace_path) {
  return fp3_engine_rtl_new_model(model_of(mode), trace_path);
}

fp3_engine *fp3_engine_rtl_new_model(const void *model_ops, const char *trace_path) {
  if (!model_ops) return NULL;
  rtl_engine *r = calloc(1, sizeof *r);
  if (!r) return NULL;
  r->mops = model_ops;
  r->ctx_sel = UINT_MAX;
  r->lane_sel = UINT_MAX;
  r->read_cycles = 5; /* the longest, until INFO1 and INFO2 tell */
  r->trace_slot = -1;
  if (trace_path) {
    if (!(r->trace_path = strdup(trace_path))) {
      free(r);
      return NULL;
    }
    if ((r->trace_slot = trace_claim(trace_path)) < 0) {
      free(r->trace_path);
      free(r);
      return NULL;
    }
  }
  r->model = r->mops->create(trace_path ? trace_tmp[r->trace_slot] : NULL);
  if (!r->model) {
    trace_finish(r); /* no run: removed, should the writer have created it */
    free(r->trace_path);
    free(r);
    return NULL;
  }
  r->base.ops = &rtl_ops;
  /* The configuration the model was built with, from its INFO registers;
   * INFO1 and INFO2 first, which say how long the others take to read:
   * 1 + 3 FMAX_PIPE cycles, and one more with lanes (fp3_top "Host
   * port"). */
  uint32_t info1 = host_read(r, FP3_HR_INFO1);
  const uint32_t info2 = host_read(r, FP3_HR_INFO2);
  r->read_cycles = FP3_HOST_READ_CYCLES((info1 >> 18) & 1, info2 >> 24);
  uint32_t info0 = host_read(r, FP3_HR_INFO0);
  r->base.config.num_contexts = info2 & 0xFFFF;
  r->base.config.has_add = (info2 >> 16) & 1;
  r->base.config.has_sub = (info2 >> 17) & 1;
  r->base.config.has_mul = (info2 >> 18) & 1;
  r->base.config.has_div = (info2 >> 19) & 1;
  r->base.config.has_sqrt = (info2 >> 20) & 1;
  r->base.config.has_sign = (info2 >> 21) & 1;
  r->base.config.wb_ports = (info2 >> 22) & 1 ? 1 : 4;
  r->base.config.div_latency = (info1 >> 19) & 0xFF;
  r->base.config.num_lanes = info2 >> 24;
  if (r->base.config.num_contexts > FP3_MAX_CONTEXTS || r->base.config.num_lanes == 0 ||
      r->base.config.num_lanes > FP3_MAX_LANES) {
    fprintf(stderr, "fp3: the RTL model has %u contexts and %u lanes, outside 1 .. %d and "
            "1 .. %d\n", r->base.config.num_contexts, r->base.config.num_lanes,
            FP3_MAX_CONTEXTS, FP3_MAX_LANES);
    rtl_destroy(&r->base);
    return NULL;
  }
  r->base.config.num_regs = info0 & 0xFFFF;
  r->base.config.imem_depth = info0 >> 16;
  r->base.config.add_latency = info1 & 0xFF;
  r->base.config.mul_latency = (info1 >> 8) & 0xFF;
  r->base.config.mode.round = (info1 >> 16) & 1 ? FPREF_RTZ : FPREF_RNE;
  r->base.config.mode.ftz = (info1 >> 17) & 1;
  r->base.config.fmax_pipe = (info1 >> 18) & 1;
  if (host_read(r, FP3_HR_ID) != FP3_ID_VALUE) {
    fprintf(stderr, "fp3: the RTL model answers with a wrong ID register\n");
    rtl_destroy(&r->base);
    return NULL;
  }
  return &r->base;
}

int fp3_engine_rtl_trace_window(fp3_engine *e, uint64_t first, uint64_t count) {
  if (!e || e->ops != &rtl_ops) return -1;
  rtl_engine *r = (rtl_engine *)e;
  r->win_set = 1;
  r->win_first = first;
  r->win_count = count;
  r->mops->trace_window(r->model, UINT64_MAX, 0); /* nothing before a run */
  return 0;
}

fp3_engine *fp3_engine_rtl_new(const char *trace_path) {
  return fp3_engine_rtl_new_mode(FPREF_IEEE, trace_path);
}
