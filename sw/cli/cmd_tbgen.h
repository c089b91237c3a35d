/*
 * cmd_tbgen.h -- `fp3 tbgen`: the input and golden files of the Icarus
 * Verilog testbench sim/tb_fp3.v (make wave).
 *
 * fp3 tbgen PROGRAM.s -o DIR [--steps N] [--set NAME=VALUE ...] writes,
 * all in $readmemh format (hex words, `//` comments):
 *
 *   DIR/program.hex   the assembled image (fp3 asm), one 64-bit word a line
 *   DIR/init.hex      FP3_DEFAULT_NUM_REGS 32-bit register values the
 *                     testbench writes before the run: the .in parameters,
 *                     0 elsewhere
 *   DIR/run.hex       TBGEN_RUN_WORDS words: how to run and what to expect
 *                     of the run (layout below)
 *   DIR/expected.hex  the final value of every register, then v and s
 *                     after every integration (TBGEN_EXP_* below)
 *
 * The expected values come from the instruction-set simulator, which
 * equals the golden model bit for bit (tests/test_engines.c); the cycle
 * and stall counts from the Verilated RTL, so the testbench also checks
 * that Icarus and Verilator agree cycle for cycle.
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
#define TBGEN_RUN_REG_V     10  /* register of .out v, 0xFFFFFFFF: none   */
#define TBGEN_RUN_REG_S     11  /* register of .out s, 0xFFFFFFFF: none   */
#define TBGEN_RUN_NCHECK    12  /* integrations with v, s in expected.hex */
#define TBGEN_RUN_RTL_LAT   13  /* Verilated model: (NUM_LANES > 1)<<17 |
                                   FMAX_PIPE<<16 | MUL_LAT<<8 | ADD_LAT,
                                   0 when not run                         */
#define TBGEN_RUN_RTL_CYCLES 14 /* its CYCLES, low word                   */
#define TBGEN_RUN_RTL_STALLS 15 /* its STALLS, low word                   */
#define TBGEN_RUN_WORDS     16

#define TBGEN_VERSION 1u
/* Most integrations whose v and s expected.hex lists (the testbench's
 * memory for them is sized for this). */
#define TBGEN_MAX_CHECK 100000u

#include <stdint.h>

#include "fpref.h"
#include "golden.h"

/* `fp3 tbgen`'s options (fp3 tbgen --help). */
typedef struct fp3_tbgen_args {
  const char *in;        /* the program (required)                         */
  const char *dir;       /* -o DIR (required)                              */
  uint32_t steps;        /* --steps, 1..TBGEN_MAX_CHECK (default 4)        */
  int use_rtl;           /* 0: --no-rtl                                    */
  fpref_mode mode;       /* --round, --ftz                                 */
  fp3_ship_params p;     /* the scene, --set values applied and validated  */
} fp3_tbgen_args;

/* The parse step of `fp3 tbgen`: FP3_ARGS_RUN with *a filled,
 * FP3_ARGS_HELP, or FP3_ARGS_BAD with the message on stderr (cliopt.h). */
int fp3_parse_tbgen(int argc, char **argv, fp3_tbgen_args *a);

/* argv[0] is "tbgen".  Exit status: 0 written, 1 a run or a write failed,
 * 2 bad arguments or program (a message on stderr). */
int fp3_cmd_tbgen(int argc, char **argv);

#endif /* FP3_CMD_TBGEN_H */
