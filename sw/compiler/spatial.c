/*
 * spatial.c -- the spatial back end (spatial.h): an ASAP schedule of the
 * compiled IR on one core per operation, delay lines that balance every
 * path, the Verilog module, its report and its test vectors.
 */
#include "spatial.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fpenv.h"
#include "fpref.h"
#include "report.h"

/* Where a node's value comes from in the module. */
enum src_kind { SRC_NONE, SRC_CONST, SRC_INPUT, SRC_STATE, SRC_CORE };

/* One IR node as the pipeline sees it. */
typedef struct snode {
  fp3_ir_node ir;
  int src;          /* enum src_kind                                     */
  int slot;         /* SRC_INPUT: its word of in_i                       */
  unsigned start;   /* SRC_CORE: the cycle its core samples the operands */
  unsigned ready;   /* the cycle its value is on its wire                */
  unsigned delay;   /* the longest delay any reader needs (0: none)      */
  int scale;        /* SRC_CORE mul: -1 fp_mul, else the operand (0 a, 1
                       b) that is a power of two: an fp_scaleb core      */
  unsigned char *tap; /* tap[d] = 1: a reader takes it d cycles late     */
  char sig[64];     /* its wire: nI_NAME                                 */
} snode;

struct fp3_spatial {
  fp3_compiled *c;
  const fp3_model *m;
  char integ[16];
  fp3_spatial_opts o;
  unsigned nn;
  snode *nd;
  unsigned ninput;  /* slots of in_i                                     */
  int *input_node;  /* the node of each slot                             */
  unsigned ncarried;
  char module[96];
  char *verilog;
  char *report;
  fp3_spatial_stats st;
};

static const char *const kind_name[FP3_IR_KINDS] = {
    "input", "const", "state", "add", "sub", "mul", "div", "sqrt", "abs", "neg", "min", "max"};
static const char *const kind_symbol[FP3_IR_KINDS] = {
    "", "", "", "+", "-", "*", "/", "sqrt", "abs", "neg", "min", "max"};

void fp3_spatial_defaults(fp3_spatial_opts *o) {
  fp3_compile_opts c;
  fp3_compile_defaults(&c);
  o->add_latency = c.add_latency;
  o->mul_latency = c.mul_latency;
  o->mul_feed = 0;
  o->mul_blocks = 4;
  o->div_latency = c.div_latency;
  o->sign_latency = 1;
  o->scaleb_latency = 2;
  o->scaleb = 1;
  o->rtz = 0;
  o->ftz = 0;
}

void fp3_spatial_clock_cores(fp3_spatial_opts *o) {
  o->add_latency = 9;
  o->mul_latency = 10;
  o->mul_feed = 1;
  o->div_latency = 34;
  o->sign_latency = 1;
  o->scaleb_latency = 4;
}

static unsigned core_latency(const fp3_spatial_opts *o, int kind) {
  switch (kind) {
  case FP3_IR_ADD:
  case FP3_IR_SUB: return o->add_latency;
  case FP3_IR_MUL: return o->mul_latency;
  case FP3_IR_DIV:
  case FP3_IR_SQRT: return o->div_latency;
  default: return o->sign_latency;
  }
}

/* A binary32 pattern that is +-2^k, normal: fraction 0, exponent field 1
 * to 254 (what rtl/fp_scaleb.v takes as b). */
static int is_pow2(uint32_t bits) {
  const uint32_t e = (bits >> 23) & 0xFF;
  return (bits & 0x7FFFFF) == 0 && e >= 1 && e <= 254;
}

static int is_op(int kind) { return kind >= FP3_IR_ADD && kind < FP3_IR_KINDS; }

/* A Verilog identifier from a model name: letters, digits, '_'. */
static void ident(char *d, size_t n, const char *s) {
  size_t k = 0;
  for (; *s && k + 1 < n; s++) d[k++] = isalnum((unsigned char)*s) ? *s : '_';
  d[k] = 0;
}

/* The module's text for node i's value read `d` cycles after it is ready. */
static void operand(const struct fp3_spatial *s, int i, unsigned d, char *buf, size_t n) {
  const snode *x = &s->nd[i];
  if (x->src == SRC_CONST) snprintf(buf, n, "32'h%08X", (unsigned)x->ir.bits);
  else if (d == 0) snprintf(buf, n, "%s", x->sig);
  else snprintf(buf, n, "%s_d%u", x->sig, d);
}

/* A node's name for comments: the model's, else a constant's value or nI. */
static void label(const struct fp3_spatial *s, int i, char *buf, size_t n) {
  const snode *x = &s->nd[i];
  if (x->src == SRC_CONST) snprintf(buf, n, "%.9g", (double)fpref_float(x->ir.bits));
  else if (x->ir.name[0]) snprintf(buf, n, "%s", x->ir.name);
  else snprintf(buf, n, "n%d", i);
}

/* "k1 = h * v" for an operation node. */
static void describe(const struct fp3_spatial *s, int i, char *buf, size_t n) {
  const snode *x = &s->nd[i];
  char me[64], a[64], b[64];
  label(s, i, me, sizeof me);
  label(s, x->ir.a, a, sizeof a);
  if (x->ir.b < 0) snprintf(buf, n, "%s = %s(%s)", me, kind_symbol[x->ir.kind], a);
  else {
    label(s, x->ir.b, b, sizeof b);
    if (x->ir.kind == FP3_IR_MIN || x->ir.kind == FP3_IR_MAX)
      snprintf(buf, n, "%s = %s(%s, %s)", me, kind_symbol[x->ir.kind], a, b);
    else snprintf(buf, n, "%s = %s %s %s", me, a, kind_symbol[x->ir.kind], b);
  }
}

/* The host's expression of node i, from the inputs and constants
 * ("(h * minv) * C"), into the n bytes of buf. */
static void expr(const struct fp3_spatial *s, int i, char *buf, size_t n) {
  const snode *x = &s->nd[i];
  const int k = x->ir.kind;
  if (!is_op(k)) {
    if (k == FP3_IR_CONST) snprintf(buf, n, "%.9g", (double)fpref_float(x->ir.bits));
    else if (k == FP3_IR_IN) snprintf(buf, n, "%s", fp3_ir_input_name(s->c, (unsigned)x->ir.id));
    else snprintf(buf, n, "%s", x->ir.name);
    return;
  }
  char a[128], b[128];
  int len; /* a long expression is cut at n - 1 characters: it is a comment */
  expr(s, x->ir.a, a, sizeof a);
  if (x->ir.b < 0) len = snprintf(buf, n, "%s(%s)", kind_symbol[k], a);
  else {
    expr(s, x->ir.b, b, sizeof b);
    if (k == FP3_IR_MIN || k == FP3_IR_MAX)
      len = snprintf(buf, n, "%s(%s, %s)", kind_symbol[k], a, b);
    else len = snprintf(buf, n, "(%s %s %s)", a, kind_symbol[k], b);
  }
  if (len >= (int)n && n > 4) memcpy(buf + n - 4, "...", 4);
}

