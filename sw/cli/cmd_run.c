/*
 * cmd_run.c -- `fp3 run` (cmd_run.h): a model's program on an engine, every
 * state variable of every object checked bit for bit against the golden
 * model after every integration, and compared with the GSL reference and
 * the model's exact solution.
 *
 * One path: a model (--model, a model scene's, a program's `.model`, or
 * models/ship.fp3m), a program for it (compiled for an integrator, or a
 * hand-written one bound to the model by name, fp3_compile_bind), one
 * object or many (--objects N, --scene), an engine.  A scene in the ship's
 * five-column format is read as a scene of models/ship.fp3m (runsetup.c),
 * its integrator the paper's RK4, rk4se (fp3_ship_scene_integrator).
 */
#include "cmd_run.h"

#include <errno.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "asm.h"
#include "cliopt.h"
#include "cmd_asm.h"
#include "cmd_model.h"
#include "compile.h"
#include "engine.h"
#include "engine_spatial.h"
#include "fpenv.h"
#include "fpref.h"
#include "model.h"
#include "modelref.h"
#include "mscene.h"
#include "report.h"
#include "runsetup.h"
#include "traceopt.h"

/* fp3-mpi (-DFP3_MPI): a scene's objects sharded across the MPI ranks
 * (mpishard.h), rank 0 reporting; build/fp3 runs them in one process. */
#ifdef FP3_MPI
#include "mpishard.h"
#define RUN_STATE_OBJECTS fp3_mpi_run_state_objects
#define SCENE_REFERENCES fp3_mpi_scene_references
#define REPORTS (fp3_mpi_rank() == 0)
#define ABORT_RANKS() MPI_Abort(MPI_COMM_WORLD, 1) /* the others wait in a collective */
#else
#define RUN_STATE_OBJECTS fp3_run_state_objects
#define SCENE_REFERENCES scene_references
#define REPORTS 1
#define ABORT_RANKS() ((void)0)
#endif

#define EXIT_FAIL 1
#define EXIT_USAGE 2

#define DEFAULT_PROGRAM "programs/ship_rk4.s" /* the paper's RK4 program */
#define MAX_CHECKED (1u << 26) /* object-steps x state variables kept for the check */
#define TABLE_ROWS 5           /* first integrations shown in the report */
#define SHOW_OBJECTS 8         /* objects shown in the report of many    */
/* The paper's measured cycles of the ship's RK4 (Woulfe & Manzke 2006,
 * §5): the first integration and each later one. */
#define PAPER_FIRST 445
#define PAPER_LATER 418

