/*
 * compile.c -- the scene compiler (compile.h): IR, folding, scheduling,
 * register allocation, assembly text, and the IR golden model.
 *
 * The golden model evaluates the IR nodes in C binary32, one operation per
 * node, compiled with -ffp-contract=off like sw/ref/integrators.c.
 */
#include "compile.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asm.h"
#include "fp3_isa.h"
#include "fpref.h"
#include "model.h"
#include "report.h"

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "the IR golden model needs float expressions evaluated in float"
#endif

/* IR nodes: a model's RK4 on six state variables with a square root
 * builds about 300 (models/projectile.fp3m). */
#define MAX_NODES 1024
#define MAX_INSNS FP3_DEFAULT_IMEM_DEPTH
/* loop-carried values: the state variables and, for rk4comp, one Kahan
 * compensation each; inputs: the params, then each carried value's
 * initial value */
#define MAX_STATE (2 * FP3_MODEL_MAX_VARS)
#define MAX_IN (3 * FP3_MODEL_MAX_VARS)
#define NOTE_LEN 72
/* body instructions: operations and a mov per carried value, at most */
#define BODY_MAX (MAX_NODES + MAX_STATE + 2)

/* ---- the IR ------------------------------------------------------------- */

/* Operations from NK_ADD on; NK_DIV .. NK_MAX come from models only
 * (unary ones have b = -1). */
enum node_kind { NK_IN, NK_CONST, NK_STATE, NK_ADD, NK_SUB, NK_MUL, NK_DIV, NK_SQRT, NK_ABS,
                 NK_NEG, NK_MIN, NK_MAX, NK_COUNT };

/* The instruction of each operation, by mnemonic: the assembler's table
 * (fp3_opc_lookup) says whether this ISA has it. */
static const char *const kind_mnemonic[NK_COUNT] = {
    NULL, NULL, NULL, "add", "sub", "mul", "div", "sqrt", "abs", "neg", "min", "max"};

typedef struct node {
  int kind;
  int a, b;        /* operands (ops)                               */
  int id;          /* NK_IN: input index (b->in_name); NK_STATE: state */
  uint32_t bits;   /* NK_CONST                                     */
  int inv;         /* loop invariant: inputs and constants only     */
  int live;        /* read by an output, directly or not (not through
                      a host node: its operands need no register)   */
  int host;        /* loop invariant computed by the host in binary32
                      (a model's div, sqrt, abs, neg, min, max on
                      params: no unit needed) and bound like an input */
  char name[FP3_MODEL_NAME_LEN]; /* for comments ("k1", "vt2", ...) */
} node;

/* A reference to a node, possibly negated (zero-term removal). */
typedef struct ref {
  int n;
  int neg;
} ref;

typedef struct builder {
  node nd[MAX_NODES];
  int nn;
  int fold, drop_zero;
  int zero;        /* the +0 constant standing for a removed term, or -1 */
  int nstate;      /* loop-carried values (fp3_model_carried)           */
  ref out[MAX_STATE]; /* their next values                              */
  int nin;         /* host inputs NK_IN id 0 .. nin-1                   */
  char in_name[MAX_IN][FP3_MODEL_NAME_LEN];
  int in_state[MAX_IN]; /* the state variable an input initialises, or -1 */
  char st_name[MAX_STATE][FP3_MODEL_NAME_LEN];
  const fp3_model *model;      /* the model compiled                      */
  char integ[16];              /* a model's integrator (fp3_model_integrators) */
  const unsigned char *pzero;  /* model params zero in every object (drop_zero) */
  int err;
} builder;

static int op_kind(int k) { return k >= NK_ADD && k < NK_COUNT; }
static int unary_kind(int k) { return k == NK_SQRT || k == NK_ABS || k == NK_NEG; }

static int new_node(builder *b, node x) {
  for (int i = 0; i < b->nn; i++) { /* hash-consing: common subexpressions */
    const node *y = &b->nd[i];
    if (y->kind == x.kind && y->a == x.a && y->b == x.b && y->id == x.id && y->bits == x.bits)
      return i;
  }
  if (b->nn == MAX_NODES) {
    b->err = 1;
    return 0;
  }
  b->nd[b->nn] = x;
  return b->nn++;
}

static ref leaf(builder *b, int kind, int id, uint32_t bits, const char *name) {
  node x = {kind, -1, -1, id, bits, kind != NK_STATE, 0, 0, ""};
  int i = new_node(b, x);
  if (!b->nd[i].name[0]) snprintf(b->nd[i].name, sizeof b->nd[i].name, "%s", name);
  return (ref){i, 0};
}

static ref konst(builder *b, float f, const char *name) {
  return leaf(b, NK_CONST, -1, fpref_bits(f), name);
}

static int is_zero(const builder *b, ref r) { return b->zero >= 0 && r.n == b->zero; }

static int is_one(const builder *b, ref r) {
  return b->nd[r.n].kind == NK_CONST && b->nd[r.n].bits == 0x3F800000u;
}

static ref state(builder *b, int which) {
  return leaf(b, NK_STATE, which, 0, b->st_name[which]);
}

static ref op(builder *b, int kind, ref x, ref y) {
  node z = {kind, x.n, y.n, -1, 0, b->nd[x.n].inv && b->nd[y.n].inv, 0, 0, ""};
  return (ref){new_node(b, z), 0};
}

static ref mul(builder *b, ref x, ref y) {
  if (is_zero(b, x)) return x;
  if (is_zero(b, y)) return y;
  if (is_one(b, x)) return y;
  if (is_one(b, y)) return x;
  ref r = op(b, NK_MUL, (ref){x.n, 0}, (ref){y.n, 0});
  r.neg = x.neg ^ y.neg; /* (-a) b = -(a b): symmetric rounding */
  return r;
}

static ref add(builder *b, ref x, ref y) {
  if (is_zero(b, y)) return x;
  if (is_zero(b, x)) return y;
  if (!x.neg && !y.neg) return op(b, NK_ADD, x, y);
  if (!x.neg) return op(b, NK_SUB, x, (ref){y.n, 0});   /* a + (-b) = a - b */
  if (!y.neg) return op(b, NK_SUB, y, (ref){x.n, 0});   /* -a + b = b - a  */
  ref r = op(b, NK_ADD, (ref){x.n, 0}, (ref){y.n, 0}); /* -a - b = -(a + b) */
  r.neg = 1;
  return r;
}

/* Name a node for the comments (the first name sticks). */
static ref nm(builder *b, ref r, const char *name) {
  node *x = &b->nd[r.n];
  if (op_kind(x->kind) && !x->name[0]) snprintf(x->name, sizeof x->name, "%s", name);
  return r;
}

static void mark_live(builder *b, int i) {
  node *x = &b->nd[i];
  if (x->live) return;
  x->live = 1;
  if (op_kind(x->kind) && !x->host) {
    mark_live(b, x->a);
    if (x->b >= 0) mark_live(b, x->b);
  }
}

/* ---- instructions ------------------------------------------------------------ */

typedef struct insn {
  unsigned opc, rd, ra, rb;
  uint32_t imm;
  char note[NOTE_LEN];
} insn;

/* Body instructions before register allocation: an op node, or a mov of a
 * value into a state register. */
typedef struct bins {
  int node;       /* IR node computed (op) or moved (mov)             */
  int is_mov;
  int dest_state; /* ST_* when it writes a state register, else -1     */
  int srcs[2];    /* operand nodes                                   */
  int issue;      /* scheduled issue cycle                           */
  int placed, height, visiting;
} bins;

struct fp3_compiled {
  builder b;
  char *text;
  fp3_image img;
  fp3_compile_stats stats;
  float val[MAX_NODES];    /* golden model: node values               */
  float in[MAX_IN];        /* host inputs: h, the params, initial values */
  int in_reg[MAX_IN];      /* register of each input, -1: none         */
  int state_reg[MAX_STATE];/* register of each state variable          */
  int host_reg[MAX_NODES]; /* register of each host-computed node, -1   */
};

/* Cycles from the issue of an instruction of `unit` to the issue of a
 * dependent one: the register file's read stage plus the unit's latency
 * (fp3_isa.h FP3_READ_CYCLES; FMAX_PIPE's move path is
 * FP3_FMAX_PIPE_PICK_STAGES longer, and its latencies count as at least
 * FP3_FMAX_PIPE_FULL_LEAD_LATENCY). */
static unsigned unit_latency(const fp3_compile_opts *o, unsigned unit) {
  unsigned lat;
  switch (unit) {
  case FP3_UNIT_ADD: lat = o->add_latency; break;
  case FP3_UNIT_MUL: lat = o->mul_latency; break;
  case FP3_UNIT_MOV: lat = o->mov_latency + (o->fmax_pipe ? FP3_FMAX_PIPE_PICK_STAGES : 0); break;
  case FP3_UNIT_DIV: lat = o->div_latency; break;
  default: return 1;
  }
  if (o->fmax_pipe && lat < FP3_FMAX_PIPE_FULL_LEAD_LATENCY) lat = FP3_FMAX_PIPE_FULL_LEAD_LATENCY;
  return FP3_READ_CYCLES + lat;
}

/* Cycles from a context's grant to its next (fp3_isa.h). */
static int issue_spacing(const fp3_compile_opts *o) {
  return o->fmax_pipe ? FP3_FMAX_PIPE_ISSUE_SPACING : FP3_ISSUE_SPACING;
}

/* The opcode of an operation, or -1 when this ISA lacks it. */
static int node_opc(int kind) {
  return op_kind(kind) ? fp3_opc_lookup(kind_mnemonic[kind]) : -1;
}

static unsigned bins_latency(const builder *b, const fp3_compile_opts *o, const bins *x) {
  if (x->is_mov) return unit_latency(o, FP3_UNIT_MOV);
  return unit_latency(o, fp3_opc_unit((unsigned)node_opc(b->nd[x->node].kind)));
}

/* Body instruction producing node i (-1: none, a prologue value). */
static int producer(const bins *bi, int nb, int ni) {
  for (int j = 0; j < nb; j++)
    if (!bi[j].is_mov && bi[j].node == ni) return j;
  return -1;
}

/* Must j issue before k?  Data: k reads j's value.  Order: j reads a
 * state register that k overwrites. */
static int data_edge(const bins *bi, int j, int k) {
  return !bi[j].is_mov && (bi[k].srcs[0] == bi[j].node || bi[k].srcs[1] == bi[j].node);
}

static int order_edge(const builder *b, const bins *bi, int j, int k) {
  if (j == k || bi[k].dest_state < 0) return 0;
  for (int q = 0; q < 2; q++) {
    int s = bi[j].srcs[q];
    if (s >= 0 && b->nd[s].kind == NK_STATE && b->nd[s].id == bi[k].dest_state) return 1;
  }
  return 0;
}

/* Does instruction k read the value of instruction p, directly or
 * through others?  (A search of the data edges from p, each instruction
 * visited once.) */
static int feeds(const bins *bi, int nb, int p, int k) {
  unsigned char *seen = calloc((size_t)nb + 1, 1);
  int *todo = malloc(((size_t)nb + 1) * sizeof *todo);
  int n = 0, found = !seen || !todo; /* out of memory: assume it does (a mov, always right) */
  if (!found) {
    todo[n++] = p;
    seen[p] = 1;
  }
  while (n > 0 && !found) {
    int j = todo[--n];
    if (j == k) found = 1;
    for (int q = 0; q < nb && !found; q++)
      if (!seen[q] && data_edge(bi, j, q)) {
        seen[q] = 1;
        todo[n++] = q;
      }
  }
  free(seen);
  free(todo);
  return found;
}

/* Longest latency path from j to the end of the integration; -1 on a
 * dependence cycle. */