/* Mark node i read d cycles after it is ready. */
static int need(struct fp3_spatial *s, int i, unsigned d) {
  snode *x = &s->nd[i];
  if (x->src == SRC_CONST || d == 0) return 0;
  if (d > x->delay) {
    unsigned char *t = realloc(x->tap, (size_t)d + 1);
    if (!t) return -1;
    memset(t + (x->delay ? x->delay + 1 : 0), 0, (size_t)d + 1 - (x->delay ? x->delay + 1 : 0));
    x->tap = t;
    x->delay = d;
  }
  x->tap[d] = 1;
  return 0;
}

/* The form of a delay segment of d stages (spatial.h's rule): 0
 * flip-flops, 1 LUT RAM, 2 block RAM. */
static int segment_style(unsigned d) {
  return d <= FP3_SPATIAL_FF_MAX ? 0 : d <= FP3_SPATIAL_LUTRAM_MAX ? 1 : 2;
}

/* The words of one ECP5 block RAM (DP16KD, PDPW16KD) 36 bits wide; a
 * delay line of up to this many reads through the block's own output
 * register (rtl/fp_delay.v's ECP5 form). */
#define EBR_WORDS 512u

/* The words of rtl/fp_delay.v's RAM for a segment of d stages in `style`:
 * the power of two >= d - (read stages) + 1. */
static unsigned segment_words(unsigned d, int style) {
  unsigned gap = d - (style == 2 ? 2u : 1u), w = 2;
  while (w < gap + 1) w *= 2;
  return w;
}

/* Add a segment of d stages to the statistics. */
static void count_segment(fp3_spatial_stats *st, unsigned d) {
  const int style = segment_style(d);
  if (style == 0) {
    st->ff_segments++;
    st->ff_stages += d;
    st->delay_ffs += 32 * d;
  } else if (style == 1) {
    st->lutram_segments++;
    st->lutram_stages += d;
    st->lutram_cells += 8 * ((segment_words(d, 1) + 15) / 16); /* 16 words x 4 bits */
  } else {
    st->ebr_segments++;
    st->ebr_stages += d;
    st->ebr_blocks += (segment_words(d, 2) + EBR_WORDS - 1) / EBR_WORDS; /* 512 x 36, 1024 x 18, ... */
  }
}

/* ---- the area estimate ---- */

/* Pseudo-kinds of the area table beside the IR's: fp_scaleb, fp_mul with
 * its feed register (FEED = 1), fp_mul of three blocks (MULT_BLOCKS = 3)
 * without and with it; fp_sign (abs, neg, min, max) is FP3_IR_ABS. */
#define AREA_SCALEB FP3_IR_KINDS
#define AREA_MUL_FEED (FP3_IR_KINDS + 1)
#define AREA_MUL_B3 (FP3_IR_KINDS + 2)
#define AREA_MUL_FEED_B3 (FP3_IR_KINDS + 3)

/* One core configuration synthesized alone: Yosys 0.23 synth_ecp5 through
 * scripts/synth.sh ecp5 (FP3_ECP5_DSP: fp_mul's product in MULT18X18D
 * with their own registers at LATENCY 6 to 9, and at 10 with FEED = 1),
 * in make pnr-spatial's flow (SYNTH_ECP5_SDFF=0: no flip-flop with a
 * synchronous set or reset), measured by
 *   scripts/spatial-core-area.sh
 * which prints these rows.  LUT4s count a CCU2C as two.  The same core
 * maps to up to about 15 % more or fewer LUT4s from one configuration to
 * the next (ABC's mapping, not the logic), and the step module as a whole
 * maps to about 8 % fewer than the sum of its cores (the folded ship:
 * 16,775 against 18,114), so a pipeline's estimate is an upper bound. */
typedef struct core_area {
  int kind;          /* FP3_IR_ADD (also sub), _MUL, _DIV, _SQRT, _ABS
                        (fp_sign), AREA_SCALEB, AREA_MUL_FEED           */
  unsigned latency;
  int round, ftz;
  unsigned lut4, ff, mult;
} core_area;

