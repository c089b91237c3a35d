/*
 * compile.h -- the compiler (`fp3 compile`): from a model (model.h) and an
 * integrator, and the params that are zero in every object of a scene, an
 * FP3 program that computes only what the scene needs, and its golden
 * model.
 *
 * The compiler builds a small expression IR: a DAG of binary32 operations
 * (add, sub, mul, and div, sqrt, abs, neg, min, max where the model has
 * them) over per-object host inputs (h, the params, each carried value's
 * initial value), constants (`li`) and the loop-carried state.  Then:
 *
 *  - folding (opts.fold): a derivative affine in the state with
 *    parameter-only coefficients is multiplied by the step as
 *    h f = (h c0) + sum_s (h c_s) y_s, each product computed by the host
 *    (the ship's v' = (T - C v) minv gives h f(v) = hmT - hmC v with hmT =
 *    (h minv) T, hmC = (h minv) C: 2 operations instead of 4); a division
 *    by a parameter-only value becomes a product with the host's
 *    reciprocal; RK4's weighted sum is summed as (k1 + k4) + 2 (k2 + k3);
 *    a sum of two negated terms becomes one negated sum.  A folded program
 *    is a different rounding sequence from the literal one: its own golden
 *    model is its reference;
 *  - zero terms (opts.drop_zero): the terms of a param that is zero in
 *    every object go (the ship without drag, C = 0: the drag products and
 *    subtractions; without thrust, T = 0: T - x becomes -x, and the
 *    negation is carried into the consumers: a + (-b) = a - b, (-a) b =
 *    -(a b), exact in RNE and RTZ).  For finite values this is the same
 *    rounding sequence except for the sign of an exactly zero intermediate
 *    (a param that is -0);
 *  - common subexpressions are shared, operations on inputs and constants
 *    alone (loop invariants) move to the prologue (run once per run, in
 *    the cores' rounding) or to the host (div, sqrt and the sign
 *    operations, which need no unit there), and operations nothing reads
 *    are removed (dead code elimination) -- all exact;
 *  - the loop body is list-scheduled for in-order single issue (a
 *    dependent instruction issues FP3_READ_CYCLES + `latency` cycles
 *    after its producer, one context every FP3_ISSUE_SPACING cycles
 *    (FP3_FMAX_PIPE_ISSUE_SPACING for the build for clock rate);
 *    priority: the longest latency path to the end of the integration),
 *    registers are allocated within num_regs, least recently written
 *    first (a register written again soon after its previous write would
 *    stall on WAW), and assembly text is emitted.  There is no load or
 *    store, so no spilling: when the latency-first schedule needs more
 *    registers than num_regs (the most values live at once), the body is
 *    scheduled again with register pressure bounded (the ready
 *    instruction that stays within the bound first, compile.c schedule),
 *    which fits 3-D RK4 (about 130 instructions) into 32 registers where
 *    latency first needs 36 or more; failing that, the program is
 *    refused with the numbers ("the program needs 33 registers; NUM_REGS
 *    is 32"), or compiled for a larger build (opts.max_regs).
 *
 * Integrators: those of model.h (fp3_model_integrators).  With fold = 0
 * and drop_zero = 0 the compiled program performs exactly the operations
 * of the integrator's literal golden model (fp3_model_step_literal; the
 * ship's rk4se: those of programs/ship_rk4.s), so its golden model equals
 * that one bit for bit.
 */
#ifndef FP3_COMPILE_H
#define FP3_COMPILE_H

#include <stddef.h>
#include <stdint.h>

#include "engine.h"
#include "image.h"
#include "model.h"
#include "mscene.h"

