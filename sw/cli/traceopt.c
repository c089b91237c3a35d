/*
 * traceopt.c -- the waveform options of `fp3 run` and `fp3 run --model`
 * (traceopt.h).
 */
#include "traceopt.h"

#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cliopt.h"

/* VCD bytes per cycle, every signal of the Verilated fp3_top, one object
 * running the ship program (programs/ship_rk4.s): the difference of the
 * files of two windows of the same run, 1 and 2,001 cycles, over 2,000
 * (the header, the reset and the reads before the run cancel out):
 *
 *   build/fp3 run --steps 100 --trace w.vcd --trace-window 0:1      434,005 bytes
 *   build/fp3 run --steps 100 --trace w.vcd --trace-window 0:2001   48,837,733 bytes
 *
 * gives 24,202 bytes a cycle for the default build (8 contexts, 1 lane;
 * 24,249 for the window 1000:2000 of the steady state).  The lanes build
 * l4 of mk/rtl.mk (the default with NUM_LANES=4), the same run and
 * windows through fp3_engine_rtl_new_model(&fp3_model_l4, "w.vcd") and
 * fp3_engine_rtl_trace_window, gives 1,240,977 and 85,105,401 bytes:
 * 41,932 a cycle (41,769 in the steady state), 5,910 more for each lane
 * past the first.  The estimate rounds both up and interpolates linearly
 * in the lanes; other parameters (contexts, latencies) change it less and
 * are not modelled.  The header, the reset and the reads before the run
 * are 18 cycles' worth on the default build, 30 on l4: TRACE_HEAD_CYCLES. */
#define TRACE_BPC_1 24300u  /* bytes a cycle, 1 lane  */
#define TRACE_BPC_L4 42000u /* bytes a cycle, 4 lanes */
#define TRACE_HEAD_CYCLES 32u

void fp3_trace_opts_init(fp3_trace_opts *t) {
  memset(t, 0, sizeof *t);
  t->win_count = FP3_TRACE_WINDOW_DEFAULT;
  t->limit = FP3_TRACE_LIMIT_DEFAULT;
}

int fp3_trace_parse_size(const char *v, uint64_t *bytes) {
  if (strcmp(v, "none") == 0) {
    *bytes = UINT64_MAX;
    return 0;
  }
  size_t n = strspn(v, "0123456789");
  if (n == 0 || n > 20) return -1;
  unsigned shift = 0;
  const char *s = v + n;
  if (*s) {
    switch (*s) {
      case 'k': case 'K': shift = 10; break;
      case 'm': case 'M': shift = 20; break;
      case 'g': case 'G': shift = 30; break;
      case 't': case 'T': shift = 40; break;
      default: return -1;
    }
    if (s[1]) return -1;
  }
  char digits[21];
  memcpy(digits, v, n);
  digits[n] = '\0';
  unsigned long long x;
  if (fp3_parse_count(digits, 1, UINT64_MAX, &x)) return -1;
  if (shift && x > (UINT64_MAX >> shift)) return -1;
  *bytes = (uint64_t)x << shift;
  return 0;
}

int fp3_trace_opt(int argc, char **argv, int *i, const char *cmd, fp3_trace_opts *t) {
  const char *v;
  int r;
  if ((r = fp3_opt_value(argc, argv, i, cmd, "--trace-window", &v)) != 0) {
    if (r < 0) return -1;
    unsigned long long first, count;
    if (fp3_parse_pair(v, 0, UINT64_MAX, 1, UINT64_MAX, "all", &first, &count)) {
      fprintf(stderr, "fp3 %s: --trace-window '%s': want FIRST:COUNT (cycles, "
                      "COUNT >= 1 or 'all')\n", cmd, v);
      return -1;
    }
    t->win_first = first;
    t->win_count = count;
    return 1;
  }
  if ((r = fp3_opt_value(argc, argv, i, cmd, "--trace-limit", &v)) != 0) {
    if (r < 0) return -1;
    if (fp3_trace_parse_size(v, &t->limit)) {
      fprintf(stderr, "fp3 %s: --trace-limit '%s': want a size in bytes, with K, M, G or T "
                      "for KiB, MiB, GiB, TiB (e.g. 500M, 4G), or 'none'\n", cmd, v);
      return -1;
    }
    return 1;
  }
  if ((r = fp3_opt_value(argc, argv, i, cmd, "--trace", &v)) != 0) {
    if (r < 0) return -1;
    t->path = v;
    return 1;
  }
  return 0;
}

int fp3_trace_check(const fp3_trace_opts *t, const char *cmd, const char *engine, int many) {
  if (!t->path) return 0;
  if (many) {
    fprintf(stderr, "fp3 %s: --trace is for one object\n", cmd);
    return -1;
  }
  if (strcmp(engine, "rtl") != 0) {
    fprintf(stderr, "fp3 %s: --trace needs --engine rtl\n", cmd);
    return -1;
  }
  return 0;
}

