/*
 * cmd_tbgen.h -- `fp3 tbgen`: the input and golden files of the Icarus
 * Verilog testbench sim/tb_fp3.v (make wave).
 *
 * fp3 tbgen PROGRAM.s -o DIR [--model FILE.fp3m] [--set NAME=VALUE ...]
 * [--steps N] runs a hand-written program on the one path of `fp3 run
 * --program`: the model is --model or the program's `.model`, the values
 * of its one object the model file's defaults overridden by --set
 * (fp3_model_args_values: h, params, state variables as NAME or NAME0),
 * and the program is bound to the model by name (fp3_compile_bind: its
 * `.integrator`, `.in`, `.out`).  It writes, all in $readmemh format (hex
 * words, `//` comments):
 *
 *   DIR/program.hex   the assembled image (fp3 asm), one 64-bit word a line
 *   DIR/init.hex      FP3_DEFAULT_NUM_REGS 32-bit register values the
 *                     testbench writes before the run: the writes of
 *                     fp3_compiled_model_start (every bound `.in`: params,
 *                     initial states, host-computed lets such as minv,
 *                     negated values such as -v0), 0 elsewhere
 *   DIR/run.hex       TBGEN_RUN_WORDS words: how to run and what to expect
 *                     of the run (layout below)
 *   DIR/expected.hex  the final value of every register, then the two
 *                     checked state variables after every integration
 *
 * The checked state variables are the model's first two (state variable
 * 0 and 1 in the order of the model file: the ship's v and s, the
 * spring's x and v); a one-state model has one, and the second register
 * is TBGEN_NO_REG.  The expected values come from the instruction-set
 * simulator, which tbgen also checks against the bound program's golden
 * model (fp3_compiled_model_step: every state variable after every
 * integration, bit for bit; a disagreement writes nothing and exits 1);
 * the cycle and stall counts come from the Verilated RTL, so the
 * testbench also checks that Icarus and Verilator agree cycle for cycle.
 */
#ifndef FP3_CMD_TBGEN_H
#define FP3_CMD_TBGEN_H

/* run.hex: word index -> meaning.  The testbench (sim/tb_fp3.v) uses the
 * same indices; both say "run.hex layout" next to them. */
#define TBGEN_RUN_MAGIC      0  /* FP3_ID_VALUE                           */
#define TBGEN_RUN_VERSION    1  /* TBGEN_VERSION                          */
#define TBGEN_RUN_NWORDS     2  /* words in program.hex                   */
#define TBGEN_RUN_NUM_REGS   3  /* words in init.hex, final regs          */
#define TBGEN_RUN_STEPS      4  /* STEPS the testbench writes             */
#define TBGEN_RUN_ERROR      5  /* expected STATUS.ERROR                  */
#define TBGEN_RUN_FAULT_PC   6  /* expected FAULT_PC (if ERROR != 0)      */
#define TBGEN_RUN_STEPS_DONE 7  /* expected STEPS_DONE                    */
#define TBGEN_RUN_ISSUED     8  /* expected ISSUED, low word              */
#define TBGEN_RUN_FLAGS      9  /* expected sticky FLAGS                  */
#define TBGEN_RUN_REG_V     10  /* register of state variable 0           */
#define TBGEN_RUN_REG_S     11  /* register of state variable 1,
                                   TBGEN_NO_REG: a one-state model        */
#define TBGEN_RUN_NCHECK    12  /* integrations listed in expected.hex    */
#define TBGEN_RUN_RTL_LAT   13  /* Verilated model: (NUM_LANES > 1)<<17 |
                                   FMAX_PIPE<<16 | MUL_LAT<<8 | ADD_LAT,
                                   0 when not run                         */
#define TBGEN_RUN_RTL_CYCLES 14 /* its CYCLES, low word                   */
#define TBGEN_RUN_RTL_STALLS 15 /* its STALLS, low word                   */
#define TBGEN_RUN_NAME_V    16  /* the name of state variable 0, the
                                   testbench's messages: TBGEN_NAME_WORDS
                                   words of ASCII, a Verilog string (the
                                   last character in the low byte of the
                                   last word, NULs before the first)      */
#define TBGEN_RUN_NAME_S    24  /* the name of state variable 1 (all 0:
                                   none)                                  */
#define TBGEN_RUN_WORDS     32

#define TBGEN_NAME_WORDS    8   /* 32 characters: FP3_MODEL_NAME_LEN - 1  */
#define TBGEN_NO_REG 0xFFFFFFFFu

/* Version 2: words 10 and 11 are the model's first two state variables
 * (version 1: the registers of `.out v` and `.out s`), words 16..31 their
 * names. */
#define TBGEN_VERSION 2u
/* Most integrations expected.hex lists (the testbench's memory for them is
 * sized for this). */
#define TBGEN_MAX_CHECK 100000u

#include <stdint.h>

#include "cmd_model.h"
#include "fpref.h"

/* `fp3 tbgen`'s options (fp3 tbgen --help). */
typedef struct fp3_tbgen_args {
  const char *in;        /* the program (required)                         */
  const char *dir;       /* -o DIR (required)                              */
  uint32_t steps;        /* --steps, 1..TBGEN_MAX_CHECK (default 4)        */
  int use_rtl;           /* 0: --no-rtl                                    */
  fpref_mode mode;       /* --round, --ftz                                 */
  fp3_model_args model;  /* model.file: --model (NULL: the program's
                            `.model`); model.set[], model.nset: the --set
                            values as text, resolved against the model by
                            the run step (fp3_model_args_values)           */
} fp3_tbgen_args;

/* The parse step of `fp3 tbgen`: FP3_ARGS_RUN with *a filled,
 * FP3_ARGS_HELP, or FP3_ARGS_BAD with the message on stderr (cliopt.h). */
int fp3_parse_tbgen(int argc, char **argv, fp3_tbgen_args *a);

/* argv[0] is "tbgen".  Exit status: 0 written, 1 a run or a write failed
 * or the ISS disagrees with the golden model, 2 bad arguments, program or
 * model (a message on stderr; nothing written into DIR). */
int fp3_cmd_tbgen(int argc, char **argv);

#endif /* FP3_CMD_TBGEN_H */