/* Compiler options. */
typedef struct fp3_compile_opts {
  int fold;              /* 1: folded host inputs, reassociated sums      */
  int drop_zero;         /* 1: remove terms zero in every object           */
  unsigned add_latency;  /* add/sub core latency, cycles (ADD_LATENCY)     */
  unsigned mul_latency;  /* mul core latency, cycles (MUL_LATENCY)         */
  unsigned mov_latency;  /* move path latency, cycles (1; FMAX_PIPE adds
                            FP3_FMAX_PIPE_PICK_STAGES; with one write-back
                            port, fp3_config.wb_ports 1, the add's less
                            those: fp3_compile_opts_for)                  */
  unsigned div_latency;  /* div/sqrt unit latency, cycles (DIV_LATENCY)   */
  unsigned num_regs;     /* registers per context (NUM_REGS of the build) */
  unsigned max_regs;     /* 0, or up to FP3_MAX_REGS: a program that does
                            not fit num_regs even with the pressure-bounded
                            schedule is compiled for a build with more:
                            the fewest it is scheduled into, if at most
                            max_regs; stats.num_regs says which          */
  unsigned fmax_pipe;    /* 1: for the build for clock rate (FMAX_PIPE=1,
                            fp3_config.fmax_pipe): its pick, fetch and
                            issue stages (fp3_isa.h FP3_FMAX_PIPE_*); needs
                            add_latency, mul_latency >
                            FP3_FMAX_PIPE_PICK_STAGES; 0: the default   */
} fp3_compile_opts;

/* fold = drop_zero = 1, latencies FP3_DEFAULT_ADD_LATENCY,
 * FP3_DEFAULT_MUL_LATENCY and FP3_DEFAULT_DIV_LATENCY (fp3_isa.h), moves
 * 1, FP3_DEFAULT_NUM_REGS,
 * the default build (fmax_pipe = 0). */
void fp3_compile_defaults(fp3_compile_opts *o);

/* The options for the build hw (as an engine reports it, engine.h): the
 * defaults, then hw's latencies (those it gives, nonzero), NUM_REGS and
 * FMAX_PIPE, and the move path's latency with one write-back port;
 * max_regs 0 (a program that does not fit hw is refused). */
void fp3_compile_opts_for(fp3_compile_opts *o, const fp3_config *hw);

/* What a compilation produced (instruction counts are static: words of
 * the program; cycles are the scheduler's estimate, an in-order issue
 * model with RAW and WAW interlocks and the option latencies). */
typedef struct fp3_compile_stats {
  unsigned body_insns;       /* per integration, endi included            */
  unsigned body_arith;       /* add/sub/mul per integration               */
  unsigned prologue_insns;   /* li and loop invariants, run once          */
  unsigned literal_body_insns; /* the same integrator with fold = 0 and
                                  drop_zero = 0 (the paper's program)     */
  unsigned dead_removed;     /* operations built but read by nothing      */
  unsigned hoisted;          /* loop-invariant operations in the prologue */
  unsigned regs;             /* registers named (the allocator spreads
                                values over the free ones, least recently
                                written first, to spare WAW stalls)      */
  unsigned regs_needed;      /* registers the schedule needs: the most
                                values live at once (inputs, constants,
                                invariants, state and temporaries)      */
  unsigned num_regs;         /* NUM_REGS of the build compiled for:
                                opts.num_regs, or more with max_regs    */
  unsigned est_cycles_first; /* first integration, prologue included      */
  unsigned est_cycles_later; /* each later integration (steady state)     */
} fp3_compile_stats;

typedef struct fp3_compiled fp3_compiled;

void fp3_compiled_free(fp3_compiled *c);

/* The assembly text (NUL-terminated, owned by c). */
const char *fp3_compiled_text(const fp3_compiled *c);

/* The assembled program (the text through fp3_asm_string). */
const fp3_image *fp3_compiled_image(const fp3_compiled *c);

const fp3_compile_stats *fp3_compiled_stats(const fp3_compiled *c);

/* Write the text to path atomically (a temporary file in the same
 * directory, then rename): on error no file is left.  0 or -1 with a
 * message. */
int fp3_compiled_write(const fp3_compiled *c, const char *path, char *msg, size_t n);

