/*
 * configure.h -- hardware sized to the scene (`fp3 configure`): from a
 * scene of a model (mscene.h) and an integrator, the RTL parameters of a
 * build that runs the scene's compiled program and nothing more.
 *
 * The scene is compiled as `fp3 run --scene` compiles it (compile.h), and
 * each parameter follows from the compiled program or the scene:
 *
 *  - HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV, HAS_SQRT, HAS_SIGN: 1 when the
 *    program has an add (or sub), a sub, a mul, a div, a sqrt, an abs, neg,
 *    min or max instruction (the prologue included);
 *  - NUM_REGS: the fewest registers k (at least 4, the compiler's minimum)
 *    into which the compiler schedules the program without losing a cycle:
 *    its estimated cycles of the first and of each later integration of one
 *    object equal those of the compilation with the default NUM_REGS (a
 *    program that needs more than the default, 3-D RK4 folded, gets the
 *    fewest registers the compiler schedules it into: NUM_REGS=33).  A
 *    build with NUM_REGS = k compiles exactly that program (`fp3 run
 *    --scene` compiles for the NUM_REGS it reads back from the hardware),
 *    and the program names registers below k only.  (The compiler takes
 *    the least recently written free register, so with the default 32 it
 *    spreads a long body over more registers than it needs.)
 *  - NUM_CONTEXTS: the fewest contexts that keep the single issue slot
 *    busy, ceil(E / I) for E the estimated cycles of a later integration
 *    of one object and I its instructions (contexts interleave: with that
 *    many objects in flight one instruction issues every cycle;
 *    docs/pipeline.md "Many objects": more contexts add area, not
 *    speed), at most the objects and FP3_MAX_CONTEXTS; a larger scene
 *    runs in batches.  With
 *    opts.context_per_object: one context per object, min(objects, 64),
 *    the whole scene in flight at once (64 contexts are several times the
 *    area of the default 8);
 *  - NUM_LANES: the lanes that put the whole scene in flight beside those
 *    contexts, ceil(objects / NUM_CONTEXTS), at most opts.max_lanes
 *    (default FP3_CONFIGURE_MAX_LANES) and, with opts.device, at most
 *    the lanes that device holds by the lane cost model of device.h
 *    (for this build's contexts, registers and multiplier); a lane adds an adder, a
 *    multiplier and a register bank but no scheduler logic, so lanes,
 *    not contexts, grow with the scene (docs/lanes.md); a larger scene
 *    runs in batches of NUM_CONTEXTS x NUM_LANES objects;
 *  - ROUND, FTZ: the cheapest FP core mode whose results stay within the
 *    error budget.  Each candidate mode (RNE, RTZ, RNE+FTZ, RTZ+FTZ) runs
 *    the program's golden model (fp3_compiled_model_step, in that mode
 *    through fpenv.h) for every object and `steps` integrations; its error
 *    is the largest, over objects and state variables, of
 *        max_k |x_k - ref(t_k)| / max(max_k |ref(t_k)|, 1)
 *    (ref: the model's GSL reference, modelref.h, rk8pd at 1e-12, k = 1
 *    .. steps).  RNE with subnormals (the default build)
 *    is always allowed; its error is the integrator's and binary32's own
 *    (the paper's s = s + h v1 is first order: about 1e-3 after 1000 steps
 *    of 1/60 s).  The budget is what a cheaper mode may add to it: a mode
 *    is allowed when, for every object, its error is at most that
 *    object's RNE error + budget.  Of the allowed modes the one with the
 *    fewest LUTs of the units the program needs wins (fp_add and fp_mul on
 *    xc2v, docs/fpga.md "FP cores": FTZ saves about 40 % of the multiplier, RTZ
 *    little); a tie goes to the earlier mode in the order above.
 *
 *  - WB_PORTS, ADD_LATENCY, MUL_LATENCY: one write-back port a lane
 *    (WB_PORTS=1, docs/lanes.md "One write-back port") when the program
 *    has no div and no sqrt, with both latencies the longer default
 *    (FP3_DEFAULT_ADD_LATENCY, 4): every unit and the move path then
 *    write back that many cycles after the read, so no two write-backs
 *    meet and a lane's register file is two RAMs without a live value
 *    table -- about two thirds of a lane's LUT4s on the chip build
 *    (device.h).  The program is compiled for those latencies (as
 *    fp3_compile_opts_for does for such a build), so one object's
 *    integration takes longer and NUM_CONTEXTS, which follows from it,
 *    grows until the issue slot is busy again: the same throughput for
 *    fewer LUTs.  A program with div or sqrt gets four ports and the
 *    default latencies; opts.wb_ports 4 asks for those always.
 *
 * IMEM_DEPTH stays at its default, the latencies of a build with four
 * write-back ports too (the compiler schedules for them).
 */
#ifndef FP3_CONFIGURE_H
#define FP3_CONFIGURE_H

#include <stddef.h>
#include <stdint.h>

#include "compile.h"
#include "device.h"
#include "engine.h"
#include "mscene.h"

/* The instruction groups a build may leave out, in the order of unit_pc:
 * add (or sub), sub, mul, div, sqrt, the sign group (abs, neg, min, max);
 * their parameters HAS_ADD .. HAS_SIGN. */