#define SIGN FP3_IR_ABS
#define SCALEB AREA_SCALEB
#define MUL_FEED AREA_MUL_FEED
#define MUL_B3 AREA_MUL_B3
#define MUL_FEED_B3 AREA_MUL_FEED_B3
static const core_area core_areas[] = {
    {FP3_IR_ADD, 4, 0, 0, 1175, 291, 0}, /* fp_add */
    {FP3_IR_ADD, 4, 0, 1, 1011, 291, 0}, /* fp_add */
    {FP3_IR_ADD, 4, 1, 0, 1053, 291, 0}, /* fp_add */
    {FP3_IR_ADD, 9, 0, 0, 907, 729, 0}, /* fp_add */
    {FP3_IR_ADD, 9, 0, 1, 1029, 729, 0}, /* fp_add */
    {FP3_IR_ADD, 9, 1, 0, 1076, 729, 0}, /* fp_add */
    {FP3_IR_ADD, 10, 0, 0, 1096, 766, 0}, /* fp_add */
    {FP3_IR_ADD, 10, 0, 1, 1037, 766, 0}, /* fp_add */
    {FP3_IR_ADD, 10, 1, 0, 998, 766, 0}, /* fp_add */
    {FP3_IR_MUL, 3, 0, 0, 1693, 187, 4}, /* fp_mul */
    {FP3_IR_MUL, 3, 0, 1, 707, 185, 4}, /* fp_mul */
    {FP3_IR_MUL, 3, 1, 0, 1222, 187, 4}, /* fp_mul */
    {FP3_IR_MUL, 9, 0, 0, 1038, 626, 4}, /* fp_mul */
    {FP3_IR_MUL, 9, 0, 1, 542, 614, 4}, /* fp_mul */
    {FP3_IR_MUL, 9, 1, 0, 984, 626, 4}, /* fp_mul */
    {FP3_IR_MUL, 10, 0, 0, 2245, 1210, 0}, /* fp_mul */
    {FP3_IR_MUL, 10, 0, 1, 1670, 1196, 0}, /* fp_mul */
    {FP3_IR_MUL, 10, 1, 0, 2159, 1210, 0}, /* fp_mul */
    {MUL_FEED, 10, 0, 0, 1041, 693, 4}, /* fp_mul, FEED 1 */
    {MUL_FEED, 10, 0, 1, 546, 679, 4}, /* fp_mul, FEED 1 */
    {MUL_FEED, 10, 1, 0, 993, 693, 4}, /* fp_mul, FEED 1 */
    {MUL_B3, 3, 0, 0, 1843, 187, 3}, /* fp_mul, MULT_BLOCKS 3 */
    {MUL_B3, 3, 0, 1, 858, 185, 3}, /* fp_mul, MULT_BLOCKS 3 */
    {MUL_B3, 3, 1, 0, 1375, 187, 3}, /* fp_mul, MULT_BLOCKS 3 */
    {MUL_B3, 9, 0, 0, 1189, 677, 3}, /* fp_mul, MULT_BLOCKS 3 */
    {MUL_B3, 9, 0, 1, 714, 665, 3}, /* fp_mul, MULT_BLOCKS 3 */
    {MUL_B3, 9, 1, 0, 1144, 677, 3}, /* fp_mul, MULT_BLOCKS 3 */
    {MUL_FEED_B3, 10, 0, 0, 1199, 744, 3}, /* fp_mul, FEED 1 MULT_BLOCKS 3 */
    {MUL_FEED_B3, 10, 0, 1, 699, 730, 3}, /* fp_mul, FEED 1 MULT_BLOCKS 3 */
    {MUL_FEED_B3, 10, 1, 0, 1157, 744, 3}, /* fp_mul, FEED 1 MULT_BLOCKS 3 */
    {FP3_IR_DIV, 8, 0, 0, 2840, 840, 0}, /* fp_div */
    {FP3_IR_DIV, 8, 0, 1, 1966, 832, 0}, /* fp_div */
    {FP3_IR_DIV, 8, 1, 0, 2473, 840, 0}, /* fp_div */
    {FP3_IR_SQRT, 8, 0, 0, 1457, 512, 0}, /* fp_sqrt */
    {FP3_IR_SQRT, 8, 0, 1, 1011, 512, 0}, /* fp_sqrt */
    {FP3_IR_SQRT, 8, 1, 0, 1407, 512, 0}, /* fp_sqrt */
    {SCALEB, 1, 0, 0, 340, 37, 0}, /* fp_scaleb, b = 0.5 or 2 */
    {SCALEB, 1, 0, 1, 105, 37, 0}, /* fp_scaleb, b = 0.5 or 2 */
    {SCALEB, 1, 1, 0, 281, 37, 0}, /* fp_scaleb, b = 0.5 or 2 */
    {SCALEB, 2, 0, 0, 150, 80, 0}, /* fp_scaleb, b = 0.5 or 2 */
    {SCALEB, 2, 0, 1, 142, 80, 0}, /* fp_scaleb, b = 0.5 or 2 */
    {SCALEB, 2, 1, 0, 175, 80, 0}, /* fp_scaleb, b = 0.5 or 2 */
    {SCALEB, 4, 0, 0, 223, 205, 0}, /* fp_scaleb, b = 0.5 or 2 */
    {SCALEB, 4, 0, 1, 227, 205, 0}, /* fp_scaleb, b = 0.5 or 2 */
    {SCALEB, 4, 1, 0, 222, 206, 0}, /* fp_scaleb, b = 0.5 or 2 */
    {SIGN, 1, 0, 0, 337, 34, 0}, /* fp_sign */
};
#undef SIGN
#undef SCALEB
#undef MUL_FEED
#undef MUL_B3
#undef MUL_FEED_B3

/* The table's row for a core: its kind, FTZ and rounding if measured (else
 * the other rounding), at the nearest measured latency; *exact = 0 when
 * the configuration itself is not in the table. */
static const core_area *area_of(int kind, unsigned lat, int rtz, int ftz, int *exact) {
  const core_area *best = NULL;
  unsigned best_cost = ~0u;
  for (size_t k = 0; k < sizeof core_areas / sizeof core_areas[0]; k++) {
    const core_area *r = &core_areas[k];
    if (r->kind != kind) continue;
    /* a different FTZ costs most, a different latency by its distance, a
     * different rounding least (fp_sign has neither) */
    unsigned cost = (kind == FP3_IR_ABS ? 0 : 1000u * (r->ftz != ftz) + (r->round != rtz)) +
                    10u * (r->latency > lat ? r->latency - lat : lat - r->latency);
    if (cost < best_cost) {
      best = r;
      best_cost = cost;
    }
  }
  *exact = best_cost == 0;
  return best;
}

/* Add the estimate of the cores, the delay segments and the valid bit's
 * line, and the pipelines that fit. */
static void estimate(struct fp3_spatial *s) {
  fp3_spatial_stats *st = &s->st;
  for (unsigned i = 0; i < s->nn; i++) {
    const snode *x = &s->nd[i];
    if (x->src != SRC_CORE) continue;
    int kind = x->ir.kind, exact;
    unsigned lat = core_latency(&s->o, kind);
    if (kind == FP3_IR_SUB) kind = FP3_IR_ADD;
    if (kind >= FP3_IR_ABS) kind = FP3_IR_ABS;
    if (x->scale >= 0) {
      kind = AREA_SCALEB;
      lat = s->o.scaleb_latency;
    } else if (kind == FP3_IR_MUL && s->o.mul_blocks == 3) {
      kind = s->o.mul_feed ? AREA_MUL_FEED_B3 : AREA_MUL_B3;
    } else if (kind == FP3_IR_MUL && s->o.mul_feed) {
      kind = AREA_MUL_FEED;
    }
    const core_area *r = area_of(kind, lat, s->o.rtz, s->o.ftz, &exact);
    st->est_lut4 += r->lut4;
    st->est_ff += r->ff;
    st->est_mult += r->mult;
    st->est_inexact += !exact;
  }
  /* delay segments, by rtl/fp_delay.v's measured form (spatial.h's table):
   * a RAM segment's address counters are 2 x log2(words) flip-flops and
   * about as many LUT4s, its read register 32 flip-flops (and block RAM's
   * fabric register 32 more); a block-RAM segment of up to 512 words
   * reads through the block's own registers (fp_delay's ECP5 form): its
   * write counter alone is in the fabric */
  for (unsigned i = 0; i < s->nn; i++) {
    const snode *x = &s->nd[i];
    for (unsigned d = 1, prev = 0; x->delay && d <= x->delay; d++) {
      if (!x->tap[d]) continue;
      const unsigned len = d - prev;
      const int style = segment_style(len);
      prev = d;
      if (style == 0) {
        st->est_ff += 32 * len;
        continue;
      }
      const unsigned words = segment_words(len, style);
      unsigned aw = 0;
      for (unsigned w = words; w > 1; w /= 2) aw++;
      if (style == 2 && words <= EBR_WORDS) st->est_ff += aw;
      else st->est_ff += 2 * aw + (style == 1 ? 32 : 64);
      if (style == 1) st->est_lut4 += 6 * 8 * ((words + 15) / 16) + 2 * aw;
      else st->est_lut4 += 2 * aw;
    }
  }
  st->est_ff += st->latency; /* the valid bit */
  st->est_ebr = st->ebr_blocks;
  /* pipelines per device: the least over the resources */
  const struct { const char *name; unsigned budget, need; } res[] = {
      {"LUT4", FP3_SPATIAL_BUDGET_LUT4, st->est_lut4},
      {"flip-flops", FP3_SPATIAL_BUDGET_FF, st->est_ff},
      {"MULT18X18D", FP3_SPATIAL_BUDGET_MULT, st->est_mult},
      {"EBR", FP3_SPATIAL_BUDGET_EBR, st->est_ebr}};
  st->fit = ~0u;
  st->limit = "none";
  for (size_t k = 0; k < sizeof res / sizeof res[0]; k++) {
    if (!res[k].need) continue;
    const unsigned f = res[k].budget / res[k].need;
    if (f < st->fit) {
      st->fit = f;
      st->limit = res[k].name;
    }
  }
}