static int height(const builder *b, const fp3_compile_opts *o, bins *bi, int nb, int j) {
  if (bi[j].height) return bi[j].height;
  if (bi[j].visiting) return -1;
  bi[j].visiting = 1;
  int lat = (int)bins_latency(b, o, &bi[j]), h = lat;
  for (int k = 0; k < nb; k++) {
    int d = data_edge(bi, j, k) ? lat : order_edge(b, bi, j, k) ? 1 : 0;
    if (!d) continue;
    int hk = height(b, o, bi, nb, k);
    if (hk < 0) return -1;
    if (d + hk > h) h = d + hk;
  }
  bi[j].visiting = 0;
  bi[j].height = h;
  return h;
}

/* Registers held for the whole run, before any temporary of the body:
 * the inputs (each state variable with its initial value), the host's
 * values, the constants and the loop invariants (as backend allocates
 * them). */
static unsigned fixed_regs(const builder *b) {
  unsigned n = 0;
  for (int k = 0; k < b->nin; k++) {
    int used = b->in_state[k] >= 0;
    for (int i = 0; i < b->nn && !used; i++)
      used = b->nd[i].live && b->nd[i].kind == NK_IN && b->nd[i].id == k;
    n += (unsigned)used;
  }
  for (int i = 0; i < b->nn; i++) {
    const node *x = &b->nd[i];
    if (x->live && (x->host || (x->inv && (x->kind == NK_CONST || op_kind(x->kind))))) n++;
  }
  return n;
}

/* List scheduling, in-order single issue: order[] gets the body.
 *
 * limit == 0: latency first.  Among the instructions whose operands are
 * placed, the one that can issue earliest (its operands' latencies), ties
 * to the longest latency path to the end of the integration.
 *
 * limit > 0: the same, but register pressure bounded (for a context
 * with `limit` registers of which `fixed` hold the run's inputs,
 * constants and invariants).  A temporary -- the result of an operation
 * that is not a state variable's -- lives from its instruction to its
 * last reader; an instruction that reads the last use of k temporaries
 * and makes one needs live - k + 1 registers while it issues (operands
 * are freed before the destination is taken, as backend allocates).  Of
 * the ready instructions, those that stay within the limit are chosen
 * latency first; when none does, the one needing the fewest registers
 * (ties: latency first).  This trades cycles of one object for
 * registers: with several contexts interleaved the issue slot stays full
 * (cycles per object-step are the instructions per step either way).
 * Greedy, so not always the least need; backend measures the need of the
 * order it gets. */
static int schedule(const builder *b, const fp3_compile_opts *o, bins *bi, int nb, int *order,
                    unsigned fixed, unsigned limit) {
  for (int j = 0; j < nb; j++) {
    bi[j].placed = 0;
    if (height(b, o, bi, nb, j) < 0) return -1;
  }
  int *remaining = calloc((size_t)nb + 1, sizeof *remaining); /* unplaced readers */
  if (!remaining) return -1;
  for (int j = 0; j < nb; j++)
    for (int k = 0; k < nb; k++)
      if (data_edge(bi, j, k)) remaining[j]++;
  unsigned live = 0; /* temporaries made and still read later */
  int cycle = 0;
  for (int placed = 0; placed < nb; placed++) {
    int best = -1, best_at = 0;
    unsigned best_need = 0;
    for (int k = 0; k < nb; k++) {
      if (bi[k].placed) continue;
      int at = cycle, ready = 1;
      unsigned frees = 0;
      for (int j = 0; j < nb && ready; j++) {
        int d = data_edge(bi, j, k), ord = order_edge(b, bi, j, k);
        if (!d && !ord) continue;
        if (!bi[j].placed) ready = 0;
        else if (d && bi[j].issue + (int)bins_latency(b, o, &bi[j]) > at)
          at = bi[j].issue + (int)bins_latency(b, o, &bi[j]);
        if (d && remaining[j] == 1 && bi[j].dest_state < 0) frees++;
      }
      if (!ready) continue;
      unsigned need = fixed + live - frees + (bi[k].dest_state < 0 && !bi[k].is_mov);
      int better;
      if (best < 0) better = 1;
      else if (limit && (need <= limit) != (best_need <= limit)) better = need <= limit;
      else if (limit && need > limit && need != best_need) better = need < best_need;
      else better = at < best_at || (at == best_at && bi[k].height > bi[best].height);
      if (better) {
        best = k;
        best_at = at;
        best_need = need;
      }
    }
    if (best < 0) {
      free(remaining);
      return -1;
    }
    bi[best].placed = 1;
    bi[best].issue = best_at;
    order[placed] = best;
    cycle = best_at + issue_spacing(o);
    for (int j = 0; j < nb; j++)
      if (data_edge(bi, j, best) && --remaining[j] == 0 && bi[j].dest_state < 0) live--;
    if (bi[best].dest_state < 0 && !bi[best].is_mov && remaining[best] > 0) live++;
  }
  free(remaining);
  return 0;
}

/* ---- text ------------------------------------------------------------------- */

/* "name = a op b" for a comment. */
/* A node's name in the comments: its own, or tN (N its IR index) for a
 * temporary nobody named. */
static const char *label(const builder *b, int i, char *buf, size_t n) {
  if (b->nd[i].name[0]) return b->nd[i].name;
  snprintf(buf, n, "t%d", i);
  return buf;
}

static void describe(const builder *b, int i, char *s, size_t n) {
  const node *x = &b->nd[i];
  static const char *const sym[NK_COUNT] = {"?", "?", "?", "+", "-", "*", "/"};
  char l0[16], l1[16], l2[16];
  const char *r = label(b, i, l0, sizeof l0), *a = label(b, x->a, l1, sizeof l1);
  if (sym[x->kind])
    snprintf(s, n, "%s = %s %s %s", r, a, sym[x->kind], label(b, x->b, l2, sizeof l2));
  else if (unary_kind(x->kind))
    snprintf(s, n, "%s = %s(%s)", r, kind_mnemonic[x->kind], a);
  else
    snprintf(s, n, "%s = %s(%s, %s)", r, kind_mnemonic[x->kind], a,
             label(b, x->b, l2, sizeof l2));
}

/* ---- compile ---------------------------------------------------------------- */

void fp3_compile_defaults(fp3_compile_opts *o) {
  o->fold = 1;
  o->drop_zero = 1;
  o->add_latency = FP3_DEFAULT_ADD_LATENCY;
  o->mul_latency = FP3_DEFAULT_MUL_LATENCY;
  o->mov_latency = 1;
  o->div_latency = FP3_DEFAULT_DIV_LATENCY;
  o->num_regs = FP3_DEFAULT_NUM_REGS;
  o->max_regs = 0;
  o->fmax_pipe = 0;
}

void fp3_compile_opts_for(fp3_compile_opts *o, const fp3_config *hw) {
  fp3_compile_defaults(o);
  if (hw->add_latency) o->add_latency = hw->add_latency;
  if (hw->mul_latency) o->mul_latency = hw->mul_latency;
  if (hw->div_latency) o->div_latency = hw->div_latency;
  if (hw->num_regs) o->num_regs = hw->num_regs;
  o->fmax_pipe = hw->fmax_pipe;
  /* One write-back port: the move path is as long as the add core
   * (fp3_top WB_PORTS; unit_latency adds FMAX_PIPE's pick stages back). */
  if (hw->wb_ports == 1)
    o->mov_latency = o->add_latency - (o->fmax_pipe ? FP3_FMAX_PIPE_PICK_STAGES : 0);
}

typedef struct regalloc {
  int reg[MAX_NODES];   /* register of each node's value, -1: none   */
  int used[FP3_MAX_REGS];
  int last_write[FP3_MAX_REGS]; /* cycle the latest write lands, for LRU */
  unsigned nregs, count;
  unsigned inuse, peak; /* registers held now, and at most            */
} regalloc;

/* A free register, least recently written first; -1 if none. */
static int take_reg(regalloc *ra) {
  int best = -1;
  for (unsigned r = 1; r <= ra->nregs; r++) {
    unsigned q = r % ra->nregs; /* r1 .. r(N-1), then r0 */
    if (ra->used[q]) continue;
    if (best < 0 || ra->last_write[q] < ra->last_write[best]) best = (int)q;
  }
  if (best >= 0) {
    ra->used[best] = 1;
    ra->count++;
    if (++ra->inuse > ra->peak) ra->peak = ra->inuse;
  }
  return best;
}

static void release_reg(regalloc *ra, int r) {
  ra->used[r] = 0;
  ra->inuse--;
}

/* Registers for the body in `order` (issue cycles in bi[].issue) within
 * nregs: the inputs in their order (each state variable's register holds
 * its initial value), the host's values, the constants, the loop
 * invariants, then the temporaries in program order, each freed after its
 * last reader (an instruction's operands are freed before its destination
 * is taken, so it may reuse one).  This is the interval allocation of one
 * straight-line body, so it succeeds exactly when the most values live at
 * once fit.  ra->reg[], in_reg[], state_reg[] get the registers.  Returns
 * that most (the registers the order needs), or 0 when nregs is too few. */
static unsigned allocate(const builder *b, const fp3_compile_opts *o, const bins *bi, int nb,
                         const int *order, unsigned nregs, regalloc *ra, int *in_reg,
                         int *state_reg) {
  memset(ra, 0, sizeof *ra);
  ra->nregs = nregs;
  for (int i = 0; i < MAX_NODES; i++) ra->reg[i] = -1;
  for (unsigned r = 0; r < ra->nregs; r++) ra->last_write[r] = -1000000;
  for (int k = 0; k < MAX_IN; k++) in_reg[k] = -1;
  for (int k = 0; k < MAX_STATE; k++) state_reg[k] = -1;
  /* inputs in their order, each state variable with its initial value */
  for (int k = 0; k < b->nin; k++) {
    int node_i = -1;
    if (b->in_state[k] >= 0) {
      state_reg[b->in_state[k]] = in_reg[k] = take_reg(ra);
      continue;
    }
    for (int i = 0; i < b->nn; i++)
      if (b->nd[i].live && b->nd[i].kind == NK_IN && b->nd[i].id == k) node_i = i;
    if (node_i >= 0) ra->reg[node_i] = in_reg[k] = take_reg(ra);
  }
  for (int i = 0; i < b->nn; i++)
    if (b->nd[i].kind == NK_STATE) ra->reg[i] = state_reg[b->nd[i].id];
  /* values the host computes (a model's div, sqrt, ... on params) */
  for (int i = 0; i < b->nn; i++)
    if (b->nd[i].live && b->nd[i].host) ra->reg[i] = take_reg(ra);
  /* constants, then loop invariants: live for the whole run */
  for (int pass = 0; pass < 2; pass++)
    for (int i = 0; i < b->nn; i++) {
      const node *x = &b->nd[i];
      if (x->live && x->inv && !x->host && (pass == 0 ? x->kind == NK_CONST : op_kind(x->kind)))
        if ((ra->reg[i] = take_reg(ra)) < 0) break;
    }
  /* temporaries of the body, in schedule order */
  int *last_use = malloc(((size_t)nb + 1) * sizeof *last_use);
  if (!last_use) return 0;
  for (int q = 0; q < nb; q++) {
    last_use[q] = -1;
    for (int p = 0; p < nb; p++)
      if (data_edge(bi, order[q], order[p]) && p > last_use[q]) last_use[q] = p;
  }
  int ok = 1;
  for (int q = 0; q < nb && ok; q++) {
    const bins *x = &bi[order[q]];
    /* operands whose last reader this is free their registers first */
    for (int p = 0; p < q; p++) {
      const bins *y = &bi[order[p]];
      if (last_use[p] == q && y->dest_state < 0 && !y->is_mov) release_reg(ra, ra->reg[y->node]);
    }
    int r;
    if (x->dest_state >= 0) r = state_reg[x->dest_state];
    else r = take_reg(ra);
    if (r < 0) ok = 0;
    else {
      if (!x->is_mov) ra->reg[x->node] = r;
      ra->last_write[r] = x->issue + (int)bins_latency(b, o, x);
      if (last_use[q] < 0 && x->dest_state < 0) release_reg(ra, r); /* never read */
    }
  }
  free(last_use);
  for (int i = 0; i < b->nn && ok; i++)
    if (b->nd[i].live && ra->reg[i] < 0) ok = 0;
  for (int w = 0; w < b->nstate; w++)
    if (state_reg[w] < 0) ok = 0;
  return ok ? ra->peak : 0;
}

