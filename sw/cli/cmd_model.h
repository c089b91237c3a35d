/*
 * cmd_model.h -- the model language on the command line (docs/models.md):
 *
 *   fp3 run --model FILE [--integrator NAME] [--literal] [--set NAME=VALUE ...]
 *           [--steps N] [--engine rtl|iss] [--json]
 *   fp3 compile --model FILE [--integrator NAME] [--literal] [-o OUT.s]
 */
#ifndef FP3_CMD_MODEL_H
#define FP3_CMD_MODEL_H

/* 1 if argv[1..argc) holds --model (or --model=FILE): the command is for a
 * model file. */
int fp3_args_have_model(int argc, char **argv);

/* `fp3 run --model`: one object of a model compiled for an integrator,
 * run on an engine, checked bit for bit after every integration against
 * the compiled program's golden model, and compared with the GSL
 * reference (rk8pd at 1e-12) and the model's `exact` lines.  argv[0] is
 * "run".  Exit status: 0 pass, 1 mismatch, run error or non-finite state,
 * 2 bad arguments, model or values (a message on stderr naming the file,
 * line and column, or the missing NAME). */
int fp3_cmd_run_model(int argc, char **argv);

/* `fp3 compile --model`: the program text (to -o FILE atomically, else
 * stdout).  argv[0] is "compile".  Exit status as fp3_cmd_compile. */
int fp3_cmd_compile_model(int argc, char **argv);

#endif /* FP3_CMD_MODEL_H */
