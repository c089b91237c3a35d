/*
 * engine.h -- one small interface to every FP3 execution engine.
 *
 * An engine runs a program image: the Verilated RTL (engine_rtl.c) or the
 * instruction-set simulator (iss.c).  Tests and the CLI run the same
 * program on two engines through this interface and compare.
 *
 * Observation: while a run goes on, the engine reports every register
 * write-back and every end-of-integration (endi) to an observer.  The RTL
 * engine takes these from the model's trace port while the machine runs
 * freely, so observing changes no cycle count (DESIGN.md "Observe, don't
 * stop").  Each write is tagged with the integration it belongs to: the
 * number of endi instructions issued before the writing instruction, plus
 * one (prologue writes belong to integration 1).  Writes to one register
 * arrive in program order on every engine; writes to different registers
 * may interleave differently on different engines.
 *
 * Contexts: a run may start several contexts (objects) at once, each with
 * its own registers, all running the same program for the same number of
 * integrations (paper §6.3).  The RTL interleaves them on one issue slot;
 * the ISS runs them one after another.  Contexts never interact, so
 * each one's results are the same on both.
 *
 * Lanes and object slots: a build with NUM_LANES lanes runs every
 * instruction of a context on each of its lanes, each lane one object
 * with registers of its own (fp3_isa.h FP3_MAX_LANES).  Every "context"
 * argument of this interface (registers, status, observer events, the
 * count a run starts) is an object slot: slot s is lane s / num_contexts
 * of context s % num_contexts, so slots 0 .. num_contexts-1 are lane 0
 * (without lanes, slot = context) and a build holds fp3_config_slots()
 * objects.  A run of n slots starts contexts 0 .. min(n, num_contexts)-1,
 * every lane of each; events of slots >= n are not reported.  The lanes
 * of a context share its PC: a beq is taken only if its operands are
 * bit-identical in every lane; errors, steps done and fault PC are the
 * context's, flags the slot's own.
 */
#ifndef FP3_ENGINE_H
#define FP3_ENGINE_H

#include <stddef.h>
#include <stdint.h>

#include "fp3_isa.h"
#include "fpref.h"
#include "progress.h"

/* Build configuration of an engine (see FP3_CONFIG in fp3_isa.h). */
typedef struct fp3_config {
  unsigned num_contexts;/* contexts a run may start                      */
  unsigned num_lanes;   /* lanes per context (NUM_LANES; 0 counts as 1)   */
  unsigned num_regs;    /* registers per context                         */
  unsigned imem_depth;  /* instruction memory entries                    */
  unsigned add_latency; /* add core, cycles (RTL only); a dependent     */
  unsigned mul_latency; /* issues FP3_READ_CYCLES + latency after it    */
  fpref_mode mode;      /* FP core options: rounding, flush-to-zero       */
  unsigned has_add;     /* 1: an add/sub core (HAS_ADD); 0: add, sub illegal */
  unsigned has_sub;     /* 1: the adder subtracts (HAS_SUB); 0: sub illegal */
  unsigned has_mul;     /* 1: a mul core (HAS_MUL); 0: mul illegal        */
  unsigned has_div;     /* 1: a divider (HAS_DIV); 0: div illegal         */
  unsigned has_sqrt;    /* 1: a square root (HAS_SQRT); 0: sqrt illegal   */
  unsigned has_sign;    /* 1: the sign group (HAS_SIGN); 0: abs, neg, min,
                           max illegal                                    */
  unsigned div_latency; /* div/sqrt unit, cycles (RTL only; INFO2)        */
  unsigned wb_ports;    /* write-back ports of a lane's register file
                           (WB_PORTS, RTL only; INFO2): 4, one per unit;
                           1, every unit's result written back (and the
                           move's consumer issuing) as the add's; 0 for
                           the ISS, which has no timing                   */
  unsigned fmax_pipe;   /* 1: the pipeline for clock rate (FMAX_PIPE, RTL
                           only): same dependent-issue distances after an
                           add or mul of latency >=
                           FP3_FMAX_PIPE_FULL_LEAD_LATENCY (shorter ones
                           and the move path count as that), a beq
                           FP3_FMAX_PIPE_CYCLES longer, a context fetching
                           every FP3_FMAX_PIPE_FETCH_SPACING cycles and
                           issuing every FP3_FMAX_PIPE_ISSUE_SPACING, host
                           reads of 4 cycles (fp3_isa.h)                  */
} fp3_config;