/* Issue cycles of the body in `order`, in-order single issue (as
 * schedule places them). */
static int schedule_times(const builder *b, const fp3_compile_opts *o, bins *bi, int nb,
                          const int *order) {
  int cycle = 0;
  for (int q = 0; q < nb; q++) {
    bins *x = &bi[order[q]];
    int at = cycle;
    for (int p = 0; p < q; p++) {
      const bins *y = &bi[order[p]];
      if (data_edge(bi, order[p], order[q]) && y->issue + (int)bins_latency(b, o, y) > at)
        at = y->issue + (int)bins_latency(b, o, y);
    }
    x->issue = at;
    cycle = at + issue_spacing(o);
  }
  return 0;
}

/* 0 if the options are usable, else -1 with the reason. */
static int check_opts(const fp3_compile_opts *o, char *msg, size_t n) {
  if (o->num_regs < 4 || o->num_regs > FP3_MAX_REGS || o->max_regs > FP3_MAX_REGS ||
      !o->add_latency || !o->mul_latency || !o->mov_latency || !o->div_latency ||
      o->fmax_pipe > 1) {
    snprintf(msg, n, "bad compiler options (num_regs 4..%d, max_regs at most %d, latencies "
             ">= 1, fmax_pipe 0 or 1)", FP3_MAX_REGS, FP3_MAX_REGS);
    return -1;
  }
  if (o->fmax_pipe &&
      (o->add_latency <= FP3_FMAX_PIPE_PICK_STAGES || o->mul_latency <= FP3_FMAX_PIPE_PICK_STAGES)) {
    snprintf(msg, n, "FMAX_PIPE needs add and mul latencies of at least %d (add %u, mul %u)",
             FP3_FMAX_PIPE_PICK_STAGES + 1, o->add_latency, o->mul_latency);
    return -1;
  }
  return 0;
}

/* c->stats.literal_body_insns from the literal IR in c->b: its loop's
 * operations and endi. */
static void count_literal(fp3_compiled *c) {
  for (int i = 0; i < c->b.nn; i++)
    if (c->b.nd[i].live && op_kind(c->b.nd[i].kind) && !c->b.nd[i].inv)
      c->stats.literal_body_insns++;
  c->stats.literal_body_insns++; /* endi */
}

/* The back end: the IR in c->b (live nodes marked), built with options o,
 * to the scheduled, register-allocated program, its text (head: the
 * caller's first comment lines) and image, and c->stats.  0, or -1 with
 * a message (c is left for the caller to free). */
static int backend(fp3_compiled *c, const fp3_compile_opts *o, const char *head, char *msg,
                   size_t n) {
  builder *b = &c->b;
  int rc = -1;
  fp3_strbuf t = {0};
  insn *code = calloc(MAX_NODES + MAX_STATE + 2, sizeof *code); /* counted, then checked */
  bins *bi = calloc(BODY_MAX, sizeof *bi);
  int *order = calloc(BODY_MAX, sizeof *order);
  regalloc *ra = calloc(1, sizeof *ra);
  if (!code || !bi || !order || !ra) {
    snprintf(msg, n, "out of memory");
    goto out;
  }
  /* ---- every operation has its instruction ---- */
  for (int i = 0; i < b->nn; i++) {
    const node *x = &b->nd[i];
    if (!op_kind(x->kind) || !x->live || x->host || node_opc(x->kind) >= 0) continue;
    const char *mn = kind_mnemonic[x->kind];
    const char *flag = x->kind == NK_DIV ? "HAS_DIV" : x->kind == NK_SQRT ? "HAS_SQRT" : NULL;
    if (flag)
      snprintf(msg, n, "model %s needs %s: this build has no %s unit (the ISA table has no "
               "'%s' instruction)", b->model->name, mn, flag, mn);
    else
      snprintf(msg, n, "model %s needs %s: the ISA table has no '%s' instruction",
               b->model->name, mn, mn);
    goto out;
  }

  /* ---- body instructions: live non-invariant ops, then moves ---- */
  int nb = 0;
  for (int i = 0; i < b->nn; i++) {
    node *x = &b->nd[i];
    if (!op_kind(x->kind)) continue;
    if (!x->live) {
      c->stats.dead_removed++;
      continue;
    }
    if (x->inv) {
      if (!x->host) c->stats.hoisted++;
      continue;
    }
    bi[nb] = (bins){i, 0, -1, {x->a, x->b}, 0, 0, 0, 0};
    nb++;
  }
  for (int w = 0; w < b->nstate; w++) {
    int src = b->out[w].n;
    if (b->nd[src].kind == NK_STATE && b->nd[src].id == w) continue; /* unchanged */
    int p = producer(bi, nb, src);
    int taken = p >= 0 && bi[p].dest_state >= 0;
    /* the producer writes the state register itself unless a reader of
     * the old value depends on the new one (Kahan's (t - y) after t):
     * then t goes to a temporary and a mov follows */
    for (int k = 0; k < nb && p >= 0 && !taken; k++)
      for (int q = 0; q < 2; q++) {
        int sn = bi[k].srcs[q];
        if (sn >= 0 && b->nd[sn].kind == NK_STATE && b->nd[sn].id == w && k != p &&
            feeds(bi, nb, p, k))
          taken = 1;
      }
    if (p >= 0 && !taken) {
      bi[p].dest_state = w;
    } else {
      bi[nb] = (bins){src, 1, w, {src, -1}, 0, 0, 0, 0};
      nb++;
    }
  }
  /* ---- schedule and registers ---- */
  const unsigned fixed = fixed_regs(b);
  unsigned nregs = o->num_regs, need = 0;
  if (schedule(b, o, bi, nb, order, fixed, 0) == 0)
    need = allocate(b, o, bi, nb, order, FP3_MAX_REGS, ra, c->in_reg, c->state_reg);
  else {
    snprintf(msg, n, "internal: the loop body cannot be ordered (a value of the "
                     "old state is needed after the new one)");
    goto out;
  }
  if (need > nregs) { /* bound the pressure; keep the order that needs fewer */
    int *order2 = calloc(BODY_MAX, sizeof *order2);
    int *best2 = calloc(BODY_MAX, sizeof *best2);
    if (!order2 || !best2) {
      free(order2);
      free(best2);
      snprintf(msg, n, "out of memory");
      goto out;
    }
    /* the greedy bound may start too many chains before it binds: a
     * tighter bound (down to fixed + 1) may end with fewer registers */
    unsigned need2 = 0;
    for (unsigned bound = nregs; bound > fixed && (!need2 || need2 > nregs); bound--) {
      unsigned k = 0;
      if (schedule(b, o, bi, nb, order2, fixed, bound) == 0)
        k = allocate(b, o, bi, nb, order2, FP3_MAX_REGS, ra, c->in_reg, c->state_reg);
      if (k && (!need2 || k < need2)) {
        need2 = k;
        memcpy(best2, order2, (BODY_MAX) * sizeof *order2);
      }
    }
    memcpy(order2, best2, (BODY_MAX) * sizeof *order2);
    if (need2 && need2 < need) { /* the pressure-bounded order needs fewer */
      memcpy(order, order2, (BODY_MAX) * sizeof *order);
      need = need2;
    }
    if (need > nregs && need <= o->max_regs) nregs = need; /* a larger build */
    free(order2);
    free(best2);
    /* the issue cycles of the order kept */
    if (schedule_times(b, o, bi, nb, order)) {
      snprintf(msg, n, "internal: the loop body cannot be ordered");
      goto out;
    }
  }
  c->stats.regs_needed = need;
  c->stats.num_regs = nregs;
  if (!need) {
    snprintf(msg, n, "the program needs more than %d registers; NUM_REGS is %u",
             FP3_MAX_REGS, o->num_regs);
    goto out;
  }
  if (need > nregs) {
    snprintf(msg, n, "the program needs %u registers; NUM_REGS is %u (%u hold the run's "
             "inputs, constants and invariants, the rest the loop's temporaries, and there "
             "is no spilling: a build with NUM_REGS=%u runs it)", need, o->num_regs, fixed,
             need);
    goto out;
  }
  if (allocate(b, o, bi, nb, order, nregs, ra, c->in_reg, c->state_reg) == 0) {
    snprintf(msg, n, "internal: register allocation failed at NUM_REGS %u", nregs);
    goto out;
  }
  int *in_reg = c->in_reg, *state_reg = c->state_reg;
  unsigned regs_used = 0;
  {
    int seen[FP3_MAX_REGS] = {0};
    for (int i = 0; i < b->nn; i++)
      if (b->nd[i].live && ra->reg[i] >= 0 && !seen[ra->reg[i]]) {
        seen[ra->reg[i]] = 1;
        regs_used++;
      }
  }
  c->stats.regs = regs_used;

  /* ---- instructions ---- */
  size_t ni = 0;
  unsigned prologue = 0;
  for (int pass = 0; pass < 2; pass++)
    for (int i = 0; i < b->nn; i++) {
      node *x = &b->nd[i];
      if (!x->live || !x->inv || x->host) continue;
      insn *in = &code[ni];
      if (pass == 0 && x->kind == NK_CONST) {
        *in = (insn){FP3_OP_LI, (unsigned)ra->reg[i], 0, 0, x->bits, ""};
        snprintf(in->note, NOTE_LEN, "%s = %.9g", x->name, (double)fpref_float(x->bits));
      } else if (pass == 1 && op_kind(x->kind)) {
        *in = (insn){(unsigned)node_opc(x->kind), (unsigned)ra->reg[i], (unsigned)ra->reg[x->a],
                     x->b >= 0 ? (unsigned)ra->reg[x->b] : 0, 0, ""};
        describe(b, i, in->note, NOTE_LEN);
        strncat(in->note, " (loop invariant)", NOTE_LEN - strlen(in->note) - 1);
      } else {
        continue;
      }
      ni++;
      prologue++;
    }
  size_t body_at = ni;
  for (int q = 0; q < nb; q++) {
    bins *x = &bi[order[q]];
    insn *in = &code[ni++];
    unsigned rd = x->dest_state >= 0 ? (unsigned)state_reg[x->dest_state]
                                     : (unsigned)ra->reg[x->node];
    if (x->is_mov) {
      *in = (insn){FP3_OP_MOV, rd, (unsigned)ra->reg[x->node], 0, 0, ""};
      snprintf(in->note, NOTE_LEN, "%s = %s", b->st_name[x->dest_state], b->nd[x->node].name);
    } else {
      const node *y = &b->nd[x->node];
      *in = (insn){(unsigned)node_opc(y->kind), rd, (unsigned)ra->reg[y->a],
                   y->b >= 0 ? (unsigned)ra->reg[y->b] : 0, 0, ""};
      describe(b, x->node, in->note, NOTE_LEN);
    }
    if (x->dest_state >= 0) {
      strncat(in->note, " -> ", NOTE_LEN - strlen(in->note) - 1);
      strncat(in->note, b->st_name[x->dest_state], NOTE_LEN - strlen(in->note) - 1);
    }
  }
  code[ni++] = (insn){FP3_OP_ENDI, 0, 0, 0, (uint32_t)body_at, "next integration"};
  if (ni > MAX_INSNS) {
    snprintf(msg, n, "the program needs %zu instructions; IMEM_DEPTH is %d", ni, MAX_INSNS);
    goto out;
  }
  c->stats.prologue_insns = prologue;
  c->stats.body_insns = (unsigned)(ni - body_at);
  c->stats.body_arith = 0;
  for (size_t k = body_at; k < ni; k++)
    if (code[k].opc != FP3_OP_MOV && code[k].opc != FP3_OP_LI && code[k].opc != FP3_OP_ENDI)
      c->stats.body_arith++;

  /* ---- estimate, on the words ---- */
  fp3_image est;
  fp3_image_init(&est);
  for (size_t k = 0; k < ni; k++)
    est.words[k] = fp3_insn_make(code[k].opc, code[k].rd, code[k].ra, code[k].rb, code[k].imm);
  est.n = ni;
  fp3_estimate_cycles(&est, o, 8, &c->stats.est_cycles_first, &c->stats.est_cycles_later);

  /* ---- text ---- */
  fp3_strbuf_printf(&t, "%s", head);
  fp3_strbuf_printf(&t, "; loop invariants moved to the prologue: %u; dead operations removed: %u\n",
      c->stats.hoisted, c->stats.dead_removed);
  fp3_strbuf_printf(&t, "; instructions per integration: %u (%u arithmetic + endi; the literal program: %u)\n",
      c->stats.body_insns, c->stats.body_arith, c->stats.literal_body_insns);
  fp3_strbuf_printf(&t, "; prologue: %u instructions; registers: %u of %u (%u live at most)\n",
                    prologue, regs_used, nregs, need);
  if (nregs > o->num_regs)
    fp3_strbuf_printf(&t, "; for a build with NUM_REGS >= %u: the default %u are too few\n", nregs,
                      o->num_regs);
  fp3_strbuf_printf(&t, "; estimated cycles%s (add/sub %u, mul %u, li/mov %u cycles to a dependent issue):\n"
          ";   first integration %u, each later one %u\n",
      o->fmax_pipe ? " for FMAX_PIPE=1" : "",
      unit_latency(o, FP3_UNIT_ADD), unit_latency(o, FP3_UNIT_MUL), unit_latency(o, FP3_UNIT_MOV),
      c->stats.est_cycles_first, c->stats.est_cycles_later);
  fp3_strbuf_printf(&t, ";\n; golden model: the IR in C binary32 (sw/compiler/compile.c, fp3_compiled_model_step)\n\n");
  /* a model's names are not the assembler's .in / .out names: the
   * bindings are comments, and fp3_compiled_model_start gives them */
  fp3_strbuf_printf(&t, "; host inputs (written before the run):\n");
  for (int k = 0; k < b->nin; k++)
    if (in_reg[k] >= 0) fp3_strbuf_printf(&t, ";   %-12s r%d\n", b->in_name[k], in_reg[k]);
  for (int i = 0; i < b->nn; i++)
    if (b->nd[i].live && b->nd[i].host) {
      char d[NOTE_LEN];
      describe(b, i, d, sizeof d);
      fp3_strbuf_printf(&t, ";   %-12s r%d  (host: %s)\n", b->nd[i].name, ra->reg[i], d);
    }
  fp3_strbuf_printf(&t, "; results: the state registers above, after each endi\n\n");
  if (nregs > FP3_DEFAULT_NUM_REGS) fp3_strbuf_printf(&t, ".regs %u\n\n", nregs);
  for (size_t k = 0; k < ni; k++) {
    const insn *x = &code[k];
    char ops[48];
    if (k == body_at) fp3_strbuf_printf(&t, "body:\n");
    if (x->opc == FP3_OP_LI) snprintf(ops, sizeof ops, "r%u, 0x%08X", x->rd, (unsigned)x->imm);
    else if (x->opc == FP3_OP_MOV) snprintf(ops, sizeof ops, "r%u, r%u", x->rd, x->ra);
    else if (x->opc == FP3_OP_ENDI) snprintf(ops, sizeof ops, "body");
    else if (!(fp3_opc_uses((unsigned)x->opc) & FP3_USES_RB)) /* sqrt, abs, neg */
      snprintf(ops, sizeof ops, "r%u, r%u", x->rd, x->ra);
    else snprintf(ops, sizeof ops, "r%u, r%u, r%u", x->rd, x->ra, x->rb);
    fp3_strbuf_printf(&t, "        %-4s %-16s ; %s\n", fp3_opc_mnemonic(x->opc), ops, x->note);
  }
  if (t.oom) {
    snprintf(msg, n, "out of memory");
    goto out;
  }
  c->text = t.s;
  t.s = NULL;
  char *errs = NULL;
  if (fp3_asm_string(c->text, "(compiled program)", &c->img, &errs)) {
    snprintf(msg, n, "internal: the emitted program does not assemble: %s", errs ? errs : "");
    free(errs);
    goto out;
  }
  free(errs);
  for (int i = 0; i < b->nn; i++) c->host_reg[i] = b->nd[i].live && b->nd[i].host ? ra->reg[i] : -1;
  rc = 0;
out:
  free(t.s);
  free(code);
  free(bi);
  free(order);
  free(ra);
  return rc;
}


