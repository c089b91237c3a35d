/*
 * cmd_tbgen.c -- `fp3 tbgen`: write the program image, the initial
 * registers and the expected results for the Icarus testbench
 * sim/tb_fp3.v (see cmd_tbgen.h for the files and their layout).
 *
 * The program goes the one path of `fp3 run --program`: its model (--model
 * or its `.model`), one object of it (the model file's defaults, --set),
 * the program bound to the model by name (fp3_compile_bind), the host's
 * register writes from the bound program (fp3_compiled_model_start).  It
 * runs on the instruction-set simulator; an observer records every state
 * variable after every integration (the last value written by an
 * instruction of that integration or an earlier one, as `fp3 run` and the
 * testbench see it), which must equal the golden model of the program's
 * `.integrator` bit for bit before anything is written: the expected
 * values of the first two state variables go into expected.hex.  The
 * Verilated RTL runs it too, for its cycle and stall counts.
 */
#include <errno.h>
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "asm.h"
#include "cliopt.h"
#include "cmd_asm.h"
#include "cmd_model.h"
#include "cmd_tbgen.h"
#include "compile.h"
#include "engine.h"
#include "fp3_isa.h"
#include "fpenv.h"
#include "fpref.h"
#include "image.h"
#include "model.h"
#include "runsetup.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2
#define NREGS FP3_DEFAULT_NUM_REGS /* the testbench's build: init.hex's words */

static void usage_tbgen(FILE *f) {
  fprintf(f,
          "usage: fp3 tbgen PROGRAM.s -o DIR [--model FILE.fp3m] [--set NAME=VALUE ...]\n"
          "                 [--steps N] [--round rne|rtz] [--ftz] [--no-rtl]\n"
          "\n"
          "Write the files of the Icarus Verilog testbench sim/tb_fp3.v\n"
          "(make wave) into DIR, in $readmemh format:\n"
          "  program.hex   the assembled program\n"
          "  init.hex      the %d registers before the run (the bound .in values)\n"
          "  run.hex       steps, counts and the expected status of the run\n"
          "  expected.hex  the final registers, and the model's first two state\n"
          "                variables after every integration\n"
          "The program is a model's, as for fp3 run --program: its `.integrator`\n"
          "names the golden model, its `.in`/`.out` lines bind registers to the\n"
          "model's names.  Expected values come from the instruction-set simulator,\n"
          "checked bit for bit against that golden model first; cycle and stall\n"
          "counts from the Verilated RTL unless --no-rtl.\n"
          "\n"
          "  -o DIR           output directory (created if missing)\n"
          "  --model FILE     the model (.fp3m, docs/models.md; default: the\n"
          "                   program's `.model`)\n"
          "  --set NAME=VALUE h, a param or a state variable's initial value (NAME\n"
          "                   or NAME0), binary32; the model file's defaults otherwise\n"
          "  --steps N        integrations, 1..%u (default 4)\n"
          "  --round R, --ftz FP core options of the RTL simulated (parameters\n"
          "                   ROUND, FTZ): rne (default) or rtz; flush to zero.  The\n"
          "                   host values, the ISS and the golden model follow\n"
          "  --no-rtl         do not run the Verilated RTL (no cycle check)\n"
          "\n"
          "Exit status: 0 written; 1 a run or write failed, or the ISS disagrees\n"
          "with the golden model; 2 bad arguments, model or program (assembler\n"
          "errors as FILE:LINE: reason).  Nothing is written unless the runs are.\n",
          NREGS, TBGEN_MAX_CHECK);
}

/* mkdir -p */
static int make_dirs(const char *dir) {
  char path[4096];
  if (snprintf(path, sizeof path, "%s", dir) >= (int)sizeof path) return -1;
  for (char *p = path + 1; *p; p++) {
    if (*p != '/') continue;
    *p = '\0';
    if (mkdir(path, 0777) != 0 && errno != EEXIST) return -1;
    *p = '/';
  }
  if (mkdir(path, 0777) != 0 && errno != EEXIST) return -1;
  return 0;
}

