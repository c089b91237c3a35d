/*
 * fuzz_options.c -- libFuzzer harness for the command line: the parse step
 * of every fp3 subcommand (cliopt.h: argv -> the subcommand's options,
 * checked, no file opened), i.e. fp3_parse_asm, fp3_parse_disasm,
 * fp3_parse_compile, fp3_parse_spatial, fp3_parse_configure, fp3_parse_bench (fp3_parse_model
 * and bench's own options), fp3_parse_tbgen, fp3_parse_testfloat and, for
 * run, frames and the model form of compile, fp3_parse_model, with the
 * option-value parsers of sw/cli/cliopt.c they share.  The run steps
 * (files, engines) are never called.
 *
 * The input is an argument vector, one argument per line.  The first line
 * names the subcommand (argv[0]), as on the fp3 command line; another
 * first line picks a parser by its first byte.  When run or bench
 * accepts, its --set values are resolved against a
 * fixed model (a damped spring, parsed once: fp3_model_args_values), as
 * the run step does first.
 *
 * What an accepted vector must give, checked here (abort() otherwise):
 * every string option points into argv (each is read, so ASan sees a
 * stray pointer), and the options the run step relies on hold: the
 * required file names are there, counts are in range, combinations the
 * parse step refuses (--trace with several objects or the ISS, a scene
 * without --seed's objects) never come out.
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cliopt.h"
#include "cmd_asm.h"
#include "cmd_bench.h"
#include "cmd_compile.h"
#include "cmd_configure.h"
#include "cmd_disasm.h"
#include "cmd_model.h"
#include "cmd_run.h"
#include "cmd_spatial.h"
#include "cmd_tbgen.h"
#include "cmd_testfloat.h"
#include "engine.h"
#include "fuzz_common.h"
#include "model.h"

#define MAX_ARGS 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int argc_;
static char **argv_;

/* A property of accepted options failed: name it and stop. */
static void fail(const char *cmd, const char *what) {
  fprintf(stderr, "fuzz_options: fp3 %s: accepted options with %s\n", cmd, what);
  abort();
}

/* s, an option's string, is NULL or one of argv's strings or a suffix of
 * one (--name=VALUE) or a string literal default; read it whole. */
static void check_str(const char *cmd, const char *s, int may_be_default) {
  if (!s) return;
  volatile size_t n = strlen(s);
  (void)n;
  for (int i = 0; i < argc_; i++) {
    size_t len = strlen(argv_[i]);
    if (s >= argv_[i] && s <= argv_[i] + len) return;
  }
  if (!may_be_default) fail(cmd, "a string that is not an argument");
}

static const fp3_model *spring(void) {
  static fp3_model model;
  static int ready;
  if (!ready) {
    static const char text[] = "model spring\n"
                               "param k, c\n"
                               "position x\n"
                               "velocity v\n"
                               "x' = v\n"
                               "v' = -k*x - c*v\n";
    char msg[256];
    if (fp3_model_parse(text, "spring.fp3m", &model, msg, sizeof msg) != 0) {
      fprintf(stderr, "fuzz_options: %s\n", msg);
      abort();
    }
    ready = 1;
  }
  return &model;
}

