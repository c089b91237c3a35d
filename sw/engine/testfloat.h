/*
 * testfloat.h -- Berkeley TestFloat vector runner for the FP cores.
 *
 * A vector file holds lines "A B RESULT FLAGS" (hex; operands and result
 * 8 digits, flags 2 digits in SoftFloat order, see fp3_isa.h FP3_FLAGS),
 * or "A RESULT FLAGS" for the one-operand sqrt, gzip-compressed or plain.  Each line runs through the Verilated core of
 * the chosen configuration (sim/fpu_model.h) or through sw/fpref; a result
 * passes when its bits equal the expected ones, or both are NaN (any
 * payload), and the flags are equal.
 */
#ifndef FP3_TESTFLOAT_H
#define FP3_TESTFLOAT_H

#include <stdio.h>

#include "fpref.h"

struct fpu_model;

typedef enum testfloat_op {
  TESTFLOAT_ADD = 0,
  TESTFLOAT_SUB = 1,
  TESTFLOAT_MUL = 2,
  TESTFLOAT_DIV = 3,
  TESTFLOAT_SQRT = 4 /* one operand: lines "A RESULT FLAGS" */
} testfloat_op;

typedef struct testfloat_stats {
  unsigned long passed;
  unsigned long failed;
} testfloat_stats;

/* Run every line of `path` through `model` (which must have the rounding and
 * FTZ of `mode`), or through fpref in `mode` when model is NULL.  A line
 * with the wrong number of fields for `op` (two operands in a sqrt file,
 * one in a div file) is malformed.  Prints
 * the first `max_print` failures to `out` (may be NULL).  Returns 0 when the
 * whole file was read (whatever the failures), -1 on an I/O error or a
 * malformed line, with a message naming the file and line to `err` (may be
 * NULL).  *st gets the counts. */
int testfloat_run(const char *path, testfloat_op op, fpref_mode mode,
                  struct fpu_model *model, FILE *out, unsigned max_print,
                  FILE *err, testfloat_stats *st);

/* The operation named `name` (add, sub, mul, div, sqrt) into *op: 0, or
 * -1 for another name. */
int testfloat_op_parse(const char *name, testfloat_op *op);

#endif /* FP3_TESTFLOAT_H */