/* ---- writing the files --------------------------------------------------- */

static FILE *open_out(const char *dir, const char *name, char *path, size_t n) {
  snprintf(path, n, "%s/%s", dir, name);
  FILE *f = fopen(path, "w");
  if (!f) fprintf(stderr, "fp3 tbgen: cannot write %s: %s\n", path, strerror(errno));
  return f;
}

static int close_out(FILE *f, const char *path) {
  int bad = ferror(f);
  if (fclose(f) != 0 || bad) {
    fprintf(stderr, "fp3 tbgen: error writing %s\n", path);
    return -1;
  }
  return 0;
}

/* name as a Verilog string of TBGEN_NAME_WORDS words into w[]: the last
 * character in the low byte of the last word, NULs before the first. */
static void pack_name(const char *name, uint32_t *w) {
  unsigned char buf[4 * TBGEN_NAME_WORDS] = {0};
  size_t len = strlen(name);
  if (len > sizeof buf) len = sizeof buf;
  memcpy(buf + sizeof buf - len, name, len);
  for (int j = 0; j < TBGEN_NAME_WORDS; j++)
    w[j] = (uint32_t)buf[4 * j] << 24 | (uint32_t)buf[4 * j + 1] << 16 |
           (uint32_t)buf[4 * j + 2] << 8 | buf[4 * j + 3];
}

