/*
 * cmd_disasm.c -- `fp3 disasm FILE.hex`: the disassembler on the command
 * line (cmd_disasm.h, disasm.h).
 */
#include "cmd_disasm.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "cliopt.h"
#include "disasm.h"
#include "fp3_isa.h"
#include "image.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2

static void usage_disasm(FILE *f) {
  fprintf(f,
          "usage: fp3 disasm FILE.hex\n"
          "\n"
          "Print the program image FILE.hex as assembly text that assembles\n"
          "back to the same words and bindings.  li immediates are shown\n"
          "with %%.9g and their bit pattern; illegal words as .word, each\n"
          "also reported on stderr (word, reason).\n"
          "\n"
          "Exit status: 0 every word legal; 1 illegal words; 2 bad arguments\n"
          "or an unreadable image.\n");
}

int fp3_parse_disasm(int argc, char **argv, fp3_disasm_args *a) {
  a->in = NULL;
  for (int i = 1; i < argc; i++) {
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    if (fp3_opt_positional("disasm", "input file", argv[i], &a->in)) return FP3_ARGS_BAD;
  }
  if (!a->in) {
    fprintf(stderr, "fp3 disasm: no input file (see fp3 disasm --help)\n");
    return FP3_ARGS_BAD;
  }
  return FP3_ARGS_RUN;
}

/* The run step: read the image, print the listing, report illegal words. */
static int run_disasm(const fp3_disasm_args *a) {
  const char *in = a->in;
  fp3_image img;
  char msg[512];
  if (fp3_image_read(in, &img, msg, sizeof msg) != 0) {
    fprintf(stderr, "fp3 disasm: %s\n", msg);
    return EXIT_USAGE;
  }
  char *text = fp3_disasm_image(&img);
  if (!text) {
    fprintf(stderr, "fp3 disasm: out of memory\n");
    return EXIT_FAIL;
  }
  fputs(text, stdout);
  free(text);
  /* Illegal words are listed as .word (the listing re-assembles to the
   * same image) and reported: the image would fault on the processor. */
  int illegal = 0;
  for (size_t w = 0; w < img.n; w++) {
    char why[200];
    if (fp3_insn_check_at(img.words[w], (uint32_t)w, FP3_DEFAULT_NUM_REGS,
                          FP3_DEFAULT_IMEM_DEPTH, why, sizeof why)) {
      fprintf(stderr, "fp3 disasm: %s: word %zu (0x%016llx): illegal instruction: %s\n", in,
              w, (unsigned long long)img.words[w], why);
      illegal++;
    }
  }
  return illegal ? EXIT_FAIL : 0;
}


int fp3_cmd_disasm(int argc, char **argv) {
  fp3_disasm_args a;
  int r = fp3_parse_disasm(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_disasm(&a) : fp3_args_exit(r, usage_disasm);
}
