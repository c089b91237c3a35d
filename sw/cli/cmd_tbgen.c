/*
 * cmd_tbgen.c -- `fp3 tbgen`: write the program image, the initial
 * registers and the expected results for the Icarus testbench
 * sim/tb_fp3.v (see cmd_tbgen.h for the files and their layout).
 *
 * The program runs on the instruction-set simulator; an observer records
 * the value of the .out registers v and s after every integration the
 * same way `fp3 run` does (the last value written by an instruction of
 * that integration or an earlier one).  The Verilated RTL runs it too,
 * for its cycle and stall counts.
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
#include "cmd_tbgen.h"
#include "engine.h"
#include "fp3_isa.h"
#include "fpref.h"
#include "golden.h"
#include "image.h"
#include "objects.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2
#define NO_REG 0xFFFFFFFFu

static void usage_tbgen(FILE *f) {
  fprintf(f,
          "usage: fp3 tbgen PROGRAM.s -o DIR [--steps N] [--set NAME=VALUE ...]\n"
          "                 [--round rne|rtz] [--ftz] [--no-rtl]\n"
          "\n"
          "Write the files of the Icarus Verilog testbench sim/tb_fp3.v\n"
          "(make wave) into DIR, in $readmemh format:\n"
          "  program.hex   the assembled program\n"
          "  init.hex      the %d registers before the run (.in parameters)\n"
          "  run.hex       steps, counts and the expected status of the run\n"
          "  expected.hex  the final registers and v, s after every integration\n"
          "Expected values come from the instruction-set simulator (bit-exact\n"
          "with the golden model); cycle and stall counts from the Verilated\n"
          "RTL unless --no-rtl.\n"
          "\n"
          "  -o DIR           output directory (created if missing)\n"
          "  --steps N        integrations, 1..%u (default 4)\n"
          "  --set NAME=VALUE scene parameter as in fp3 run (T C m h v0 s0)\n"
          "  --round R, --ftz FP core options of the RTL simulated (parameters\n"
          "                   ROUND, FTZ): rne (default) or rtz; flush to zero\n"
          "  --no-rtl         do not run the Verilated RTL (no cycle check)\n"
          "\n"
          "Exit status: 0 written; 1 a run or write failed; 2 bad arguments\n"
          "or program (assembler errors as FILE:LINE: reason).\n",
          FP3_DEFAULT_NUM_REGS, TBGEN_MAX_CHECK);
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

/* ---- recording v and s after every integration -------------------------- */

typedef struct recorder {
  fp3_track t;        /* v, s (registers -1: not bound)     */
  uint32_t *val[2];   /* val[w][k-1]: after integration k   */
} recorder;

static void rec_final(void *ctx, int w, uint32_t k, uint32_t bits) {
  ((recorder *)ctx)->val[w][k - 1] = bits;
}