/* Estimated cycles of an image run by one context of the build `lat`
 * describes (latencies, fmax_pipe): the prologue, then the loop body (from
 * the target of the last endi) for `iterations` >= 2 integrations.  The
 * model of fp3_scheduler.v, in cycles of its grants: one fetch at a time,
 * at most every FP3_FETCH_SPACING cycles (FP3_FMAX_PIPE_FETCH_SPACING),
 * into a queue of FP3_QUEUE_WORDS, whose slot frees in the cycle after its
 * word's grant; the first fetch in cycle 0 after START (with fmax_pipe
 * FP3_FMAX_PIPE_START_STAGES later); a word granted
 * FP3_START_CYCLES (+ FP3_FMAX_PIPE_FETCH_STAGES +
 * FP3_FMAX_PIPE_GRANT_STAGES) after its fetch at the earliest, at most one
 * grant every FP3_ISSUE_SPACING (FP3_FMAX_PIPE_ISSUE_SPACING) cycles, a
 * dependent one FP3_READ_CYCLES + `latency` cycles after its producer's
 * (with fmax_pipe a latency of at least FP3_FMAX_PIPE_FULL_LEAD_LATENCY), a
 * destination written again only when its previous write has landed; an
 * issue FP3_FMAX_PIPE_PICK_STAGES after its grant with fmax_pipe, else in
 * the grant's cycle.  Exact for one context of either build on programs
 * without beq; a beq is not modelled (the compiler emits none): it counts
 * as an instruction without a result, not taken, resolved at once.
 * *first: cycles from START to the end of the first integration (the
 * cycle after its endi's issue), *later: from the last endi but one to
 * the last.  Returns 0, or -1 for an image without endi, with an unknown
 * opcode, or iterations < 2. */
int fp3_estimate_cycles(const fp3_image *img, const fp3_compile_opts *lat,
                        unsigned iterations, unsigned *first, unsigned *later);

/* Instructions per integration of an image: the words from the target of
 * its last endi through that endi (0 without endi). */
unsigned fp3_image_body_insns(const fp3_image *img);

/* ---- models (model.h, docs/models.md) ------------------------------------ */

/* Compile model m for integrator `integrator` (fp3_model_integrators()).
 * With o->fold = o->drop_zero = 0 (--literal) the program performs exactly
 * the operations of fp3_model_step_literal, so its golden model equals
 * that one bit for bit; the only rewrites are exact ones (negations
 * carried into subtractions and products, model.h), and loop-invariant
 * values are computed once: add, sub, mul in the prologue, the others
 * (1/m, sqrt(k), -g, ...) by the host in binary32 and written into a
 * register before the run.  With o->fold, divisions by parameter-only
 * values become products with the host's reciprocal and RK4's sum is
 * (k1 + k4) + 2 (k2 + k3); with o->drop_zero, params marked in
 * param_zero[] (zero in every object; may be NULL) and zero numbers are
 * removed terms (as fp3_compile).  Returns 0 and *out, or -1 with a
 * message: unknown integrator, symeuler on an unsplit model, an operation
 * the ISA table lacks ("model projectile needs sqrt: this build has no
 * HAS_SQRT unit ..."), more registers than num_regs (and max_regs: "the
 * program needs 33 registers; NUM_REGS is 32 ...") or words than
 * IMEM_DEPTH ("the program needs 290 instructions; IMEM_DEPTH is 256").
 * A program compiled for more than FP3_DEFAULT_NUM_REGS registers starts
 * with `.regs N` (asm.h). 
 * Integrator rk4comp carries a Kahan compensation per state variable in a
 * register of its own (fp3_compiled_carried), 0 at the start.
 * The text lists inputs and results in comments (the host's folded values
 * have no name in the model for an `.in` line to bind):
 * fp3_compiled_model_start gives the writes. */
int fp3_compile_model(const fp3_model *m, const char *integrator, const fp3_compile_opts *o,
                      const unsigned char *param_zero, fp3_compiled **out, char *msg,
                      size_t n);

/* The IR of model m for `integrator` and its golden model, without a
 * program: for back ends other than the processor (spatial.h), so no
 * register, instruction or ISA limit applies.  Options as
 * fp3_compile_model (only fold and drop_zero matter).  The result has no
 * text (fp3_compiled_text is NULL), an empty image, zero stats and no
 * registers (fp3_compiled_model_start returns no writes;
 * fp3_compiled_state_reg gives UINT_MAX); its golden model
 * (fp3_compiled_model_step, fp3_ir_value) is the same as
 * fp3_compile_model's.  0, or -1 with a message (unknown integrator, one
 * that does not apply to m, an IR too large). */
int fp3_compile_model_ir(const fp3_model *m, const char *integrator, const fp3_compile_opts *o,
                         const unsigned char *param_zero, fp3_compiled **out, char *msg,
                         size_t n);

