/*
 * configure.c -- hardware sized to the scene (configure.h).
 */
#include "configure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fp3_isa.h"
#include "fpenv.h"
#include "image.h"
#include "modelref.h"

/* xc2v LUTs of fp_add and fp_mul at the default latencies, per candidate
 * mode (RNE, RTZ, RNE+FTZ, RTZ+FTZ): docs/fpga.md "FP cores", `make synth`. */
static const unsigned add_luts[FP3_CONFIGURE_MODES] = {914, 764, 951, 818};
static const unsigned mul_luts[FP3_CONFIGURE_MODES] = {1356, 1337, 779, 813};

void fp3_configure_defaults(fp3_configure_opts *o) {
  o->integrator = "rk4";
  o->literal = 0;
  o->budget = 1e-4;
  o->steps = 1000;
  o->context_per_object = 0;
  o->max_lanes = FP3_CONFIGURE_MAX_LANES;
  o->device = NULL;
  o->wb_ports = 0;
}

int fp3_configure_line(const fp3_config *c, char *buf, size_t n) {
  return snprintf(buf, n,
                  "NUM_CONTEXTS=%u NUM_LANES=%u NUM_REGS=%u HAS_ADD=%u HAS_SUB=%u HAS_MUL=%u "
                  "HAS_DIV=%u HAS_SQRT=%u HAS_SIGN=%u ROUND=%d FTZ=%d ADD_LATENCY=%u "
                  "MUL_LATENCY=%u WB_PORTS=%u",
                  c->num_contexts, c->num_lanes ? c->num_lanes : 1, c->num_regs, c->has_add,
                  c->has_sub, c->has_mul, c->has_div, c->has_sqrt, c->has_sign,
                  c->mode.round == FPREF_RTZ ? 1 : 0, c->mode.ftz ? 1 : 0,
                  c->add_latency ? c->add_latency : FP3_DEFAULT_ADD_LATENCY,
                  c->mul_latency ? c->mul_latency : FP3_DEFAULT_MUL_LATENCY,
                  c->wb_ports == 1 ? 1u : 4u);
}

/* The first pc of each unit's instructions in img (r->unit_pc, -1: none). */
static void find_units(const fp3_image *img, int unit_pc[FP3_CONFIGURE_UNITS]) {
  for (int u = 0; u < FP3_CONFIGURE_UNITS; u++) unit_pc[u] = -1;
  for (size_t pc = 0; pc < img->n; pc++) {
    int u = -1;
    switch (fp3_insn_opc(img->words[pc])) {
    case FP3_OP_ADD: u = 0; break;
    case FP3_OP_SUB: u = 1; break;
    case FP3_OP_MUL: u = 2; break;
    case FP3_OP_DIV: u = 3; break;
    case FP3_OP_SQRT: u = 4; break;
    case FP3_OP_ABS: case FP3_OP_NEG: case FP3_OP_MIN: case FP3_OP_MAX: u = 5; break;
    }
    if (u >= 0 && unit_pc[u] < 0) unit_pc[u] = (int)pc;
  }
}

/* Highest register a word of img names, or a binding names, plus one. */
static unsigned regs_named(const fp3_image *img) {
  unsigned top = 0;
  for (size_t pc = 0; pc < img->n; pc++) {
    const int uses = fp3_opc_uses(fp3_insn_opc(img->words[pc]));
    if (uses <= 0) continue;
    const unsigned reg[3] = {fp3_insn_rd(img->words[pc]), fp3_insn_ra(img->words[pc]),
                             fp3_insn_rb(img->words[pc])};
    const int bit[3] = {FP3_USES_RD, FP3_USES_RA, FP3_USES_RB};
    for (int f = 0; f < 3; f++)
      if ((uses & bit[f]) && reg[f] + 1 > top) top = reg[f] + 1;
  }
  for (unsigned i = 0; i < img->nbind_in + img->nbind_out; i++) {
    const fp3_binding *bd = i < img->nbind_in ? &img->bind_in[i] : &img->bind_out[i - img->nbind_in];
    if ((unsigned)bd->reg + 1 > top) top = (unsigned)bd->reg + 1;
  }
  return top;
}

/* max_k |x_k - e_k| / max(max_k |e_k|, 1) */
static double rel_error(double maxdiff, double maxabs) {
  return maxdiff / (maxabs > 1.0 ? maxabs : 1.0);
}

