/*
 * progress.c -- a progress line for long runs, on a terminal only
 * (progress.h).
 */
#include "progress.h"

#include <math.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

static double monotonic_seconds(void *ctx) {
  (void)ctx;
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void fp3_progress_start_on(fp3_progress *p, FILE *out, const char *label, uint64_t total,
                           const char *unit, size_t width, fp3_progress_clock clock,
                           void *clock_ctx) {
  memset(p, 0, sizeof *p);
  p->out = label ? out : NULL;
  p->label = label;
  p->unit = unit ? unit : "";
  p->total = total;
  p->width = width;
  p->clock = clock ? clock : monotonic_seconds;
  p->clock_ctx = clock_ctx;
  p->stride = 1;
  if (p->out) p->t0 = p->last_check = p->clock(p->clock_ctx);
}

void fp3_progress_start(fp3_progress *p, const char *label, uint64_t total, const char *unit,
                        int show) {
  FILE *out = NULL;
  size_t width = 0;
  if (show && label && isatty(fileno(stderr))) {
    struct winsize ws;
    out = stderr;
    /* one column short of the width: a line that fills the last column
     * makes some terminals wrap, and '\r' then rewrites the second row */
    if (ioctl(fileno(stderr), TIOCGWINSZ, &ws) == 0 && ws.ws_col > 1) width = ws.ws_col - 1u;
  }
  fp3_progress_start_on(p, out, label, total, unit, width, NULL, NULL);
}

/* x grouped by thousands ("10,000,000") into buf. */
static void grouped(char *buf, size_t n, uint64_t x) {
  char digits[24];
  int len = snprintf(digits, sizeof digits, "%llu", (unsigned long long)x);
  size_t k = 0;
  for (int i = 0; i < len && k + 1 < n; i++) {
    if (i > 0 && (len - i) % 3 == 0 && k + 2 < n) buf[k++] = ',';
    buf[k++] = digits[i];
  }
  buf[k] = '\0';
}

/* "about 4 min left" for s seconds into buf. */
static void time_left(char *buf, size_t n, double s) {
  if (s < 59.5)
    snprintf(buf, n, "about %.0f s left", s < 1.0 ? 1.0 : s);
  else if (s < 59.5 * 60.0)
    snprintf(buf, n, "about %.0f min left", s / 60.0);
  else if (s < 48.0 * 3600.0)
    snprintf(buf, n, "about %.1f h left", s / 3600.0);
  else
    snprintf(buf, n, "about %.1f days left", s / 86400.0);
}

size_t fp3_progress_format(char *buf, size_t n, const char *label, uint64_t done,
                           uint64_t total, const char *unit, double elapsed) {
  char d[32], t[32], r[32], left[40];
  size_t len = 0;
  if (n == 0) return 0;
  buf[0] = '\0';
#define ADD(...)                                                  \
  do {                                                            \
    if (len < n) {                                                \
      int k_ = snprintf(buf + len, n - len, __VA_ARGS__);         \
      if (k_ > 0) len += (size_t)k_;                              \
    }                                                             \
  } while (0)
  grouped(d, sizeof d, done);
  if (total) {
    grouped(t, sizeof t, total);
    /* rounded down: 100.0 % only when everything is done */
    ADD("%s: %s of %s %s (%.1f %%)", label, d, t, unit,
        floor(1000.0 * (double)done / (double)total) / 10.0);
  } else {
    ADD("%s: %s %s", label, d, unit);
  }
  const double rate = elapsed > 0.0 ? (double)done / elapsed : 0.0;
  if (rate > 0.0) {
    if (rate >= 100.0)
      grouped(r, sizeof r, (uint64_t)(rate + 0.5));
    else
      snprintf(r, sizeof r, "%.3g", rate);
    ADD(", %s/s", r);
    if (total > done) {
      time_left(left, sizeof left, (double)(total - done) / rate);
      ADD(", %s", left);
    }
  }
#undef ADD
  return len < n ? len : n - 1;
}

/* The line, padded with spaces over what is left of the last one. */
static void draw(fp3_progress *p, uint64_t done, double now) {
  char line[256];
  size_t len = fp3_progress_format(line, sizeof line, p->label, done, p->total, p->unit,
                                   now - p->t0);
  if (p->width && len > p->width) len = p->width;
  fprintf(p->out, "\r%.*s", (int)len, line);
  for (size_t i = len; i < p->shown; i++) fputc(' ', p->out);
  fputc('\r', p->out);
  fflush(p->out);
  p->shown = len;
  p->last_show = now;
}

void fp3_progress_tick(fp3_progress *p, uint64_t done) {
  if (!p->out) return;
  const double now = p->clock(p->clock_ctx);
  const double since = now - p->last_check;
  p->calls = 0;
  p->last_check = now;
  if (since < FP3_PROGRESS_CHECK_MIN && p->stride < FP3_PROGRESS_MAX_STRIDE)
    p->stride *= 2;
  else if (since > FP3_PROGRESS_CHECK_MAX && p->stride > 1)
    p->stride /= 2;
  if (now - p->t0 >= FP3_PROGRESS_DELAY &&
      (p->shown == 0 || now - p->last_show >= FP3_PROGRESS_PERIOD))
    draw(p, done, now);
}

void fp3_progress_finish(fp3_progress *p) {
  if (p->out && p->shown) {
    fputc('\r', p->out);
    for (size_t i = 0; i < p->shown; i++) fputc(' ', p->out);
    fputc('\r', p->out);
    fflush(p->out);
  }
  p->shown = 0;
  p->out = NULL;
}