static void usage(FILE *f) {
  fprintf(f,
          "usage: fp3 run [--model FILE.fp3m] [--program FILE.s | --integrator NAME [--literal]]\n"
          "               [--set NAME=VALUE ...] [--steps N]\n"
          "               [--engine rtl|iss|spatial [--pipelines N] [--clock-cores]|uart:DEVICE[@BAUD]]\n"
          "               [--objects N [--seed S] | --scene FILE]\n"
          "               [--round rne|rtz] [--ftz] [--json]\n"
          "               [--trace FILE.vcd [--trace-window FIRST:COUNT] [--trace-limit SIZE]]\n"
          "\n"
          "Run a model's program on the engine and compare every state variable\n"
          "after every integration with the golden model, bit for bit; report the\n"
          "error against GSL rk8pd (1e-12) and the model's exact solution.\n"
          "Without --model, --program, --integrator and --scene: the paper's\n"
          "program %s on models/ship.fp3m.\n"
          "\n"
          "  --model FILE      the model (.fp3m, docs/models.md; default %s, or\n"
          "                    the program's `.model`, or the scene's)\n"
          "  --program FILE    a hand-written program for the model: its `.integrator`\n"
          "                    names the golden model, its `.in`/`.out` lines bind\n"
          "                    registers to the model's names (programs/ship_*.s)\n"
          "  --integrator I    compile the model for I (default rk4), one of\n"
          "                    %s\n"
          "  --literal         the integrator exactly as docs/models.md writes it\n"
          "                    (default: folded)\n"
          "  --set NAME=VALUE  h, a param or a state variable's initial value (NAME or\n"
          "                    NAME0), binary32; the model file's defaults otherwise\n"
          "  --steps N         integrations, 1..4294967295 (default %u)\n"
          "  --engine E        rtl (Verilated RTL, default) or iss (simulator; its\n"
          "                    cycles are instructions, one issued a cycle), spatial (the\n"
          "                    model's step as one pipeline, fp3 spatial: Verilated on\n"
          "                    first use into build/spatial-cache, or $FP3_SPATIAL_CACHE;\n"
          "                    its C++ compiler $FP3_SPATIAL_CXX, else clang++ or g++;\n"
          "                    not with --program or --trace; docs/spatial.md;\n"
          "                    --pipelines N, 1..255 (default 1): N pipelines, object o\n"
          "                    in pipeline o mod N, as the chip's; --clock-cores: the\n"
          "                    cores' latencies of the chip make pnr-spatial places,\n"
          "                    fp3 spatial --clock-cores), or a board\n"
          "                    on a serial line: uart:DEVICE[@BAUD] (default 3000000),\n"
          "                    uart:socket://HOST:PORT (docs/board.md; no trace port:\n"
          "                    the state after the run is compared)\n"
          "  --objects N       N objects on the contexts and lanes, in batches: object 0\n"
          "                    the --set values, the others each value (h excepted)\n"
          "                    times its own factor in [0.75, 1.25] from --seed S\n"
          "  --scene FILE      a model scene ('model FILE', 'h STEP', a header naming\n"
          "                    the columns, one object a line; scenes/); a ship scene\n"
          "                    of five columns 'h STEP', then 'T C m v0 s0' a line, is a\n"
          "                    scene of models/ship.fp3m whose integrator is rk4se\n"
          "                    (the paper's RK4) unless --integrator names another\n"
          "  --round R, --ftz  the cores' rounding (rne, rtz) and flush-to-zero; the\n"
          "                    host values, the ISS and the golden model follow\n"
          "  --json            one JSON object (docs/json.md) instead of the report\n"
          "  --trace FILE      waveform of a one-object run on the rtl engine: a VCD of\n"
          "                    cycles FIRST .. FIRST+COUNT-1 (default 0:%u; COUNT\n"
          "                    'all': to the end), written under a temporary name and\n"
          "                    renamed when the run is over (none left on a failure or a\n"
          "                    signal); its size is estimated first and refused above\n"
          "                    --trace-limit SIZE (default 1G; K, M, G, T or none)\n"
          "\n"
          "Exit status: 0 the run finished without error and bit-exact with the\n"
          "golden model; 1 it did not (or a state went non-finite); 2 bad\n"
          "arguments, model or program.\n",
          DEFAULT_PROGRAM, FP3_DEFAULT_MODEL, fp3_model_integrators(), FP3_RUN_DEFAULT_STEPS,
          FP3_TRACE_WINDOW_DEFAULT);
}

/* ---- one object --------------------------------------------------------------- */

