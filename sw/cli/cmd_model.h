/*
 * cmd_model.h -- what the subcommands share about models (docs/models.md):
 * the options of run, frames and bench, the --set values, compiling a
 * model for an engine, watching state registers (fp3 bench itself:
 * cmd_bench.h).
 */
#ifndef FP3_CMD_MODEL_H
#define FP3_CMD_MODEL_H

#include <stddef.h>
#include <stdint.h>

#include "compile.h"
#include "engine.h"
#include "fpref.h"
#include "model.h"
#include "traceopt.h"

/* A state beyond FP3_GROWTH_BOUND (1 + max |initial state|) counts as
 * diverged: the trials and the engine runs of `fp3 bench`'s stability and the
 * divergence `fp3 run` reports. */
#define FP3_GROWTH_BOUND 1e3

/* The options of run, frames and bench
 * (fp3 run --model x --help); each command takes its own subset. */
typedef struct fp3_model_args {
  const char *cmd;     /* the command, for messages ("run", "frames", ...) */
  const char *file, *integ, *engine, *out;
  const char *program; /* run: --program FILE.s (a hand-written program)  */
  const char *scene;   /* --scene FILE                                  */
  size_t objects;      /* run: --objects (0: none)                      */
  uint64_t seed;       /* run: --seed                                   */
  int literal, json, seeded;
  unsigned pipelines;  /* run, frames: --pipelines N of --engine spatial
                          (0: one)                                      */
  int clock_cores;     /* run, frames: --clock-cores of --engine spatial
                          (the cores make pnr-spatial places)           */
  int no_rest_skip;    /* frames: --no-rest-skip                        */
  int integ_given;     /* --integrator given                            */
  double t_end;        /* bench: --t-end (0: 600 h)                     */
  unsigned points;     /* bench: --points (default 6)                   */
  const char *stab;    /* bench: --stability FILE.csv                   */
  const char *long_out; /* bench: --long FILE.csv                       */
  uint32_t long_steps; /* bench: --long-steps                           */
  fpref_mode mode;     /* run: --round, --ftz (model scenes, --objects) */
  uint32_t steps;      /* run: --steps (default 1000); frames: --frames
                          (default 600)                                 */
  const char *set[2 * FP3_MODEL_MAX_VARS + 8]; /* --set NAME=VALUE      */
  int nset;
  fp3_trace_opts trace; /* run, one object: --trace, --trace-window,
                           --trace-limit                                */
  unsigned long long harbour; /* frames: --harbour N, a generated harbour
                           of the ship model (0: none)                  */
  double fmax;         /* frames: --fmax [MHz] for frames per second     */
  uint32_t wake_frame; /* frames: --wake F:K:NAME=VALUE[*PARAM]: before
                          frame F (0: never) ...                          */
  size_t wake_count;   /* ... the first K objects whose param NAME is 0 ... */
  char wake_param[FP3_MODEL_NAME_LEN]; /* ... get NAME = VALUE, or VALUE
                          times their param PARAM (binary32)              */
  float wake_value;
  char wake_times[FP3_MODEL_NAME_LEN]; /* PARAM, or "" */
} fp3_model_args;

/* The parse step of command cmd ("run", "frames" or "bench"): FP3_ARGS_RUN with *a filled, FP3_ARGS_HELP, or
 * FP3_ARGS_BAD with the message on stderr (cliopt.h).  The --set values
 * are kept as text: they name the model's params and state variables,
 * which only the model file gives (fp3_model_args_values). */
int fp3_parse_model(int argc, char **argv, const char *cmd, fp3_model_args *a);

/* The integrator of a run, compile or configure of scene (NULL: none):
 * on a ship scene (five columns, sw/scene/objects.h) *integ, unless given
 * (--integrator), becomes the paper's RK4, the model integrator rk4se,
 * and the ship's names that a model gives another meaning (rk4, rk4comp,
 * verlet) are refused with the model's name.  0, or -1 with the message
 * on stderr (fp3 CMD: ...). */
int fp3_ship_scene_integrator(const char *scene, int given, const char **integ,
                              const char *cmd);

/* The values of one object of model m into in[] (params, in[0] the step
 * h) and y0[] (initial state): the model file's defaults (`param k = 40`,
 * `position x = 0.5`, `param h = 0.015625`), each overridden by a --set
 * of a (the last --set of a name counts).  --set NAME0=VALUE gives state
 * variable NAME's initial value where m has no param or state NAME0.
 * Each value finite, h > 0.  0, or -1 with the message on stderr; what
 * still has no value is named in one message, each with its declaring
 * line: "fp3 run: FILE: no value for param k (line 3), state variable x
 * (line 5): give --set k=VALUE --set x=VALUE, or a default in the model
 * file (param k = VALUE)". */
int fp3_model_args_values(const fp3_model *m, const fp3_model_args *a, float *in, float *y0);


/* Compile model m for a's integrator (a->literal: the literal form; else
 * folded, the params zero[k] = 1 removed) for the build hw (NULL: the
 * default build).  grow: the build may have more registers (the ISS, and
 * bench): a program that needs more than hw's NUM_REGS is
 * compiled for the fewest that run it; else it is refused with the
 * numbers.  The program, or NULL with the message on stderr ("fp3 CMD:
 * ..."). */
fp3_compiled *fp3_model_compile_for(const fp3_model *m, const fp3_model_args *a,
                                    const unsigned char *zero, const fp3_config *hw, int grow,
                                    const char *cmd);

/* The ISS *e reshaped for program c when c needs more registers than it
 * has (fp3_model_compile_for with grow), said on stderr.  0, or -1. */
int fp3_model_fit_engine(fp3_engine **e, const fp3_compiled *c, const char *cmd);

/* The state registers of one object watched during a run
 * (fp3_observer): v[(k - 1) nstate + i] the value of state variable i
 * after integration k (seen[] marks the written ones; v NULL: none kept),
 * and the cycles of the first and last endi. */
typedef struct fp3_state_obs {
  unsigned nstate, reg[2 * FP3_MODEL_MAX_VARS];
  uint32_t steps;
  uint32_t *v;
  unsigned char *seen;
  uint64_t cyc_first, cyc_last;
  uint32_t endis;
} fp3_state_obs;

void fp3_state_obs_write(void *ctx, unsigned reg, uint32_t value, uint32_t k);
void fp3_state_obs_endi(void *ctx, uint32_t k, uint64_t cycle);

#endif /* FP3_CMD_MODEL_H */