/* A hand-written program as the program of model m: img (assembled from
 * `program`, named in messages) names its integrator (`.integrator`) and
 * binds its registers by name (asm.h `.in` / `.out`).  The result is used
 * as a compiled model's (fp3_compiled_model_start writes the bound
 * inputs, fp3_compiled_model_step is the integrator's literal golden
 * model, fp3_model_step_literal, as the IR of a --literal compile
 * evaluates it), and so runs wherever a compiled program runs.  Its
 * stats come from the image: body_insns (fp3_image_body_insns), the
 * registers it names, the cycle estimate for the latencies of o.
 * Carried values the program does not bind (compensations) have no
 * register (fp3_compiled_state_reg gives UINT_MAX).  Returns 0 and
 * *out, or -1 with "PROGRAM:LINE: reason": no or an unknown .integrator,
 * one that does not apply to m, an `.in` name that is no param, state
 * variable (NAME or NAME0) or parameter-only let of m, an `.out` name
 * that is no state variable, a state variable without `.out`. */
int fp3_compile_bind(const fp3_model *m, const fp3_image *img, const char *program,
                     const fp3_compile_opts *o, fp3_compiled **out, char *msg, size_t n);

/* fp3_compile_bind of the program in file `path`, assembled here
 * (fp3_asm_file): 0 and *out, or -1 with the assembler's errors ("FILE:LINE:
 * reason", the first of them) or the binder's message in msg. */
int fp3_compile_bind_file(const fp3_model *m, const char *path, const fp3_compile_opts *o,
                          fp3_compiled **out, char *msg, size_t n);

/* Start the golden model of a compiled model for one object: in[] = h and
 * the params (m->nparam values), y0 the initial state; the host values
 * are computed in the caller's FP environment (fpenv_enter for the cores'
 * mode).  reg[], val[] (max entries) get the register writes the host
 * makes before the run: params, initial states, host-computed values.
 * Returns the number of writes. */
size_t fp3_compiled_model_start(fp3_compiled *c, const float *in, const float *y0,
                                unsigned *reg, uint32_t *val, size_t max);

/* fp3_compiled_model_start from any carried values yc[]
 * (fp3_compiled_carried of them: the state, then compensations or
 * accelerations) instead of an initial state: the writes that restart an
 * object from where it is, with params in[] (a woken object's new ones). */
size_t fp3_compiled_model_start_from(fp3_compiled *c, const float *in, const float *yc,
                                     unsigned *reg, uint32_t *val, size_t max);

/* One integration of the golden model: y (m->nstate values) gets the new
 * state (the compensations of rk4comp stay inside c). */
void fp3_compiled_model_step(fp3_compiled *c, float *y);

/* One integration of the golden model from any carried values: params
 * in[] (h first, m->nparam values) and yc[] (fp3_compiled_carried values:
 * the state, then rk4comp's compensations) give ycnew[] (as many), in the
 * caller's FP environment.  It restarts the golden model: a later
 * fp3_compiled_model_step continues from ycnew. */
void fp3_compiled_model_step_from(fp3_compiled *c, const float *in, const float *yc,
                                  float *ycnew);

/* The values a model's program carries from one integration to the next:
 * its state variables, then (rk4comp) one Kahan compensation each, so
 * m->nstate or 2 m->nstate.  The registers of the compensations start at
 * 0 (fp3_compiled_model_start writes them). */
unsigned fp3_compiled_carried(const fp3_compiled *c);

/* The register holding carried value i (state variable i for i <
 * m->nstate). */
unsigned fp3_compiled_state_reg(const fp3_compiled *c, unsigned i);

/* The golden model of compiled model c over the objects of model scene sc,
 * as the runners of mscene.h want it: g->golden for
 * fp3_run_state_objects (the state variables), g->stepper (each object
 * stepped from any carried values, fp3_compiled_model_step_from, for
 * fp3_run_state_frames: its nstate is fp3_compiled_carried, so rk4comp's
 * compensations are restarted from the engine's and compared as the state
 * is).  g keeps c, sc and the carried values' registers; it must outlive
 * the runs. */
typedef struct fp3_scene_gold {
  fp3_compiled *c;
  const fp3_mscene *sc;
  unsigned reg[FP3_STEPPER_MAX_VARS];
  fp3_state_golden golden;
  fp3_state_stepper stepper;
} fp3_scene_gold;