static void parse_model(const char *cmd, int argc, char **argv) {
  fp3_model_args a;
  if (fp3_parse_model(argc, argv, cmd, &a) != FP3_ARGS_RUN) return;
  if (!a.scene && !a.file && strcmp(cmd, "run") != 0 && !a.harbour && !a.objects)
    fail(cmd, "neither --model, a scene, --objects nor a harbour");
  if (a.trace.path && (a.objects || a.scene || strcmp(a.engine, "rtl") != 0))
    fail(cmd, "--trace with several objects or the ISS");
  if (a.trace.win_count < 1) fail(cmd, "an empty trace window");
  check_str(cmd, a.program, 0);
  check_str(cmd, a.trace.path, 0);
  if (a.nset < 0 || a.nset > (int)(sizeof a.set / sizeof a.set[0])) fail(cmd, "a --set count");
  if (a.steps < 1 || a.points < 1 || a.points > 24) fail(cmd, "a count out of range");
  /* a board (uart:...) only where the state is compared after a run, the
   * spatial engine only where a model's objects run */
  const int board = (strcmp(cmd, "run") == 0 || strcmp(cmd, "frames") == 0) &&
                    fp3_engine_is_uart(a.engine);
  const int spatial = (strcmp(cmd, "run") == 0 || strcmp(cmd, "frames") == 0) &&
                      strcmp(a.engine, "spatial") == 0;
  if (strcmp(a.engine, "rtl") != 0 && strcmp(a.engine, "iss") != 0 && !board && !spatial)
    fail(cmd, "an engine");
  check_str(cmd, a.engine, 1);
  check_str(cmd, a.file, 0);
  check_str(cmd, a.scene, 0);
  check_str(cmd, a.integ, 1);
  check_str(cmd, a.out, 0);
  check_str(cmd, a.stab, 0);
  check_str(cmd, a.long_out, 0);
  for (int i = 0; i < a.nset; i++) check_str(cmd, a.set[i], 0);
  if (!a.scene && (strcmp(cmd, "run") == 0 || strcmp(cmd, "bench") == 0)) {
    float in[FP3_MODEL_MAX_VARS] = {0}, y0[FP3_MODEL_MAX_VARS] = {0};
    if (fp3_model_args_values(spring(), &a, in, y0) == 0 && !(in[0] > 0.0f))
      fail(cmd, "a step h <= 0");
  }
}


static void parse_bench(int argc, char **argv) {
  static fp3_bench_args b;
  if (fp3_parse_bench(argc, argv, &b) != FP3_ARGS_RUN) return;
  if (!b.a.file || (b.only && !b.dir) || (b.dir && (b.a.out || b.a.stab || b.a.long_out)))
    fail("bench", "no model, --only without --out, or --out with a part's file");
  if (b.hmax < 0.0 || b.a.points < 1 || b.a.points > 24 || b.a.long_steps < 2)
    fail("bench", "a value out of range");
  check_str("bench", b.dir, 0);
  check_str("bench", b.only, 0);
  check_str("bench", b.a.integ, 1);
  check_str("bench", b.a.out, 0);
  check_str("bench", b.a.stab, 0);
  check_str("bench", b.a.long_out, 0);
  for (int i = 0; i < b.a.nset; i++) check_str("bench", b.a.set[i], 0);
  float in[FP3_MODEL_MAX_VARS] = {0}, y0[FP3_MODEL_MAX_VARS] = {0};
  if (fp3_model_args_values(spring(), &b.a, in, y0) == 0 && !(in[0] > 0.0f))
    fail("bench", "a step h <= 0");
}

static void parse_tbgen(int argc, char **argv) {
  fp3_tbgen_args a;
  if (fp3_parse_tbgen(argc, argv, &a) != FP3_ARGS_RUN) return;
  if (!a.in || !a.dir) fail("tbgen", "no program or no folder");
  if (a.steps < 1 || a.steps > TBGEN_MAX_CHECK) fail("tbgen", "--steps out of range");
  for (int i = 0; i < a.model.nset; i++) check_str("tbgen", a.model.set[i], 0);
  check_str("tbgen", a.in, 0);
  check_str("tbgen", a.dir, 0);
}

static void parse_asm(int argc, char **argv) {
  fp3_asm_args a;
  if (fp3_parse_asm(argc, argv, &a) != FP3_ARGS_RUN) return;
  if (!a.in) fail("asm", "no input");
  check_str("asm", a.in, 0);
  check_str("asm", a.out, 0);
}

static void parse_disasm(int argc, char **argv) {
  fp3_disasm_args a;
  if (fp3_parse_disasm(argc, argv, &a) != FP3_ARGS_RUN) return;
  if (!a.in) fail("disasm", "no input");
  check_str("disasm", a.in, 0);
}

static void parse_testfloat(int argc, char **argv) {
  fp3_testfloat_args a;
  if (fp3_parse_testfloat(argc, argv, &a) != FP3_ARGS_RUN) return;
  if (!a.path) fail("testfloat", "no vector file");
  if ((unsigned)a.op > TESTFLOAT_SQRT) fail("testfloat", "an operation out of range");
  check_str("testfloat", a.path, 0);
}