void fp3_compiled_free(fp3_compiled *c) {
  if (!c) return;
  free(c->text);
  free(c);
}

const char *fp3_compiled_text(const fp3_compiled *c) { return c->text; }
const fp3_image *fp3_compiled_image(const fp3_compiled *c) { return &c->img; }
const fp3_compile_stats *fp3_compiled_stats(const fp3_compiled *c) { return &c->stats; }

/* ---- models (model.h) -------------------------------------------------- */

/* Exact rewrites only: a + (-b) = a - b, (-a) + b = b - a, a - (-b) =
 * a + b (IEEE 754 defines subtraction so), (-a) b = -(a b), (-a)/b =
 * -(a/b), |(-a)| = |a| (sign-symmetric rounding: RNE, RTZ).  A negation
 * that must exist as a value (an output, sqrt's or min's operand, a sum
 * of two negated terms) is pushed into an invariant factor of a product
 * or quotient, -(a b) = (-a) b with -a computed by the host, or else
 * becomes a neg instruction.  (-a) + (-b) is rewritten -(a + b) only in a
 * folded program (its own golden model is its reference): the two differ
 * in the sign of an exact zero. */
static ref m_value(builder *b, ref x);
static void golden_begin(fp3_compiled *c, const float *y0);
static void golden_advance(fp3_compiled *c, float *y);

/* A node for -x without a neg instruction where an exact form exists, else
 * -1. */
static int neg_push(builder *b, int i) {
  node x = b->nd[i];
  if (x.kind == NK_CONST) return leaf(b, NK_CONST, -1, x.bits ^ 0x80000000u, "nconst").n;
  if (x.inv) { /* the host flips it */
    node z = {NK_NEG, i, -1, -1, 0, 1, 0, 0, ""};
    int k = new_node(b, z);
    if (!b->nd[k].name[0]) snprintf(b->nd[k].name, sizeof b->nd[k].name, "-%.24s", x.name);
    return k;
  }
  if (x.kind != NK_MUL && x.kind != NK_DIV) return -1;
  int na = neg_push(b, x.a);
  if (na >= 0) x.a = na;
  else if (x.kind == NK_MUL && (na = neg_push(b, x.b)) >= 0) x.b = na;
  else return -1;
  x.name[0] = '\0';
  x.live = 0;
  int k = new_node(b, x);
  if (!b->nd[k].name[0]) {
    char t_[FP3_MODEL_NAME_LEN];
    snprintf(t_, sizeof t_, "-%.24s", b->nd[i].name);
    memcpy(b->nd[k].name, t_, sizeof t_);
  }
  return k;
}

/* x as a value: its negation carried out. */
static ref m_value(builder *b, ref x) {
  if (!x.neg) return x;
  int k = neg_push(b, x.n);
  if (k < 0) k = op(b, NK_NEG, (ref){x.n, 0}, (ref){-1, 0}).n;
  return (ref){k, 0};
}

static ref m_unary(builder *b, int kind, ref x) {
  node z = {kind, x.n, -1, -1, 0, b->nd[x.n].inv, 0, 0, ""};
  return (ref){new_node(b, z), 0};
}

static ref m_add(builder *b, ref x, ref y) {
  if (x.neg && y.neg && !b->fold) x = m_value(b, x); /* (-a) + (-b): one negation made */
  return add(b, x, y);
}

static ref m_div(builder *b, ref x, ref y) {
  if (is_zero(b, x)) return x;
  ref r;
  if (b->fold && b->nd[y.n].inv && !b->nd[x.n].inv) { /* x / p = x * (1/p), host 1/p */
    ref one = konst(b, 1.0f, "one");
    node z = {NK_DIV, one.n, y.n, -1, 0, 1, 0, 0, ""};
    int k = new_node(b, z);
    if (!b->nd[k].name[0]) {
      char t_[FP3_MODEL_NAME_LEN];
      snprintf(t_, sizeof t_, "1/%.24s", b->nd[y.n].name);
      memcpy(b->nd[k].name, t_, sizeof t_);
    }
    r = mul(b, (ref){x.n, 0}, (ref){k, 0});
    r.neg ^= y.neg;
    return r;
  }
  node z = {NK_DIV, x.n, y.n, -1, 0, b->nd[x.n].inv && b->nd[y.n].inv, 0, 0, ""};
  r = (ref){new_node(b, z), x.neg ^ y.neg};
  return r;
}

/* ---- the affine fold ------------------------------------------------------ *
 *
 * A derivative that is affine in the state with loop-invariant
 * coefficients, f_i(y) = c_0 + sum_s c_s y_s (the ship's (T - C v) minv =
 * T minv - (C minv) v, a spring's -(k x + c v)/m), is multiplied by the
 * step as hm f_i = (hm c_0) + sum_s (hm c_s) y_s: the host computes each
 * product hm c in binary32 (RNE) once per object, and the loop keeps one
 * mul per state term and one add per term more, 2 instructions for the
 * ship instead of 4.  A factor common to every term (the ship's minv) is
 * kept apart and multiplied into the step first, (hm minv) T: the ship's
 * hmT = (h minv) T and hmC = (h minv) C of Bourg's folded form.  A
 * different rounding sequence from the literal program (like every fold):
 * the program's own IR is its golden model. */

/* An affine form sc (c0 + sum_s c[s] y_s) (n = -1: absent; c: a zero
 * term, sc: 1). */
typedef struct lin {
  int ok;              /* 1: affine in the state, invariant coefficients */
  ref sc;
  ref c0;
  ref c[MAX_STATE];
} lin;

static int lin_has(ref r) { return r.n >= 0; }

static void lin_clear(lin *l, unsigned ns) {
  l->ok = 1;
  l->sc = l->c0 = (ref){-1, 0};
  for (unsigned s = 0; s < ns; s++) l->c[s] = (ref){-1, 0};
}

/* r as a coefficient: absent when it is the removed zero term. */
static ref lin_coef(const builder *b, ref r) { return is_zero(b, r) ? (ref){-1, 0} : r; }

static ref lin_sum(builder *b, ref x, ref y) {
  if (!lin_has(x)) return y;
  if (!lin_has(y)) return x;
  return lin_coef(b, m_add(b, x, y));
}

/* x * f (div = 0) or x / f (div = 1) for an invariant f. */
static ref lin_scale(builder *b, ref x, ref f, int div) {
  if (!lin_has(x)) return x;
  return lin_coef(b, div ? m_div(b, x, f) : mul(b, f, x));
}

