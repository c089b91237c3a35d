/*
 * report.c -- formatting and file helpers shared by every layer (report.h).
 */
#include "report.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fp3_isa.h"

void fp3_flags_text(uint32_t flags, char *buf, size_t n) {
  static const struct {
    const char *name;
    unsigned bit;
  } tab[] = {
#define X(name, bit) {#name, bit},
      FP3_FLAGS(X)
#undef X
  };
  buf[0] = '\0';
  for (size_t i = 0; i < sizeof tab / sizeof tab[0]; i++)
    if (flags & tab[i].bit) {
      size_t len = strlen(buf);
      snprintf(buf + len, n - len, "%s%s", len ? " " : "", tab[i].name);
    }
  for (char *p = buf; *p; p++)
    if (*p >= 'A' && *p <= 'Z') *p = (char)(*p - 'A' + 'a');
  if (!buf[0]) snprintf(buf, n, "none");
}

const char *fp3_error_text(unsigned err) {
  switch (err) {
#define X(name, code, desc) \
  case code:                \
    return desc;
    FP3_ERRORS(X)
#undef X
  default:
    return "unknown error";
  }
}

const char *fp3_error_name(unsigned err) {
  switch (err) {
#define X(name, code, desc) \
  case code:                \
    return #name;
    FP3_ERRORS(X)
#undef X
  default:
    return "UNKNOWN";
  }
}

/* Distance in units in the last place between two binary32 patterns. */
int64_t fp3_ulp_distance(uint32_t a, uint32_t b) {
  int64_t x = (a & 0x80000000u) ? -(int64_t)(a & 0x7fffffffu) : (int64_t)a;
  int64_t y = (b & 0x80000000u) ? -(int64_t)(b & 0x7fffffffu) : (int64_t)b;
  return x > y ? x - y : y - x;
}

void fp3_json_string(FILE *f, const char *s) {
  fputc('"', f);
  for (; *s; s++) {
    unsigned char c = (unsigned char)*s;
    if (c == '"' || c == '\\')
      fprintf(f, "\\%c", c);
    else if (c < 0x20)
      fprintf(f, "\\u%04x", c);
    else
      fputc(c, f);
  }
  fputc('"', f);
}

/* %.9g for a float, %.17g for a double; null when not finite (JSON). */
void fp3_json_float(FILE *f, float x) {
  if (isfinite(x))
    fprintf(f, "%.9g", (double)x);
  else
    fputs("null", f);
}

void fp3_json_double(FILE *f, double x) {
  if (isfinite(x))
    fprintf(f, "%.17g", x);
  else
    fputs("null", f);
}


void fp3_strbuf_printf(fp3_strbuf *b, const char *fmt, ...) {
  va_list ap;
  va_start(ap, fmt);
  int k = vsnprintf(NULL, 0, fmt, ap);
  va_end(ap);
  if (k < 0 || b->oom) return;
  if (b->len + (size_t)k + 1 > b->cap) {
    size_t cap = b->cap ? b->cap * 2 : 4096;
    while (cap < b->len + (size_t)k + 1) cap *= 2;
    char *g = realloc(b->s, cap);
    if (!g) {
      b->oom = 1;
      return;
    }
    b->s = g;
    b->cap = cap;
  }
  va_start(ap, fmt);
  vsnprintf(b->s + b->len, b->cap - b->len, fmt, ap);
  va_end(ap);
  b->len += (size_t)k;
}

int fp3_write_text_atomic(const char *path, const char *text, char *msg, size_t n) {
  size_t len = strlen(path);
  char *tmp = malloc(len + 16);
  if (!tmp) {
    snprintf(msg, n, "out of memory");
    return -1;
  }
  snprintf(tmp, len + 16, "%s.tmpXXXXXX", path);
  int fd = mkstemp(tmp);
  if (fd < 0) {
    snprintf(msg, n, "%s: %s", path, strerror(errno));
    free(tmp);
    return -1;
  }
  mode_t um = umask(0); /* mkstemp makes 0600: give the file the usual mode */
  umask(um);
  fchmod(fd, 0666 & ~um);
  FILE *f = fdopen(fd, "w");
  int bad = !f || fputs(text, f) < 0;
  if (f) bad |= fclose(f) != 0;
  else close(fd);
  if (!bad && rename(tmp, path) != 0) bad = 1;
  if (bad) {
    snprintf(msg, n, "%s: %s", path, strerror(errno ? errno : EIO));
    unlink(tmp);
    free(tmp);
    return -1;
  }
  free(tmp);
  return 0;
}

void fp3_json_member_float(FILE *f, const char *key, float x) {
  fprintf(f, ", \"%s\": ", key);
  fp3_json_float(f, x);
}

void fp3_json_member_double(FILE *f, const char *key, double x) {
  fprintf(f, ", \"%s\": ", key);
  fp3_json_double(f, x);
}
