/*
 * cmd_disasm.h -- `fp3 disasm FILE.hex`: a program image as assembly text
 * (disasm.h) on the command line.
 */
#ifndef FP3_CMD_DISASM_H
#define FP3_CMD_DISASM_H

/* `fp3 disasm`'s options. */
typedef struct fp3_disasm_args {
  const char *in; /* the program image (required) */
} fp3_disasm_args;

/* The parse step of `fp3 disasm`: FP3_ARGS_RUN with *a filled,
 * FP3_ARGS_HELP, or FP3_ARGS_BAD with the message on stderr (cliopt.h). */
int fp3_parse_disasm(int argc, char **argv, fp3_disasm_args *a);

/* argv[0] is "disasm".  Exit status: 0 every word legal, 1 illegal words
 * (each reported on stderr), 2 bad arguments or an unreadable image. */
int fp3_cmd_disasm(int argc, char **argv);

#endif /* FP3_CMD_DISASM_H */