/* Objects a build holds at once: num_contexts x num_lanes (slots). */
unsigned fp3_config_slots(const fp3_config *c);

/* Check that a program only needs the units a build has: every add, sub,
 * mul, div, sqrt, abs, neg, min and max in words[0..n) has its unit
 * (has_add, has_sub, has_mul, has_div, has_sqrt, has_sign of c; sub needs
 * has_add and has_sub; abs, neg, min, max need has_sign).  Register fields are not checked here:
 * an out-of-range one stays an illegal instruction of the run.  The RTL raises
 * ILLEGAL_INSN on an instruction for a missing unit; the host refuses
 * before running instead.  Returns 0, or -1 with the first offence in msg,
 * naming the unit and the parameter: "the program uses mul (pc 12), but
 * this hardware has no multiplier (built with HAS_MUL=0)". */
int fp3_config_check_program(const fp3_config *c, const uint64_t *words, size_t n,
                             char *msg, size_t len);

/* Status and counters after a run. */
typedef struct fp3_status {
  int done;              /* 1 when the run has ended                      */
  unsigned error;        /* enum fp3_error, of context 0                  */
  uint32_t fault_pc;     /* PC of the faulting instruction if error != 0  */
  uint32_t steps_done;   /* integrations completed (endi issued), ctx 0   */
  unsigned any_error;    /* 1 if any context ended with an error          */
  uint32_t flags;        /* sticky exception flags of all slots (OR)      */
  uint64_t cycles;       /* clock cycles START..DONE (ISS: instructions)  */
  uint64_t issued;       /* instructions issued                           */
  uint64_t stalls;       /* cycles an instruction waited on a hazard      */
  uint64_t unit_issued[FP3_NUM_UNITS]; /* instructions issued per unit, FP3_UNIT_* */
} fp3_status;

/* Status of one object slot after a run (its context's, its own flags). */
typedef struct fp3_ctx_status {
  unsigned error;       /* enum fp3_error                                 */
  uint32_t fault_pc;    /* PC of the faulting instruction if error != 0   */
  uint32_t steps_done;  /* integrations completed                         */
  uint32_t flags;       /* sticky exception flags of this slot (lane)      */
} fp3_ctx_status;

/* Observer callbacks; any may be NULL.  on_write and on_endi report
 * context 0 only (one-object runs); on_ctx_write and on_ctx_endi report
 * every context.  progress (may be NULL): each endi of context 0 reports
 * its integration to it (fp3_progress_update), as fp3_engine_run's
 * progress line does. */
typedef struct fp3_observer {
  void *ctx;
  /* A result was written to register `reg`. */
  void (*on_write)(void *ctx, unsigned reg, uint32_t value,
                   uint32_t integration);
  /* The endi closing integration `integration` (1-based) issued in `cycle`
   * (cycles counted from 0 at START; the ISS counts instructions). */
  void (*on_endi)(void *ctx, uint32_t integration, uint64_t cycle);
  void (*on_ctx_write)(void *ctx, unsigned context, unsigned reg,
                       uint32_t value, uint32_t integration);
  void (*on_ctx_endi)(void *ctx, unsigned context, uint32_t integration,
                      uint64_t cycle);
  fp3_progress *progress;
} fp3_observer;

/* The values two watched registers hold after each integration, rebuilt
 * from a run's write events (fp3_observer.on_write): a register keeps its
 * value until it is written again, so its value after integration k is
 * the last one an instruction of integration k or earlier wrote.  Each
 * integration 1 .. last is handed to final(ctx, which, k, bits) once per
 * watched register, in order, as soon as a write of a later integration
 * shows that k is over, and by fp3_track_advance at the end of the run.
 * Set reg, cur (the registers' values at START), next_k = 1, last, final
 * and ctx before the run. */
typedef struct fp3_track {
  int reg[2];         /* the registers watched (-1: none)            */
  uint32_t cur[2];    /* the value each holds now                    */
  uint32_t next_k[2]; /* the next integration to hand over           */
  uint32_t last;      /* the last integration to hand over           */
  void (*final)(void *ctx, int which, uint32_t k, uint32_t bits);
  void *ctx;
} fp3_track;

/* Hand over register `which`'s integrations before `upto` (its current
 * value stands for each). */
void fp3_track_advance(fp3_track *t, int which, uint32_t upto);

/* A write event: integration `integration` wrote `value` to `reg`. */
void fp3_track_write(fp3_track *t, unsigned reg, uint32_t value, uint32_t integration);