/* Reference states of one model object at every integration (GSL). */
typedef struct refrec {
  unsigned ns;
  double *y;   /* steps x ns */
  double *ymax;
} refrec;

static void ref_cb(void *ctx, uint32_t k, const double *y) {
  refrec *rr = ctx;
  for (unsigned i = 0; i < rr->ns; i++) {
    rr->y[(size_t)(k - 1) * rr->ns + i] = y[i];
    if (fabs(y[i]) > rr->ymax[i]) rr->ymax[i] = fabs(y[i]);
  }
}

/* The error of every candidate mode for a model scene: the compiled
 * program's golden model in each mode (host values in the same mode)
 * against the GSL reference (modelref.h) at every integration, the same
 * relative measure max_k |x_k - e_k| / max(max_k |e_k|, 1) of every state
 * variable, the largest. */
static int measure_model_modes(fp3_compiled *c, const fp3_mscene *sc, uint32_t steps,
                               fp3_configure_result *r, char *msg, size_t n) {
  const fp3_model *m = sc->model;
  const unsigned ns = m->nstate, np = m->nparam;
  double ymax[FP3_MODEL_MAX_VARS];
  refrec rr = {ns, malloc((size_t)steps * ns * sizeof(double)), ymax};
  if (!rr.y) {
    snprintf(msg, n, "out of memory");
    return -1;
  }
  for (int k = 0; k < FP3_CONFIGURE_MODES; k++)
    r->err[k] = r->added[k] = fpenv_supported(r->mode[k]) ? 0.0 : NAN;
  for (size_t i = 0; i < sc->n; i++) {
    double din[FP3_MODEL_MAX_VARS], dy0[FP3_MODEL_MAX_VARS], yend[FP3_MODEL_MAX_VARS];
    for (unsigned k = 0; k < np; k++) din[k] = sc->in[i * np + k];
    for (unsigned k = 0; k < ns; k++) dy0[k] = sc->y0[i * ns + k], ymax[k] = 0.0;
    char rmsg[256];
    if (fp3_model_gsl(m, din, dy0, steps, ref_cb, &rr, yend, rmsg, sizeof rmsg)) {
      snprintf(msg, n, "object %zu: the reference failed: %s", i, rmsg);
      free(rr.y);
      return -1;
    }
    double e_rne = 0;
    for (int md = 0; md < FP3_CONFIGURE_MODES; md++) {
      if (isnan(r->err[md])) continue;
      fpenv_saved env;
      if (fpenv_enter(r->mode[md], &env)) continue;
      unsigned wr[512];
      uint32_t wv[512];
      double d[FP3_MODEL_MAX_VARS] = {0};
      float y[FP3_MODEL_MAX_VARS];
      fp3_compiled_model_start(c, sc->in + i * np, sc->y0 + i * ns, wr, wv, 512);
      for (uint32_t k = 1; k <= steps; k++) {
        fp3_compiled_model_step(c, y);
        for (unsigned v = 0; v < ns; v++) { /* non-finite: infinitely wrong */
          double ev = isfinite(y[v]) ? fabs((double)y[v] - rr.y[(size_t)(k - 1) * ns + v])
                                     : INFINITY;
          if (ev > d[v]) d[v] = ev;
        }
      }
      fpenv_leave(&env);
      double e = 0;
      for (unsigned v = 0; v < ns; v++) e = fmax(e, rel_error(d[v], ymax[v]));
      if (md == 0) e_rne = e;
      if (e > r->err[md]) r->err[md] = e;
      if (md > 0 && e - e_rne > r->added[md]) r->added[md] = e - e_rne;
    }
  }
  free(rr.y);
  return 0;
}

/* What is configured: a model scene and its params zero in every object. */
typedef struct cfg_src {
  const fp3_mscene *ms;
  unsigned char zero[FP3_MODEL_MAX_VARS];
} cfg_src;

static int configure_src(const cfg_src *src, const fp3_configure_opts *o,
                         fp3_configure_result *r, fp3_compiled **compiled, char *msg,
                         size_t n);

int fp3_configure_model(const fp3_mscene *sc, const fp3_configure_opts *o,
                        fp3_configure_result *r, fp3_compiled **compiled, char *msg,
                        size_t n) {
  cfg_src src;
  memset(&src, 0, sizeof src);
  src.ms = sc;
  const fp3_model *m = sc->model;
  for (unsigned k = 0; k < m->nparam; k++) {
    src.zero[k] = sc->n > 0;
    for (size_t i = 0; i < sc->n && src.zero[k]; i++)
      src.zero[k] = sc->in[i * m->nparam + k] == 0.0f;
  }
  return configure_src(&src, o, r, compiled, msg, n);
}