static int run_one(const fp3_model_args *a, fp3_run_setup *s) {
  const fp3_model *m = s->m;
  const unsigned ns = m->nstate;
  fp3_compiled *c = s->c;
  fp3_engine *e = s->e;
  fp3_state_obs ob;
  memset(&ob, 0, sizeof ob);
  int rc = EXIT_FAIL;
  unsigned regs[4 * FP3_MODEL_MAX_VARS];
  uint32_t vals[4 * FP3_MODEL_MAX_VARS];
  fpenv_saved env;
  if (fpenv_enter(a->mode, &env)) return EXIT_USAGE; /* checked by the parse */
  size_t nw = fp3_compiled_model_start(c, s->in, s->y0, regs, vals, 4 * FP3_MODEL_MAX_VARS);
  fpenv_leave(&env);
  const fp3_image *img = fp3_compiled_image(c);
  int erc = fp3_engine_load(e, img->words, img->n);
  if (erc) {
    fprintf(stderr, "fp3 run: %s: refused by the %s engine: %s\n",
            s->program ? s->program : m->file, a->engine, fp3_engine_error(e));
    return EXIT_FAIL;
  }
  for (size_t w = 0; w < nw && erc == 0; w++) erc = fp3_engine_write_reg(e, regs[w], vals[w]);
  ob.nstate = ns;
  ob.steps = a->steps;
  for (unsigned i = 0; i < ns; i++) ob.reg[i] = fp3_compiled_state_reg(c, i);
  /* every integration when the engine reports its write-backs; a board's
   * (no trace port) is compared after the run, its final state */
  if ((uint64_t)a->steps * ns <= MAX_CHECKED && !fp3_engine_untraced(e)) {
    ob.v = calloc((size_t)a->steps * ns, sizeof *ob.v);
    ob.seen = calloc((size_t)a->steps * ns, 1);
    if (!ob.v || !ob.seen) {
      fprintf(stderr, "fp3 run: out of memory\n");
      goto out;
    }
  }
  fp3_status st;
  memset(&st, 0, sizeof st);
  if (erc == 0) {
    fp3_observer obs = {.ctx = &ob, .on_write = fp3_state_obs_write, .on_endi = fp3_state_obs_endi};
    erc = fp3_engine_run(e, a->steps, &obs, &st);
  }
  if (erc) {
    fprintf(stderr, "fp3 run: %s engine: %s\n", a->engine, fp3_engine_error(e));
    goto out;
  }
  fp3_trace_note(&a->trace, "run", st.cycles);
  const uint32_t done = st.steps_done < a->steps ? st.steps_done : a->steps;
  /* the bit-for-bit check, every integration; the first non-finite value;
   * the first rows of the report */
  uint32_t cur[FP3_MODEL_MAX_VARS], mism_k = 0, nonfinite_k = 0, gwant = 0, ggot = 0;
  uint32_t row[TABLE_ROWS][FP3_MODEL_MAX_VARS];
  unsigned mism_i = 0, nonfinite_i = 0;
  uint64_t mismatches = 0;
  float g[FP3_MODEL_MAX_VARS] = {0};
  /* divergence: a state past the growth bound (fp3 bench's criterion);
   * a position may grow without bound, so only the other states count */
  double bound = 0.0;
  uint32_t diverged_k = 0;
  unsigned diverged_i = 0;
  for (unsigned i = 0; i < ns; i++) bound = fmax(bound, fabs((double)s->y0[i]));
  bound = FP3_GROWTH_BOUND * (1.0 + bound);
  for (unsigned i = 0; i < ns; i++) cur[i] = fpref_bits(s->y0[i]), g[i] = s->y0[i];
  fpenv_enter(a->mode, &env);
  for (uint32_t k = 1; k <= done; k++) {
    fp3_compiled_model_step(c, g);
    for (unsigned i = 0; i < ns; i++) {
      size_t q = (size_t)(k - 1) * ns + i;
      if (ob.v && ob.seen[q]) cur[i] = ob.v[q];
      if (!ob.v && k == done) fp3_engine_read_reg(e, ob.reg[i], &cur[i]);
      if ((ob.v || k == done) && cur[i] != fpref_bits(g[i]) && !mismatches++)
        mism_k = k, mism_i = i, ggot = cur[i], gwant = fpref_bits(g[i]);
      if (!nonfinite_k && !isfinite(g[i])) nonfinite_k = k, nonfinite_i = i;
      if (!diverged_k && m->role[i] != FP3_MR_POSITION && !(fabs((double)g[i]) <= bound))
        diverged_k = k, diverged_i = i;
      if (k <= TABLE_ROWS) row[k - 1][i] = ob.v ? cur[i] : fpref_bits(g[i]);
    }
  }
  fpenv_leave(&env);
  double ref[FP3_MODEL_MAX_VARS], ex[FP3_MODEL_MAX_VARS];
  char rmsg[256] = "";
  fp3_run_references(m, s->in, s->y0, done, !nonfinite_k, ref, ex, rmsg, sizeof rmsg);
  const int have_ref = done > 0 && !nonfinite_k && !isnan(ref[0]);
  const double cyc_first = ob.endis >= 1 ? (double)ob.cyc_first + 1.0 : NAN;
  const double cyc_per =
      ob.endis >= 2 ? (double)(ob.cyc_last - ob.cyc_first) / (double)(ob.endis - 1) : NAN;
  const int ok = st.error == FP3_ERR_NONE && done == a->steps && mismatches == 0 && !nonfinite_k;
  const int paper = strcmp(m->name, "ship") == 0;
  char flags[96];
  fp3_flags_text(st.flags, flags, sizeof flags);
  if (a->json) {
    fp3_run_json_head(a, s, NULL);
    printf(", \"steps\": %" PRIu32 ", \"steps_done\": %" PRIu32 ", \"objects\": 1", a->steps,
           st.steps_done);
    printf(", \"contexts\": 1, \"lanes\": 1, \"batches\": 1");
    printf(", \"cycles\": %" PRIu64 ", \"issued\": %" PRIu64 ", \"stalls\": %" PRIu64, st.cycles,
           st.issued, st.stalls);
    fp3_json_member_double(stdout, "cycles_first_step", cyc_first);
    fp3_json_member_double(stdout, "cycles_later_step", cyc_per);
    printf(", \"cycles_per_object_step\": %.9g", (double)st.cycles / (double)a->steps);
    printf(", \"golden_mismatches\": %" PRIu64 ", \"first_mismatch\": ", mismatches);
    if (mismatches)
      printf("{\"object\": 0, \"integration\": %" PRIu32 ", \"variable\": \"%s\", \"got\": "
             "\"0x%08" PRIX32 "\", \"want\": \"0x%08" PRIX32 "\"}", mism_k, m->state[mism_i],
             ggot, gwant);
    else
      printf("null");
    printf(", \"nonfinite_from\": ");
    if (nonfinite_k)
      printf("{\"object\": 0, \"integration\": %" PRIu32 ", \"variable\": \"%s\"}", nonfinite_k,
             m->state[nonfinite_i]);
    else
      printf("null");
    printf(", \"diverged_from\": ");
    if (diverged_k)
      printf("{\"integration\": %" PRIu32 ", \"variable\": \"%s\", \"bound\": %.9g}",
             diverged_k, m->state[diverged_i], bound);
    else
      printf("null");
    fp3_run_json_error(st.error, 0, st.fault_pc);
    printf(", \"flags\": \"%s\", \"flags_bits\": %" PRIu32 ", \"params\": {", flags, st.flags);
    for (unsigned k = 0; k < m->nparam; k++) {
      printf("%s\"%s\": ", k ? ", " : "", m->param[k]);
      fp3_json_float(stdout, s->in[k]);
    }
    for (unsigned k = 0; k < ns; k++) {
      printf(", \"%s0\": ", m->state[k]);
      fp3_json_float(stdout, s->y0[k]);
    }
    printf("}, \"max_error_ref\": ");
    double emax = have_ref ? 0.0 : NAN;
    for (unsigned k = 0; have_ref && k < ns; k++)
      if (!(fabs((double)fpref_float(cur[k]) - ref[k]) <= emax))
        emax = fabs((double)fpref_float(cur[k]) - ref[k]);
    fp3_json_double(stdout, emax);
    printf(", \"results\": [");
    fp3_run_json_object(m, cur, g, ref, ex);
    printf("], \"pass\": %s}\n", ok ? "true" : "false");
  } else {
    printf("FP3 run: engine %s, model %s (%s), ", a->engine, m->name, m->file);
    if (s->program) printf("program %s (%s)", s->program, s->integ);
    else printf("integrator %s %s", s->integ, s->literal ? "literal" : "folded");
    printf(", %" PRIu32 " integrations\n", a->steps);
    const fp3_compile_stats *cs = fp3_compiled_stats(c);
    printf("program: %zu words, %u instructions per integration, %u registers (NUM_REGS %u)\n",
           img->n, cs->body_insns, cs->regs_needed, e->config.num_regs);
    printf("object:");
    for (unsigned k = 0; k < m->nparam; k++)
      printf(" %s = %.9g", m->param[k], (double)s->in[k]);
    for (unsigned k = 0; k < ns; k++) printf(", %s0 = %.9g", m->state[k], (double)s->y0[k]);
    printf("\n");
    if (done > 0) { /* the first integrations against the exact solution */
      printf("\n%10s %10s", "step", "t");
      for (unsigned k = 0; k < ns && k < 4; k++)
        printf(" %15s%s", m->state[k], isnan(ex[0]) ? "" : "           exact");
      printf("\n");
      for (uint32_t k = 1; k <= done && k <= TABLE_ROWS; k++) {
        double din[FP3_MODEL_MAX_VARS], dy0[FP3_MODEL_MAX_VARS], exk;
        for (unsigned q = 0; q < m->nparam; q++) din[q] = s->in[q];
        for (unsigned q = 0; q < ns; q++) dy0[q] = s->y0[q];
        printf("%10" PRIu32 " %10.4f", k, (double)k * (double)s->in[0]);
        for (unsigned q = 0; q < ns && q < 4; q++) {
          printf(" %15.9g", (double)fpref_float(row[k - 1][q]));
          if (!isnan(ex[0]))
            printf(" %15.9g",
                   fp3_model_exact(m, q, din, dy0, (double)k * din[0], &exk) ? NAN : exk);
        }
        printf("\n");
      }
      if (done > TABLE_ROWS) printf("%10s\n", "...");
    }
    printf("\n%-12s %16s %16s %22s %12s %12s\n", "state", "value", "golden", "reference (GSL)",
           "error", "exact");
    for (unsigned k = 0; k < ns; k++) {
      printf("%-12s %16.9g %16.9g", m->state[k], (double)fpref_float(cur[k]), (double)g[k]);
      if (have_ref) printf(" %22.15g %12.3g", ref[k], (double)fpref_float(cur[k]) - ref[k]);
      else printf(" %22s %12s", "-", "-");
      if (!isnan(ex[k])) printf(" %12.9g", ex[k]);
      printf("\n");
    }
    if (!have_ref && rmsg[0]) printf("reference: %s\n", rmsg);
    printf("golden model: %" PRIu64 " mismatches in %" PRIu32 " integrations%s\n", mismatches,
           done, ob.v ? " (every state variable, bit for bit)" : " (the final state only)");
    if (mismatches)
      printf("  first at integration %" PRIu32 ": %s = 0x%08" PRIX32 " (%.9g), golden 0x%08" PRIX32
             " (%.9g), %" PRId64 " ulp\n", mism_k, m->state[mism_i], ggot,
             (double)fpref_float(ggot), gwant, (double)fpref_float(gwant),
             fp3_ulp_distance(ggot, gwant));
    if (ob.endis >= 1) {
      printf("cycles: first integration %.0f", cyc_first);
      if (paper) printf(" (paper %d)", PAPER_FIRST);
      if (ob.endis >= 2) {
        printf(", later %.2f per integration", cyc_per);
        if (paper) printf(" (paper %d)", PAPER_LATER);
      }
      printf("\n");
    }
    printf("        total %" PRIu64 " %s, %" PRIu64 " issued, %" PRIu64 " stalls\n", st.cycles,
           strcmp(a->engine, "iss") == 0 ? "instructions" : "cycles", st.issued, st.stalls);
    printf("flags: %s\n", flags);
    if (diverged_k)
      printf("DIVERGED: state variable %s is beyond %g, %g (1 + max |initial state|), from "
             "integration %" PRIu32 " on (the largest stable h: fp3 bench --model %s "
             "--stability FILE.csv)\n", m->state[diverged_i], bound, FP3_GROWTH_BOUND,
             diverged_k, m->file);
    if (nonfinite_k)
      printf("NON-FINITE: state variable %s is not finite after integration %" PRIu32
             " (flags: %s)\n", m->state[nonfinite_i], nonfinite_k, flags);
    if (st.error != FP3_ERR_NONE)
      printf("run error: %s at pc %" PRIu32 ": %s\n", fp3_error_name(st.error), st.fault_pc,
             fp3_engine_error(e)[0] ? fp3_engine_error(e) : fp3_error_text(st.error));
    if (ok)
      printf("PASS: %" PRIu32 " integrations on %s bit-exact with the golden model\n", a->steps,
             a->engine);
    else if (st.error != FP3_ERR_NONE)
      printf("FAIL: run error %s after %" PRIu32 " of %" PRIu32 " integrations\n",
             fp3_error_name(st.error), st.steps_done, a->steps);
    else if (done != a->steps)
      printf("FAIL: the run ended after %" PRIu32 " of %" PRIu32 " integrations\n", done,
             a->steps);
    else if (mismatches)
      printf("FAIL: %" PRIu64 " golden mismatches, first at integration %" PRIu32 "\n",
             mismatches, mism_k);
    else
      printf("FAIL: a state variable is not finite\n");
  }
  if (nonfinite_k)
    fprintf(stderr, "fp3 run: %s: state variable %s is not finite after integration %" PRIu32
            " of %s\n", m->file, m->state[nonfinite_i], nonfinite_k, s->integ);
  rc = ok ? 0 : EXIT_FAIL;
out:
  free(ob.v);
  free(ob.seen);
  return rc;
}

