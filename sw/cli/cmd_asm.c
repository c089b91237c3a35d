/*
 * cmd_asm.c -- `fp3 asm FILE.s`: the assembler on the command line, and
 * the assembler's results as every subcommand reports them (cmd_asm.h).
 */
#include "cmd_asm.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asm.h"
#include "cliopt.h"
#include "image.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2

void fp3_print_asm_errors(const char *errs) {
  if (!errs || !*errs) {
    fprintf(stderr, "assembly failed\n");
    return;
  }
  fputs(errs, stderr);
  if (errs[strlen(errs) - 1] != '\n') fputc('\n', stderr);
}

int fp3_refuse_endless(const char *cmd, const char *path, const fp3_image *img) {
  if (fp3_image_ends(img)) return 0;
  if (img->n == 0)
    fprintf(stderr, "fp3 %s: %s: no instructions: a program needs a loop body ending "
            "in 'endi LABEL', or 'halt'\n", cmd, path);
  else
    fprintf(stderr, "fp3 %s: %s: no 'endi' or 'halt' in its %zu instruction(s): the "
            "program would run off the end of the instruction memory (a fault)\n",
            cmd, path, img->n);
  return 1;
}

static void usage_asm(FILE *f) {
  fprintf(f,
          "usage: fp3 asm FILE.s [-o FILE.hex]\n"
          "\n"
          "Assemble FILE.s into a program image in $readmemh format (one\n"
          "64-bit word per line, 16 hex digits; the .in/.out bindings as\n"
          "comments).  Without -o the output is FILE.hex next to FILE.s.\n"
          "The output is written atomically: on any error none is left.\n"
          "Errors are reported as FILE:LINE: reason, all of them.\n"
          "Exit status: 0 written, 2 usage or assembly errors, 1 write error.\n");
}

int fp3_parse_asm(int argc, char **argv, fp3_asm_args *a) {
  a->in = a->out = NULL;
  for (int i = 1; i < argc; i++) {
    const char *v;
    int r;
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    if ((r = fp3_opt_output(argc, argv, &i, "asm", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->out = v;
    } else if (fp3_opt_positional("asm", "input file", argv[i], &a->in)) {
      return FP3_ARGS_BAD;
    }
  }
  if (!a->in) {
    fprintf(stderr, "fp3 asm: no input file (see fp3 asm --help)\n");
    return FP3_ARGS_BAD;
  }
  return FP3_ARGS_RUN;
}

/* The run step: assemble, refuse a program that cannot end, write. */
static int run_asm(const fp3_asm_args *a) {
  const char *in = a->in, *outp = a->out;
  char *def = NULL;
  if (!outp) {
    size_t n = strlen(in);
    def = malloc(n + 5);
    if (!def) return EXIT_FAIL;
    memcpy(def, in, n + 1);
    char *dot = strrchr(def, '.');
    char *slash = strrchr(def, '/');
    if (dot && (!slash || dot > slash)) *dot = '\0';
    strcat(def, ".hex");
    outp = def;
  }
  fp3_image img;
  char *errs = NULL;
  int rc = 0;
  if (fp3_asm_file(in, &img, &errs) != 0) {
    fp3_print_asm_errors(errs);
    rc = EXIT_USAGE;
  } else if (fp3_refuse_endless("asm", in, &img)) {
    rc = EXIT_USAGE;
  } else {
    char msg[512];
    if (fp3_image_write(&img, outp, in, msg, sizeof msg) != 0) {
      fprintf(stderr, "fp3 asm: %s\n", msg);
      rc = EXIT_FAIL;
    }
  }
  free(errs);
  free(def);
  return rc;
}

int fp3_cmd_asm(int argc, char **argv) {
  fp3_asm_args a;
  int r = fp3_parse_asm(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_asm(&a) : fp3_args_exit(r, usage_asm);
}