/* The common factor multiplied into each coefficient. */
static void lin_unscale(builder *b, lin *l, unsigned ns) {
  if (!lin_has(l->sc)) return;
  l->c0 = lin_scale(b, l->c0, l->sc, 0);
  for (unsigned s = 0; s < ns; s++) l->c[s] = lin_scale(b, l->c[s], l->sc, 0);
  l->sc = (ref){-1, 0};
}

static int lin_invariant(const lin *l, unsigned ns) {
  for (unsigned s = 0; s < ns; s++)
    if (lin_has(l->c[s])) return 0;
  return 1;
}

/* The affine form of model node i (operands' forms in L) whose value is
 * ri; not affine: ok = 0. */
static void lin_node(builder *b, const fp3_model *m, lin *L, unsigned i, ref ri) {
  const unsigned ns = m->nstate;
  const fp3_mexpr *x = &m->node[i];
  lin *l = &L[i];
  lin_clear(l, ns);
  if (b->nd[ri.n].inv) { /* constants, params, lets of params */
    l->c0 = lin_coef(b, ri);
    return;
  }
  const lin *a = x->a >= 0 ? &L[x->a] : NULL, *c = x->b >= 0 ? &L[x->b] : NULL;
  l->ok = 0;
  switch (x->kind) {
  case FP3_ME_STATE:
    l->ok = 1;
    l->c[x->id] = konst(b, 1.0f, "one");
    break;
  case FP3_ME_ADD:
  case FP3_ME_SUB:
  case FP3_ME_NEG:
    if (!a->ok || (c && !c->ok)) break;
    *l = *a;
    if (x->kind == FP3_ME_NEG) {
      l->c0.neg ^= 1;
      for (unsigned s = 0; s < ns; s++) l->c[s].neg ^= 1;
      break;
    }
    lin e_ = *c;
    if (!lin_has(l->sc) || !lin_has(e_.sc) || l->sc.n != e_.sc.n || l->sc.neg != e_.sc.neg) {
      lin_unscale(b, l, ns); /* a factor common to both stays apart */
      lin_unscale(b, &e_, ns);
    }
    for (unsigned s = 0; s <= ns; s++) {
      ref *d = s < ns ? &l->c[s] : &l->c0;
      ref e = s < ns ? e_.c[s] : e_.c0;
      e.neg ^= x->kind == FP3_ME_SUB;
      *d = lin_sum(b, *d, e);
    }
    l->ok = 1;
    break;
  case FP3_ME_MUL:
  case FP3_ME_DIV: {
    const lin *v = a, *f = c; /* affine v times (or over) invariant f */
    if (x->kind == FP3_ME_MUL && a->ok && lin_invariant(a, ns)) v = c, f = a;
    if (!v->ok || !f->ok || !lin_invariant(f, ns)) break;
    if (!lin_has(f->c0)) { /* a removed zero factor */
      if (x->kind == FP3_ME_DIV) break;
      l->ok = 1;
      break;
    }
    *l = *v;
    if (x->kind == FP3_ME_MUL) {
      l->sc = lin_has(l->sc) ? mul(b, l->sc, f->c0) : f->c0;
      break;
    }
    lin_unscale(b, l, ns);
    l->c0 = lin_scale(b, l->c0, f->c0, 1);
    for (unsigned s = 0; s < ns; s++) l->c[s] = lin_scale(b, l->c[s], f->c0, 1);
    break;
  }
  default: break; /* sqrt, abs, min, max of the state: not affine */
  }
}

/* Operations of the loop (non-invariant) under node i, each once. */
static unsigned loop_ops(const builder *b, int i, unsigned char *seen) {
  const node *x = &b->nd[i];
  if (seen[i] || x->inv || !op_kind(x->kind)) return 0;
  seen[i] = 1;
  return 1 + loop_ops(b, x->a, seen) + (x->b >= 0 ? loop_ops(b, x->b, seen) : 0);
}

/* A loop-invariant product the host computes (bound like an input). */
static ref host_value(builder *b, ref r, const char *pre, const char *fs, const char *of) {
  node *x = &b->nd[r.n];
  if (op_kind(x->kind) && x->inv) {
    x->host = 1;
    if (!x->name[0]) snprintf(x->name, sizeof x->name, "%.3s%.12s_%.12s", pre, fs, of);
  }
  return r;
}

/* hm * f for state variable i's derivative f at the stage y: the affine
 * form (L, when given, with b->fold) when it takes fewer instructions
 * than the expression, else hm f. */
static ref m_hf(builder *b, ref hm, ref f, const lin *L, const ref *y, unsigned i,
                const char *pre) {
  if (!L || !b->fold || !L->ok || b->err) return mul(b, hm, f);
  const unsigned ns = b->model->nstate;
  unsigned terms = lin_has(L->c0), muls = 0;
  for (unsigned s = 0; s < ns; s++) muls += lin_has(L->c[s]);
  terms += muls;
  unsigned char *seen = calloc((size_t)b->nn, 1);
  if (!seen) {
    b->err = 1;
    return mul(b, hm, f);
  }
  const unsigned expr = loop_ops(b, f.n, seen) + 1;
  free(seen);
  if (terms == 0 || muls + terms - 1 >= expr) return mul(b, hm, f);
  const char *fs = b->st_name[i];
  if (lin_has(L->sc)) hm = mul(b, hm, L->sc);
  ref acc = {-1, 0};
  for (unsigned s = 0; s < ns; s++)
    if (lin_has(L->c[s]))
      acc = lin_sum(b, acc, mul(b, host_value(b, mul(b, hm, L->c[s]), pre, fs, b->st_name[s]),
                                y[s]));
  if (lin_has(L->c0)) acc = lin_sum(b, acc, host_value(b, mul(b, hm, L->c0), pre, fs, "0"));
  return acc;
}

/* The model's derivatives at state y (refs): f[i] for each state, and
 * with L (b->fold) the affine form of each derivative in L[i]. */
static void m_fl(builder *b, const fp3_model *m, const ref *y, ref *f, lin *L, const char *tag) {
  ref *r = calloc(m->nn ? m->nn : 1, sizeof *r);
  lin *nl = L && b->fold ? calloc(m->nn ? m->nn : 1, sizeof *nl) : NULL;
  if (!r || (L && b->fold && !nl)) {
    free(r);
    free(nl);
    b->err = 1;
    return;
  }
  for (unsigned i = 0; i < m->nn && !b->err; i++) {
    const fp3_mexpr *x = &m->node[i];
    if (x->exact_only) continue;
    ref a = x->a >= 0 ? r[x->a] : (ref){0, 0}, c = x->b >= 0 ? r[x->b] : (ref){0, 0};
    switch (x->kind) {
    case FP3_ME_NUM: {
      char num[24]; /* an unnamed number is named by its value */
      snprintf(num, sizeof num, "%.9g", (double)fpref_float(x->bits));
      const char *cn = num;
      for (unsigned d = 0; d < m->ndef; d++)
        if (m->def_node[d] == (int)i) cn = m->def[d];
      if (b->drop_zero && (x->bits & 0x7FFFFFFFu) == 0) {
        r[i] = konst(b, 0.0f, "zero");
        b->zero = r[i].n;
      } else {
        r[i] = konst(b, fpref_float(x->bits), cn);
      }
      break;
    }
    case FP3_ME_PARAM:
      if (b->drop_zero && b->pzero && b->pzero[x->id]) {
        r[i] = konst(b, 0.0f, "zero");
        b->zero = r[i].n;
      } else {
        r[i] = leaf(b, NK_IN, x->id, 0, m->param[x->id]);
      }
      break;
    case FP3_ME_STATE: r[i] = y[x->id]; break;
    case FP3_ME_ADD: r[i] = m_add(b, a, c); break;
    case FP3_ME_SUB: c.neg ^= 1; r[i] = m_add(b, a, c); break;
    case FP3_ME_MUL: r[i] = mul(b, a, c); break;
    case FP3_ME_DIV: r[i] = m_div(b, a, c); break;
    case FP3_ME_NEG: r[i] = a; r[i].neg ^= 1; break;
    case FP3_ME_SQRT: r[i] = m_unary(b, NK_SQRT, m_value(b, a)); break;
    case FP3_ME_ABS: a.neg = 0; r[i] = m_unary(b, NK_ABS, a); break;
    case FP3_ME_MIN:
    case FP3_ME_MAX:
      r[i] = op(b, x->kind == FP3_ME_MIN ? NK_MIN : NK_MAX, m_value(b, a), m_value(b, c));
      break;
    default: b->err = 1; break;
    }
    for (unsigned d = 0; d < m->ndef; d++)
      if (m->def_is_let[d] && m->def_node[d] == (int)i) nm(b, r[i], m->def[d]);
    if (nl) lin_node(b, m, nl, i, r[i]);
  }
  for (unsigned i = 0; i < m->nstate && !b->err; i++) {
    f[i] = r[m->deriv[i]];
    char s_[FP3_MODEL_NAME_LEN];
    snprintf(s_, sizeof s_, "f%.2s_%.24s", tag, m->state[i]);
    nm(b, f[i], s_);
    if (L) {
      if (nl) L[i] = nl[m->deriv[i]];
      else L[i].ok = 0;
    }
  }
  free(r);
  free(nl);
}

static void m_f(builder *b, const fp3_model *m, const ref *y, ref *f, const char *tag) {
  m_fl(b, m, y, f, NULL, tag);
}

/* tag_state: "k1_x" etc. for the comments. */
static ref m_nm(builder *b, ref r, const char *what, unsigned i) {
  char s_[FP3_MODEL_NAME_LEN];
  snprintf(s_, sizeof s_, "%.4s_%.24s", what, b->st_name[i]);
  return nm(b, r, s_);
}

/* out[i] = y_i + d, Kahan-compensated with the carried c_i (state ns + i):
 * yk = d - c; t = y + yk; c = (t - y) - yk (fp3_model_step_literal). */
static void m_kahan(builder *b, const fp3_model *m, ref yi, ref d, unsigned i) {
  const unsigned ns = m->nstate;
  ref nc = state(b, (int)(ns + i)), ny = yi;
  nc.neg ^= 1;
  ny.neg ^= 1;
  ref yk = m_nm(b, m_add(b, d, nc), "yk", i);
  ref t_ = m_nm(b, m_add(b, yi, yk), "n", i);
  ref z = m_nm(b, m_add(b, t_, ny), "z", i);
  yk.neg ^= 1;
  b->out[ns + i] = m_add(b, z, yk);
  b->out[i] = t_;
}

/* RK4's weighted sum of k1..k4: literal ((k1 + 2 k2) + 2 k3) + k4, or
 * folded (k1 + k4) + 2 (k2 + k3). */
static ref m_rk4_sum(builder *b, ref two, ref k1, ref k2, ref k3, ref k4) {
  if (b->fold) return m_add(b, m_add(b, k1, k4), mul(b, two, m_add(b, k2, k3)));
  ref sum = m_add(b, k1, mul(b, two, k2));
  sum = m_add(b, sum, mul(b, two, k3));
  return m_add(b, sum, k4);
}

/* The RK4 family (fp3_model_step_literal): rk4 and rk4comp (all: every
 * state variable in the k form), rk4vs and rk4vscomp, rk4se and rk4secomp
 * (se); comp: the updates Kahan-compensated. */