/* Deliver one event to an observer (engines call these). */
void fp3_observe_write(const fp3_observer *obs, unsigned context, unsigned reg,
                       uint32_t value, uint32_t integration);
void fp3_observe_endi(const fp3_observer *obs, unsigned context,
                      uint32_t integration, uint64_t cycle);

typedef struct fp3_engine fp3_engine;

/* Operations of one engine kind.  Each returns 0 on success and a negative
 * value on failure, with a message from fp3_engine_error(). */
typedef struct fp3_engine_ops {
  const char *name; /* "rtl" or "iss" */
  int (*load_program)(fp3_engine *e, const uint64_t *words, size_t n);
  int (*write_reg)(fp3_engine *e, unsigned context, unsigned reg,
                   uint32_t value);
  int (*read_reg)(fp3_engine *e, unsigned context, unsigned reg,
                  uint32_t *value);
  /* Run slots 0 .. contexts-1 for `steps` integrations each (see
   * "Lanes and object slots" above). */
  int (*run)(fp3_engine *e, uint32_t steps, unsigned contexts,
             const fp3_observer *obs, fp3_status *st);
  int (*ctx_status)(fp3_engine *e, unsigned context, fp3_ctx_status *cs);
  void (*destroy)(fp3_engine *e);
  /* 1: a run reports no write-back or endi events to its observer (a
   * board behind a serial line has no trace port); its callers compare
   * the state the registers hold after the run.  0 (the RTL, the ISS):
   * every event is reported. */
  int untraced;
} fp3_engine_ops;

/* Common head of every engine object. */
struct fp3_engine {
  const fp3_engine_ops *ops;
  fp3_config config;
  char error[256]; /* last error message */
  const char *progress; /* label of the progress line, NULL: none
                           (fp3_engine_show_progress)                     */
};

/* Constructors.  Return NULL when out of memory (or, for the RTL, when the
 * model does not answer with FP3_ID_VALUE; a message goes to stderr). */
fp3_engine *fp3_engine_iss_new(void);
/* An ISS whose FP operations follow core options `mode` (RTZ, FTZ);
 * FP3_MAX_CONTEXTS contexts of one lane. */
fp3_engine *fp3_engine_iss_new_mode(fpref_mode mode);
/* An ISS shaped like a build: num_contexts, num_lanes, num_regs (0: the
 * default FP3_DEFAULT_NUM_REGS) and mode of c (the lanes of a context run
 * in lock step, as the RTL's: beq across lanes), every unit.  NULL when
 * out of memory or when c has no context or more than FP3_MAX_CONTEXTS
 * contexts, FP3_MAX_LANES lanes, or num_regs is 1 or above FP3_MAX_REGS. */
fp3_engine *fp3_engine_iss_new_config(const fp3_config *c);
/* trace_path: VCD waveform file to write (NULL: none), every signal of the
 * model.  The model writes it under a temporary name in the same folder,
 * TRACE_PATH.tmp.PID; fp3_engine_free closes it and renames it to
 * trace_path if a run completed (fp3_engine_run returned 0, whatever the
 * program did) and none failed, and removes it otherwise (no run, a
 * failed run), so trace_path is never a cut-off waveform.  While the
 * temporary is open, SIGINT, SIGTERM and SIGHUP remove it and then end
 * the process with the signal's default action (the exit status is the
 * signal's); a signal the process ignores stays ignored, and the earlier
 * actions are restored when the engine is freed.  At most 4 traced
 * engines at once.  NULL (a message on stderr) if the temporary cannot be
 * created, the name is too long, or 4 traced engines are open. */
fp3_engine *fp3_engine_rtl_new(const char *trace_path);
/* The RTL built with core options `mode` (parameters ROUND, FTZ);
 * trace_path as fp3_engine_rtl_new's. */
fp3_engine *fp3_engine_rtl_new_mode(fpref_mode mode, const char *trace_path);
/* The RTL of one Verilated build (model_ops: a `const fp3_model_ops *` of
 * sim/fp3_model.h, e.g. a test build with another NUM_CONTEXTS);
 * trace_path as fp3_engine_rtl_new's. */
fp3_engine *fp3_engine_rtl_new_model(const void *model_ops, const char *trace_path);
/* Waveform window of an RTL engine created with a trace path: each run
 * writes only its cycles first .. first+count-1 (cycle 0 is the first
 * after START; count UINT64_MAX: to the end), nothing outside runs.
 * Returns -1 for an engine that is not the RTL. */