/* ---- many objects: a model scene, or --objects N -------------------------- */

#ifndef FP3_MPI
/* The GSL reference (want_ref 0: none) and the exact solution of every
 * object of sc after `steps` integrations, into ref[] and ex[] (objects x
 * state variables); fp3-mpi shards them as it shards the objects (slots a
 * batch: fp3_mpi_scene_references). */
static void scene_references(const fp3_model *m, const fp3_mscene *sc, unsigned slots,
                             uint32_t steps, int want_ref, double *ref, double *ex) {
  const unsigned np = m->nparam, ns = m->nstate;
  (void)slots;
  for (size_t o = 0; o < sc->n; o++) {
    char rmsg[256];
    fp3_run_references(m, sc->in + o * np, sc->y0 + o * ns, steps, want_ref, ref + o * ns,
                       ex + o * ns, rmsg, sizeof rmsg);
  }
}
#endif

static int run_many(const fp3_model_args *a, fp3_run_setup *s) {
  const fp3_mscene *sc = &s->sc;
  const fp3_model *m = s->m;
  const unsigned ns = m->nstate;
  char msg[512];
  fp3_state_result res;
  memset(&res, 0, sizeof res);
  double *ref = NULL, *ex = NULL;
  int rc = EXIT_FAIL;
  fp3_scene_gold sg;
  fp3_scene_gold_init(&sg, s->c, sc);
  const fp3_image *img = fp3_compiled_image(s->c);
  if (RUN_STATE_OBJECTS(s->e, img->words, img->n, sc->n, a->steps, a->mode, &sg.golden, &res,
                        msg, sizeof msg)) {
    if (REPORTS) fprintf(stderr, "fp3 run: %s engine: %s\n", a->engine, msg);
    goto out;
  }
  ref = malloc(sc->n * ns * sizeof *ref);
  ex = malloc(sc->n * ns * sizeof *ex);
  if (!ref || !ex) {
    fprintf(stderr, "fp3 run: out of memory\n");
    ABORT_RANKS();
    goto out;
  }
  const int nonfinite = res.nonfinite_object != SIZE_MAX;
  SCENE_REFERENCES(m, sc, fp3_config_slots(&s->e->config), a->steps, !nonfinite, ref, ex);
  if (!REPORTS) { /* another rank of fp3-mpi: rank 0 has the results */
    rc = 0;
    goto out;
  }
  double max_err = 0.0;
  size_t ref_fail = 0;
  for (size_t o = 0; o < sc->n; o++) {
    if (isnan(ref[o * ns])) {
      ref_fail++;
      continue;
    }
    for (unsigned k = 0; k < ns; k++) {
      double d = fabs((double)fpref_float(res.y[o * ns + k]) - ref[o * ns + k]);
      if (d > max_err || d != d) max_err = d;
    }
  }
  const double object_steps = (double)res.objects * (double)a->steps;
  const double per = (double)res.cycles / object_steps;
  /* the share of cycles in which the adder / the multiplier took an instruction */
  const double add_util =
      res.cycles ? (double)res.unit_issued[FP3_UNIT_ADD] / (double)res.cycles : 0.0;
  const double mul_util =
      res.cycles ? (double)res.unit_issued[FP3_UNIT_MUL] / (double)res.cycles : 0.0;
  const int ok = res.mismatches == 0 && res.error == FP3_ERR_NONE && !nonfinite;
  const fp3_compile_stats *cs = fp3_compiled_stats(s->c);
  char flags[96];
  fp3_flags_text(res.flags, flags, sizeof flags);
  const char *where = a->scene ? a->scene : "generated (--objects, --seed)";
  if (a->json) {
    fp3_run_json_head(a, s, where);
    printf(", \"steps\": %" PRIu32 ", \"steps_done\": %" PRIu32 ", \"objects\": %zu", a->steps,
           res.error ? 0 : a->steps, res.objects);
    printf(", \"contexts\": %u, \"lanes\": %u, \"batches\": %zu", res.contexts, res.lanes,
           res.batches);
    printf(", \"cycles\": %" PRIu64 ", \"issued\": %" PRIu64 ", \"stalls\": %" PRIu64, res.cycles,
           res.issued, res.stalls);
    printf(", \"cycles_first_step\": null, \"cycles_later_step\": null");
    printf(", \"cycles_per_object_step\": %.9g", per);
    if (!res.final_only) { /* a board counts no issues per unit: both left out */
      printf(", \"issued_per_object_step\": %.9g", (double)res.issued / object_steps);
      printf(", \"utilization\": {\"add\": %.6f, \"mul\": %.6f}", add_util, mul_util);
    }
    printf(", \"golden_mismatches\": %" PRIu64 ", \"first_mismatch\": ", res.mismatches);
    if (res.mismatches)
      printf("{\"object\": %zu, \"integration\": %" PRIu32 ", \"variable\": \"%s\", \"got\": "
             "\"0x%08" PRIX32 "\", \"want\": \"0x%08" PRIX32 "\"}", res.first_object,
             res.first_step, m->state[res.first_var], res.first_got, res.first_want);
    else
      printf("null");
    printf(", \"nonfinite_from\": ");
    if (nonfinite)
      printf("{\"object\": %zu, \"integration\": %" PRIu32 ", \"variable\": \"%s\"}",
             res.nonfinite_object, res.nonfinite_step, m->state[res.nonfinite_var]);
    else
      printf("null");
    fp3_run_json_error(res.error, res.error_object, res.error_pc);
    printf(", \"flags\": \"%s\", \"flags_bits\": %" PRIu32 ", \"params\": null", flags,
           res.flags);
    printf(", \"max_error_ref\": ");
    fp3_json_double(stdout, ref_fail == sc->n ? NAN : max_err);
    printf(", \"results\": [");
    for (size_t o = 0; o < sc->n; o++) {
      printf("%s", o ? ", " : "");
      fp3_run_json_object(m, res.y + o * ns, NULL, ref + o * ns, ex + o * ns);
    }
    printf("], \"pass\": %s}\n", ok ? "true" : "false");
  } else {
    printf("FP3 run: engine %s, model %s (%s), ", a->engine, m->name, sc->model_path);
    if (s->program) printf("program %s (%s)", s->program, s->integ);
    else printf("integrator %s %s", s->integ, s->literal ? "literal" : "folded");
    printf(", %zu objects, %" PRIu32 " integrations each\n", res.objects, a->steps);
    printf("program: %u instructions per integration", cs->body_insns);
    if (!s->literal) printf(" (literal program %u)", cs->literal_body_insns);
    printf(", %u registers needed (NUM_REGS %u); scheduler estimate %u cycles per integration of "
           "one object\n", cs->regs_needed, s->e->config.num_regs, cs->est_cycles_later);
    printf("scene: %s; %u contexts x %u lanes per batch, %zu batch%s\n\n", where, res.contexts,
           res.lanes, res.batches, res.batches == 1 ? "" : "es");
    printf("  object");
    for (unsigned k = 0; k < ns; k++) printf(" %14s %14s", m->state[k], "reference");
    printf("\n");
    for (size_t o = 0; o < sc->n && o < SHOW_OBJECTS; o++) {
      printf("%8zu", o);
      for (unsigned k = 0; k < ns; k++)
        printf(" %14.7g %14.7g", (double)fpref_float(res.y[o * ns + k]), ref[o * ns + k]);
      printf("\n");
    }
    if (sc->n > SHOW_OBJECTS) printf("     ... (%zu more)\n", sc->n - SHOW_OBJECTS);
    if (res.final_only)
      printf("\ngolden model: %" PRIu64 " mismatches in the final state of %zu objects after "
             "%" PRIu32 " integrations (every state variable, bit for bit; the engine reports "
             "no write-backs)\n", res.mismatches, res.objects, a->steps);
    else
      printf("\ngolden model: %" PRIu64 " mismatches in %.0f object-steps (every state variable, "
             "bit for bit)\n", res.mismatches, object_steps);
    if (res.mismatches)
      printf("  first: object %zu, integration %" PRIu32 ", %s = 0x%08" PRIX32
             ", golden 0x%08" PRIX32 "\n", res.first_object, res.first_step,
             m->state[res.first_var], res.first_got, res.first_want);
    if (ref_fail < sc->n)
      printf("error against the GSL reference (rk8pd, 1e-12): largest %.3g over %zu objects\n",
             max_err, sc->n - ref_fail);
    printf("cycles: %" PRIu64 " in all, %.2f per object-step (issued %.2f per object-step)\n",
           res.cycles, per, (double)res.issued / object_steps);
    if (fp3_engine_spatial_is(s->e))
      printf("pipeline: latency %u cycles, %u cores; an object entered in %.1f %% of the "
             "cycles\n", fp3_engine_spatial_latency(s->e), fp3_engine_spatial_cores(s->e),
             100 * object_steps / (double)res.cycles);
    else if (res.final_only)
      printf("utilization: not measured (the engine reports no issues per unit)\n");
    else
      printf("utilization: adder %.1f %%, multiplier %.1f %%\n", 100 * add_util, 100 * mul_util);
    printf("flags: %s\n", flags);
    if (res.error)
      printf("error: object %zu: %s at pc %" PRIu32 "\n", res.error_object,
             fp3_error_text(res.error), res.error_pc);
    if (ok)
      printf("PASS: %zu objects x %" PRIu32 " integrations on %s bit-exact with the golden "
             "model\n", res.objects, a->steps, a->engine);
    else
      printf("FAIL\n");
  }
  if (nonfinite) {
    size_t o = res.nonfinite_object;
    char line[32] = "";
    if (sc->line && sc->line[o]) snprintf(line, sizeof line, ":%d", sc->line[o]);
    fprintf(stderr, "fp3 run: %s%s: object %zu: state variable %s is not finite after "
            "integration %" PRIu32 " of %s\n", a->scene ? a->scene : m->file, line, o,
            m->state[res.nonfinite_var], res.nonfinite_step, s->integ);
  }
  rc = ok ? 0 : EXIT_FAIL;
out:
  free(ref);
  free(ex);
  fp3_state_result_free(&res);
  return rc;
}

/* ---- fp3 run ------------------------------------------------------------------ */

int fp3_cmd_run(int argc, char **argv) {
  fp3_model_args a;
  int r = fp3_parse_model(argc, argv, "run", &a);
  if (r != FP3_ARGS_RUN) return fp3_args_exit(r, usage);
  fp3_run_setup s;
  memset(&s, 0, sizeof s);
  fp3_image_init(&s.img);
  /* one object or --objects: the paper's program; a scene: its compiled one */
  int rc = fp3_run_setup_program(&a, &s, "run", a.scene ? NULL : DEFAULT_PROGRAM);
  if (!rc) rc = fp3_run_setup_model(&a, &s, "run");
  if (!rc) rc = fp3_run_setup_engine(&a, &s, "run");
  if (!rc) rc = s.many ? run_many(&a, &s) : REPORTS ? run_one(&a, &s) : 0;
  fp3_run_setup_free(&s);
  return rc;
}