static void m_build_rk4(builder *b, const fp3_model *m, const ref *y, ref h, int all, int se,
                        int comp) {
  const unsigned ns = m->nstate;
  static const char *const ktag[3] = {"k1", "k2", "k3"}, *const ytag[3] = {"y2", "y3", "y4"};
  static const char *const ftag[4] = {"1", "2", "3", "4"};
  ref f[4][MAX_STATE], k[3][MAX_STATE], t[MAX_STATE];
  lin L[MAX_STATE]; /* the affine forms at the latest stage (y, then t) */
  ref half = konst(b, FP3_RK4_HALF, "half"), two = konst(b, FP3_RK4_TWO, "two");
  ref sixth = konst(b, FP3_RK4_SIXTH, "sixth");
  m_fl(b, m, y, f[0], L, ftag[0]);
  for (unsigned st = 0; st < 3; st++) {
    for (unsigned j = 0; j < ns; j++)
      k[st][j] = m_nm(b, m_hf(b, h, f[st][j], &L[j], st ? t : y, j, "h"), ktag[st], j);
    for (unsigned j = 0; j < ns; j++)
      t[j] = se && m->role[j] == FP3_MR_POSITION
                 ? y[j]
                 : m_nm(b, m_add(b, y[j], st < 2 ? mul(b, half, k[st][j]) : k[st][j]),
                        ytag[st], j);
    m_fl(b, m, t, f[st + 1], L, ftag[st + 1]);
  }
  for (unsigned i = 0; i < ns; i++) {
    ref d;
    if (all || m->role[i] == FP3_MR_VELOCITY) {
      ref k4 = m_nm(b, m_hf(b, h, f[3][i], &L[i], t, i, "h"), "k4", i);
      d = mul(b, sixth, m_nm(b, m_rk4_sum(b, two, k[0][i], k[1][i], k[2][i], k4), "sum", i));
    } else if (!se) { /* (h sixth) ((f1 + 2 (f2 + f3)) + f4) */
      ref h6 = nm(b, mul(b, h, sixth), "h6");
      ref u = m_add(b, f[0][i], mul(b, two, m_add(b, f[1][i], f[2][i])));
      d = mul(b, h6, m_nm(b, m_add(b, u, f[3][i]), "u", i));
    } else {
      continue;
    }
    if (comp) m_kahan(b, m, y[i], d, i);
    else b->out[i] = m_nm(b, m_add(b, y[i], d), "n", i);
  }
  if (!se) return;
  for (unsigned j = 0; j < ns; j++) t[j] = m->role[j] == FP3_MR_VELOCITY ? b->out[j] : y[j];
  m_fl(b, m, t, f[0], L, "5"); /* positions by the new velocities */
  for (unsigned i = 0; i < ns; i++)
    if (m->role[i] == FP3_MR_POSITION) {
      ref d = m_nm(b, m_hf(b, h, f[0][i], &L[i], t, i, "h"), "d", i);
      if (comp) m_kahan(b, m, y[i], d, i);
      else b->out[i] = m_nm(b, m_add(b, y[i], d), "n", i);
    }
}

/* verletp (fp3_model_step_literal): a_u carried in state ns + u. */
static void m_build_verletp(builder *b, const fp3_model *m, const ref *y, ref h) {
  const unsigned ns = m->nstate;
  ref f[MAX_STATE] = {{0, 0}}, t[MAX_STATE] = {{0, 0}}, a[MAX_STATE] = {{0, 0}};
  ref half = konst(b, FP3_RK4_HALF, "half");
  ref hh = nm(b, mul(b, half, h), "hh");
  ref hh2 = nm(b, mul(b, half, nm(b, mul(b, h, h), "hsq")), "hh2");
  for (unsigned i = 0; i < ns; i++) a[i] = state(b, (int)(ns + i));
  for (unsigned i = 0; i < ns; i++) {
    if (m->role[i] == FP3_MR_POSITION) {
      const unsigned p = (unsigned)fp3_model_pair(m, i);
      ref ds = m_nm(b, m_add(b, mul(b, h, y[p]), mul(b, hh2, a[p])), "ds", i);
      t[i] = m_nm(b, m_add(b, y[i], ds), "n", i);
    } else {
      t[i] = m_nm(b, m_add(b, y[i], mul(b, h, a[i])), "up", i);
    }
  }
  m_f(b, m, t, f, "p");
  for (unsigned i = 0; i < ns; i++)
    b->out[i] = m->role[i] == FP3_MR_POSITION
                    ? t[i]
                    : m_nm(b, m_add(b, y[i], mul(b, hh, m_nm(b, m_add(b, a[i], f[i]), "sa", i))),
                           "n", i);
  for (unsigned i = 0; i < ns; i++) t[i] = b->out[i];
  m_f(b, m, t, f, "a"); /* the next integration's acceleration */
  for (unsigned i = 0; i < ns; i++)
    b->out[ns + i] = m->role[i] == FP3_MR_VELOCITY ? f[i] : a[i];
}

/* The literal integrators of model.h (fp3_model_step_literal), or folded
 * (b->fold: RK4's sum as (k1 + k4) + 2 (k2 + k3)). */
static int m_build(builder *b, const fp3_model *m, const char *integ) {
  const unsigned ns = m->nstate;
  ref y[MAX_STATE] = {{0, 0}}, f[MAX_STATE] = {{0, 0}}, t[MAX_STATE] = {{0, 0}};
  lin L[MAX_STATE];
  for (unsigned i = 0; i < ns; i++) y[i] = state(b, (int)i);
  ref h = leaf(b, NK_IN, 0, 0, "h");
  if (strcmp(integ, "euler") == 0) {
    m_fl(b, m, y, f, L, "");
    for (unsigned i = 0; i < ns; i++)
      b->out[i] = m_nm(b, m_add(b, y[i], m_hf(b, h, f[i], &L[i], y, i, "h")), "n", i);
  } else if (strcmp(integ, "rk2") == 0) {
    ref hh = nm(b, mul(b, konst(b, FP3_RK4_HALF, "half"), h), "hh");
    m_fl(b, m, y, f, L, "1");
    for (unsigned j = 0; j < ns; j++)
      t[j] = m_nm(b, m_add(b, y[j], m_hf(b, hh, f[j], &L[j], y, j, "hh")), "ym", j);
    m_fl(b, m, t, f, L, "2");
    for (unsigned i = 0; i < ns; i++)
      b->out[i] = m_nm(b, m_add(b, y[i], m_hf(b, h, f[i], &L[i], t, i, "h")), "n", i);
  } else if (strcmp(integ, "rk4") == 0 || strcmp(integ, "rk4comp") == 0) {
    m_build_rk4(b, m, y, h, 1, 0, strcmp(integ, "rk4comp") == 0);
  } else if (strncmp(integ, "rk4se", 5) == 0 || strncmp(integ, "rk4vs", 5) == 0) {
    if (!fp3_model_integrator_known(integ)) return -1;
    if (!fp3_model_split(m)) return -2;
    m_build_rk4(b, m, y, h, 0, strncmp(integ, "rk4se", 5) == 0, strstr(integ, "comp") != NULL);
  } else if (strcmp(integ, "verletp") == 0) {
    if (!fp3_model_split(m)) return -2;
    if (!fp3_model_integrator_applies(m, integ)) return -4;
    m_build_verletp(b, m, y, h);
  } else if (strcmp(integ, "symeuler") == 0) {
    if (!fp3_model_split(m)) return -2;
    m_fl(b, m, y, f, L, "1");
    for (unsigned i = 0; i < ns; i++)
      t[i] = m->role[i] == FP3_MR_VELOCITY
                 ? m_nm(b, m_add(b, y[i], m_hf(b, h, f[i], &L[i], y, i, "h")), "n", i)
                 : y[i];
    m_fl(b, m, t, f, L, "2");
    for (unsigned i = 0; i < ns; i++)
      b->out[i] = m->role[i] == FP3_MR_POSITION
                      ? m_nm(b, m_add(b, y[i], m_hf(b, h, f[i], &L[i], t, i, "h")), "n", i)
                      : t[i];
  } else if (strcmp(integ, "verlet") == 0) {
    /* kick, drift, kick (fp3_model_step_literal); each evaluation of f
     * keeps only the derivatives its update reads (dead code elimination) */
    if (!fp3_model_split(m)) return -2;
    if (!fp3_model_verlet_ok(m, NULL, NULL)) return -3;
    ref hh = nm(b, mul(b, konst(b, FP3_RK4_HALF, "half"), h), "hh");
    m_fl(b, m, y, f, L, "1");
    for (unsigned i = 0; i < ns; i++)
      t[i] = m->role[i] == FP3_MR_VELOCITY
                 ? m_nm(b, m_add(b, y[i], m_hf(b, hh, f[i], &L[i], y, i, "hh")), "uh", i)
                 : y[i];
    m_fl(b, m, t, f, L, "2");
    ref u[MAX_STATE]; /* the stage of f: t is updated below */
    memcpy(u, t, sizeof u);
    for (unsigned i = 0; i < ns; i++)
      if (m->role[i] == FP3_MR_POSITION)
        t[i] = m_nm(b, m_add(b, y[i], m_hf(b, h, f[i], &L[i], u, i, "h")), "n", i);
    m_fl(b, m, t, f, L, "3");
    for (unsigned i = 0; i < ns; i++)
      b->out[i] = m->role[i] == FP3_MR_VELOCITY
                      ? m_nm(b, m_add(b, t[i], m_hf(b, hh, f[i], &L[i], t, i, "hh")), "n", i)
                      : t[i];
  } else {
    return -1;
  }
  for (int i = 0; i < b->nstate; i++) b->out[i] = m_value(b, b->out[i]);
  return 0;
}

static int model_ir(builder *b, const fp3_model *m, const char *integ,
                    const fp3_compile_opts *o, const unsigned char *pzero, char *msg, size_t n) {
  memset(b, 0, sizeof *b);
  b->fold = o->fold;
  b->drop_zero = o->drop_zero;
  b->zero = -1;
  b->model = m;
  b->pzero = pzero;
  /* rk4comp carries a compensation per state variable (c_NAME, 0 at
   * the start) beside it */
  const unsigned carried = fp3_model_carried(m, integ);
  b->nstate = (int)carried;
  b->nin = (int)(m->nparam + carried);
  snprintf(b->integ, sizeof b->integ, "%s", integ);
  for (unsigned i = 0; i < carried; i++)
    snprintf(b->st_name[i], FP3_MODEL_NAME_LEN, "%s%.24s",
             i < m->nstate ? "" : strcmp(integ, "verletp") == 0 ? "a_" : "c_",
             m->state[i % m->nstate]);
  for (int k = 0; k < b->nin; k++) {
    unsigned q = (unsigned)k;
    if (q < m->nparam) snprintf(b->in_name[k], FP3_MODEL_NAME_LEN, "%s", m->param[q]);
    else {
      char st_[FP3_MODEL_NAME_LEN];
      memcpy(st_, b->st_name[q - m->nparam], sizeof st_);
      snprintf(b->in_name[k], FP3_MODEL_NAME_LEN, "%.24s(0)", st_);
    }
    b->in_state[k] = q < m->nparam ? -1 : (int)(q - m->nparam);
  }
  int rc = m_build(b, m, integ);
  if (rc == -1) {
    snprintf(msg, n, "unknown integrator '%s' for a model (%s)", integ, fp3_model_integrators());
    return -1;
  }
  if (rc == -3) {
    unsigned vel = 0, reads = 0;
    fp3_model_verlet_ok(m, &vel, &reads);
    snprintf(msg, n, "integrator verlet needs accelerations that do not read velocities: "
             "%s' reads velocity %s (symeuler, rk2 or rk4 take it)", m->state[vel],
             m->state[reads]);
    return -1;
  }
  if (rc == -4) {
    snprintf(msg, n, "integrator verletp needs each position's derivative to be a velocity "
             "(x' = v)");
    return -1;
  }
  if (rc == -2) {
    snprintf(msg, n, "integrator %s needs the state split into positions and velocities "
             "(`position` and `velocity` lines, docs/models.md)", integ);
    return -1;
  }
  if (b->err) {
    snprintf(msg, n, "model %s: the IR has more than %d nodes", m->name, MAX_NODES);
    return -1;
  }
  /* invariant operations without an add/sub/mul instruction: the host's */
  for (int i = 0; i < b->nn; i++) {
    node *x = &b->nd[i];
    if (op_kind(x->kind) && x->inv && x->kind != NK_ADD && x->kind != NK_SUB && x->kind != NK_MUL)
      x->host = 1;
  }
  for (int w = 0; w < b->nstate; w++) mark_live(b, b->out[w].n);
  return 0;
}

