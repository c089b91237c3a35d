/*
 * fuzz_testfloat.c -- libFuzzer harness for the TestFloat vector reader
 * (testfloat_run, sw/engine/testfloat.c: lines "A B RESULT FLAGS" in hex,
 * "A RESULT FLAGS" for sqrt, gzip or plain).
 *
 * The first input byte picks the operation (add, sub, mul, div, sqrt) and
 * the mode (RNE or RTZ, FTZ or not); the rest is the vector file, written
 * to DIR/v.txt (gzip data is read as gzip, as for a user's file).  Vectors
 * run through the reference sw/fpref (model NULL), not a Verilated core:
 * the reader is under test, and the harness links no RTL.
 */
#include <stdint.h>
#include <stdio.h>

#include "fuzz_common.h"
#include "testfloat.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size < 1) return 0;
  static FILE *null_out;
  if (!null_out) null_out = fopen("/dev/null", "w");
  testfloat_op op = (testfloat_op)(data[0] % 5);
  fpref_mode mode;
  mode.round = (data[0] >> 3) & 1 ? FPREF_RTZ : FPREF_RNE;
  mode.ftz = (data[0] >> 4) & 1;
  testfloat_stats st;
  const char *path = fuzz_write("v.txt", data + 1, size - 1);
  testfloat_run(path, op, mode, NULL, null_out, 3, null_out, &st);
  return 0;
}