static void rec_write(void *ctx, unsigned reg, uint32_t value,
                      uint32_t integration) {
  fp3_track_write(&((recorder *)ctx)->t, reg, value, integration);
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

int fp3_parse_tbgen(int argc, char **argv, fp3_tbgen_args *a) {
  a->in = a->dir = NULL;
  a->steps = 4;
  a->use_rtl = 1;
  a->mode = FPREF_IEEE;
  fp3_ship_default(&a->p);
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
    } else if ((r = fp3_opt_value(argc, argv, &i, "tbgen", "--set", &v)) != 0) {
      if (r < 0 || fp3_ship_set("tbgen", &a->p, v)) return FP3_ARGS_BAD;
    } else if ((r = fp3_opt_mode(argc, argv, &i, "tbgen", &a->mode)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
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
  char msg[512];
  if (fp3_ship_validate(&a->p, msg, sizeof msg)) {
    fprintf(stderr, "fp3 tbgen: %s\n", msg);
    return FP3_ARGS_BAD;
  }
  return FP3_ARGS_RUN;
}

/* The run step: assemble, run the ISS (and the RTL), write the files. */
static int run_tbgen(const fp3_tbgen_args *a) {
  const char *in = a->in, *dir = a->dir;
  const uint32_t steps = a->steps;
  const int use_rtl = a->use_rtl;
  const fpref_mode mode = a->mode;
  const fp3_ship_params p = a->p;
  char msg[512];
  fp3_image img;
  char *errs = NULL;
  if (fp3_asm_file(in, &img, &errs) != 0) {
    fp3_print_asm_errors(errs);
    free(errs);
    return EXIT_USAGE;
  }
  free(errs);

  /* registers before the run: the .in parameters, 0 elsewhere */
  uint32_t init[FP3_DEFAULT_NUM_REGS] = {0}; /* the assembler keeps .in below r32 */
  fp3_in_registers(&img, &p, init);

  /* the reference run on the ISS */
  recorder rec;
  memset(&rec, 0, sizeof rec);
  rec.t.last = steps;
  rec.t.final = rec_final;
  rec.t.ctx = &rec;
  for (int w = 0; w < 2; w++) {
    rec.t.reg[w] = img.out_reg[w == 0 ? FP3_OUT_V : FP3_OUT_S];
    rec.t.next_k[w] = 1;
    if (rec.t.reg[w] >= 0) rec.t.cur[w] = init[rec.t.reg[w]];
    rec.val[w] = calloc(steps, sizeof *rec.val[w]);
    if (!rec.val[w]) {
      fprintf(stderr, "fp3 tbgen: out of memory\n");
      free(rec.val[0]);
      return EXIT_FAIL;
    }
  }
  int rc = EXIT_FAIL;
  uint32_t final_regs[FP3_DEFAULT_NUM_REGS];
  fp3_status st;
  memset(&st, 0, sizeof st);
  fp3_engine *iss = fp3_engine_iss_new_mode(mode);
  int erc = iss ? fp3_engine_load(iss, img.words, img.n) : -1;
  for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS && erc == 0; r++)
    erc = fp3_engine_write_reg(iss, r, init[r]);
  if (erc == 0) {
    fp3_observer obs = {.ctx = &rec, .on_write = rec_write};
    erc = fp3_engine_run(iss, steps, &obs, &st);
  }
  for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS && erc == 0; r++)
    erc = fp3_engine_read_reg(iss, r, &final_regs[r]);
  if (erc != 0) {
    fprintf(stderr, "fp3 tbgen: iss engine: %s\n",
            iss ? fp3_engine_error(iss) : "out of memory");
    fp3_engine_free(iss);
    goto out;
  }
  fp3_engine_free(iss);
  uint32_t ncheck = st.steps_done < steps ? st.steps_done : steps;
  if (rec.t.reg[0] < 0 && rec.t.reg[1] < 0) ncheck = 0;
  for (int w = 0; w < 2; w++) fp3_track_advance(&rec.t, w, ncheck + 1);

  /* cycles and stalls on the Verilated RTL */
  uint32_t rtl_lat = 0, rtl_cycles = 0, rtl_stalls = 0;
  if (use_rtl) {
    fp3_engine *rtl = fp3_engine_rtl_new_mode(mode, NULL);
    fp3_status rst;
    int r2 = rtl ? fp3_engine_load(rtl, img.words, img.n) : -1;
    for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS && r2 == 0; r++)
      r2 = fp3_engine_write_reg(rtl, r, init[r]);
    if (r2 == 0) r2 = fp3_engine_run(rtl, steps, NULL, &rst);
    if (r2 == 0 && rtl->config.num_regs == FP3_DEFAULT_NUM_REGS) {
      rtl_lat = (uint32_t)(rtl->config.num_lanes > 1) << 17 | (rtl->config.fmax_pipe & 1u) << 16 |
                (rtl->config.mul_latency & 0xFFu) << 8 | (rtl->config.add_latency & 0xFFu);
      rtl_cycles = (uint32_t)rst.cycles;
      rtl_stalls = (uint32_t)rst.stalls;
    } else {
      fprintf(stderr, "fp3 tbgen: note: no cycle counts from the Verilated RTL%s%s\n",
              rtl ? ": " : "", rtl ? fp3_engine_error(rtl) : "");
    }
    fp3_engine_free(rtl);
  }

  if (make_dirs(dir) != 0) {
    fprintf(stderr, "fp3 tbgen: cannot create %s: %s\n", dir, strerror(errno));
    goto out;
  }
  char path[4200];
  snprintf(path, sizeof path, "%s/program.hex", dir);
  if (fp3_image_write(&img, path, in, msg, sizeof msg) != 0) {
    fprintf(stderr, "fp3 tbgen: %s\n", msg);
    goto out;
  }

  FILE *f = open_out(dir, "init.hex", path, sizeof path);
  if (!f) goto out;
  fprintf(f, "// init.hex -- registers r0..r%d before the run (fp3 tbgen %s)\n",
          FP3_DEFAULT_NUM_REGS - 1, in);
  fprintf(f, "// scene: T=%.9g C=%.9g m=%.9g h=%.9g v0=%.9g s0=%.9g\n",
          (double)p.T, (double)p.C, (double)p.m, (double)p.h, (double)p.v0,
          (double)p.s0);
  for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS; r++)
    fprintf(f, "%08" PRIx32 "  // r%u\n", init[r], r);
  if (close_out(f, path)) goto out;

  uint32_t run[TBGEN_RUN_WORDS] = {0};
  run[TBGEN_RUN_MAGIC] = FP3_ID_VALUE;
  run[TBGEN_RUN_VERSION] = TBGEN_VERSION;
  run[TBGEN_RUN_NWORDS] = (uint32_t)img.n;
  run[TBGEN_RUN_NUM_REGS] = FP3_DEFAULT_NUM_REGS;
  run[TBGEN_RUN_STEPS] = steps;
  run[TBGEN_RUN_ERROR] = st.error;
  run[TBGEN_RUN_FAULT_PC] = st.fault_pc;
  run[TBGEN_RUN_STEPS_DONE] = st.steps_done;
  run[TBGEN_RUN_ISSUED] = (uint32_t)st.issued;
  run[TBGEN_RUN_FLAGS] = st.flags;
  run[TBGEN_RUN_REG_V] = rec.t.reg[0] >= 0 ? (uint32_t)rec.t.reg[0] : NO_REG;
  run[TBGEN_RUN_REG_S] = rec.t.reg[1] >= 0 ? (uint32_t)rec.t.reg[1] : NO_REG;
  run[TBGEN_RUN_NCHECK] = ncheck;
  run[TBGEN_RUN_RTL_LAT] = rtl_lat;
  run[TBGEN_RUN_RTL_CYCLES] = rtl_cycles;
  run[TBGEN_RUN_RTL_STALLS] = rtl_stalls;
  static const char *const run_names[TBGEN_RUN_WORDS] = {
      "magic (ID)", "format version", "program words", "registers",
      "STEPS to run", "expected ERROR", "expected FAULT_PC",
      "expected STEPS_DONE", "expected ISSUED (low word)", "expected FLAGS",
      "register of v (ffffffff: none)", "register of s (ffffffff: none)",
      "integrations with v, s in expected.hex",
      "Verilated RTL FMAX_PIPE<<16 | MUL_LATENCY<<8 | ADD_LATENCY (0: not run)",
      "Verilated RTL CYCLES (low word)", "Verilated RTL STALLS (low word)"};
  f = open_out(dir, "run.hex", path, sizeof path);
  if (!f) goto out;
  fprintf(f, "// run.hex -- the run for sim/tb_fp3.v (fp3 tbgen %s)\n", in);
  for (int k = 0; k < TBGEN_RUN_WORDS; k++)
    fprintf(f, "%08" PRIx32 "  // %2d %s\n", run[k], k, run_names[k]);
  if (close_out(f, path)) goto out;

  f = open_out(dir, "expected.hex", path, sizeof path);
  if (!f) goto out;
  fprintf(f, "// expected.hex -- results of %s, %" PRIu32
             " integrations, from the ISS (fp3 tbgen)\n", in, steps);
  fprintf(f, "// final registers r0..r%d\n", FP3_DEFAULT_NUM_REGS - 1);
  for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS; r++)
    fprintf(f, "%08" PRIx32 "  // r%u = %.9g\n", final_regs[r], r,
            (double)fpref_float(final_regs[r]));
  fprintf(f, "// v, s after every integration\n");
  for (uint32_t k = 1; k <= ncheck; k++) {
    uint32_t v = rec.val[0][k - 1], s = rec.val[1][k - 1];
    fprintf(f, "%08" PRIx32 " %08" PRIx32 "  // %" PRIu32 ": v %.9g s %.9g\n",
            v, s, k, (double)fpref_float(v), (double)fpref_float(s));
  }
  if (close_out(f, path)) goto out;
  printf("fp3 tbgen: %s -> %s/{program,init,run,expected}.hex: %zu words, "
         "%" PRIu32 " integrations, %" PRIu32 " checked",
         in, dir, img.n, steps, ncheck);
  if (rtl_lat)
    printf(", Verilator %" PRIu32 " cycles", rtl_cycles);
  printf("\n");
  rc = 0;
out:
  free(rec.val[0]);
  free(rec.val[1]);
  return rc;
}

int fp3_cmd_tbgen(int argc, char **argv) {
  fp3_tbgen_args a;
  int r = fp3_parse_tbgen(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_tbgen(&a) : fp3_args_exit(r, usage_tbgen);
}