static void parse_compile(int argc, char **argv) {
  fp3_compile_args a;
  if (fp3_parse_compile(argc, argv, &a) != FP3_ARGS_RUN) return;
  if (!a.scene == !a.model || (a.json && !a.out))
    fail("compile", "not one of a scene and --model, or --json without -o");
  check_str("compile", a.model, 0);
  if (a.opts.add_latency < 1 || a.opts.add_latency > 64 || a.opts.mul_latency < 1 ||
      a.opts.mul_latency > 64)
    fail("compile", "a latency out of range");
  check_str("compile", a.scene, 0);
  check_str("compile", a.out, 0);
  check_str("compile", a.integ, 1);
}

static void parse_spatial(int argc, char **argv) {
  fp3_spatial_args a;
  if (fp3_parse_spatial(argc, argv, &a) != FP3_ARGS_RUN) return;
  if ((!a.model && !a.scene) || !a.dir) fail("spatial", "no model or scene, or no -o DIR");
  if (a.scene && a.vec_objects) fail("spatial", "--vectors with --scene");
  if (a.opts.add_latency < 1 || a.opts.add_latency > 64 || a.opts.mul_latency < 1 ||
      a.opts.mul_latency > 64 || a.opts.div_latency < 1 || a.opts.div_latency > 64 ||
      a.vec_steps < 1)
    fail("spatial", "a latency or --steps out of range");
  if (a.opts.mul_blocks != 3 && a.opts.mul_blocks != 4) fail("spatial", "--mult-blocks not 3 or 4");
  check_str("spatial", a.model, 0);
  check_str("spatial", a.scene, 0);
  check_str("spatial", a.dir, 0);
  check_str("spatial", a.integ, 1);
}

static void parse_configure(int argc, char **argv) {
  fp3_configure_args a;
  if (fp3_parse_configure(argc, argv, &a) != FP3_ARGS_RUN) return;
  if (!a.scene || !(a.opts.budget > 0.0) || a.opts.steps < 1 || a.opts.max_lanes < 1)
    fail("configure", "no scene or a value out of range");
  check_str("configure", a.scene, 0);
  check_str("configure", a.out, 0);
  check_str("configure", a.opts.integrator, 1);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static const char *const cmds[] = {"asm",    "disasm", "run",   "compile",
                                     "configure", "frames", "bench", "tbgen",
                                     "testfloat", "spatial"};
  const size_t ncmds = sizeof cmds / sizeof cmds[0];
  char *text = fuzz_strdup(data, size);
  char *argv[MAX_ARGS + 1];
  int argc = 0;
  for (char *p = text; argc < MAX_ARGS;) {
    argv[argc++] = p;
    char *nl = strchr(p, '\n');
    if (!nl) break;
    *nl = '\0';
    p = nl + 1;
  }
  argv[argc] = NULL;
  argc_ = argc;
  argv_ = argv;

  /* argv[0]: "CMD" or "CMD model"; another word picks by its first byte */
  char *first = argv[0];
  int model = 0;
  char *sp = strchr(first, ' ');
  if (sp && strcmp(sp, " model") == 0) {
    *sp = '\0';
    model = 1;
  }
  size_t c = ncmds;
  for (size_t k = 0; k < ncmds; k++)
    if (strcmp(first, cmds[k]) == 0) c = k;
  if (c == ncmds) c = (unsigned char)first[0] % ncmds;
  const char *cmd = cmds[c];
  (void)model; /* "bench model": bench has one form */
  if (strcmp(cmd, "run") == 0 || strcmp(cmd, "frames") == 0) parse_model(cmd, argc, argv);
  else if (strcmp(cmd, "asm") == 0) parse_asm(argc, argv);
  else if (strcmp(cmd, "disasm") == 0) parse_disasm(argc, argv);
  else if (strcmp(cmd, "compile") == 0) parse_compile(argc, argv);
  else if (strcmp(cmd, "configure") == 0) parse_configure(argc, argv);
  else if (strcmp(cmd, "spatial") == 0) parse_spatial(argc, argv);
  else if (strcmp(cmd, "bench") == 0) parse_bench(argc, argv);
  else if (strcmp(cmd, "testfloat") == 0) parse_testfloat(argc, argv);
  else parse_tbgen(argc, argv);
  free(text);
  return 0;
}