/* The schedule: sources, ASAP cycles, the pipeline's latency, the taps. */
static int schedule(struct fp3_spatial *s, char *msg, size_t n) {
  fp3_compiled *c = s->c;
  const unsigned carried = s->ncarried;
  unsigned char *used = calloc(s->nn ? s->nn : 1, 1);
  if (!used) goto oom;
  for (unsigned i = 0; i < s->nn; i++) {
    snode *x = &s->nd[i];
    fp3_ir_node_get(c, i, &x->ir);
    snprintf(x->sig, sizeof x->sig, "n%u", i);
    if (x->ir.name[0]) {
      char id[40];
      ident(id, sizeof id, x->ir.name);
      snprintf(x->sig, sizeof x->sig, "n%u_%s", i, id);
    }
  }
  /* what the pipeline reads: the live operations' operands (a host
   * value's operands are the host's) and the next carried values */
  for (unsigned i = 0; i < s->nn; i++) {
    const fp3_ir_node *x = &s->nd[i].ir;
    if (!is_op(x->kind) || !x->live || x->host) continue;
    used[i] = 1;
    used[x->a] = 1;
    if (x->b >= 0) used[x->b] = 1;
  }
  for (unsigned w = 0; w < carried; w++) used[fp3_ir_carried_next(c, w)] = 1;
  for (unsigned i = 0; i < s->nn; i++) {
    snode *x = &s->nd[i];
    if (!used[i]) continue;
    if (x->ir.kind == FP3_IR_CONST) x->src = SRC_CONST;
    else if (x->ir.kind == FP3_IR_STATE) x->src = SRC_STATE;
    else if (x->ir.kind == FP3_IR_IN || x->ir.host) {
      x->src = SRC_INPUT;
      x->slot = (int)s->ninput;
      s->input_node[s->ninput++] = (int)i;
    } else {
      /* operands come first in the IR: their cycles are known */
      unsigned t = 0;
      const snode *a = &s->nd[x->ir.a], *b = x->ir.b >= 0 ? &s->nd[x->ir.b] : NULL;
      if (a->src != SRC_CONST && a->ready > t) t = a->ready;
      if (b && b->src != SRC_CONST && b->ready > t) t = b->ready;
      x->src = SRC_CORE;
      x->start = t;
      x->scale = -1;
      if (x->ir.kind == FP3_IR_MUL && s->o.scaleb) {
        if (b && b->src == SRC_CONST && is_pow2(b->ir.bits)) x->scale = 1;
        else if (a->src == SRC_CONST && is_pow2(a->ir.bits)) x->scale = 0;
      }
      if (x->scale >= 0) {
        x->ready = t + s->o.scaleb_latency;
        s->st.scaleb++;
      } else {
        x->ready = t + core_latency(&s->o, x->ir.kind);
        s->st.cores[x->ir.kind]++;
      }
      s->st.ncores++;
    }
  }
  if (s->ninput == 0) {
    snprintf(msg, n, "model %s: the step reads no input (nothing to pipeline)", s->m->name);
    free(used);
    return -1;
  }
  unsigned L = 1;
  for (unsigned w = 0; w < carried; w++) {
    const snode *y = &s->nd[fp3_ir_carried_next(c, w)];
    if (y->src != SRC_CONST && y->ready > L) L = y->ready;
  }
  s->st.latency = L;
  /* every reader's tap: an operand read when its core starts, a carried
   * value at L */
  for (unsigned i = 0; i < s->nn; i++) {
    const snode *x = &s->nd[i];
    if (x->src != SRC_CORE) continue;
    if (need(s, x->ir.a, x->start - s->nd[x->ir.a].ready)) goto oom;
    if (x->ir.b >= 0 && need(s, x->ir.b, x->start - s->nd[x->ir.b].ready)) goto oom;
  }
  for (unsigned w = 0; w < carried; w++) {
    int y = (int)fp3_ir_carried_next(c, w);
    if (need(s, y, L - s->nd[y].ready)) goto oom;
  }
  for (unsigned i = 0; i < s->nn; i++) {
    const snode *x = &s->nd[i];
    if (!x->delay) continue;
    s->st.delay_lines++;
    s->st.delay_stages += x->delay;
    if (x->delay > s->st.longest_delay) s->st.longest_delay = x->delay;
    for (unsigned d = 1, prev = 0; d <= x->delay; d++)
      if (x->tap[d]) {
        count_segment(&s->st, d - prev);
        prev = d;
      }
  }
  s->st.inputs = s->ninput;
  s->st.carried = carried;
  free(used);
  return 0;
oom:
  free(used);
  snprintf(msg, n, "out of memory");
  return -1;
}