void fp3_scene_gold_init(fp3_scene_gold *g, fp3_compiled *c, const fp3_mscene *sc);

/* Waking objects of scene sc run frame by frame with program c
 * (fp3_run_state_frames): before frame `frame`, the first `count`
 * objects whose param `param` is 0 get param = value, or value times
 * their param `times` (NULL or "": none) in binary32, when that is not 0;
 * such an object restarts from the carried values its bank holds with its
 * new params (fp3_compiled_model_start_from writes its bank's
 * host-written registers: params, host values, initial values), and the
 * golden model steps it with the new params too (they are sc's).
 * w->wake is what fp3_run_state_frames takes.  0, or -1 with the reason:
 * a name that is no param of the model (h neither), a carried value
 * without a register. */
typedef struct fp3_scene_waker {
  fp3_compiled *c;
  fp3_mscene *sc;
  int param, times;
  float value;
  fp3_state_wake wake;
} fp3_scene_waker;

int fp3_scene_waker_init(fp3_scene_waker *w, fp3_compiled *c, fp3_mscene *sc, uint32_t frame,
                         size_t count, const char *param, float value, const char *times,
                         char *msg, size_t n);

/* ---- the IR, read-only (back ends that are not the processor: spatial.h) -- */

/* The kind of an IR node: leaves, then the operations.  The order is the
 * compiler's own (compile.c enum node_kind). */
enum fp3_ir_kind { FP3_IR_IN, FP3_IR_CONST, FP3_IR_STATE, FP3_IR_ADD, FP3_IR_SUB, FP3_IR_MUL,
                   FP3_IR_DIV, FP3_IR_SQRT, FP3_IR_ABS, FP3_IR_NEG, FP3_IR_MIN, FP3_IR_MAX,
                   FP3_IR_KINDS };

/* One IR node of a compiled model as fp3_ir_node_get reads it. */
typedef struct fp3_ir_node {
  int kind;          /* enum fp3_ir_kind                                   */
  int a, b;          /* operand nodes of an operation (b = -1: unary)      */
  int id;            /* FP3_IR_IN: the input (fp3_ir_input_name);
                        FP3_IR_STATE: the carried value it reads           */
  uint32_t bits;     /* FP3_IR_CONST: the binary32 pattern                 */
  int inv;           /* loop invariant: a function of inputs and constants */
  int live;          /* the next carried values read it, directly or not   */
  int host;          /* a loop invariant the host computes in binary32 and
                        writes like an input (its operands are not live
                        through it)                                        */
  const char *name;  /* the model's name for it ("k1", "hmT"), or ""      */
} fp3_ir_node;

/* Number of IR nodes of c; node indices are 0 .. that - 1, and every
 * operation's operands have lower indices (a topological order). */
unsigned fp3_ir_nodes(const fp3_compiled *c);

/* Node i of c (i < fp3_ir_nodes(c)). */
void fp3_ir_node_get(const fp3_compiled *c, unsigned i, fp3_ir_node *x);

/* The node whose value carried value w (< fp3_compiled_carried(c)) takes
 * after one integration. */
unsigned fp3_ir_carried_next(const fp3_compiled *c, unsigned w);

/* The name of carried value w (a state variable, or c_NAME / a_NAME). */
const char *fp3_ir_carried_name(const fp3_compiled *c, unsigned w);

/* The name of input k (a param, h first, or NAME(0)). */
const char *fp3_ir_input_name(const fp3_compiled *c, unsigned k);

/* The golden model's value of node i: after fp3_compiled_model_start (or
 * _start_from) the inputs, constants and every loop invariant (the host's
 * values among them); after a step, also the step's operations. */
float fp3_ir_value(const fp3_compiled *c, unsigned i);

/* The register of the compiled program that holds node i's value when
 * the host has written fp3_compiled_model_start's writes: an input's
 * (FP3_IR_IN), a carried value's (FP3_IR_STATE: fp3_compiled_state_reg),
 * a host value's (host set); -1 for any other node, and for every node of
 * fp3_compile_model_ir (no registers).  The spatial engine
 * (engine_spatial.h) reads a pipeline's inputs from these registers. */
int fp3_ir_node_reg(const fp3_compiled *c, unsigned i);

#endif /* FP3_COMPILE_H */
