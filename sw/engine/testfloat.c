/*
 * testfloat.c -- Berkeley TestFloat vector runner (see testfloat.h).
 *
 * Streams the file through zlib (gzopen reads gzip and plain files alike)
 * in batches, and runs each batch back to back through the core, one
 * operation per cycle (fpu_model_run).
 */
#include "testfloat.h"

#include <ctype.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "../sim/fpu_model.h" /* relative: no -Isim needed */

#define TF_BATCH 4096
#define TF_LINE_MAX 256

/* Parse one hex field of 1..max_digits digits at *pp; skips leading blanks. */
static int parse_hex(const char **pp, unsigned max_digits, uint32_t *v) {
  const char *p = *pp;
  while (*p == ' ' || *p == '\t') p++;
  uint32_t x = 0;
  unsigned n = 0;
  while (isxdigit((unsigned char)*p)) {
    if (++n > max_digits) return -1;
    int c = (unsigned char)*p++;
    x = (x << 4) | (uint32_t)(isdigit(c) ? c - '0' : tolower(c) - 'a' + 10);
  }
  if (n == 0) return -1;
  if (*p != '\0' && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r')
    return -1;
  *pp = p;
  *v = x;
  return 0;
}

/* Fields of a line: operands, result and flags; sqrt has one operand. */
static int op_fields(testfloat_op op) { return op == TESTFLOAT_SQRT ? 3 : 4; }

/* One line of `nfields` hex fields (the last 2 digits, the others 8) into
 * v[0 .. nfields-1].  1: a vector, 0: blank line, -1: malformed. */
static int parse_line(const char *line, int nfields, uint32_t v[4]) {
  const char *p = line;
  while (*p == ' ' || *p == '\t') p++;
  if (*p == '\n' || *p == '\r' || *p == '\0') return 0;
  for (int i = 0; i < nfields; i++)
    if (parse_hex(&p, i == nfields - 1 ? 2 : 8, &v[i]) != 0) return -1;
  while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n') p++;
  return *p == '\0' ? 1 : -1;
}

#define TF_NUM_OPS 5
static const char *const op_names[TF_NUM_OPS] = {"add", "sub", "mul", "div",
                                                  "sqrt"};

static uint32_t ref_apply(testfloat_op op, uint32_t a, uint32_t b,
                          fpref_mode mode, unsigned *flags) {
  switch (op) {
  case TESTFLOAT_ADD: return fpref_add(a, b, mode, flags);
  case TESTFLOAT_SUB: return fpref_sub(a, b, mode, flags);
  case TESTFLOAT_MUL: return fpref_mul(a, b, mode, flags);
  case TESTFLOAT_DIV: return fpref_div(a, b, mode, flags);
  default:            return fpref_sqrt(a, mode, flags);
  }
}

typedef struct tf_batch {
  uint32_t a[TF_BATCH], b[TF_BATCH], want[TF_BATCH], y[TF_BATCH];
  uint8_t want_flags[TF_BATCH], flags[TF_BATCH];
  unsigned long line[TF_BATCH];
  size_t n;
} tf_batch;

static int run_batch(tf_batch *bt, testfloat_op op, fpref_mode mode,
                     struct fpu_model *model, FILE *out, unsigned max_print,
                     FILE *err, const char *path, testfloat_stats *st) {
  if (model) {
    static const fpu_op ops[TF_NUM_OPS] = {FPU_OP_ADD, FPU_OP_SUB, FPU_OP_MUL,
                                           FPU_OP_DIV, FPU_OP_SQRT};
    if (fpu_model_run(model, ops[op], bt->n, bt->a, bt->b, bt->y,
                      bt->flags) != 0) {
      if (err)
        fprintf(err, "%s: the core's valid_o did not follow its latency\n",
                path);
      return -1;
    }
  } else {
    for (size_t i = 0; i < bt->n; i++) {
      unsigned fl = 0;
      bt->y[i] = ref_apply(op, bt->a[i], bt->b[i], mode, &fl);
      bt->flags[i] = (uint8_t)fl;
    }
  }
  for (size_t i = 0; i < bt->n; i++) {
    int same = bt->y[i] == bt->want[i] ||
               (fpref_is_nan(bt->y[i]) && fpref_is_nan(bt->want[i]));
    if (same && bt->flags[i] == bt->want_flags[i]) {
      st->passed++;
      continue;
    }
    if (out && st->failed < max_print) {
      char operands[32];
      if (op == TESTFLOAT_SQRT)
        snprintf(operands, sizeof operands, "%08X", (unsigned)bt->a[i]);
      else
        snprintf(operands, sizeof operands, "%08X %08X", (unsigned)bt->a[i],
                 (unsigned)bt->b[i]);
      fprintf(out,
              "%s:%lu: %s %s: expected %08X flags %02X, got %08X flags %02X\n",
              path, bt->line[i], op_names[op], operands,
              (unsigned)bt->want[i], (unsigned)bt->want_flags[i],
              (unsigned)bt->y[i], (unsigned)bt->flags[i]);
    }
    st->failed++;
  }
  bt->n = 0;
  return 0;
}

int testfloat_run(const char *path, testfloat_op op, fpref_mode mode,
                  struct fpu_model *model, FILE *out, unsigned max_print,
                  FILE *err, testfloat_stats *st) {
  st->passed = 0;
  st->failed = 0;
  if ((unsigned)op >= TF_NUM_OPS) {
    if (err) fprintf(err, "testfloat: bad operation %d\n", (int)op);
    return -1;
  }
  gzFile gz = gzopen(path, "rb");
  if (!gz) {
    if (err) fprintf(err, "%s: cannot open\n", path);
    return -1;
  }
  tf_batch *bt = malloc(sizeof *bt);
  if (!bt) {
    gzclose(gz);
    if (err) fprintf(err, "%s: out of memory\n", path);
    return -1;
  }
  bt->n = 0;
  char line[TF_LINE_MAX];
  unsigned long lineno = 0;
  int rc = 0;
  while (gzgets(gz, line, sizeof line) != NULL) {
    lineno++;
    size_t len = strlen(line);
    if (len == sizeof line - 1 && line[len - 1] != '\n') {
      if (err) fprintf(err, "%s:%lu: line too long\n", path, lineno);
      rc = -1;
      break;
    }
    uint32_t v[4];
    int nf = op_fields(op);
    int k = parse_line(line, nf, v);
    if (k < 0) {
      if (err)
        fprintf(err, "%s:%lu: malformed line (want \"%s\" in hex for %s)\n",
                path, lineno,
                nf == 3 ? "A RESULT FLAGS" : "A B RESULT FLAGS", op_names[op]);
      rc = -1;
      break;
    }
    if (k == 0) continue;
    bt->a[bt->n] = v[0];
    bt->b[bt->n] = nf == 3 ? 0 : v[1];
    bt->want[bt->n] = v[nf - 2];
    bt->want_flags[bt->n] = (uint8_t)v[nf - 1];
    bt->line[bt->n] = lineno;
    if (++bt->n == TF_BATCH &&
        run_batch(bt, op, mode, model, out, max_print, err, path, st) != 0) {
      rc = -1;
      break;
    }
  }
  if (rc == 0) {
    int errnum = 0;
    const char *msg = gzerror(gz, &errnum);
    if (errnum != Z_OK && errnum != Z_STREAM_END) {
      if (err) fprintf(err, "%s:%lu: read error: %s\n", path, lineno, msg);
      rc = -1;
    } else if (bt->n > 0) {
      rc = run_batch(bt, op, mode, model, out, max_print, err, path, st);
    }
  }
  free(bt);
  gzclose(gz);
  return rc;
}

int testfloat_op_parse(const char *name, testfloat_op *op) {
  for (int k = 0; k < TF_NUM_OPS; k++)
    if (strcmp(name, op_names[k]) == 0) {
      *op = (testfloat_op)k;
      return 0;
    }
  return -1;
}
