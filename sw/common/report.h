/*
 * report.h -- small formatting and file helpers shared by every layer:
 * exception-flag and error names, ulp distance, JSON values, a growing
 * string, and atomic writes (the CLI's reports, the compiler's listing).
 */
#ifndef FP3_REPORT_H
#define FP3_REPORT_H

#include <stdint.h>
#include <stdio.h>

/* Names of the set exception flags ("inexact underflow"), or "none". */
void fp3_flags_text(uint32_t flags, char *buf, size_t n);

/* Description ("illegal instruction") and name ("ILLEGAL_INSN") of a run
 * error code (enum fp3_error). */
const char *fp3_error_text(unsigned err);
const char *fp3_error_name(unsigned err);

/* Distance in units in the last place between two binary32 patterns
 * (signed-magnitude order, so -0 and +0 are 0 apart). */
int64_t fp3_ulp_distance(uint32_t a, uint32_t b);

/* JSON values: a string with escapes; a float (%.9g, round-trips to the
 * same binary32) or a double (%.17g), null when not finite. */
void fp3_json_string(FILE *f, const char *s);
void fp3_json_float(FILE *f, float x);
void fp3_json_double(FILE *f, double x);

/* A member after the first of a JSON object: `, "key": ` and the value as
 * fp3_json_float / fp3_json_double write it. */
void fp3_json_member_float(FILE *f, const char *key, float x);
void fp3_json_member_double(FILE *f, const char *key, double x);

/* A growing NUL-terminated string: start with {0}; s is malloc'd (the
 * caller frees it), NULL until the first append.  After a failed
 * allocation oom is 1 and later appends do nothing. */
typedef struct fp3_strbuf {
  char *s;
  size_t len, cap;
  int oom;
} fp3_strbuf;

/* Append printf-formatted text (any length). */
void fp3_strbuf_printf(fp3_strbuf *b, const char *fmt, ...)
    __attribute__((format(printf, 2, 3)));

/* Write text to path atomically: a temporary file in the same directory
 * (the usual mode, umask applied), then rename.  On any error no file is
 * left and path is untouched.  Returns 0, or -1 with "PATH: reason". */
int fp3_write_text_atomic(const char *path, const char *text, char *msg, size_t n);

#endif /* FP3_REPORT_H */