/* The module's text. */
static void emit(struct fp3_spatial *s, fp3_strbuf *t) {
  fp3_compiled *c = s->c;
  const fp3_spatial_stats *st = &s->st;
  const unsigned carried = s->ncarried;
  char buf[256], a[96], b[96];
  fp3_strbuf_printf(t,
      "// %s.v -- generated by `fp3 spatial` (sw/compiler/spatial.c) from\n"
      "// model %s (%s), integrator %s.\n"
      "//\n"
      "// One integration step of one object per cycle (initiation interval 1):\n"
      "// the operations of the compiled program's golden model\n"
      "// (fp3_compiled_model_step), each on its own core, so the new carried\n"
      "// values equal it bit for bit.  Loop invariants are computed for every\n"
      "// object (its inputs travel with it): the step is a DAG with no state.\n"
      "//\n"
      "// Schedule: as soon as possible; inputs in cycle 0, an operation when its\n"
      "// last operand is ready, its result `LATENCY` of its core later.\n"
      "// Balancing: each value has one delay line (fp_pipe segments between\n"
      "// taps) as long as its latest reader needs; a reader in cycle s of a value\n"
      "// ready in cycle r taps it at s - r stages.  A segment of up to %u stages\n"
      "// is flip-flops (fp_pipe), up to %u LUT RAM (fp_delay STYLE 1), longer\n"
      "// block RAM (fp_delay STYLE 2).\n"
      "//\n"
      "// Latency: %u cycles.  Cores: %u (",
      s->module, s->m->name, s->m->file, s->integ, FP3_SPATIAL_FF_MAX, FP3_SPATIAL_LUTRAM_MAX,
      st->latency, st->ncores);
  int first = 1;
  for (int k = FP3_IR_ADD; k < FP3_IR_KINDS; k++)
    if (st->cores[k]) {
      fp3_strbuf_printf(t, "%s%u %s", first ? "" : ", ", st->cores[k], kind_name[k]);
      first = 0;
    }
  if (st->scaleb) fp3_strbuf_printf(t, "%s%u scaleb", first ? "" : ", ", st->scaleb);
  fp3_strbuf_printf(t, ").\n// Delay lines: %u, %u stages (longest %u): %u flip-flops, %u LUT-RAM\n"
                       "// cells, %u block RAMs.\n"
                       "// Cores: %s, %s.\n//\n",
                    st->delay_lines, st->delay_stages, st->longest_delay, st->delay_ffs,
                    st->lutram_cells, st->ebr_blocks,
                    s->o.rtz ? "round toward zero" : "round to nearest even",
                    s->o.ftz ? "subnormals flushed to zero" : "subnormals supported");
  fp3_strbuf_printf(t, "// Ports:\n"
                       "//   valid_i  an object is presented this cycle\n"
                       "//   in_i     its inputs, 32 bits each (word k at [32k +: 32]):\n");
  for (unsigned k = 0; k < s->ninput; k++) {
    const snode *x = &s->nd[s->input_node[k]];
    if (x->ir.kind == FP3_IR_IN)
      fp3_strbuf_printf(t, "//              %2u  %s\n", k, fp3_ir_input_name(c, (unsigned)x->ir.id));
    else {
      label(s, s->input_node[k], a, sizeof a);
      expr(s, s->input_node[k], buf, sizeof buf);
      fp3_strbuf_printf(t, "//              %2u  %s = %s  (the host's, in binary32)\n", k, a, buf);
    }
  }
  fp3_strbuf_printf(t, "//   y_i      its carried values (word w):\n");
  for (unsigned w = 0; w < carried; w++)
    fp3_strbuf_printf(t, "//              %2u  %s\n", w, fp3_ir_carried_name(c, w));
  fp3_strbuf_printf(t, "//   valid_o  LATENCY cycles after valid_i: y_o holds that object's\n"
                       "//   y_o      new carried values, in y_i's order\n"
                       "//   flags_o  the IEEE 754 exception flags the cores raised two cycles\n"
                       "//            before on objects (OR; bubbles raise none), each core's\n"
                       "//            {invalid, infinite, overflow, underflow, inexact}\n"
                       "`default_nettype none\n\n"
                       "module %s (\n"
                       "  input  wire          clk_i,\n"
                       "  input  wire          rst_i,\n"
                       "  input  wire          valid_i,\n"
                       "  input  wire [%u:0] in_i,\n"
                       "  input  wire [%u:0] y_i,\n"
                       "  output wire          valid_o,\n"
                       "  output wire [%u:0] y_o,\n"
                       "  output wire [4:0]    flags_o\n"
                       ");\n\n"
                       "  localparam integer LATENCY = %u;\n"
                       "  localparam integer ROUND   = %d;\n"
                       "  localparam integer FTZ     = %d;\n\n",
                    s->module, 32 * s->ninput - 1, 32 * carried - 1, 32 * carried - 1,
                    st->latency, s->o.rtz, s->o.ftz);
  /* inputs */
  fp3_strbuf_printf(t, "  // ---- inputs (cycle 0) ----\n");
  for (unsigned k = 0; k < s->ninput; k++) {
    const snode *x = &s->nd[s->input_node[k]];
    fp3_strbuf_printf(t, "  wire [31:0] %s = in_i[%u +: 32];\n", x->sig, 32 * k);
  }
  for (unsigned i = 0; i < s->nn; i++) {
    const snode *x = &s->nd[i];
    if (x->src == SRC_STATE)
      fp3_strbuf_printf(t, "  wire [31:0] %s = y_i[%u +: 32];\n", x->sig, 32 * (unsigned)x->ir.id);
  }
  /* wires of the cores' results and the delay taps, before their use */
  fp3_strbuf_printf(t, "\n  // ---- core results and delay taps ----\n");
  for (unsigned i = 0; i < s->nn; i++) {
    const snode *x = &s->nd[i];
    if (x->src == SRC_CORE)
      fp3_strbuf_printf(t, "  wire [31:0] %s;\n  wire        %s_valid;\n  wire [4:0]  %s_flags;\n",
                        x->sig, x->sig, x->sig);
    for (unsigned d = 1, prev = 0; d <= x->delay; d++)
      if (x->tap[d]) {
        fp3_strbuf_printf(t, "  wire [31:0] %s_d%u;\n", x->sig, d);
        if (segment_style(d - prev) == 0)
          fp3_strbuf_printf(t, "  wire        unused_%s_d%u;\n", x->sig, d);
        prev = d;
      }
  }
  /* cores */
  fp3_strbuf_printf(t, "\n  // ---- cores, in the IR's order ----\n");
  for (unsigned i = 0; i < s->nn; i++) {
    const snode *x = &s->nd[i];
    if (x->src != SRC_CORE) continue;
    const int k = x->ir.kind;
    const snode *pa = &s->nd[x->ir.a];
    operand(s, x->ir.a, x->start - pa->ready, a, sizeof a);
    if (x->ir.b >= 0) operand(s, x->ir.b, x->start - s->nd[x->ir.b].ready, b, sizeof b);
    else snprintf(b, sizeof b, "32'h00000000");
    describe(s, (int)i, buf, sizeof buf);
    fp3_strbuf_printf(t, "\n  // IR node %u: %s  (%s%s; cycles %u -> %u)\n", i, buf, kind_name[k],
                      x->ir.inv ? ", loop invariant" : "", x->start, x->ready);
    const unsigned lat = core_latency(&s->o, k);
    if (x->scale >= 0) {
      /* a times a constant +-2^k: the other operand is a_i */
      const int other = x->scale == 1 ? x->ir.a : x->ir.b;
      operand(s, other, x->start - s->nd[other].ready, a, sizeof a);
      fp3_strbuf_printf(t, "  // a multiply by a power of two: an exponent adjustment, no multiplier\n"
                           "  fp_scaleb #(.LATENCY(%u), .ROUND(ROUND), .FTZ(FTZ)) u_%s (\n"
                           "    .clk_i(clk_i), .rst_i(rst_i), .valid_i(1'b1),\n"
                           "    .a_i(%s), .b_i(32'h%08X),\n",
                        s->o.scaleb_latency, x->sig, a,
                        (unsigned)s->nd[x->scale == 1 ? x->ir.b : x->ir.a].ir.bits);
    } else
    switch (k) {
    case FP3_IR_ADD:
    case FP3_IR_SUB:
      fp3_strbuf_printf(t, "  fp_add #(.LATENCY(%u), .ROUND(ROUND), .FTZ(FTZ)) u_%s (\n"
                           "    .clk_i(clk_i), .rst_i(rst_i), .valid_i(1'b1), .sub_i(1'b%d),\n"
                           "    .a_i(%s), .b_i(%s),\n",
                        lat, x->sig, k == FP3_IR_SUB, a, b);
      break;
    case FP3_IR_MUL:
    case FP3_IR_DIV:
      fp3_strbuf_printf(t, "  %s #(.LATENCY(%u),%s%s .ROUND(ROUND), .FTZ(FTZ)) u_%s (\n"
                           "    .clk_i(clk_i), .rst_i(rst_i), .valid_i(1'b1),\n"
                           "    .a_i(%s), .b_i(%s),\n",
                        k == FP3_IR_MUL ? "fp_mul" : "fp_div", lat,
                        k == FP3_IR_MUL && s->o.mul_feed ? " .FEED(1)," : "",
                        k == FP3_IR_MUL && s->o.mul_blocks == 3 ? " .MULT_BLOCKS(3)," : "",
                        x->sig, a, b);
      break;
    case FP3_IR_SQRT:
      fp3_strbuf_printf(t, "  fp_sqrt #(.LATENCY(%u), .ROUND(ROUND), .FTZ(FTZ)) u_%s (\n"
                           "    .clk_i(clk_i), .rst_i(rst_i), .valid_i(1'b1),\n"
                           "    .a_i(%s),\n",
                        lat, x->sig, a);
      break;
    default: /* fp_sign: op 0 abs, 1 neg, 2 min, 3 max */
      fp3_strbuf_printf(t, "  fp_sign #(.LATENCY(%u)) u_%s (\n"
                           "    .clk_i(clk_i), .rst_i(rst_i), .valid_i(1'b1), .op_i(2'd%d),\n"
                           "    .a_i(%s), .b_i(%s),\n",
                        lat, x->sig, k - FP3_IR_ABS, a, b);
      break;
    }
    fp3_strbuf_printf(t, "    .valid_o(%s_valid), .y_o(%s), .flags_o(%s_flags)\n  );\n", x->sig,
                      x->sig, x->sig);
  }
  /* delay lines */
  fp3_strbuf_printf(t, "\n  // ---- delay lines: one per value, tapped where its readers need it ----\n");
  for (unsigned i = 0; i < s->nn; i++) {
    const snode *x = &s->nd[i];
    if (!x->delay) continue;
    label(s, (int)i, a, sizeof a);
    fp3_strbuf_printf(t, "  // %s: ready in cycle %u, read until cycle %u\n", a, x->ready,
                      x->ready + x->delay);
    unsigned prev = 0;
    for (unsigned d = 1; d <= x->delay; d++) {
      if (!x->tap[d]) continue;
      operand(s, (int)i, prev, b, sizeof b);
      const int style = segment_style(d - prev);
      if (style == 0)
        fp3_strbuf_printf(t, "  fp_pipe #(.WIDTH(32), .DEPTH(%u)) u_%s_d%u (\n"
                             "    .clk_i(clk_i), .rst_i(rst_i), .valid_i(1'b0), .data_i(%s),\n"
                             "    .valid_o(unused_%s_d%u), .data_o(%s_d%u)\n  );\n",
                          d - prev, x->sig, d, b, x->sig, d, x->sig, d);
      else
        fp3_strbuf_printf(t, "  fp_delay #(.WIDTH(32), .DEPTH(%u), .STYLE(%d)) u_%s_d%u (  // %s\n"
                             "    .clk_i(clk_i), .data_i(%s), .data_o(%s_d%u)\n  );\n",
                          d - prev, style, x->sig, d, style == 1 ? "LUT RAM" : "block RAM", b,
                          x->sig, d);
      prev = d;
    }
  }
  /* outputs */
  fp3_strbuf_printf(t, "\n  // ---- outputs (cycle LATENCY) ----\n");
  for (unsigned w = 0; w < carried; w++) {
    int y = (int)fp3_ir_carried_next(c, w);
    operand(s, y, st->latency - s->nd[y].ready, a, sizeof a);
    fp3_strbuf_printf(t, "  assign y_o[%u +: 32] = %s;  // %s\n", 32 * w, a,
                      fp3_ir_carried_name(c, w));
  }
  /* the valid bit, tapped: a core's result in cycle T is the object's
   * that entered in cycle T - ready */
  fp3_strbuf_printf(t, "\n  // The valid bit travels beside the objects: obj_v[c] is valid_i of c\n"
                       "  // cycles before.\n"
                       "  reg  [LATENCY:1] obj_v_q;\n"
                       "  wire [LATENCY:0] obj_v = {obj_v_q, valid_i};\n"
                       "  always @(posedge clk_i)\n"
                       "    obj_v_q <= rst_i ? {LATENCY{1'b0}} : obj_v[LATENCY-1:0];\n"
                       "  assign valid_o = obj_v_q[LATENCY];\n");
  /* exception flags: each core's where its result is an object's
   * (registered beside the core), then their OR (registered) */
  fp3_strbuf_printf(t, "\n  // ---- exception flags: a core's count when its result is an object's\n"
                       "  // (registered beside the core), then their OR (registered) ----\n");
  for (unsigned i = 0; i < s->nn; i++)
    if (s->nd[i].src == SRC_CORE)
      fp3_strbuf_printf(t, "  reg  [4:0] %s_fq;\n", s->nd[i].sig);
  fp3_strbuf_printf(t, "  reg  [4:0] flags_q;\n"
                       "  always @(posedge clk_i) begin\n");
  for (unsigned i = 0; i < s->nn; i++)
    if (s->nd[i].src == SRC_CORE)
      fp3_strbuf_printf(t, "    %s_fq <= %s_flags & {5{obj_v[%u]}};\n", s->nd[i].sig, s->nd[i].sig,
                        s->nd[i].ready);
  fp3_strbuf_printf(t, "    flags_q <= 5'd0");
  for (unsigned i = 0; i < s->nn; i++)
    if (s->nd[i].src == SRC_CORE) fp3_strbuf_printf(t, "\n             | %s_fq", s->nd[i].sig);
  fp3_strbuf_printf(t, ";\n  end\n  assign flags_o = flags_q;\n");
  /* the cores' own valid bits are not used (valid_i is 1: the module's
   * valid bit, above, marks the objects), nor the delay lines' (wires
   * named unused_*) */
  fp3_strbuf_printf(t, "\n  // Not used: the cores' valid bits (the module's own, above, marks\n"
                       "  // the objects) and, in the unused_* wires above, the delay lines'.\n");
  fp3_strbuf_printf(t, "  wire unused_core_outputs = &{1'b0");
  for (unsigned i = 0; i < s->nn; i++)
    if (s->nd[i].src == SRC_CORE) fp3_strbuf_printf(t, ",\n    %s_valid", s->nd[i].sig);
  fp3_strbuf_printf(t, ",\n    1'b0};\n\nendmodule\n\n`default_nettype wire\n");
}

