/*
 * cmd_spatial.c -- `fp3 spatial`: a model compiled (compile.h) and its
 * integration step written as a pipelined Verilog module (spatial.h).
 */
#include "cmd_spatial.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cliopt.h"
#include "cmd_model.h"
#include "model.h"
#include "mscene.h"
#include "report.h"
#include "runsetup.h"
#include "spatial_top.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2

static void usage(FILE *f) {
  fp3_spatial_opts d;
  fp3_spatial_defaults(&d);
  fprintf(f,
          "usage: fp3 spatial MODEL.fp3m | --scene FILE -o DIR [--integrator I] [--literal]\n"
          "                   [--round rne|rtz] [--ftz]\n"
          "                   [--add-latency N] [--mul-latency N] [--div-latency N]\n"
          "                   [--mul-feed] [--mult-blocks 4|3] [--clock-cores]\n"
          "                   [--scaleb-latency N] [--no-scaleb] [--no-fit-check]\n"
          "                   [--vectors N [--steps K] [--seed S]]\n"
          "                   [--pipelines N [--objects M]]\n"
          "\n"
          "Write a model's integration step as one fully pipelined Verilog module,\n"
          "DIR/fp3_spatial_MODEL_INTEGRATOR.v, that takes one object per cycle and\n"
          "returns its new state LATENCY cycles later (docs/spatial.md).  Every\n"
          "operation of the compiled program (fp3 compile) gets its own core\n"
          "(rtl/fp_add.v, fp_mul or for a constant +-2^k fp_scaleb, fp_div, fp_sqrt,\n"
          "fp_sign), scheduled as soon as possible, and delay lines (flip-flops,\n"
          "LUT RAM or block RAM by length) balance every path, so the results equal\n"
          "the program's golden model bit for bit.  The report (latency, cores,\n"
          "delay lines, the area estimate and the pipelines that fit the LFE5U-85F)\n"
          "goes to standard error and DIR/report.txt.\n"
          "The integrators: %s.\n"
          "\n"
          "  -o DIR           the folder to write (made if missing, in a folder that\n"
          "                   exists); on any error no file is left\n"
          "  --scene FILE     a pipeline for this scene's objects: a param zero in\n"
          "                   every object drops its terms (as fp3 compile SCENE does;\n"
          "                   not with --literal).  The model is the scene's: a model\n"
          "                   scene names it; a ship scene is read as a scene of\n"
          "                   MODEL.fp3m if given, else of models/ship.fp3m\n"
          "  --integrator I   default rk4 (rk4se, the paper's RK4, for a ship scene)\n"
          "  --literal        the integrator's literal operations (docs/models.md);\n"
          "                   default: the compiler's folded program\n"
          "  --round rne|rtz  the cores' rounding (default rne)\n"
          "  --ftz            flush-to-zero cores\n"
          "  --add-latency N, --mul-latency N, --div-latency N   core latencies\n"
          "                   (default %u, %u, %u; div also for sqrt)\n"
          "  --mul-feed       fp_mul's feed register in front of its MULT18X18D\n"
          "                   (needs --mul-latency 7 to 10)\n"
          "  --mult-blocks 4|3   MULT18X18D per multiply (default 4); 3 cuts the\n"
          "                   product as 18 x 18, two 18 x 6 and a 6 x 6 piece in\n"
          "                   LUTs (70 to 100 LUT4s more), for chips that run out of\n"
          "                   multiplier blocks first (needs --mul-latency at most\n"
          "                   9, 10 with --mul-feed)\n"
          "  --scaleb-latency N   the latency of fp_scaleb, a multiply by a constant\n"
          "                   +-2^k as an exponent adjustment (default %u)\n"
          "  --clock-cores    the chip builds' cores, for clock rate: add 9, mul 10\n"
          "                   with its feed register, div/sqrt 34, scaleb 4 (what\n"
          "                   make pnr-spatial places); a latency option after it\n"
          "                   overrides its value\n"
          "  --no-scaleb      every multiply on fp_mul (for comparison)\n"
          "  --no-fit-check   write the module even if its area estimate does not\n"
          "                   fit the LFE5U-85F once (for simulation); without it\n"
          "                   such a model is refused with the numbers, exit 2\n"
          "  --vectors N      also DIR/vectors.txt: N objects (the model's defaults,\n"
          "                   then each value scaled in [0.75, 1.25]), their inputs and\n"
          "                   the golden model's state after each of K steps\n"
          "  --steps K        default 4\n"
          "  --seed S         the objects' scale factors (default 1)\n"
          "  --pipelines N    also DIR/MODULE_top.v, a chip of N copies of the module\n"
          "                   in the frame (object memory, feeder, write-back) behind\n"
          "                   an AXI4-Lite slave (sw/isa/fp3_spatial_regs.h), 1..255\n"
          "  --objects M      the objects the chip holds: a multiple of N, at least 2N\n"
          "                   (default 512 N)\n"
          "\n"
          "Exit status: 0 written; 2 bad arguments, model or integrator, or a\n"
          "pipeline that does not fit the LFE5U-85F; 1 the files could not be\n"
          "written.\n",
          fp3_model_integrators(), d.add_latency, d.mul_latency, d.div_latency,
          d.scaleb_latency);
}