int fp3_trace_writable(const fp3_trace_opts *t, const char *cmd) {
  if (!t->path) return 0;
  const char *path = t->path;
  const char *slash = strrchr(path, '/');
  char dir[4096];
  if (!slash) {
    snprintf(dir, sizeof dir, ".");
  } else {
    size_t len = (size_t)(slash - path);
    if (len == 0) len = 1; /* "/x.vcd" */
    if (len >= sizeof dir) len = sizeof dir - 1;
    memcpy(dir, path, len);
    dir[len] = '\0';
  }
  const char *bad = NULL;
  if (access(dir, W_OK | X_OK) != 0) bad = dir;
  else if (access(path, F_OK) == 0 && access(path, W_OK) != 0) bad = path;
  if (bad) {
    fprintf(stderr, "fp3 %s: cannot write the trace file %s (%s: %s)\n", cmd, path, bad,
            strerror(errno));
    return -1;
  }
  return 0;
}

uint64_t fp3_trace_bytes_per_cycle(const fp3_config *c) {
  const uint64_t lanes = c->num_lanes ? c->num_lanes : 1;
  const uint64_t per_lane = (TRACE_BPC_L4 - TRACE_BPC_1 + 2) / 3;
  return TRACE_BPC_1 + (lanes - 1) * per_lane;
}

uint64_t fp3_trace_run_cycles(uint32_t steps, uint64_t first, uint64_t later) {
  if (steps == 0) return 0;
  const uint64_t more = steps - 1;
  if (later && more > (UINT64_MAX - first) / later) return UINT64_MAX;
  return first + more * later;
}

/* bytes as "12.3 MiB", "4.56 GiB" or "1362 GiB" (KiB below a MiB). */
static void size_text(uint64_t bytes, char *buf, size_t n) {
  const char *unit = "KiB";
  double x = (double)bytes / 1024.0;
  if (bytes >= (1ull << 30)) unit = "GiB", x = (double)bytes / (double)(1ull << 30);
  else if (bytes >= (1ull << 20)) unit = "MiB", x = (double)bytes / (double)(1ull << 20);
  snprintf(buf, n, x >= 100.0 ? "%.0f %s" : "%.3g %s", x, unit);
}

/* The window as the user gave it: "FIRST:COUNT" or "FIRST:all". */
static void window_text(const fp3_trace_opts *t, char *buf, size_t n) {
  if (t->win_count == UINT64_MAX)
    snprintf(buf, n, "%" PRIu64 ":all", t->win_first);
  else
    snprintf(buf, n, "%" PRIu64 ":%" PRIu64, t->win_first, t->win_count);
}

int fp3_trace_prepare(const fp3_trace_opts *t, const char *cmd, fp3_engine *e,
                      uint64_t run_cycles, const char *basis) {
  if (!t->path) return 0;
  uint64_t cycles = 0;
  if (t->win_first < run_cycles) {
    cycles = run_cycles - t->win_first;
    if (t->win_count < cycles) cycles = t->win_count;
  }
  const uint64_t bpc = fp3_trace_bytes_per_cycle(&e->config);
  const uint64_t all = cycles + TRACE_HEAD_CYCLES;
  const uint64_t bytes = all > UINT64_MAX / bpc ? UINT64_MAX : all * bpc;
  char est[32], lim[32], win[64];
  size_text(bytes, est, sizeof est);
  window_text(t, win, sizeof win);
  if (bytes > t->limit) {
    size_text(t->limit, lim, sizeof lim);
    const int giga = bytes >= (1ull << 30);
    fprintf(stderr,
            "fp3 %s: --trace %s: the waveform would be about %s (%" PRIu64 " cycles of window "
            "%s, of about %" PRIu64 " in the run, estimated %s; about %" PRIu64 " bytes a "
            "cycle), above the limit of %s: raise it with --trace-limit SIZE (e.g. "
            "--trace-limit %" PRIu64 "%s, or none) or narrow --trace-window FIRST:COUNT\n",
            cmd, t->path, est, cycles, win, run_cycles, basis, bpc, lim,
            (bytes >> (giga ? 30 : 20)) + 1, giga ? "G" : "M");
    return -1;
  }
  if (bytes > FP3_TRACE_WARN_BYTES)
    fprintf(stderr,
            "fp3 %s: warning: --trace %s: the waveform will be about %s (%" PRIu64
            " cycles of window %s, of about %" PRIu64 " in the run, estimated %s; about %" PRIu64
            " bytes a cycle)\n",
            cmd, t->path, est, cycles, win, run_cycles, basis, bpc);
  fp3_engine_rtl_trace_window(e, t->win_first, t->win_count);
  return 0;
}

void fp3_trace_note(const fp3_trace_opts *t, const char *cmd, uint64_t cycles) {
  if (!t->path) return;
  if (t->win_first >= cycles)
    fprintf(stderr, "fp3 %s: trace %s: empty, the run has %" PRIu64
            " cycles (--trace-window FIRST:COUNT)\n", cmd, t->path, cycles);
  else
    fprintf(stderr, "fp3 %s: trace %s: cycles %" PRIu64 "..%" PRIu64
            " of the run's %" PRIu64 " (--trace-window FIRST:COUNT for others)\n",
            cmd, t->path, t->win_first,
            (t->win_count > cycles - t->win_first ? cycles : t->win_first + t->win_count) - 1,
            cycles);
}