int fp3_compile_model(const fp3_model *m, const char *integrator, const fp3_compile_opts *o,
                      const unsigned char *param_zero, fp3_compiled **outp, char *msg,
                      size_t n) {
  *outp = NULL;
  if (check_opts(o, msg, n)) return -1;
  fp3_compiled *c = calloc(1, sizeof *c);
  if (!c) {
    snprintf(msg, n, "out of memory");
    return -1;
  }
  fp3_strbuf h = {0};
  int rc = -1;
  fp3_compile_opts lit = *o;
  lit.fold = lit.drop_zero = 0;
  if (model_ir(&c->b, m, integrator, &lit, NULL, msg, n)) goto out;
  count_literal(c);
  if (model_ir(&c->b, m, integrator, o, param_zero, msg, n)) goto out;
  fp3_strbuf_printf(&h, "; model %s (%s) -- compiled by fp3 for integrator %s, %s%s\n;\n",
                    m->name, m->file, integrator,
                    o->fold ? "folded" : "literal (docs/models.md, bit for bit)",
                    o->drop_zero ? ", terms zero in every object removed" : "");
  if (o->fold)
    fp3_strbuf_printf(&h, "; folded: divisions by parameter-only values are products with "
                          "the host's reciprocal\n");
  if (h.oom) {
    snprintf(msg, n, "out of memory");
    goto out;
  }
  rc = backend(c, o, h.s, msg, n);
out:
  free(h.s);
  if (rc) fp3_compiled_free(c);
  else *outp = c;
  return rc;
}

int fp3_compile_model_ir(const fp3_model *m, const char *integrator, const fp3_compile_opts *o,
                         const unsigned char *param_zero, fp3_compiled **outp, char *msg,
                         size_t n) {
  *outp = NULL;
  fp3_compiled *c = calloc(1, sizeof *c);
  if (!c) {
    snprintf(msg, n, "out of memory");
    return -1;
  }
  if (model_ir(&c->b, m, integrator, o, param_zero, msg, n)) {
    fp3_compiled_free(c);
    return -1;
  }
  /* no registers: the golden model's start binds none */
  for (int k = 0; k < MAX_IN; k++) c->in_reg[k] = -1;
  for (int k = 0; k < MAX_STATE; k++) c->state_reg[k] = -1;
  for (int i = 0; i < MAX_NODES; i++) c->host_reg[i] = -1;
  fp3_image_init(&c->img);
  *outp = c;
  return 0;
}

/* The IR node an `.in` name stands for: a param's or an initial state's
 * input leaf (NAME, or NAME0 for state variable NAME), or a
 * parameter-only let (an invariant node of that name); -1 if none. */
static int bind_node(builder *b, const fp3_model *m, const char *name) {
  int k = fp3_model_param(m, name);
  if (k >= 0) return leaf(b, NK_IN, k, 0, m->param[k]).n;
  k = fp3_model_state(m, name);
  size_t len = strlen(name);
  if (k < 0 && len > 1 && name[len - 1] == '0') {
    char base[FP3_BIND_NAME_LEN];
    snprintf(base, sizeof base, "%.*s", (int)(len - 1), name);
    k = fp3_model_state(m, base);
  }
  if (k >= 0) return leaf(b, NK_IN, (int)m->nparam + k, 0, b->in_name[m->nparam + (unsigned)k]).n;
  for (int i = 0; i < b->nn; i++)
    if (b->nd[i].inv && op_kind(b->nd[i].kind) && strcmp(b->nd[i].name, name) == 0) return i;
  return -1;
}

int fp3_compile_bind(const fp3_model *m, const fp3_image *img, const char *program,
                     const fp3_compile_opts *o, fp3_compiled **outp, char *msg, size_t n) {
  *outp = NULL;
  const char *integ = img->integrator;
  if (!integ[0]) {
    snprintf(msg, n, "%s: no `.integrator NAME` line: the program names the integrator whose "
             "golden model it computes (%s)", program, fp3_model_integrators());
    return -1;
  }
  if (!fp3_model_integrator_known(integ)) {
    snprintf(msg, n, "%s: .integrator %s: not an integrator of the model language (%s)", program,
             integ, fp3_model_integrators());
    return -1;
  }
  fp3_compiled *c = calloc(1, sizeof *c);
  if (!c) {
    snprintf(msg, n, "out of memory");
    return -1;
  }
  fp3_compile_opts lit = *o;
  lit.fold = lit.drop_zero = 0;
  char why[400];
  if (model_ir(&c->b, m, integ, &lit, NULL, why, sizeof why)) {
    snprintf(msg, n, "%s: .integrator %s on model %s (%s): %s", program, integ, m->name, m->file,
             why);
    goto fail;
  }
  builder *b = &c->b;
  c->img = *img;
  for (int k = 0; k < MAX_IN; k++) c->in_reg[k] = -1;
  for (int k = 0; k < MAX_STATE; k++) c->state_reg[k] = -1;
  for (int k = 0; k < MAX_NODES; k++) c->host_reg[k] = -1;
  for (unsigned q = 0; q < img->nbind_in; q++) {
    const fp3_binding *x = &img->bind_in[q];
    const int neg = x->name[0] == '-';
    int i = bind_node(b, m, x->name + neg);
    if (i < 0) {
      snprintf(msg, n, "%s:%d: .in %s: model %s (%s) has no param, state variable or "
               "parameter-only let '%s'", program, x->line, x->name, m->name, m->file,
               x->name + neg);
      goto fail;
    }
    if (neg) { /* the host flips the sign bit: an invariant node of its own */
      node z = {NK_NEG, i, -1, -1, 0, 1, 0, 1, ""};
      i = new_node(b, z);
      snprintf(b->nd[i].name, sizeof b->nd[i].name, "%s", x->name);
    }
    if (b->err) {
      snprintf(msg, n, "model %s: the IR has more than %d nodes", m->name, MAX_NODES);
      goto fail;
    }
    if (b->nd[i].kind == NK_IN) c->in_reg[b->nd[i].id] = x->reg;
    else c->host_reg[i] = x->reg;
  }
  for (unsigned q = 0; q < img->nbind_out; q++) {
    const fp3_binding *x = &img->bind_out[q];
    int k = -1;
    for (int w = 0; w < b->nstate; w++)
      if (strcmp(b->st_name[w], x->name) == 0) k = w;
    if (k < 0) {
      snprintf(msg, n, "%s:%d: .out %s: model %s (%s) has no state variable '%s'", program,
               x->line, x->name, m->name, m->file, x->name);
      goto fail;
    }
    c->state_reg[k] = x->reg;
  }
  for (unsigned i = 0; i < m->nstate; i++)
    if (c->state_reg[i] < 0) {
      snprintf(msg, n, "%s: no `.out %s, rN`: state variable %s of model %s is not checked "
               "against the golden model", program, m->state[i], m->state[i], m->name);
      goto fail;
    }
  /* the figures of compiled programs, from the image */
  fp3_compile_stats *st = &c->stats;
  unsigned top = 0;
  for (size_t k = 0; k < img->n; k++) {
    const uint64_t w = img->words[k];
    const int uses = fp3_opc_uses(fp3_insn_opc(w));
    const unsigned r[3] = {fp3_insn_rd(w), fp3_insn_ra(w), fp3_insn_rb(w)};
    const int used[3] = {FP3_USES_RD, FP3_USES_RA, FP3_USES_RB};
    for (int f = 0; f < 3; f++)
      if (uses > 0 && (uses & used[f]) && r[f] + 1 > top) top = r[f] + 1;
  }
  for (unsigned q = 0; q < img->nbind_in; q++)
    if ((unsigned)img->bind_in[q].reg + 1 > top) top = (unsigned)img->bind_in[q].reg + 1;
  st->body_insns = st->literal_body_insns = fp3_image_body_insns(img);
  size_t endi_at = 0;
  for (size_t k = 0; k < img->n; k++)
    if (fp3_insn_opc(img->words[k]) == FP3_OP_ENDI) endi_at = k;
  for (size_t k = endi_at + 1 - st->body_insns; st->body_insns && k <= endi_at; k++) {
    const unsigned opc = fp3_insn_opc(img->words[k]);
    st->body_arith += opc == FP3_OP_ADD || opc == FP3_OP_SUB || opc == FP3_OP_MUL;
  }
  st->prologue_insns = (unsigned)img->n - st->body_insns;
  st->regs = st->regs_needed = top;
  st->num_regs = o->num_regs > top ? o->num_regs : top;
  fp3_estimate_cycles(img, o, 3, &st->est_cycles_first, &st->est_cycles_later);
  *outp = c;
  return 0;
fail:
  fp3_compiled_free(c);
  return -1;
}

int fp3_compile_bind_file(const fp3_model *m, const char *path, const fp3_compile_opts *o,
                          fp3_compiled **out, char *msg, size_t n) {
  *out = NULL;
  fp3_image *img = malloc(sizeof *img);
  char *errs = NULL;
  if (!img) {
    snprintf(msg, n, "out of memory");
    return -1;
  }
  fp3_image_init(img);
  int rc = fp3_asm_file(path, img, &errs);
  if (rc) {
    size_t len = errs ? strcspn(errs, "\n") : 0;
    snprintf(msg, n, "%.*s", (int)len, errs ? errs : "");
    if (!len) snprintf(msg, n, "%s: cannot assemble", path);
  } else {
    rc = fp3_compile_bind(m, img, path, o, out, msg, n);
  }
  free(errs);
  free(img);
  return rc;
}

unsigned fp3_compiled_state_reg(const fp3_compiled *c, unsigned i) {
  return (unsigned)c->state_reg[i];
}

/* The golden model set to params in[] and carried values yc[] (b->nstate
 * of them): the inputs, then every invariant node. */
static void begin_carried(fp3_compiled *c, const float *in, const float *yc) {
  const builder *b = &c->b;
  const fp3_model *m = b->model;
  for (unsigned k = 0; k < m->nparam; k++) c->in[k] = in[k];
  for (int k = 0; k < b->nstate; k++) c->in[m->nparam + (unsigned)k] = yc[k];
  golden_begin(c, yc);
}

size_t fp3_compiled_model_start(fp3_compiled *c, const float *in, const float *y0,
                                unsigned *reg, uint32_t *val, size_t max) {
  const fp3_model *m = c->b.model;
  float yc[MAX_STATE] = {0}; /* the carried values: the state, then the others */
  for (unsigned k = 0; k < m->nstate; k++) yc[k] = y0[k];
  fp3_model_start_literal(m, c->b.integ, in, yc);
  return fp3_compiled_model_start_from(c, in, yc, reg, val, max);
}

size_t fp3_compiled_model_start_from(fp3_compiled *c, const float *in, const float *yc,
                                     unsigned *reg, uint32_t *val, size_t max) {
  const builder *b = &c->b;
  begin_carried(c, in, yc);
  size_t w = 0;
  for (int k = 0; k < b->nin && w < max; k++)
    if (c->in_reg[k] >= 0) {
      reg[w] = (unsigned)c->in_reg[k];
      val[w++] = fpref_bits(c->in[k]);
    }
  for (int i = 0; i < b->nn && w < max; i++)
    if (c->host_reg[i] >= 0) {
      reg[w] = (unsigned)c->host_reg[i];
      val[w++] = fpref_bits(c->val[i]);
    }
  return w;
}