int fp3_parse_spatial(int argc, char **argv, fp3_spatial_args *a) {
  memset(a, 0, sizeof *a);
  a->integ = "rk4";
  a->vec_steps = 4;
  a->seed = 1;
  fp3_spatial_defaults(&a->opts);
  int steps_given = 0, integ_given = 0;
  for (int i = 1; i < argc; i++) {
    const char *v;
    unsigned long long k;
    fpref_mode mode = {a->opts.rtz ? FPREF_RTZ : FPREF_RNE, a->opts.ftz};
    int r;
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    if ((r = fp3_opt_output(argc, argv, &i, "spatial", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->dir = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, "spatial", "--integrator", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->integ = v;
      integ_given = 1;
    } else if ((r = fp3_opt_mode(argc, argv, &i, "spatial", &mode)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->opts.rtz = mode.round == FPREF_RTZ;
      a->opts.ftz = mode.ftz;
    } else if ((r = fp3_opt_count(argc, argv, &i, "spatial", "--add-latency", 1, 64, "cycles",
                                  &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->opts.add_latency = (unsigned)k;
    } else if ((r = fp3_opt_count(argc, argv, &i, "spatial", "--mul-latency", 1, 64, "cycles",
                                  &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->opts.mul_latency = (unsigned)k;
    } else if ((r = fp3_opt_count(argc, argv, &i, "spatial", "--div-latency", 1, 64, "cycles",
                                  &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->opts.div_latency = (unsigned)k;
    } else if ((r = fp3_opt_count(argc, argv, &i, "spatial", "--scaleb-latency", 1, 64,
                                  "cycles", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->opts.scaleb_latency = (unsigned)k;
    } else if ((r = fp3_opt_count(argc, argv, &i, "spatial", "--mult-blocks", 3, 4,
                                  "MULT18X18D", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->opts.mul_blocks = (unsigned)k;
    } else if (strcmp(argv[i], "--clock-cores") == 0) {
      fp3_spatial_clock_cores(&a->opts);
    } else if (strcmp(argv[i], "--mul-feed") == 0) {
      a->opts.mul_feed = 1;
    } else if (strcmp(argv[i], "--no-scaleb") == 0) {
      a->opts.scaleb = 0;
    } else if (strcmp(argv[i], "--no-fit-check") == 0) {
      a->no_fit_check = 1;
    } else if ((r = fp3_opt_count(argc, argv, &i, "spatial", "--vectors", 1, 1000000,
                                  "objects", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->vec_objects = (size_t)k;
    } else if ((r = fp3_opt_count(argc, argv, &i, "spatial", "--steps", 1, 100000, "steps",
                                  &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->vec_steps = (unsigned)k;
      steps_given = 1;
    } else if ((r = fp3_opt_seed(argc, argv, &i, "spatial", &a->seed)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_count(argc, argv, &i, "spatial", "--pipelines", 1, 255,
                                  "pipelines", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->pipelines = (unsigned)k;
    } else if ((r = fp3_opt_count(argc, argv, &i, "spatial", "--objects", 2, 1u << 20,
                                  "objects", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->objects = (unsigned)k;
    } else if ((r = fp3_opt_value(argc, argv, &i, "spatial", "--scene", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->scene = v;
    } else if (strcmp(argv[i], "--literal") == 0) {
      a->literal = 1;
    } else if (fp3_opt_positional("spatial", "model", argv[i], &a->model)) {
      return FP3_ARGS_BAD;
    }
  }
  if (!a->model && !a->scene) {
    fprintf(stderr, "fp3 spatial: no model file or --scene FILE (see fp3 spatial --help)\n");
    return FP3_ARGS_BAD;
  }
  if (a->scene && a->vec_objects) {
    fprintf(stderr, "fp3 spatial: --vectors makes its objects from the model's defaults, not "
                    "the scene's; run the scene on the chip with fp3 run --scene %s --engine "
                    "spatial\n", a->scene);
    return FP3_ARGS_BAD;
  }
  if (!a->dir) {
    fprintf(stderr, "fp3 spatial: no output folder: -o DIR (see fp3 spatial --help)\n");
    return FP3_ARGS_BAD;
  }
  if (steps_given && !a->vec_objects) {
    fprintf(stderr, "fp3 spatial: --steps needs --vectors N\n");
    return FP3_ARGS_BAD;
  }
  if (a->objects && !a->pipelines) {
    fprintf(stderr, "fp3 spatial: --objects needs --pipelines N\n");
    return FP3_ARGS_BAD;
  }
  if (a->pipelines && !a->objects) a->objects = fp3_spatial_default_objects(a->pipelines);
  /* a ship scene's RK4 is the model integrator rk4se (as fp3 compile's) */
  if (a->scene && !a->model && fp3_ship_scene_integrator(a->scene, integ_given, &a->integ,
                                                         "spatial"))
    return FP3_ARGS_BAD;
  if (!fp3_model_integrator_known(a->integ)) {
    fprintf(stderr, "fp3 spatial: unknown integrator '%s' (%s)\n", a->integ,
            fp3_model_integrators());
    return FP3_ARGS_BAD;
  }
  return FP3_ARGS_RUN;
}

/* DIR/NAME. */
static void join(char *d, size_t n, const char *dir, const char *name) {
  snprintf(d, n, "%s/%s", dir, name);
}

/* Write the files (name, text) into dir, made if missing; on error remove
 * those written and the folder if it was made here.  0, or -1 with a
 * message. */
static int write_all(const char *dir, const char *const *name, const char *const *text,
                     int nfiles, char *msg, size_t n) {
  int made = 0;
  struct stat sb;
  if (stat(dir, &sb) != 0) {
    if (mkdir(dir, 0777) != 0) {
      snprintf(msg, n, "%s: %s", dir, strerror(errno));
      return -1;
    }
    made = 1;
  } else if (!S_ISDIR(sb.st_mode)) {
    snprintf(msg, n, "%s: not a folder", dir);
    return -1;
  }
  char path[4096];
  for (int k = 0; k < nfiles; k++) {
    join(path, sizeof path, dir, name[k]);
    if (fp3_write_text_atomic(path, text[k], msg, n)) {
      for (int j = 0; j < k; j++) {
        join(path, sizeof path, dir, name[j]);
        unlink(path);
      }
      if (made) rmdir(dir);
      return -1;
    }
  }
  return 0;
}

/* The model: MODEL.fp3m, or the scene's (fp3_mscene_read_any; a ship scene
 * as a scene of MODEL.fp3m or of the shipped ship), with zero[k] = 1 for
 * each param zero in every object of the scene and *objects its objects
 * (0 without a scene).  The model, or NULL with
 * the message on stderr. */
static fp3_model *load_model(const fp3_spatial_args *a, unsigned char *zero, size_t *objects) {
  char msg[512];
  fp3_model *m = NULL;
  if (a->scene) {
    if (a->model && fp3_scene_is_model(a->scene)) {
      fprintf(stderr, "fp3 spatial: %s names its model: MODEL.fp3m or a model scene, not "
                      "both\n", a->scene);
      return NULL;
    }
    if (!(m = fp3_scene_model(a->scene, a->model, zero, objects, msg, sizeof msg)))
      fprintf(stderr, "fp3 spatial: %s\n", msg);
    return m;
  }
  if (!(m = malloc(sizeof *m))) {
    fprintf(stderr, "fp3 spatial: out of memory\n");
    return NULL;
  }
  if (fp3_model_load(a->model, m, msg, sizeof msg)) {
    fprintf(stderr, "fp3 spatial: %s\n", msg);
    free(m);
    return NULL;
  }
  return m;
}

static int run_spatial(const fp3_spatial_args *a) {
  char msg[512];
  int rc = EXIT_USAGE;
  fp3_compiled *c = NULL;
  fp3_spatial *s = NULL;
  char *vectors = NULL, *vname = NULL, *top = NULL, *tname = NULL;
  fp3_strbuf rep = {0};
  unsigned char zero[FP3_MODEL_MAX_VARS] = {0};
  size_t scene_objects = 0;
  fp3_model *m = load_model(a, zero, &scene_objects);
  if (!m) return EXIT_USAGE;
  fp3_compile_opts co;
  fp3_compile_defaults(&co);
  if (a->literal) co.fold = co.drop_zero = 0;
  else co.drop_zero = a->scene != NULL; /* without a scene no param is known to be zero */
  /* the IR alone: the processor's register and instruction limits do not
   * apply to a pipeline */
  if (fp3_compile_model_ir(m, a->integ, &co, zero, &c, msg, sizeof msg)) {
    fprintf(stderr, "fp3 spatial: %s: %s\n", m->file, msg);
    goto out;
  }
  if (fp3_spatial_build(c, m, a->integ, &a->opts, &s, msg, sizeof msg)) {
    fprintf(stderr, "fp3 spatial: %s: %s\n", m->file, msg);
    goto out;
  }
  const fp3_spatial_stats *st = fp3_spatial_stats_of(s);
  if (st->fit == 0 && !a->no_fit_check) {
    fprintf(stderr,
            "fp3 spatial: %s: the pipeline does not fit the LFE5U-85F once: it needs %u LUT4, "
            "%u flip-flops, %u MULT18X18D, %u EBR against %u, %u, %u, %u available to "
            "pipelines (%s is short; --no-fit-check writes it for simulation)\n",
            m->file, st->est_lut4, st->est_ff, st->est_mult, st->est_ebr,
            FP3_SPATIAL_BUDGET_LUT4, FP3_SPATIAL_BUDGET_FF, FP3_SPATIAL_BUDGET_MULT,
            FP3_SPATIAL_BUDGET_EBR, st->limit);
    goto out;
  }
  if (a->vec_objects &&
      fp3_spatial_vectors(s, a->vec_objects, a->vec_steps, a->seed, &vectors, msg, sizeof msg)) {
    fprintf(stderr, "fp3 spatial: %s\n", msg);
    goto out;
  }
  size_t vl = strlen(fp3_spatial_module(s)) + 8;
  char topmod[128];
  if (!(vname = malloc(vl)) || !(tname = malloc(vl + 4))) {
    rc = EXIT_FAIL;
    goto out;
  }
  snprintf(vname, vl, "%s.v", fp3_spatial_module(s));
  fp3_strbuf_printf(&rep, "%s", fp3_spatial_report(s));
  if (a->scene) {
    fp3_strbuf_printf(&rep, "scene: %s, %zu objects; terms removed, zero in every object: ",
                      a->scene, scene_objects);
    const unsigned any = co.drop_zero ? fp3_zero_params_list(m, zero, &rep) : 0;
    fp3_strbuf_printf(&rep, "%s\n", any ? "" : co.drop_zero ? "none" : "none (--literal)");
  }
  fp3_strbuf_printf(&rep, "hash: %016llx (FNV-1a 64 of %s)\n",
                    (unsigned long long)fp3_spatial_hash(s), vname);
  if (a->pipelines) {
    if (fp3_spatial_top(s, a->pipelines, a->objects, 0, topmod, sizeof topmod, &top, msg,
                        sizeof msg)) {
      fprintf(stderr, "fp3 spatial: %s: %s\n", m->file, msg);
      goto out;
    }
    snprintf(tname, vl + 4, "%s.v", topmod);
    fp3_strbuf_printf(&rep,
                      "chip: %s, %u pipelines, %u objects, object strides %u (state) and "
                      "%u (inputs) words\n",
                      topmod, a->pipelines, a->objects, 1u << fp3_spatial_state_log(s),
                      1u << fp3_spatial_input_log(s));
  }
  if (rep.oom) {
    rc = EXIT_FAIL;
    goto out;
  }
  const char *names[4] = {vname, "report.txt", tname, "vectors.txt"};
  const char *texts[4] = {fp3_spatial_verilog(s), rep.s, top, vectors};
  int nf = 2;
  if (top) nf = 3;
  if (vectors) {
    names[nf] = "vectors.txt";
    texts[nf++] = vectors;
  }
  if (write_all(a->dir, names, texts, nf, msg, sizeof msg)) {
    fprintf(stderr, "fp3 spatial: %s\n", msg);
    rc = EXIT_FAIL;
    goto out;
  }
  fprintf(stderr, "fp3 spatial: %s, integrator %s%s -> %s/%s\n%s", m->name, a->integ,
          a->literal ? " (literal)" : " (folded)", a->dir, vname, rep.s);
  rc = 0;
out:
  free(rep.s);
  free(top);
  free(tname);
  free(vname);
  free(vectors);
  fp3_spatial_free(s);
  fp3_compiled_free(c);
  free(m);
  return rc;
}

int fp3_cmd_spatial(int argc, char **argv) {
  fp3_spatial_args a;
  int r = fp3_parse_spatial(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_spatial(&a) : fp3_args_exit(r, usage);
}
