/*
 * fuzz_options.c -- libFuzzer harness for the command-line option parsers:
 * sw/cli/cliopt.c (fp3_opt_value, fp3_opt_positional, fp3_parse_count,
 * fp3_is_help) as the model subcommands use it, i.e. the whole argument
 * parsing of `fp3 run --model` and `fp3 compile --model` (parse_args and
 * apply_set of sw/cli/cmd_model.c) without compiling or running anything;
 * and the option-value parsers the other subcommands share or keep:
 * cliopt.c's counts, --seed, --round and A:B pairs (fp3_opt_count,
 * fp3_opt_seed, fp3_opt_round, fp3_parse_pair), `fp3 bench`'s positive
 * numbers (parse_pos of sw/cli/cmd_bench.c) and `fp3 tbgen --set
 * NAME=VALUE` (set_scene of sw/cli/cmd_tbgen.c).
 *
 * The input is an argument vector, one argument per line.  The first line
 * picks what is parsed: "bench" and "tbgen" give each further line to
 * that subcommand's value parser, "counts" the vector to the shared
 * count, seed, rounding and pair parsers; "compile" runs parse_args as
 * `fp3 compile --model`, anything else as `fp3 run --model`.  When
 * parse_args accepts them, each --set NAME=VALUE is applied to a fixed
 * model (a damped spring, parsed once), as the subcommand does before it
 * compiles.
 *
 * The subcommands' sources are included, not linked, to reach their
 * static functions; the functions of them that run an engine are never called (the fuzz build
 * links with --gc-sections, which drops them and what only they need).
 * The subcommands' loops over argv (fp3_cmd_bench, fp3_cmd_tbgen, ...) go
 * on to run engines and write files, so they are not fuzzed here.
 */
#include "cmd_model.c"
#include "cmd_bench.c"
#include "cmd_tbgen.c"

#include "fuzz_common.h"

#define MAX_ARGS 64

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static fp3_model model;
  static int ready;
  if (!ready) {
    static const char spring[] = "model spring\n"
                                 "param k, c\n"
                                 "position x\n"
                                 "velocity v\n"
                                 "x' = v\n"
                                 "v' = -k*x - c*v\n";
    char msg[256];
    if (fp3_model_parse(spring, "spring.fp3m", &model, msg, sizeof msg) != 0) {
      fprintf(stderr, "fuzz_options: %s\n", msg);
      abort();
    }
    ready = 1;
  }
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
  if (strcmp(argv[0], "bench") == 0 || strcmp(argv[0], "tbgen") == 0 ||
      strcmp(argv[0], "counts") == 0) {
    fp3_ship_params p;
    memset(&p, 0, sizeof p);
    for (int i = 1; i < argc; i++) {
      double x;
      unsigned long long n, a, b;
      uint64_t seed;
      fpref_mode mode;
      memset(&mode, 0, sizeof mode);
      if (argv[0][0] == 'b') {
        (void)parse_pos("--from", argv[i], &x);
      } else if (argv[0][0] == 't') {
        (void)set_scene(&p, argv[i]);
      } else {
        /* the shared shapes: a count, --seed, --round, a pair A:B */
        int j = i;
        if (fp3_opt_count(argc, argv, &j, "counts", "--steps", 1, 1000000, "steps", &n) != 0 ||
            fp3_opt_seed(argc, argv, &j, "counts", &seed) != 0 ||
            fp3_opt_round(argc, argv, &j, "counts", &mode) != 0)
          i = j;
        (void)fp3_parse_pair(argv[i], 0, 64, 1, 1000, "all", &a, &b);
      }
    }
    free(text);
    return 0;
  }
  const char *cmd = strcmp(argv[0], "compile") == 0 ? "compile" : "run";
  fp3_args_have_model(argc, argv);
  margs a;
  if (parse_args(argc, argv, cmd, &a) == 0 && strcmp(cmd, "run") == 0) {
    float in[FP3_MODEL_MAX_VARS] = {0}, y0[FP3_MODEL_MAX_VARS] = {0};
    unsigned char given[2 * FP3_MODEL_MAX_VARS] = {0};
    for (int i = 0; i < a.nset; i++)
      if (apply_set(&model, a.set[i], in, y0, given) != 0) break;
  }
  free(text);
  return 0;
}