void fp3_compiled_model_step(fp3_compiled *c, float *y) {
  float yc[MAX_STATE];
  golden_advance(c, yc);
  for (unsigned i = 0; i < c->b.model->nstate; i++) y[i] = yc[i];
}

void fp3_compiled_model_step_from(fp3_compiled *c, const float *in, const float *yc,
                                  float *ycnew) {
  begin_carried(c, in, yc);
  golden_advance(c, ycnew);
}

unsigned fp3_compiled_carried(const fp3_compiled *c) { return (unsigned)c->b.nstate; }

/* ---- a model scene's golden model (mscene.h runners) ---------------------- */

static size_t sg_start(void *ctx, size_t obj, unsigned *reg, uint32_t *val, size_t max) {
  fp3_scene_gold *g = ctx;
  const fp3_model *m = g->sc->model;
  return fp3_compiled_model_start(g->c, g->sc->in + obj * m->nparam,
                                  g->sc->y0 + obj * m->nstate, reg, val, max);
}

static void sg_step(void *ctx, float *y) {
  fp3_scene_gold *g = ctx;
  fp3_compiled_model_step(g->c, y);
}

static void sg_step_from(void *ctx, size_t obj, const float *y, float *ynew) {
  fp3_scene_gold *g = ctx;
  fp3_compiled_model_step_from(g->c, g->sc->in + obj * g->sc->model->nparam, y, ynew);
}

void fp3_scene_gold_init(fp3_scene_gold *g, fp3_compiled *c, const fp3_mscene *sc) {
  const unsigned ns = sc->model->nstate, carried = fp3_compiled_carried(c);
  g->c = c;
  g->sc = sc;
  for (unsigned i = 0; i < carried; i++) g->reg[i] = fp3_compiled_state_reg(c, i);
  g->golden = (fp3_state_golden){g, ns, g->reg, sg_start, sg_step};
  g->stepper = (fp3_state_stepper){g, carried, g->reg, sg_start, sg_step_from};
}

/* ---- waking objects of a scene -------------------------------------------- */

/* fp3_state_wake.wake of fp3_scene_waker (compile.h). */
static int waker_wake(void *ctx, size_t obj, uint32_t *bank, unsigned nregs) {
  fp3_scene_waker *w = ctx;
  const unsigned np = w->sc->model->nparam, carried = fp3_compiled_carried(w->c);
  float *in = w->sc->in + obj * np;
  const float v = w->times >= 0 ? w->value * in[w->times] : w->value;
  if (in[w->param] != 0.0f || v == 0.0f) return 0;
  in[w->param] = v;
  float yc[MAX_STATE];
  for (unsigned i = 0; i < carried; i++) yc[i] = fpref_float(bank[w->c->state_reg[i]]);
  unsigned reg[MAX_IN + MAX_NODES];
  uint32_t val[MAX_IN + MAX_NODES];
  const size_t nw = fp3_compiled_model_start_from(w->c, in, yc, reg, val, MAX_IN + MAX_NODES);
  for (size_t k = 0; k < nw; k++)
    if (reg[k] < nregs) bank[reg[k]] = val[k];
  return 1;
}

int fp3_scene_waker_init(fp3_scene_waker *w, fp3_compiled *c, fp3_mscene *sc, uint32_t frame,
                         size_t count, const char *param, float value, const char *times,
                         char *msg, size_t n) {
  const fp3_model *m = sc->model;
  memset(w, 0, sizeof *w);
  w->c = c;
  w->sc = sc;
  w->value = value;
  w->param = fp3_model_param(m, param);
  w->times = times && times[0] ? fp3_model_param(m, times) : -1;
  if (w->param <= 0 || (times && times[0] && w->times <= 0)) {
    snprintf(msg, n, "model %s (%s) has no param '%s'", m->name, m->file,
             w->param <= 0 ? param : times);
    return -1;
  }
  for (unsigned i = 0; i < fp3_compiled_carried(c); i++)
    if (c->state_reg[i] < 0) {
      snprintf(msg, n, "the program binds no register for carried value %u", i);
      return -1;
    }
  w->wake = (fp3_state_wake){frame, count, waker_wake, w};
  return 0;
}

/* ---- golden model -------------------------------------------------------- */

static float eval(const builder *b, const float *val, int i) {
  const node *x = &b->nd[i];
  const float p = val[x->a], q = x->b >= 0 ? val[x->b] : 0.0f;
  float r;
  switch (x->kind) {
  case NK_ADD: r = p + q; break;
  case NK_SUB: r = p - q; break;
  case NK_MUL: r = p * q; break;
  case NK_DIV: r = p / q; break;
  case NK_SQRT: r = sqrtf(p); break;
  case NK_ABS: r = fpref_float(fpref_bits(p) & 0x7FFFFFFFu); break; /* IEEE 754 §5.5.1 */
  case NK_NEG: r = fpref_float(fpref_bits(p) ^ 0x80000000u); break;
  case NK_MIN: r = fp3_model_minmax32(p, q, 0); break;
  default: r = fp3_model_minmax32(p, q, 1); break;
  }
  return r;
}

/* Leaves from c->in and y0, then every invariant node (the prologue and
 * the host's values). */
static void golden_begin(fp3_compiled *c, const float *y0) {
  const builder *b = &c->b;
  for (int i = 0; i < b->nn; i++) {
    const node *x = &b->nd[i];
    if (x->kind == NK_IN) c->val[i] = c->in[x->id];
    else if (x->kind == NK_CONST) c->val[i] = fpref_float(x->bits);
    else if (x->kind == NK_STATE) c->val[i] = y0[x->id];
    else if (x->inv) c->val[i] = eval(b, c->val, i);
  }
}

/* One integration: y gets the new state. */
static void golden_advance(fp3_compiled *c, float *y) {
  const builder *b = &c->b;
  for (int i = 0; i < b->nn; i++)
    if (op_kind(b->nd[i].kind) && b->nd[i].live && !b->nd[i].inv)
      c->val[i] = eval(b, c->val, i);
  for (int w = 0; w < b->nstate; w++) y[w] = c->val[b->out[w].n];
  for (int i = 0; i < b->nn; i++)
    if (b->nd[i].kind == NK_STATE) c->val[i] = y[b->nd[i].id];
}

/* ---- the IR, read-only (compile.h) ----------------------------------------- */

_Static_assert((int)FP3_IR_IN == NK_IN && (int)FP3_IR_STATE == NK_STATE &&
               (int)FP3_IR_ADD == NK_ADD && (int)FP3_IR_MAX == NK_MAX &&
               (int)FP3_IR_KINDS == NK_COUNT, "fp3_ir_kind follows enum node_kind");

unsigned fp3_ir_nodes(const fp3_compiled *c) { return (unsigned)c->b.nn; }

void fp3_ir_node_get(const fp3_compiled *c, unsigned i, fp3_ir_node *x) {
  const node *y = &c->b.nd[i];
  *x = (fp3_ir_node){y->kind, y->a, y->b, y->id, y->bits, y->inv, y->live, y->host, y->name};
}

unsigned fp3_ir_carried_next(const fp3_compiled *c, unsigned w) {
  return (unsigned)c->b.out[w].n;
}

const char *fp3_ir_carried_name(const fp3_compiled *c, unsigned w) { return c->b.st_name[w]; }

const char *fp3_ir_input_name(const fp3_compiled *c, unsigned k) { return c->b.in_name[k]; }

float fp3_ir_value(const fp3_compiled *c, unsigned i) { return c->val[i]; }

int fp3_ir_node_reg(const fp3_compiled *c, unsigned i) {
  const node *y = &c->b.nd[i];
  if (y->kind == NK_IN) return c->in_reg[y->id];
  if (y->kind == NK_STATE) return c->state_reg[y->id];
  return c->host_reg[i];
}

/* ---- output file ----------------------------------------------------------- */

int fp3_compiled_write(const fp3_compiled *c, const char *path, char *msg, size_t n) {
  return fp3_write_text_atomic(path, c->text, msg, n);
}

/* ---- cycle estimate ----------------------------------------------------------- */

unsigned fp3_image_body_insns(const fp3_image *img) {
  for (size_t k = img->n; k-- > 0;)
    if (fp3_insn_opc(img->words[k]) == FP3_OP_ENDI) {
      size_t loop = fp3_insn_imm(img->words[k]);
      return loop <= k ? (unsigned)(k - loop + 1) : 0;
    }
  return 0;
}

int fp3_estimate_cycles(const fp3_image *img, const fp3_compile_opts *lat,
                        unsigned iterations, unsigned *first, unsigned *later) {
  size_t endi_at = img->n;
  for (size_t k = 0; k < img->n; k++)
    if (fp3_insn_opc(img->words[k]) == FP3_OP_ENDI) endi_at = k;
  if (endi_at == img->n || iterations < 2) return -1;
  size_t loop = fp3_insn_imm(img->words[endi_at]);
  /* Times are cycles of the scheduler's grants (fp3_scheduler.v; the
   * issue of the default build).  Fetch to grant, fetch to fetch, grant to
   * issue: */
  const long to_grant =
      FP3_START_CYCLES + (lat->fmax_pipe ? FP3_FMAX_PIPE_FETCH_STAGES + FP3_FMAX_PIPE_GRANT_STAGES : 0);
  const long fetch_spacing = lat->fmax_pipe ? FP3_FMAX_PIPE_FETCH_SPACING : FP3_FETCH_SPACING;
  const long pick = lat->fmax_pipe ? FP3_FMAX_PIPE_PICK_STAGES : 0;
  long ready[256] = {0};   /* a register's earliest grant to read or write it */
  /* The cycle from which the slot of word k (k mod FP3_QUEUE_WORDS) is free
   * for it: the cycle after the grant of the word FP3_QUEUE_WORDS before. */
  long slot_free[FP3_QUEUE_WORDS] = {0};
  long fetch = lat->fmax_pipe ? FP3_FMAX_PIPE_START_STAGES : 0; /* the earliest next fetch */
  long t = 0;              /* the earliest next grant                      */
  long prev_endi = -1;     /* the last endi's issue                        */
  unsigned it = 0;
  for (size_t pc = 0, words = 0; it < iterations && pc < img->n; words++) {
    uint64_t w = img->words[pc];
    unsigned opc = fp3_insn_opc(w), unit = fp3_opc_unit(opc);
    int uses = fp3_opc_uses(opc);
    if (uses < 0) return -1;
    long *slot = &slot_free[words % FP3_QUEUE_WORDS];
    if (*slot > fetch) fetch = *slot;
    long at = fetch + to_grant > t ? fetch + to_grant : t;
    fetch += fetch_spacing;
    if ((uses & FP3_USES_RA) && ready[fp3_insn_ra(w)] > at) at = ready[fp3_insn_ra(w)];
    if ((uses & FP3_USES_RB) && ready[fp3_insn_rb(w)] > at) at = ready[fp3_insn_rb(w)];
    if ((uses & FP3_USES_RD) && ready[fp3_insn_rd(w)] > at) at = ready[fp3_insn_rd(w)];
    if (uses & FP3_USES_RD) ready[fp3_insn_rd(w)] = at + (long)unit_latency(lat, unit);
    *slot = at + 1;
    t = at + issue_spacing(lat);
    if (opc == FP3_OP_ENDI) {
      const long issue = at + pick;
      it++;
      if (it == 1) *first = (unsigned)(issue + 1);
      else *later = (unsigned)(issue - prev_endi);
      prev_endi = issue;
      pc = loop;
    } else {
      pc++;
    }
  }
  return 0;
}