static int configure_src(const cfg_src *src, const fp3_configure_opts *o,
                         fp3_configure_result *r, fp3_compiled **compiled, char *msg,
                         size_t n) {
  memset(r, 0, sizeof *r);
  const size_t nobj = src->ms->n;
  if (compiled) *compiled = NULL;
  if (nobj == 0) {
    snprintf(msg, n, "the scene has no objects");
    return -1;
  }
  if (!(o->budget > 0.0) || !isfinite(o->budget)) {
    snprintf(msg, n, "the error budget must be a positive number");
    return -1;
  }
  if (o->steps == 0) {
    snprintf(msg, n, "the accuracy check needs at least one integration");
    return -1;
  }
  if (o->max_lanes < 1 || o->max_lanes > FP3_MAX_LANES) {
    snprintf(msg, n, "NUM_LANES at most %u: want 1 .. %d lanes", o->max_lanes, FP3_MAX_LANES);
    return -1;
  }
  if (o->wb_ports != 0 && o->wb_ports != 1 && o->wb_ports != 4) {
    snprintf(msg, n, "%u write-back ports: want 1 or 4 (0: chosen)", o->wb_ports);
    return -1;
  }
  const char *integ = o->integrator ? o->integrator : "rk4";
  fp3_compile_opts co;
  fp3_compile_defaults(&co);
  if (o->literal) co.fold = co.drop_zero = 0;

  /* the program as fp3 run --scene compiles it for the default build, or
   * for the fewest registers above its NUM_REGS it fits */
  fp3_compiled *c = NULL;
  co.max_regs = FP3_MAX_REGS;
  if (fp3_compile_model(src->ms->model, integ, &co, src->zero, &c, msg, n)) return -1;

  /* write-back ports: one unless the program divides or takes a root
   * (the units do not depend on the latencies compiled for) */
  find_units(fp3_compiled_image(c), r->unit_pc);
  const int has_divsqrt = r->unit_pc[3] >= 0 || r->unit_pc[4] >= 0;
  if (o->wb_ports == 1 && has_divsqrt) {
    const int u = r->unit_pc[3] >= 0 ? 3 : 4;
    snprintf(msg, n, "one write-back port needs a program without div and sqrt (their unit "
             "writes back later than the others); this one has %s at pc %d",
             u == 3 ? "div" : "sqrt", r->unit_pc[u]);
    fp3_compiled_free(c);
    return -1;
  }
  r->cfg.wb_ports = o->wb_ports ? o->wb_ports : has_divsqrt ? 4 : 1;
  r->cfg.add_latency = FP3_DEFAULT_ADD_LATENCY;
  r->cfg.mul_latency = FP3_DEFAULT_MUL_LATENCY;
  if (r->cfg.wb_ports == 1) {
    /* every unit writes back at the same latency: the longer default */
    const unsigned lat = r->cfg.add_latency > r->cfg.mul_latency ? r->cfg.add_latency
                                                                  : r->cfg.mul_latency;
    r->cfg.add_latency = r->cfg.mul_latency = lat;
    /* the options fp3 run --scene takes from such a build */
    fp3_compile_opts_for(&co, &r->cfg);
    if (o->literal) co.fold = co.drop_zero = 0;
    co.num_regs = FP3_DEFAULT_NUM_REGS;
    co.max_regs = FP3_MAX_REGS;
    fp3_compiled_free(c);
    c = NULL;
    if (fp3_compile_model(src->ms->model, integ, &co, src->zero, &c, msg, n)) return -1;
  }
  co.max_regs = 0;
  co.num_regs = fp3_compiled_stats(c)->num_regs;
  r->regs_default = regs_named(fp3_compiled_image(c));
  r->est_first = fp3_compiled_stats(c)->est_cycles_first;
  r->est_later = fp3_compiled_stats(c)->est_cycles_later;
  r->body_insns = fp3_compiled_stats(c)->body_insns;

  /* the fewest registers that lose no cycle; the build compiles for them */
  r->cfg.num_regs = co.num_regs;
  for (unsigned k = 4; k <= r->regs_default && k < co.num_regs; k++) {
    fp3_compile_opts ko = co;
    ko.num_regs = k;
    fp3_compiled *ck = NULL;
    char kmsg[256];
    if (fp3_compile_model(src->ms->model, integ, &ko, src->zero, &ck, kmsg, sizeof kmsg)) continue;
    const fp3_compile_stats *st = fp3_compiled_stats(ck);
    if (st->est_cycles_first == r->est_first && st->est_cycles_later == r->est_later) {
      fp3_compiled_free(c);
      c = ck;
      r->cfg.num_regs = k;
      break;
    }
    fp3_compiled_free(ck);
  }
  const fp3_image *img = fp3_compiled_image(c);
  r->regs_used = regs_named(img);

  /* units (their pcs in the program the build runs) */
  find_units(img, r->unit_pc);
  r->cfg.has_add = r->unit_pc[0] >= 0 || r->unit_pc[1] >= 0;
  r->cfg.has_sub = r->unit_pc[1] >= 0;
  r->cfg.has_mul = r->unit_pc[2] >= 0;
  r->cfg.has_div = r->unit_pc[3] >= 0;
  r->cfg.has_sqrt = r->unit_pc[4] >= 0;
  r->cfg.has_sign = r->unit_pc[5] >= 0;
  r->cfg.div_latency = FP3_DEFAULT_DIV_LATENCY;

  r->objects = nobj;
  /* contexts that keep the issue slot busy: one object's integration
   * takes est_later cycles for body_insns issues */
  r->contexts_issue = (r->est_later + r->body_insns - 1) / r->body_insns;
  if (r->contexts_issue < 1) r->contexts_issue = 1;
  size_t nc = o->context_per_object ? FP3_MAX_CONTEXTS : r->contexts_issue;
  if (nc > FP3_MAX_CONTEXTS) nc = FP3_MAX_CONTEXTS;
  if (nc > nobj) nc = nobj;
  r->cfg.num_contexts = (unsigned)nc;
  /* lanes: the rest of the scene in flight beside the contexts */
  size_t nl = nc ? (nobj + nc - 1) / nc : 1;
  r->lanes_scene = nl > FP3_MAX_LANES ? FP3_MAX_LANES : (unsigned)nl;
  if (nl > o->max_lanes) nl = o->max_lanes;
  if (o->device) {
    const unsigned dl = fp3_device_lanes(o->device, (unsigned)nc, r->cfg.num_regs,
                                         (int)r->cfg.has_mul, r->cfg.wb_ports, &r->fit);
    if (dl == 0) {
      snprintf(msg, n, "the %s (%s) does not hold one lane of this build (%s): %u + %u "
               "LUT4s against %u (%u per mille of its %u, the share that routes), %u "
               "MULT18X18D of %u, %u EBR of %u",
               o->device->part, o->device->name, r->fit.limit, r->fit.luts_fixed,
               r->fit.luts_lane0, r->fit.luts_allowed, r->fit.routable_permille,
               o->device->luts, r->fit.dsp_lane, o->device->dsps, r->fit.ebr_fixed + r->fit.ebr_lane,
               o->device->ebrs);
      fp3_compiled_free(c);
      return -1;
    }
    if (nl > dl) nl = dl;
  }
  r->cfg.num_lanes = (unsigned)nl;
  r->cfg.imem_depth = FP3_DEFAULT_IMEM_DEPTH;

  /* rounding and subnormals */
  for (int m = 0; m < FP3_CONFIGURE_MODES; m++) {
    r->mode[m].round = (m & 1) ? FPREF_RTZ : FPREF_RNE;
    r->mode[m].ftz = (m & 2) ? 1 : 0;
    r->luts[m] = (r->cfg.has_add ? add_luts[m] : 0) + (r->cfg.has_mul ? mul_luts[m] : 0);
  }
  if (measure_model_modes(c, src->ms, o->steps, r, msg, n)) {
    fp3_compiled_free(c);
    return -1;
  }
  r->chosen = 0;
  for (int m = 0; m < FP3_CONFIGURE_MODES; m++) {
    r->allowed[m] = m == 0 || (!isnan(r->err[m]) && r->added[m] <= o->budget);
    if (r->allowed[m] && r->luts[m] < r->luts[r->chosen]) r->chosen = m;
  }
  r->cfg.mode = r->mode[r->chosen];
  if (compiled) *compiled = c;
  else fp3_compiled_free(c);
  return 0;
}