static void make_report(struct fp3_spatial *s, fp3_strbuf *t) {
  const fp3_spatial_stats *st = &s->st;
  fp3_strbuf_printf(t, "module: %s\n", s->module);
  fp3_strbuf_printf(t, "latency: %u cycles (initiation interval 1)\n", st->latency);
  fp3_strbuf_printf(t, "inputs: %u words per object; carried: %u\n", st->inputs, st->carried);
  fp3_strbuf_printf(t, "cores: %u", st->ncores);
  for (int k = FP3_IR_ADD; k < FP3_IR_KINDS; k++)
    if (st->cores[k]) fp3_strbuf_printf(t, ", %s %u", kind_name[k], st->cores[k]);
  if (st->scaleb) fp3_strbuf_printf(t, ", scaleb %u", st->scaleb);
  fp3_strbuf_printf(t, "\ndelay lines: %u values, %u stages (longest %u stages)\n",
                    st->delay_lines, st->delay_stages, st->longest_delay);
  fp3_strbuf_printf(t, "delay flip-flops: %u segments, %u stages, %u flip-flops\n",
                    st->ff_segments, st->ff_stages, st->delay_ffs);
  fp3_strbuf_printf(t, "delay LUT RAM: %u segments, %u stages, %u TRELLIS_DPR16X4\n",
                    st->lutram_segments, st->lutram_stages, st->lutram_cells);
  fp3_strbuf_printf(t, "delay block RAM: %u segments, %u stages, %u DP16KD\n",
                    st->ebr_segments, st->ebr_stages, st->ebr_blocks);
  fp3_strbuf_printf(t, "estimate per pipeline: %u LUT4, %u flip-flops, %u MULT18X18D, %u EBR%s\n",
                    st->est_lut4, st->est_ff, st->est_mult, st->est_ebr,
                    st->est_inexact ? " (some cores at the nearest measured configuration)" : "");
  fp3_strbuf_printf(t, "LFE5U-85F: %u LUT4, %u flip-flops, %u MULT18X18D, %u EBR; a pipeline's share "
                       "%.1f %%, %.1f %%, %.1f %%, %.1f %%\n",
                    FP3_SPATIAL_DEVICE_LUT4, FP3_SPATIAL_DEVICE_FF, FP3_SPATIAL_DEVICE_MULT,
                    FP3_SPATIAL_DEVICE_EBR, 100.0 * st->est_lut4 / FP3_SPATIAL_DEVICE_LUT4,
                    100.0 * st->est_ff / FP3_SPATIAL_DEVICE_FF,
                    100.0 * st->est_mult / FP3_SPATIAL_DEVICE_MULT,
                    100.0 * st->est_ebr / FP3_SPATIAL_DEVICE_EBR);
  fp3_strbuf_printf(t, "pipelines that fit: %u (limited by %s; within 7/8 of the LUT4s and "
                       "flip-flops, every MULT18X18D, the EBRs less 16: the rest for the frame "
                       "and routing)\n",
                    st->fit, st->limit);
  fp3_strbuf_printf(t, "cores: latencies add/sub %u, mul %u%s%s, div/sqrt %u, sign %u, scaleb %u%s; %s%s\n",
                    s->o.add_latency, s->o.mul_latency, s->o.mul_feed ? " (feed)" : "",
                    s->o.mul_blocks == 3 ? " (3 MULT18X18D)" : "",
                    s->o.div_latency, s->o.sign_latency,
                    s->o.scaleb_latency, s->o.scaleb ? "" : " (off: fp_mul)",
                    s->o.rtz ? "rtz" : "rne", s->o.ftz ? ", ftz" : "");
}