int fp3_engine_rtl_trace_window(fp3_engine *e, uint64_t first, uint64_t count);
/* A board behind a serial line, speaking LiteX's UARTBone protocol to its
 * UART bridge (rtl/fp3_uartbone.v, engine_uart.c; docs/board.md).  spec
 * is what follows "uart:" in --engine: DEVICE[@BAUD] (a serial device or
 * pseudo-terminal; BAUD default 3000000) or socket://HOST:PORT.  Reads
 * the build's INFO registers and checks ID.  NULL with the reason in err
 * (naming the device) when the device cannot be opened, does not answer
 * within the timeout, answers short, or answers with a wrong ID.
 * Environment: FP3_UART_TIMEOUT_MS, the longest wait for one answer
 * (default 5000); FP3_UART_STATS=1, the frames and words of the session
 * on stderr when the engine is freed. */
fp3_engine *fp3_engine_uart_new(const char *spec, char *err, size_t n);
/* 1 when name is "uart:" followed by something (a uart engine's name). */
int fp3_engine_is_uart(const char *name);
/* 0 when the engine's runs report every write-back and endi to their
 * observer, 1 when they report none (fp3_engine_ops.untraced). */
int fp3_engine_untraced(const fp3_engine *e);
/* Upper bound on the cycles of a legal run of `steps` integrations of
 * `contexts` contexts on build c: every integration passes at most the
 * whole instruction memory once (beq branches only ahead), each
 * instruction waiting at most the longest latency or a beq's resolution.
 * Exceeding it means the machine hung. */
uint64_t fp3_config_cycle_limit(const fp3_config *c, uint32_t steps, unsigned contexts);
/* By name, "rtl", "iss" or "uart:SPEC"; NULL for an unknown name (or a
 * uart engine that cannot be opened: the reason on stderr). */
fp3_engine *fp3_engine_new(const char *name);

/* Thin dispatchers over e->ops.  The forms without a context use context
 * 0 and run one context.  fp3_engine_load first checks the program against
 * the engine's build (fp3_config_check_program) and refuses, -1 with that
 * message in fp3_engine_error(), a program that needs a unit the build
 * lacks: every path that runs a program refuses before running. */
int fp3_engine_load(fp3_engine *e, const uint64_t *words, size_t n);
int fp3_engine_write_reg(fp3_engine *e, unsigned reg, uint32_t value);
int fp3_engine_read_reg(fp3_engine *e, unsigned reg, uint32_t *value);
int fp3_engine_run(fp3_engine *e, uint32_t steps, const fp3_observer *obs,
                   fp3_status *st);

/* One object's cycles (context 0, registers as they are): load words[0..n)
 * and run k >= 2 integrations; *first gets the cycles from the start to
 * the end of the first integration (the cycle after its endi issued, as
 * fp3 run counts cycles_first_step), *later those from the endi of
 * integration k-1 to that of integration k.  The timing of a program
 * without beq does not depend on the values.  0, or -1 (load or run
 * failed, a context error, fewer endi than k). */
int fp3_engine_endi_cycles(fp3_engine *e, const uint64_t *words, size_t n, uint32_t k,
                           unsigned *first, unsigned *later);
int fp3_engine_write_ctx_reg(fp3_engine *e, unsigned context, unsigned reg,
                             uint32_t value);
int fp3_engine_read_ctx_reg(fp3_engine *e, unsigned context, unsigned reg,
                            uint32_t *value);
int fp3_engine_run_contexts(fp3_engine *e, uint32_t steps, unsigned contexts,
                            const fp3_observer *obs, fp3_status *st);
int fp3_engine_ctx_status(fp3_engine *e, unsigned context, fp3_ctx_status *cs);
void fp3_engine_free(fp3_engine *e);
const char *fp3_engine_error(const fp3_engine *e);

/* Progress of long runs on a terminal (progress.h).  After
 * fp3_engine_show_progress(e, "fp3 run") the runs on e that may last long
 * show a progress line on stderr when it is a terminal, prefixed with the
 * label: fp3_engine_run counts the integrations of context 0, and the runs
 * of many objects (fp3_run_state_objects) their
 * object-steps, those frame by frame (fp3_run_state_frames) their
 * frames.  fp3_engine_run_contexts alone shows
 * none: its caller knows the whole run.  label NULL (an engine's default)
 * shows none; the CLI passes NULL for --json.  label must outlive the
 * engine's runs. */
void fp3_engine_show_progress(fp3_engine *e, const char *label);

#endif /* FP3_ENGINE_H */
