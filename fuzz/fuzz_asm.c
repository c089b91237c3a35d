/*
 * fuzz_asm.c -- libFuzzer harness for the assembler (sw/isa/asm.c).
 *
 * The input is a source file: it is written to DIR/top.s and assembled
 * with fp3_asm_file, so that `.include` works as for a user: DIR also holds
 * ship_scene.inc (the register names and host bindings of
 * programs/ship_scene.inc, which the seed programs include), and an input
 * may include itself ("top.s"), which reaches the nesting limit.  The errors
 * string is freed; ASan reports a leak of anything else.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "asm.h"
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static int ready;
  if (!ready) {
    static const char inc[] = ".reg T r1\n.reg C r2\n.reg minv r3\n"
                              ".reg h r4\n.reg v r5\n.reg s r6\n"
                              ".in T, T\n.in C, C\n.in minv, minv\n.in h, h\n"
                              ".in v0, v\n.in s0, s\n.out v, v\n.out s, s\n";
    fuzz_write("ship_scene.inc", (const uint8_t *)inc, strlen(inc));
    ready = 1;
  }
  static fp3_image img;
  char *errors = NULL;
  fp3_asm_file(fuzz_write("top.s", data, size), &img, &errors);
  free(errors);
  return 0;
}