int fp3_spatial_build(fp3_compiled *c, const fp3_model *m, const char *integ,
                      const fp3_spatial_opts *o, fp3_spatial **out, char *msg, size_t n) {
  *out = NULL;
  if (o->add_latency < 1 || o->mul_latency < 1 || o->div_latency < 1 || o->sign_latency < 1 ||
      o->add_latency > 64 || o->mul_latency > 64 || o->div_latency > 64 || o->sign_latency > 3 ||
      o->scaleb_latency < 1 || o->scaleb_latency > 64) {
    snprintf(msg, n, "core latencies must be 1 to 64 (fp_sign: 1 to 3)");
    return -1;
  }
  if (o->mul_feed && (o->mul_latency < 7 || o->mul_latency > 10)) {
    snprintf(msg, n, "fp_mul's feed register needs a multiply latency of 7 to 10 (the DSP "
             "product with the blocks' own registers), not %u", o->mul_latency);
    return -1;
  }
  if (o->mul_blocks != 3 && o->mul_blocks != 4) {
    snprintf(msg, n, "fp_mul's product takes 4 or 3 MULT18X18D, not %u", o->mul_blocks);
    return -1;
  }
  if (o->mul_blocks == 3 && o->mul_latency - (o->mul_feed ? 1u : 0u) > 9) {
    snprintf(msg, n, "3 MULT18X18D per multiply needs fp_mul's DSP product: a multiply latency "
             "of at most 9 (10 with the feed register), not %u", o->mul_latency);
    return -1;
  }
  struct fp3_spatial *s = calloc(1, sizeof *s);
  if (!s) {
    snprintf(msg, n, "out of memory");
    return -1;
  }
  s->c = c;
  s->m = m;
  s->o = *o;
  snprintf(s->integ, sizeof s->integ, "%s", integ);
  s->nn = fp3_ir_nodes(c);
  s->ncarried = fp3_compiled_carried(c);
  char mid[40], iid[20];
  ident(mid, sizeof mid, m->name);
  ident(iid, sizeof iid, integ);
  snprintf(s->module, sizeof s->module, "fp3_spatial_%s_%s", mid, iid);
  s->nd = calloc(s->nn ? s->nn : 1, sizeof *s->nd);
  s->input_node = calloc(s->nn ? s->nn : 1, sizeof *s->input_node);
  if (!s->nd || !s->input_node) {
    snprintf(msg, n, "out of memory");
    fp3_spatial_free(s);
    return -1;
  }
  if (schedule(s, msg, n)) {
    fp3_spatial_free(s);
    return -1;
  }
  estimate(s);
  fp3_strbuf t = {0}, r = {0};
  emit(s, &t);
  make_report(s, &r);
  if (t.oom || r.oom) {
    free(t.s);
    free(r.s);
    snprintf(msg, n, "out of memory");
    fp3_spatial_free(s);
    return -1;
  }
  s->verilog = t.s;
  s->report = r.s;
  *out = s;
  return 0;
}

