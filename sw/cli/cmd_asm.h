/*
 * cmd_asm.h -- `fp3 asm FILE.s [-o FILE.hex]`: the assembler (asm.h) on
 * the command line; and how the subcommands that assemble a program
 * report the assembler's messages and a program that cannot end.
 */
#ifndef FP3_CMD_ASM_H
#define FP3_CMD_ASM_H

#include "image.h"

/* `fp3 asm`'s options (fp3 asm --help). */
typedef struct fp3_asm_args {
  const char *in;   /* the program (required)                           */
  const char *out;  /* -o FILE, or NULL: FILE.hex next to the program   */
} fp3_asm_args;

/* The parse step of `fp3 asm`: FP3_ARGS_RUN with *a filled,
 * FP3_ARGS_HELP, or FP3_ARGS_BAD with the message on stderr (cliopt.h). */
int fp3_parse_asm(int argc, char **argv, fp3_asm_args *a);

/* argv[0] is "asm".  Exit status: 0 written, 1 a write error, 2 bad
 * arguments, assembly errors (FILE:LINE: reason, all of them) or a
 * program that cannot end. */
int fp3_cmd_asm(int argc, char **argv);

/* The assembler's messages errs (fp3_asm_file; NULL or empty: "assembly
 * failed") on stderr, ending in a newline. */
void fp3_print_asm_errors(const char *errs);

/* Refuse an assembled program that cannot end (fp3_image_ends): print
 * "fp3 CMD: FILE: reason" on stderr and return 1; 0 if it can end. */
int fp3_refuse_endless(const char *cmd, const char *path, const fp3_image *img);

#endif /* FP3_CMD_ASM_H */
