/*
 * cliopt.h -- option parsing shared by the fp3 subcommands.
 */
#ifndef FP3_CLIOPT_H
#define FP3_CLIOPT_H

/* "--name VALUE" or "--name=VALUE": returns 1 and sets *val (advancing *i
 * past a separate value) if argv[*i] is that option, -1 with a message on
 * stderr ("fp3 CMD: option --name needs a value") if the value is
 * missing, 0 if argv[*i] is another argument. */
int fp3_opt_value(int argc, char **argv, int *i, const char *cmd, const char *name,
                  const char **val);

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

/* 1 if a is --help or -h. */
int fp3_is_help(const char *a);

#endif /* FP3_CLIOPT_H */
