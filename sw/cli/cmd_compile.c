/*
 * cmd_compile.c -- `fp3 compile`: a model or a scene compiled into a
 * program (cmd_compile.h, compile.h).
 */
#include "cmd_compile.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cliopt.h"
#include "compile.h"
#include "model.h"
#include "mscene.h"
#include "cmd_model.h"
#include "runsetup.h"
#include "report.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2

static void usage(FILE *f) {
  fprintf(f,
          "usage: fp3 compile (SCENE | --model FILE.fp3m) [--integrator NAME] [-o PROGRAM.s]\n"
          "                   [--literal | --no-fold] [--keep-zero]\n"
          "                   [--add-latency N] [--mul-latency N] [--fmax-pipe]\n"
          "                   [--json]\n"
          "\n"
          "Compile a model for an integrator into an FP3 program: --model FILE, or a\n"
          "scene of it (docs/models.md); the integrators: %s.\n"
          "A model scene names its model ('model FILE' first); a ship scene ('h STEP',\n"
          "then 'T C m v0 s0' per object, see fp3 run --help) is a scene of\n"
          "models/ship.fp3m, whose integrator is rk4se (the paper's RK4) by default.\n"
          "The compiler folds what it can on the host (a division by a parameter-only\n"
          "value becomes a product with its reciprocal; a derivative affine in the\n"
          "state, h f = (h c0) + sum (h c_s) y_s, the ship's hmT - hmC v), removes\n"
          "the terms of params zero in every object of the scene, moves loop\n"
          "invariants to the prologue, removes dead operations, list-schedules the\n"
          "loop body for the latencies and allocates registers.\n"
          "fp3 run --scene runs the compiled program by default and checks every\n"
          "object after every integration against the IR's golden model.\n"
          "\n"
          "  --model FILE     the model (instead of a scene)\n"
          "  --integrator I   default rk4 (a ship scene: rk4se)\n"
          "  -o FILE          write the assembly to FILE (atomically: on any error\n"
          "                   no file is left); default: standard output\n"
          "  --no-fold        no folded inputs: the integrator's literal operations\n"
          "  --keep-zero      keep terms that are zero in the whole scene\n"
          "  --literal        both: the integrator's operations as docs/models.md\n"
          "                   writes them (the ship's rk4se: those of programs/ship_rk4.s)\n"
          "  --add-latency N, --mul-latency N   core latencies (ADD_LATENCY, MUL_LATENCY) to schedule for\n"
          "                   (default %u and %u, sw/isa/fp3_isa.h)\n"
          "  --fmax-pipe      schedule and estimate for the build for clock rate\n"
          "                   (FMAX_PIPE=1: a latency counts as at least %d, a context\n"
          "                   fetches at most every %d cycles and issues at most every\n"
          "                   %d; add and mul latencies of at least %d)\n"
          "  --json           the report as one JSON object on standard output\n"
          "                   (with -o only)\n"
          "\n"
          "The report (standard error, or --json): instructions per integration\n"
          "of the literal program and of the compiled one, and the scheduler's\n"
          "estimate of cycles per integration of one object (one context; exact\n"
          "for the RTL of these latencies and pipeline).\n"
          "Exit status: 0 written; 2 bad arguments, scene or integrator; 1 the\n"
          "output could not be written.\n",
          fp3_model_integrators(), (unsigned)FP3_DEFAULT_ADD_LATENCY,
          (unsigned)FP3_DEFAULT_MUL_LATENCY, FP3_FMAX_PIPE_FULL_LEAD_LATENCY,
          FP3_FMAX_PIPE_FETCH_SPACING, FP3_FMAX_PIPE_ISSUE_SPACING,
          FP3_FMAX_PIPE_PICK_STAGES + 1);
}