int fp3_parse_tbgen(int argc, char **argv, fp3_tbgen_args *a) {
  memset(a, 0, sizeof *a);
  a->steps = 4;
  a->use_rtl = 1;
  a->mode = FPREF_IEEE;
  fp3_model_args *m = &a->model;
  m->cmd = "tbgen";
  m->integ = "";
  m->engine = "iss";
  m->mode = FPREF_IEEE;
  fp3_trace_opts_init(&m->trace);
  for (int i = 1; i < argc; i++) {
    const char *v;
    unsigned long long k;
    int r;
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    if ((r = fp3_opt_value(argc, argv, &i, "tbgen", "-o", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->dir = v;
    } else if ((r = fp3_opt_count(argc, argv, &i, "tbgen", "--steps", 1, TBGEN_MAX_CHECK,
                                  "integrations", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->steps = (uint32_t)k;
    } else if ((r = fp3_opt_value(argc, argv, &i, "tbgen", "--model", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      m->file = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, "tbgen", "--set", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      if (m->nset == (int)(sizeof m->set / sizeof m->set[0])) {
        fprintf(stderr, "fp3 tbgen: too many --set\n");
        return FP3_ARGS_BAD;
      }
      m->set[m->nset++] = v;
    } else if ((r = fp3_opt_mode(argc, argv, &i, "tbgen", &a->mode)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      m->mode = a->mode;
    } else if (strcmp(argv[i], "--no-rtl") == 0) {
      a->use_rtl = 0;
    } else if (fp3_opt_positional("tbgen", "program", argv[i], &a->in)) {
      return FP3_ARGS_BAD;
    }
  }
  if (!a->in || !a->dir) {
    fprintf(stderr, "fp3 tbgen: %s (see fp3 tbgen --help)\n",
            !a->in ? "no program" : "no output directory (-o DIR)");
    return FP3_ARGS_BAD;
  }
  m->program = a->in;
  m->steps = a->steps;
  return FP3_ARGS_RUN;
}

/* ---- the program on its model ------------------------------------------- */

typedef struct tbgen_setup {
  fp3_run_setup r;           /* the program, its model, the values         */
  uint32_t init[NREGS];      /* the registers before the run            */
  unsigned sreg[FP3_MODEL_MAX_VARS]; /* the state variables' registers  */
} tbgen_setup;

/* Assemble the program, load its model, take the object's values, bind
 * the program and compute the host's writes.  0, or an exit status with
 * the message on stderr. */
static int setup(const fp3_tbgen_args *a, tbgen_setup *s) {
  char msg[512];
  char *errs = NULL;
  fp3_image_init(&s->r.img);
  if (fp3_asm_file(a->in, &s->r.img, &errs) != 0) {
    fp3_print_asm_errors(errs);
    free(errs);
    return EXIT_USAGE;
  }
  free(errs);
  if (!a->model.file && !s->r.img.model[0]) { /* no fallback to the ship: say which model */
    fprintf(stderr, "fp3 tbgen: %s has no `.model \"FILE.fp3m\"` line: give --model FILE.fp3m "
            "(the ship: --model models/ship.fp3m)\n", a->in);
    return EXIT_USAGE;
  }
  s->r.program = a->in;
  int rc = fp3_run_setup_model(&a->model, &s->r, "tbgen");
  if (rc) return rc;
  fp3_compile_opts o;
  fp3_compile_defaults(&o);
  if (fp3_compile_bind(s->r.m, &s->r.img, a->in, &o, &s->r.c, msg, sizeof msg)) {
    fprintf(stderr, "fp3 tbgen: %s\n", msg);
    return EXIT_USAGE;
  }
  unsigned reg[4 * FP3_MODEL_MAX_VARS];
  uint32_t val[4 * FP3_MODEL_MAX_VARS];
  fpenv_saved env;
  if (fpenv_enter(a->mode, &env)) return EXIT_USAGE; /* checked by the parse */
  size_t nw = fp3_compiled_model_start(s->r.c, s->r.in, s->r.y0, reg, val, 4 * FP3_MODEL_MAX_VARS);
  fpenv_leave(&env);
  for (size_t w = 0; w < nw; w++) {
    if (reg[w] >= NREGS) {
      fprintf(stderr, "fp3 tbgen: %s: the host writes r%u; the testbench's build has %d "
              "registers\n", a->in, reg[w], NREGS);
      return EXIT_USAGE;
    }
    s->init[reg[w]] = val[w];
  }
  for (unsigned i = 0; i < s->r.m->nstate; i++) {
    s->sreg[i] = fp3_compiled_state_reg(s->r.c, i);
    if (s->sreg[i] >= NREGS) {
      fprintf(stderr, "fp3 tbgen: %s: state variable %s is in r%u; the testbench's build has "
              "%d registers\n", a->in, s->r.m->state[i], s->sreg[i], NREGS);
      return EXIT_USAGE;
    }
  }
  return 0;
}

/* ---- the runs -------------------------------------------------------------- */

/* The reference run on the ISS: *st, the final registers, and in ob every
 * state variable written in each integration. */
static int run_iss(const fp3_tbgen_args *a, const tbgen_setup *s, fp3_state_obs *ob,
                   fp3_status *st, uint32_t *final_regs) {
  const fp3_image *img = fp3_compiled_image(s->r.c);
  memset(st, 0, sizeof *st);
  fp3_engine *iss = fp3_engine_iss_new_mode(a->mode);
  int erc = iss ? fp3_engine_load(iss, img->words, img->n) : -1;
  for (unsigned r = 0; r < NREGS && erc == 0; r++) erc = fp3_engine_write_reg(iss, r, s->init[r]);
  if (erc == 0) {
    fp3_observer obs = {.ctx = ob, .on_write = fp3_state_obs_write};
    erc = fp3_engine_run(iss, a->steps, &obs, st);
  }
  for (unsigned r = 0; r < NREGS && erc == 0; r++)
    erc = fp3_engine_read_reg(iss, r, &final_regs[r]);
  if (erc != 0)
    fprintf(stderr, "fp3 tbgen: iss engine: %s\n", iss ? fp3_engine_error(iss) : "out of memory");
  fp3_engine_free(iss);
  return erc != 0;
}

/* The ISS's state after integrations 1..ncheck against the golden model
 * of the bound program, every state variable; exp[k-1][0..1] gets the
 * first two.  0, or -1 with the first difference on stderr. */
static int check_golden(const fp3_tbgen_args *a, tbgen_setup *s, const fp3_state_obs *ob,
                        uint32_t ncheck, uint32_t (*exp)[2]) {
  const fp3_model *m = s->r.m;
  const unsigned ns = m->nstate;
  uint32_t cur[FP3_MODEL_MAX_VARS];
  float g[FP3_MODEL_MAX_VARS];
  for (unsigned i = 0; i < ns; i++) cur[i] = s->init[s->sreg[i]], g[i] = s->r.y0[i];
  fpenv_saved env;
  fpenv_enter(a->mode, &env);
  int rc = 0;
  for (uint32_t k = 1; k <= ncheck && rc == 0; k++) {
    fp3_compiled_model_step(s->r.c, g);
    for (unsigned i = 0; i < ns; i++) {
      size_t q = (size_t)(k - 1) * ns + i;
      if (ob->seen[q]) cur[i] = ob->v[q];
      if (cur[i] != fpref_bits(g[i]) && rc == 0) {
        fprintf(stderr, "fp3 tbgen: %s: the ISS disagrees with the golden model (.integrator "
                "%s, model %s): after integration %" PRIu32 " %s = 0x%08" PRIx32 " (%.9g), "
                "golden 0x%08" PRIx32 " (%.9g); nothing written\n", a->in, s->r.img.integrator,
                m->file, k, m->state[i], cur[i], (double)fpref_float(cur[i]), fpref_bits(g[i]),
                (double)g[i]);
        rc = -1;
      }
    }
    exp[k - 1][0] = cur[0];
    exp[k - 1][1] = ns > 1 ? cur[1] : 0;
  }
  fpenv_leave(&env);
  return rc;
}

/* Cycles and stalls on the Verilated RTL: *lat (0 when it did not run),
 * *cycles, *stalls. */
static void run_rtl(const fp3_tbgen_args *a, const tbgen_setup *s, uint32_t *lat,
                    uint32_t *cycles, uint32_t *stalls) {
  const fp3_image *img = fp3_compiled_image(s->r.c);
  *lat = *cycles = *stalls = 0;
  fp3_engine *rtl = fp3_engine_rtl_new_mode(a->mode, NULL);
  fp3_status rst;
  int r2 = rtl ? fp3_engine_load(rtl, img->words, img->n) : -1;
  for (unsigned r = 0; r < NREGS && r2 == 0; r++) r2 = fp3_engine_write_reg(rtl, r, s->init[r]);
  if (r2 == 0) r2 = fp3_engine_run(rtl, a->steps, NULL, &rst);
  if (r2 == 0 && rtl->config.num_regs == NREGS) {
    *lat = (uint32_t)(rtl->config.num_lanes > 1) << 17 | (rtl->config.fmax_pipe & 1u) << 16 |
           (rtl->config.mul_latency & 0xFFu) << 8 | (rtl->config.add_latency & 0xFFu);
    *cycles = (uint32_t)rst.cycles;
    *stalls = (uint32_t)rst.stalls;
  } else {
    fprintf(stderr, "fp3 tbgen: note: no cycle counts from the Verilated RTL%s%s\n",
            rtl ? ": " : "", rtl ? fp3_engine_error(rtl) : "");
  }
  fp3_engine_free(rtl);
}

/* ---- the files --------------------------------------------------------------- */

static int write_files(const fp3_tbgen_args *a, const tbgen_setup *s, const fp3_status *st,
                       const uint32_t *final_regs, uint32_t ncheck, uint32_t (*exp)[2],
                       const uint32_t *rtl) {
  const char *in = a->in, *dir = a->dir;
  const fp3_model *m = s->r.m;
  const fp3_image *img = fp3_compiled_image(s->r.c);
  const int two = m->nstate > 1;
  char msg[512], path[4200];
  if (make_dirs(dir) != 0) {
    fprintf(stderr, "fp3 tbgen: cannot create %s: %s\n", dir, strerror(errno));
    return -1;
  }
  snprintf(path, sizeof path, "%s/program.hex", dir);
  if (fp3_image_write(img, path, in, msg, sizeof msg) != 0) {
    fprintf(stderr, "fp3 tbgen: %s\n", msg);
    return -1;
  }

  FILE *f = open_out(dir, "init.hex", path, sizeof path);
  if (!f) return -1;
  fprintf(f, "// init.hex -- registers r0..r%d before the run (fp3 tbgen %s)\n", NREGS - 1, in);
  fprintf(f, "// model %s (%s), .integrator %s:", m->name, m->file, s->r.img.integrator);
  for (unsigned k = 0; k < m->nparam; k++)
    fprintf(f, " %s=%.9g", m->param[k], (double)s->r.in[k]);
  for (unsigned k = 0; k < m->nstate; k++)
    fprintf(f, " %s0=%.9g", m->state[k], (double)s->r.y0[k]);
  fprintf(f, "\n");
  for (unsigned r = 0; r < NREGS; r++) fprintf(f, "%08" PRIx32 "  // r%u\n", s->init[r], r);
  if (close_out(f, path)) return -1;

  uint32_t run[TBGEN_RUN_WORDS] = {0};
  run[TBGEN_RUN_MAGIC] = FP3_ID_VALUE;
  run[TBGEN_RUN_VERSION] = TBGEN_VERSION;
  run[TBGEN_RUN_NWORDS] = (uint32_t)img->n;
  run[TBGEN_RUN_NUM_REGS] = NREGS;
  run[TBGEN_RUN_STEPS] = a->steps;
  run[TBGEN_RUN_ERROR] = st->error;
  run[TBGEN_RUN_FAULT_PC] = st->fault_pc;
  run[TBGEN_RUN_STEPS_DONE] = st->steps_done;
  run[TBGEN_RUN_ISSUED] = (uint32_t)st->issued;
  run[TBGEN_RUN_FLAGS] = st->flags;
  run[TBGEN_RUN_REG_V] = s->sreg[0];
  run[TBGEN_RUN_REG_S] = two ? s->sreg[1] : TBGEN_NO_REG;
  run[TBGEN_RUN_NCHECK] = ncheck;
  run[TBGEN_RUN_RTL_LAT] = rtl[0];
  run[TBGEN_RUN_RTL_CYCLES] = rtl[1];
  run[TBGEN_RUN_RTL_STALLS] = rtl[2];
  pack_name(m->state[0], run + TBGEN_RUN_NAME_V);
  if (two) pack_name(m->state[1], run + TBGEN_RUN_NAME_S);
  char names[TBGEN_RUN_WORDS][96] = {
      "magic (ID)", "format version", "program words", "registers",
      "STEPS to run", "expected ERROR", "expected FAULT_PC",
      "expected STEPS_DONE", "expected ISSUED (low word)", "expected FLAGS", "", "",
      "integrations in expected.hex",
      "Verilated RTL (NUM_LANES>1)<<17 | FMAX_PIPE<<16 | MUL_LATENCY<<8 | ADD_LATENCY (0: not run)",
      "Verilated RTL CYCLES (low word)", "Verilated RTL STALLS (low word)"};
  snprintf(names[TBGEN_RUN_REG_V], sizeof names[0], "register of state variable 0 (%s)",
           m->state[0]);
  snprintf(names[TBGEN_RUN_REG_S], sizeof names[0], "register of state variable 1 (%s)",
           two ? m->state[1] : "ffffffff: none");
  for (int j = 0; j < TBGEN_NAME_WORDS; j++) {
    snprintf(names[TBGEN_RUN_NAME_V + j], sizeof names[0], "name of state variable 0 (%s), "
             "word %d", m->state[0], j);
    snprintf(names[TBGEN_RUN_NAME_S + j], sizeof names[0], "name of state variable 1 (%s), "
             "word %d", two ? m->state[1] : "none", j);
  }
  f = open_out(dir, "run.hex", path, sizeof path);
  if (!f) return -1;
  fprintf(f, "// run.hex -- the run for sim/tb_fp3.v (fp3 tbgen %s, format version %u)\n", in,
          TBGEN_VERSION);
  for (int k = 0; k < TBGEN_RUN_WORDS; k++)
    fprintf(f, "%08" PRIx32 "  // %2d %s\n", run[k], k, names[k]);
  if (close_out(f, path)) return -1;

  f = open_out(dir, "expected.hex", path, sizeof path);
  if (!f) return -1;
  fprintf(f, "// expected.hex -- results of %s, %" PRIu32
             " integrations, from the ISS, equal to the golden model (fp3 tbgen)\n", in,
          a->steps);
  fprintf(f, "// final registers r0..r%d\n", NREGS - 1);
  for (unsigned r = 0; r < NREGS; r++)
    fprintf(f, "%08" PRIx32 "  // r%u = %.9g\n", final_regs[r], r,
            (double)fpref_float(final_regs[r]));
  fprintf(f, "// %s%s%s after every integration%s\n", m->state[0], two ? ", " : "",
          two ? m->state[1] : "", two ? "" : " (and a word 0 in place of a second)");
  for (uint32_t k = 1; k <= ncheck; k++) {
    uint32_t v = exp[k - 1][0], w = exp[k - 1][1];
    fprintf(f, "%08" PRIx32 " %08" PRIx32 "  // %" PRIu32 ": %s %.9g", v, w, k, m->state[0],
            (double)fpref_float(v));
    if (two) fprintf(f, " %s %.9g", m->state[1], (double)fpref_float(w));
    fprintf(f, "\n");
  }
  return close_out(f, path);
}

/* The run step: the program on its model, the ISS checked against the
 * golden model (and the RTL run), the files. */
static int run_tbgen(const fp3_tbgen_args *a) {
  tbgen_setup *s = calloc(1, sizeof *s);
  if (!s) {
    fprintf(stderr, "fp3 tbgen: out of memory\n");
    return EXIT_FAIL;
  }
  fp3_state_obs ob;
  memset(&ob, 0, sizeof ob);
  uint32_t (*exp)[2] = NULL;
  int rc = setup(a, s);
  if (rc) goto out;
  rc = EXIT_FAIL;
  const unsigned ns = s->r.m->nstate;
  ob.nstate = ns;
  ob.steps = a->steps;
  for (unsigned i = 0; i < ns; i++) ob.reg[i] = s->sreg[i];
  ob.v = calloc((size_t)a->steps * ns, sizeof *ob.v);
  ob.seen = calloc((size_t)a->steps * ns, 1);
  exp = calloc(a->steps, sizeof *exp);
  if (!ob.v || !ob.seen || !exp) {
    fprintf(stderr, "fp3 tbgen: out of memory\n");
    goto out;
  }
  fp3_status st;
  uint32_t final_regs[NREGS];
  if (run_iss(a, s, &ob, &st, final_regs)) goto out;
  const uint32_t ncheck = st.steps_done < a->steps ? st.steps_done : a->steps;
  if (check_golden(a, s, &ob, ncheck, exp)) goto out;
  uint32_t rtl[3] = {0, 0, 0};
  if (a->use_rtl) run_rtl(a, s, &rtl[0], &rtl[1], &rtl[2]);
  if (write_files(a, s, &st, final_regs, ncheck, exp, rtl)) goto out;
  printf("fp3 tbgen: %s -> %s/{program,init,run,expected}.hex: %zu words, model %s, "
         "%" PRIu32 " integrations, %" PRIu32 " checked (%s%s%s)", a->in, a->dir,
         fp3_compiled_image(s->r.c)->n, s->r.m->name, a->steps, ncheck, s->r.m->state[0],
         ns > 1 ? ", " : "", ns > 1 ? s->r.m->state[1] : "");
  if (rtl[0]) printf(", Verilator %" PRIu32 " cycles", rtl[1]);
  printf("\n");
  rc = 0;
out:
  free(ob.v);
  free(ob.seen);
  free(exp);
  fp3_run_setup_free(&s->r);
  free(s);
  return rc;
}

int fp3_cmd_tbgen(int argc, char **argv) {
  fp3_tbgen_args a;
  int r = fp3_parse_tbgen(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_tbgen(&a) : fp3_args_exit(r, usage_tbgen);
}