void fp3_spatial_free(fp3_spatial *s) {
  if (!s) return;
  for (unsigned i = 0; s->nd && i < s->nn; i++) free(s->nd[i].tap);
  free(s->nd);
  free(s->input_node);
  free(s->verilog);
  free(s->report);
  free(s);
}

const char *fp3_spatial_module(const fp3_spatial *s) { return s->module; }

int fp3_spatial_input_node(const fp3_spatial *s, unsigned k) { return s->input_node[k]; }
const char *fp3_spatial_verilog(const fp3_spatial *s) { return s->verilog; }
const char *fp3_spatial_report(const fp3_spatial *s) { return s->report; }
const fp3_spatial_stats *fp3_spatial_stats_of(const fp3_spatial *s) { return &s->st; }

/* xorshift64 (Marsaglia), as a factor in [0.75, 1.25]. */
static float factor(uint64_t *x) {
  *x ^= *x << 13;
  *x ^= *x >> 7;
  *x ^= *x << 17;
  return 0.75f + 0.5f * (float)((double)(*x >> 11) / 9007199254740992.0);
}

int fp3_spatial_vectors(fp3_spatial *s, size_t nobj, unsigned steps, uint64_t seed,
                        char **text, char *msg, size_t n) {
  *text = NULL;
  const fp3_model *m = s->m;
  fp3_compiled *c = s->c;
  const unsigned nc = s->ncarried;
  fpref_mode mode = {s->o.rtz ? FPREF_RTZ : FPREF_RNE, s->o.ftz};
  fpenv_saved saved;
  if (fpenv_enter(mode, &saved)) {
    snprintf(msg, n, "this host cannot compute in the cores' rounding (%s%s)",
             fpenv_round_name(mode), s->o.ftz ? " ftz" : "");
    return -1;
  }
  fp3_strbuf t = {0};
  float in[FP3_MODEL_MAX_VARS], y0[FP3_MODEL_MAX_VARS], yc[2 * FP3_MODEL_MAX_VARS];
  unsigned reg[4 * FP3_MODEL_MAX_VARS + 1024];
  uint32_t val[4 * FP3_MODEL_MAX_VARS + 1024];
  uint64_t x = seed ? seed : 1;
  char *objects = NULL, *trace = NULL;
  fp3_strbuf ob = {0}, tr = {0};
  float *state = calloc(nobj * nc + 1, sizeof *state);
  float *params = calloc(nobj * m->nparam + 1, sizeof *params);
  if (!state || !params) goto oom;
  fp3_strbuf_printf(&t, "fp3-spatial-vectors %zu %u %u %u %u\n", nobj, steps, s->ninput, nc,
                    s->st.latency);
  for (size_t o = 0; o < nobj; o++) {
    for (unsigned k = 0; k < m->nparam; k++) {
      in[k] = m->param_has_def[k] ? m->param_def[k] : 0.0f;
      if (o > 0 && k > 0) in[k] *= factor(&x);
    }
    for (unsigned k = 0; k < m->nstate; k++) {
      y0[k] = m->state_has_def[k] ? m->state_def[k] : 0.0f;
      if (o > 0) y0[k] *= factor(&x);
    }
    fp3_compiled_model_start(c, in, y0, reg, val, sizeof reg / sizeof reg[0]);
    for (unsigned k = 0; k < s->ninput; k++)
      fp3_strbuf_printf(&ob, "%08X ", (unsigned)fpref_bits(fp3_ir_value(c, (unsigned)s->input_node[k])));
    /* the initial carried values, as the start computed them */
    for (unsigned i = 0; i < s->nn; i++)
      if (s->nd[i].ir.kind == FP3_IR_STATE) yc[s->nd[i].ir.id] = fp3_ir_value(c, i);
    for (unsigned w = 0; w < nc; w++) {
      /* a carried value no operation reads has no STATE node: its start */
      int has = 0;
      for (unsigned i = 0; i < s->nn; i++)
        if (s->nd[i].ir.kind == FP3_IR_STATE && (unsigned)s->nd[i].ir.id == w) has = 1;
      if (!has) yc[w] = w < m->nstate ? y0[w] : 0.0f;
      fp3_strbuf_printf(&ob, "%s%08X", w ? " " : "", (unsigned)fpref_bits(yc[w]));
      state[o * nc + w] = yc[w];
    }
    fp3_strbuf_printf(&ob, "\n");
    memcpy(params + o * m->nparam, in, m->nparam * sizeof *in);
  }
  for (unsigned st = 0; st < steps; st++)
    for (size_t o = 0; o < nobj; o++) {
      float next[2 * FP3_MODEL_MAX_VARS];
      fp3_compiled_model_step_from(c, params + o * m->nparam, state + o * nc, next);
      for (unsigned w = 0; w < nc; w++) {
        state[o * nc + w] = next[w];
        fp3_strbuf_printf(&tr, "%s%08X", w ? " " : "", (unsigned)fpref_bits(next[w]));
      }
      fp3_strbuf_printf(&tr, "\n");
    }
  fpenv_leave(&saved);
  objects = ob.s;
  trace = tr.s;
  if (t.oom || ob.oom || tr.oom) goto oom_left;
  fp3_strbuf_printf(&t, "%s%s", objects ? objects : "", trace ? trace : "");
  free(objects);
  free(trace);
  free(state);
  free(params);
  if (t.oom) {
    free(t.s);
    snprintf(msg, n, "out of memory");
    return -1;
  }
  *text = t.s;
  return 0;
oom:
  fpenv_leave(&saved);
  objects = ob.s;
  trace = tr.s;
oom_left:
  free(objects);
  free(trace);
  free(t.s);
  free(state);
  free(params);
  snprintf(msg, n, "out of memory");
  return -1;
}
