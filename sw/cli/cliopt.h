/*
 * cliopt.h -- option parsing shared by the fp3 subcommands.
 */
#ifndef FP3_CLIOPT_H
#define FP3_CLIOPT_H

#include <stdint.h>
#include <stdio.h>

#include "fpref.h"

/* Every subcommand is two steps: a parse step, fp3_parse_CMD(argc, argv,
 * &args), that turns the argument vector into the subcommand's options
 * and checks them (no file is opened, nothing is written but the message
 * of a bad argument on stderr), and the run step that reads the files,
 * runs the engines and writes the outputs.  The parse step returns one of
 * these.  tests/test_cli.sh checks the messages; fuzz/fuzz_options.c
 * fuzzes every parse step. */
enum {
  FP3_ARGS_RUN = 0,  /* the options are valid: run                          */
  FP3_ARGS_HELP = 1, /* --help or -h: print the usage, exit 0               */
  FP3_ARGS_BAD = -1  /* a bad argument, reported on stderr: exit 2          */
};

/* The exit status of a parse step's result r other than FP3_ARGS_RUN:
 * FP3_ARGS_HELP prints usage(stdout) and gives 0, FP3_ARGS_BAD gives 2
 * (the usage error status of every subcommand). */
int fp3_args_exit(int r, void (*usage)(FILE *));

/* "--name VALUE" or "--name=VALUE": returns 1 and sets *val (advancing *i
 * past a separate value) if argv[*i] is that option, -1 with a message on
 * stderr ("fp3 CMD: option --name needs a value") if the value is
 * missing, 0 if argv[*i] is another argument. */
int fp3_opt_value(int argc, char **argv, int *i, const char *cmd, const char *name,
                  const char **val);

/* -o FILE or --output FILE (each also with =FILE): 1, 0, -1 as
 * fp3_opt_value. */
int fp3_opt_output(int argc, char **argv, int *i, const char *cmd, const char **val);

/* argv[i] = arg, which no option of command cmd matched: an unknown option
 * ("-x", "--x"; "-" alone is a file name), else a positional argument,
 * stored in *one if it is the first.  Returns 0, or -1 with a message on
 * stderr: "fp3 CMD: unknown option '--x' (see fp3 CMD --help)" or "fp3
 * CMD: more than one WHAT ('arg')". */
int fp3_opt_positional(const char *cmd, const char *what, const char *arg, const char **one);

/* A count option's value: 0 and *out if v is a decimal integer (digits
 * only) in lo..hi, else -1 (the caller names the option in its message). */
int fp3_parse_count(const char *v, unsigned long long lo, unsigned long long hi,
                    unsigned long long *out);

/* A count option, "NAME VALUE" or "NAME=VALUE" with a decimal integer
 * in lo..hi (fp3_parse_count): 1 and *out if argv[*i] is that option, 0
 * if it is another argument, -1 with a message on stderr for a missing
 * or bad value ("fp3 CMD: NAME 'V': want LO..HI UNIT"; unit may be "").
 * Every subcommand parses its counts so: one shape, one message. */
int fp3_opt_count(int argc, char **argv, int *i, const char *cmd, const char *name,
                  unsigned long long lo, unsigned long long hi, const char *unit,
                  unsigned long long *out);

/* --seed S: an unsigned 64-bit integer, decimal or 0x hexadecimal
 * (strtoull base 0, so a leading 0 is octal); 1, 0, -1 as
 * fp3_opt_count ("fp3 CMD: --seed 'V': want an unsigned 64-bit
 * integer ..."). */
int fp3_opt_seed(int argc, char **argv, int *i, const char *cmd, uint64_t *out);

/* The arithmetic mode's options: --round rne|rtz sets mode->round,
 * --ftz sets mode->ftz (flush subnormals to zero); 1, 0, -1 as
 * fp3_opt_count ("fp3 CMD: unknown rounding 'V' (rne or rtz)"). */
int fp3_opt_mode(int argc, char **argv, int *i, const char *cmd, fpref_mode *mode);

/* "A:B", two decimal counts, A in lo1..hi1 and B in lo2..hi2 (or B the
 * word `all`, if all is not NULL: *b = ULLONG_MAX).  0, or -1 (the
 * caller names the option in its message). */
int fp3_parse_pair(const char *v, unsigned long long lo1, unsigned long long hi1,
                   unsigned long long lo2, unsigned long long hi2, const char *all,
                   unsigned long long *a, unsigned long long *b);

/* 1 if a is --help or -h. */
int fp3_is_help(const char *a);

#endif /* FP3_CLIOPT_H */
