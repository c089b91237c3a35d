/*
 * progress.h -- a progress line for long runs, on a terminal only.
 *
 * A run that may last long (`fp3 run --steps 4294967295`) says how far it
 * is on one line of stderr, rewritten in place with '\r':
 *
 *   fp3 run: 123,456 of 10,000,000 integrations (1.2 %), 40,000/s, about 4 min left
 *
 * It is shown only when the caller asks for it (the CLI does unless
 * --json) and stderr is a terminal (isatty): output to a file or a pipe
 * gets no progress line, and a log stays as it was.  Nothing appears
 * before the run has lasted FP3_PROGRESS_DELAY seconds, so short runs
 * print nothing, and the line is rewritten at most every
 * FP3_PROGRESS_PERIOD seconds.  The rate is the average since the start,
 * the time left what is left at that rate.
 *
 * fp3_progress_update() is cheap enough to call for every integration: it
 * counts calls and reads the clock only every `stride` calls, a stride
 * that doubles while the clock is read more often than every
 * FP3_PROGRESS_CHECK_MIN seconds and halves when it is read less often
 * than every FP3_PROGRESS_CHECK_MAX.  fp3_progress_finish() erases the
 * line ('\r', spaces, '\r'), so what is printed next starts on a clean
 * line.
 *
 * Use: fp3_progress_start(), fp3_progress_update() as work gets done,
 * fp3_progress_finish() once (also after an error).  One fp3_progress per
 * run; nothing is allocated.
 */
#ifndef FP3_PROGRESS_H
#define FP3_PROGRESS_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define FP3_PROGRESS_DELAY 2.0       /* s of run before the line appears  */
#define FP3_PROGRESS_PERIOD 0.25     /* s between two rewrites, at least  */
#define FP3_PROGRESS_CHECK_MIN 0.01  /* s: clock reads closer: stride x 2 */
#define FP3_PROGRESS_CHECK_MAX 0.05  /* s: clock reads further: stride / 2 */
#define FP3_PROGRESS_MAX_STRIDE (1u << 24)

/* A clock in seconds, monotonic (any origin). */
typedef double (*fp3_progress_clock)(void *ctx);

/* One progress line.  The fields are the module's; read none of them but
 * `out` (NULL: the line is off and every call returns at once). */
typedef struct fp3_progress {
  FILE *out;                 /* where the line goes; NULL: off            */
  const char *label, *unit;  /* "fp3 run", "integrations"                 */
  uint64_t total;            /* units of the whole run (0: unknown)       */
  size_t width;              /* the line is cut to this many characters
                                (0: not cut)                              */
  fp3_progress_clock clock;
  void *clock_ctx;
  double t0, last_check, last_show;
  uint32_t calls, stride;
  size_t shown;              /* characters on the screen, 0: none          */
} fp3_progress;

/* Start a run of `total` units named `unit` (plural, "integrations"),
 * the line prefixed with `label` ("fp3 run"), on stderr, cut to the
 * terminal's width.  The line is off unless `show` is set, label is not
 * NULL and stderr is a terminal.  label and unit must outlive the run. */
void fp3_progress_start(fp3_progress *p, const char *label, uint64_t total, const char *unit,
                        int show);

/* The same on any stream `out` (NULL: off), whether a terminal or not,
 * with clock `clock(clock_ctx)` (NULL: CLOCK_MONOTONIC) and lines cut to
 * `width` characters (0: not cut): what tests use. */
void fp3_progress_start_on(fp3_progress *p, FILE *out, const char *label, uint64_t total,
                           const char *unit, size_t width, fp3_progress_clock clock,
                           void *clock_ctx);

/* The clock read and the line rewritten if it is time (the slow part of
 * fp3_progress_update; call that instead). */
void fp3_progress_tick(fp3_progress *p, uint64_t done);

/* `done` units of the total are done (never fewer than at the last call). */
static inline void fp3_progress_update(fp3_progress *p, uint64_t done) {
  if (p->out && ++p->calls >= p->stride) fp3_progress_tick(p, done);
}

/* End of the run: the line, if one was shown, is erased. */
void fp3_progress_finish(fp3_progress *p);

/* The text of the line (no '\r') into buf (n bytes, always terminated):
 * `done` of `total` units after `elapsed` seconds.  Counts grouped by
 * thousands; the percentage, rate and time left only when they are
 * known.  Returns the length of the text. */
size_t fp3_progress_format(char *buf, size_t n, const char *label, uint64_t done,
                           uint64_t total, const char *unit, double elapsed);

#endif /* FP3_PROGRESS_H */
