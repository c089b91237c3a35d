/*
 * traceopt.h -- the waveform options of `fp3 run` and `fp3 run --model`:
 * --trace FILE.vcd, --trace-window FIRST:COUNT and --trace-limit SIZE,
 * their checks, the size of the waveform estimated before the run against
 * the limit, the engine's window, and the note after the run.
 *
 * A command calls, in this order: fp3_trace_opts_init and fp3_trace_opt
 * (parse step), fp3_trace_check (the combination of options, parse step),
 * fp3_trace_writable (before the RTL engine is created with t->path),
 * fp3_trace_prepare (once the engine and the run's length are known, before
 * the run), fp3_trace_note (after the run).  The engine writes the file
 * under a temporary name and renames it when it is freed after a run that
 * completed (engine.h fp3_engine_rtl_new).
 */
#ifndef FP3_TRACEOPT_H
#define FP3_TRACEOPT_H

#include <stdint.h>

#include "engine.h"

#define FP3_TRACE_WINDOW_DEFAULT 10000u          /* cycles --trace writes      */
#define FP3_TRACE_LIMIT_DEFAULT (1ull << 30)     /* bytes: --trace-limit 1G    */
#define FP3_TRACE_WARN_BYTES (100ull << 20)      /* bytes: a warning above     */

typedef struct fp3_trace_opts {
  const char *path;   /* --trace FILE.vcd, or NULL: no waveform                   */
  uint64_t win_first; /* --trace-window FIRST:COUNT [cycles of the run, cycle 0   */
  uint64_t win_count; /*   the first after START]; COUNT UINT64_MAX: to the end   */
  uint64_t limit;     /* --trace-limit [bytes]; UINT64_MAX: none                  */
} fp3_trace_opts;

/* No trace, window 0:FP3_TRACE_WINDOW_DEFAULT, limit FP3_TRACE_LIMIT_DEFAULT. */
void fp3_trace_opts_init(fp3_trace_opts *t);

/* One of --trace FILE, --trace-window FIRST:COUNT (COUNT >= 1 or `all`),
 * --trace-limit SIZE (fp3_trace_parse_size), each also as --opt=VALUE,
 * at argv[*i]: 1 (the value stored in *t, *i past it), 0 if argv[*i] is
 * another argument, -1 with a message on stderr naming command cmd
 * ("fp3 CMD: --trace-window '5': want FIRST:COUNT ..."). */
int fp3_trace_opt(int argc, char **argv, int *i, const char *cmd, fp3_trace_opts *t);

/* SIZE of --trace-limit: a decimal count of bytes, optionally followed by
 * K, M, G or T (KiB, MiB, GiB, TiB: powers of 1024, either case), or
 * `none` (no limit: UINT64_MAX).  0 and *bytes, or -1 for anything else,
 * 0 and a value that overflows 64 bits included. */
int fp3_trace_parse_size(const char *v, uint64_t *bytes);

/* The parse step's check of a trace: --trace needs engine "rtl" and one
 * object (many: the command runs several objects, a scene or --objects).
 * 0 (also without --trace), or -1 with a message on stderr ("fp3 CMD:
 * --trace needs --engine rtl", "fp3 CMD: --trace is for one object"). */
int fp3_trace_check(const fp3_trace_opts *t, const char *cmd, const char *engine, int many);

/* Whether t->path can be written: its folder writable (the temporary and
 * the rename are made there) and the file, if it exists, writable.
 * Nothing is created.  0 (also without --trace), or -1 with "fp3 CMD:
 * cannot write the trace file PATH (FOLDER-OR-PATH: reason)" on stderr. */
int fp3_trace_writable(const fp3_trace_opts *t, const char *cmd);

/* VCD bytes a clock cycle of the run adds to a trace of a build of
 * configuration c (all signals; measured, see traceopt.c). */
uint64_t fp3_trace_bytes_per_cycle(const fp3_config *c);

/* Cycles of a one-object run of `steps` integrations, the first taking
 * `first` cycles and each later one `later` (saturating at UINT64_MAX). */
uint64_t fp3_trace_run_cycles(uint32_t steps, uint64_t first, uint64_t later);

/* Before the run on engine e (created with t->path): estimate the
 * waveform, the cycles of the window that fall within run_cycles (the
 * run's estimated cycles; `basis` says in a few words where that estimate
 * comes from, for the messages) times fp3_trace_bytes_per_cycle of e's
 * build plus the header.  Above t->limit: -1 with a message on stderr
 * giving the estimate in MB or GB, the window and --trace-limit SIZE (the
 * command exits 2; freeing e removes the temporary).  Above
 * FP3_TRACE_WARN_BYTES and within the limit: a warning with the estimate
 * on stderr.  Then the window is set on e (fp3_engine_rtl_trace_window).
 * 0 (also without --trace) or -1. */
int fp3_trace_prepare(const fp3_trace_opts *t, const char *cmd, fp3_engine *e,
                      uint64_t run_cycles, const char *basis);

/* After a run of `cycles` cycles: "fp3 CMD: trace PATH: cycles A..B of
 * the run's N" (or that the window is empty) on stderr.  Nothing without
 * --trace. */
void fp3_trace_note(const fp3_trace_opts *t, const char *cmd, uint64_t cycles);

#endif /* FP3_TRACEOPT_H */
