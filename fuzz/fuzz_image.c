/*
 * fuzz_image.c -- libFuzzer harness for the program-image reader
 * (fp3_image_read, sw/isa/image.c: 16-hex-digit words, `//` comments with
 * the register bindings).
 *
 * The input is written to DIR/in.hex and read.  An image that reads must
 * survive a round trip: fp3_image_write then fp3_image_read gives the same
 * words and bindings (abort otherwise, which libFuzzer reports as a crash).
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static fp3_image img, back;
  char msg[512];
  if (fp3_image_read(fuzz_write("in.hex", data, size), &img, msg, sizeof msg) != 0) return 0;
  char out[512];
  snprintf(out, sizeof out, "%s", fuzz_path("out.hex"));
  if (fp3_image_write(&img, out, "fuzz", msg, sizeof msg) != 0) {
    fprintf(stderr, "fuzz_image: write failed: %s\n", msg);
    abort();
  }
  if (fp3_image_read(out, &back, msg, sizeof msg) != 0) {
    fprintf(stderr, "fuzz_image: the written image does not read back: %s\n", msg);
    abort();
  }
  int same = back.n == img.n && back.nbind_in == img.nbind_in &&
             back.nbind_out == img.nbind_out &&
             memcmp(back.words, img.words, img.n * sizeof img.words[0]) == 0;
  for (unsigned i = 0; same && i < img.nbind_in + img.nbind_out; i++) {
    const fp3_binding *a = i < img.nbind_in ? &img.bind_in[i] : &img.bind_out[i - img.nbind_in];
    const fp3_binding *b = i < img.nbind_in ? &back.bind_in[i] : &back.bind_out[i - img.nbind_in];
    same = strcmp(a->name, b->name) == 0 && a->reg == b->reg;
  }
  if (!same) {
    fprintf(stderr, "fuzz_image: the image changed in a write/read round trip\n");
    abort();
  }
  return 0;
}