#define FP3_CONFIGURE_UNITS 6
/* Default upper bound of the derived NUM_LANES, a bound on the hardware
 * a scene may ask for (16 lanes: 16 adders, multipliers and register
 * banks); the LFE5U-85F holds 16 lanes of the build for clock rate with
 * one write-back port (docs/lanes.md "Chip build"). */
#define FP3_CONFIGURE_MAX_LANES 16

/* The candidate FP core modes, in tie-break order. */
#define FP3_CONFIGURE_MODES 4

/* Options of fp3_configure. */
typedef struct fp3_configure_opts {
  const char *integrator; /* compile.h integrator name (default "rk4")     */
  int literal;            /* 1: no folding, no zero-term removal (the      */
                          /* paper's operations, fp3 compile --literal)    */
  double budget;          /* error budget, relative (> 0)                  */
  uint32_t steps;         /* integrations of the accuracy check (>= 1)     */
  int context_per_object; /* 1: NUM_CONTEXTS = min(objects, 64)            */
  unsigned max_lanes;     /* NUM_LANES at most (1 .. FP3_MAX_LANES)        */
  const fp3_device *device; /* NULL, or NUM_LANES at most what it holds   */
  unsigned wb_ports;      /* 0: one when the program has no div or sqrt,  */
                          /* else four; 1 or 4: that many (1 with div or  */
                          /* sqrt is an error)                            */
} fp3_configure_opts;

/* integrator "rk4", literal 0, budget 1e-4, steps 1000, contexts by the
 * issue rule, max_lanes FP3_CONFIGURE_MAX_LANES, no device, write-back
 * ports chosen (wb_ports 0). */
void fp3_configure_defaults(fp3_configure_opts *o);

/* What fp3_configure derived, and why. */
typedef struct fp3_configure_result {
  fp3_config cfg;          /* the parameters; imem_depth at its default,   */
                           /* add/mul latencies and wb_ports by the rule   */
                           /* above                                        */
  size_t objects;          /* objects in the scene                         */
  int unit_pc[FP3_CONFIGURE_UNITS]; /* first pc of an add, sub, mul, div,  */
                           /* sqrt, abs/neg/min/max; -1: none              */
  unsigned regs_default;   /* registers named (highest + 1) when compiled  */
                           /* for the default NUM_REGS                     */
  unsigned regs_used;      /* ... when compiled for cfg.num_regs           */
  unsigned est_first;      /* estimated cycles, first integration          */
  unsigned est_later;      /* ... each later one (one object)              */
  unsigned body_insns;     /* instructions per integration                 */
  unsigned contexts_issue; /* contexts that fill the issue slot, ceil(E/I) */
  unsigned lanes_scene;    /* lanes that put the scene in flight,          */
                           /* ceil(objects / NUM_CONTEXTS)                 */
  fp3_device_fit fit;      /* with opts.device: what the lane model gave   */
  fpref_mode mode[FP3_CONFIGURE_MODES]; /* RNE, RTZ, RNE+FTZ, RTZ+FTZ       */
  double err[FP3_CONFIGURE_MODES];  /* relative error (max over objects);  */
                                    /* NAN: the host cannot run the mode   */
  double added[FP3_CONFIGURE_MODES]; /* max over objects of the error minus */
                                     /* the object's RNE error (0 for RNE) */
  int allowed[FP3_CONFIGURE_MODES]; /* 1: added <= budget (RNE always)     */
  unsigned luts[FP3_CONFIGURE_MODES]; /* xc2v LUTs of the needed FP cores   */
  int chosen;              /* index of the mode in cfg.mode                */
} fp3_configure_result;

/* Derive the parameters for model scene sc: its model compiled as `fp3
 * run --scene` compiles it (params zero in every object removed unless
 * o->literal), the units, NUM_REGS and NUM_CONTEXTS, ROUND and FTZ by the
 * rules above.  Returns 0 and *r, or -1 with a message: unknown
 * integrator, empty scene, bad options (budget not a positive finite
 * number, steps 0, max_lanes outside 1 .. FP3_MAX_LANES, wb_ports not 0,
 * 1 or 4), one write-back port asked for a program with div or sqrt, a
 * device that does not hold one lane of the build, a reference that fails
 * (naming the object), out of memory.  *compiled (if not NULL) receives
 * the program compiled for the derived NUM_REGS (free with
 * fp3_compiled_free). */
int fp3_configure_model(const fp3_mscene *sc, const fp3_configure_opts *o,
                        fp3_configure_result *r, fp3_compiled **compiled, char *msg,
                        size_t n);

/* The parameters as one line of make variables, no newline:
 * "NUM_CONTEXTS=8 NUM_LANES=2 NUM_REGS=16 HAS_ADD=1 HAS_SUB=0 HAS_MUL=1 HAS_DIV=0
 * HAS_SQRT=0 HAS_SIGN=0 ROUND=0 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=4 WB_PORTS=1"
 * (a latency or wb_ports of 0: the default, FP3_DEFAULT_*_LATENCY and 4).
 * Returns the length (as snprintf). */
int fp3_configure_line(const fp3_config *c, char *buf, size_t n);

#endif /* FP3_CONFIGURE_H */