int fp3_parse_compile(int argc, char **argv, fp3_compile_args *a) {
  a->scene = a->out = a->model = NULL;
  a->integ = "rk4";
  a->json = 0;
  int given = 0; /* --integrator */
  fp3_compile_defaults(&a->opts);
  fp3_compile_opts *o = &a->opts;
  for (int i = 1; i < argc; i++) {
    const char *v;
    unsigned long long k;
    int r;
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    if ((r = fp3_opt_output(argc, argv, &i, "compile", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->out = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, "compile", "--model", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->model = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, "compile", "--integrator", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->integ = v;
      given = 1;
    } else if ((r = fp3_opt_count(argc, argv, &i, "compile", "--add-latency", 1, 64, "cycles",
                                  &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->add_latency = (unsigned)k;
    } else if ((r = fp3_opt_count(argc, argv, &i, "compile", "--mul-latency", 1, 64, "cycles",
                                  &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->mul_latency = (unsigned)k;
    } else if (strcmp(argv[i], "--fmax-pipe") == 0) {
      o->fmax_pipe = 1;
    } else if (strcmp(argv[i], "--literal") == 0) {
      o->fold = o->drop_zero = 0;
    } else if (strcmp(argv[i], "--no-fold") == 0) {
      o->fold = 0;
    } else if (strcmp(argv[i], "--keep-zero") == 0) {
      o->drop_zero = 0;
    } else if (strcmp(argv[i], "--json") == 0) {
      a->json = 1;
    } else if (fp3_opt_positional("compile", "scene", argv[i], &a->scene)) {
      return FP3_ARGS_BAD;
    }
  }
  if (!a->scene == !a->model) {
    fprintf(stderr, "fp3 compile: %s (see fp3 compile --help)\n",
            a->model ? "--model FILE or a scene, not both" : "no scene file or --model FILE");
    return FP3_ARGS_BAD;
  }
  if (a->json && !a->out) {
    fprintf(stderr, "fp3 compile: --json needs -o FILE (the program and the report would "
                    "share standard output)\n");
    return FP3_ARGS_BAD;
  }
  if (fp3_ship_scene_integrator(a->scene, given, &a->integ, "compile")) return FP3_ARGS_BAD;
  return FP3_ARGS_RUN;
}

/* The model of a (--model, or a model scene's, whose params zero in every
 * object go into zero[]) compiled for a's integrator and options, for as
 * many registers as it needs.  0 and *c, or the exit status; *mp the model
 * (the caller frees it after c). */
static int compile_model(const fp3_compile_args *a, unsigned char *zero, size_t *objects,
                         fp3_model **mp, fp3_compiled **c) {
  char msg[512];
  fp3_model *m = NULL;
  if (a->scene) {
    if (!(m = fp3_scene_model(a->scene, NULL, zero, objects, msg, sizeof msg))) {
      fprintf(stderr, "fp3 compile: %s\n", msg);
      return EXIT_USAGE;
    }
  } else {
    if (!(m = malloc(sizeof *m))) return EXIT_FAIL;
    if (fp3_model_load(a->model, m, msg, sizeof msg)) {
      fprintf(stderr, "fp3 compile: %s\n", msg);
      free(m);
      return EXIT_USAGE;
    }
  }
  fp3_compile_opts o = a->opts;
  o.max_regs = FP3_MAX_REGS; /* compiled for the fewest registers that hold it */
  int rc = 0;
  if (!fp3_model_integrator_known(a->integ)) {
    fprintf(stderr, "fp3 compile: unknown integrator '%s' for a model (%s)\n", a->integ,
            fp3_model_integrators());
    rc = EXIT_USAGE;
  } else if (fp3_compile_model(m, a->integ, &o, zero, c, msg, sizeof msg)) {
    fprintf(stderr, "fp3 compile: %s: %s\n", m->file, msg);
    rc = EXIT_USAGE;
  }
  *mp = m; /* the program reads it: freed after */
  return rc;
}

/* The run step: read, compile, write, report. */
static int run_compile(const fp3_compile_args *a) {
  const char *scene = a->scene, *outp = a->out, *integ = a->integ;
  const int json = a->json;
  const fp3_compile_opts o = a->opts;
  char msg[512];
  fp3_compiled *c = NULL;
  fp3_model *m = NULL;
  unsigned char zero[FP3_MODEL_MAX_VARS] = {0};
  size_t objects = 0;
  int rc = compile_model(a, zero, &objects, &m, &c);
  if (rc) {
    free(m);
    return rc;
  }
  if (outp) {
    if (fp3_compiled_write(c, outp, msg, sizeof msg)) {
      fprintf(stderr, "fp3 compile: %s\n", msg);
      rc = EXIT_FAIL;
    }
  } else {
    fputs(fp3_compiled_text(c), stdout);
  }
  const fp3_compile_stats *st = fp3_compiled_stats(c);
  fp3_strbuf zeros = {0}; /* the params whose terms went */
  const unsigned zl = o.drop_zero ? fp3_zero_params_list(m, zero, &zeros) : 0;
  if (rc == 0 && json) {
    printf("{\"scene\": ");
    if (scene) fp3_json_string(stdout, scene);
    else printf("null");
    printf(", \"model_file\": ");
    fp3_json_string(stdout, m->file);
    printf(", \"objects\": %zu, \"integrator\": ", objects);
    fp3_json_string(stdout, integ);
    printf(", \"fold\": %s, \"drop_zero\": %s, \"params_zero\": [", o.fold ? "true" : "false",
           o.drop_zero ? "true" : "false");
    for (unsigned k = 1, first = 1; k < m->nparam; k++)
      if (zero[k] && o.drop_zero) {
        printf("%s", first ? "" : ", ");
        fp3_json_string(stdout, m->param[k]);
        first = 0;
      }
    printf("], \"insns_per_step\": %u, \"arith_per_step\": %u, \"literal_insns_per_step\": %u",
           st->body_insns, st->body_arith, st->literal_body_insns);
    printf(", \"prologue_insns\": %u, \"hoisted\": %u, \"dead_removed\": %u, \"registers\": %u"
           ", \"registers_needed\": %u, \"num_regs\": %u", st->prologue_insns, st->hoisted,
           st->dead_removed, st->regs, st->regs_needed, st->num_regs);
    printf(", \"add_latency\": %u, \"mul_latency\": %u, \"fmax_pipe\": %s", o.add_latency,
           o.mul_latency, o.fmax_pipe ? "true" : "false");
    printf(", \"est_cycles_first_step\": %u, \"est_cycles_per_step\": %u}\n",
           st->est_cycles_first, st->est_cycles_later);
  } else if (rc == 0) {
    char what[600];
    if (scene) snprintf(what, sizeof what, "%s (%zu objects)", scene, objects);
    else snprintf(what, sizeof what, "%s", m->file);
    fprintf(stderr, "fp3 compile: %s, %s %s: %u instructions per integration (literal program "
            "%u), prologue %u, %u registers needed (NUM_REGS %u); estimated %u cycles per later "
            "integration of one object (first %u)%s%s%s\n", what, integ,
            o.fold ? "folded" : "literal", st->body_insns, st->literal_body_insns,
            st->prologue_insns, st->regs_needed, st->num_regs, st->est_cycles_later,
            st->est_cycles_first, o.fmax_pipe ? " for FMAX_PIPE=1" : "",
            zl ? "; removed, zero in every object: " : "", zl && zeros.s ? zeros.s : "");
  }
  free(zeros.s);
  fp3_compiled_free(c);
  free(m);
  return rc;
}

int fp3_cmd_compile(int argc, char **argv) {
  fp3_compile_args a;
  int r = fp3_parse_compile(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_compile(&a) : fp3_args_exit(r, usage);
}
