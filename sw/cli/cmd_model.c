/*
 * cmd_model.c -- `fp3 run --model` and `fp3 compile --model` (cmd_model.h).
 */
#include "cmd_model.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cliopt.h"
#include "compile.h"
#include "engine.h"
#include "fpref.h"
#include "model.h"
#include "modelref.h"
#include "report.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2
#define DEFAULT_STEPS 1000u
/* object-steps x state variables the bit-for-bit check keeps */
#define MAX_CHECKED (1u << 26)

int fp3_args_have_model(int argc, char **argv) {
  for (int i = 1; i < argc; i++)
    if (strcmp(argv[i], "--model") == 0 || strncmp(argv[i], "--model=", 8) == 0) return 1;
  return 0;
}

static void usage(FILE *f) {
  fprintf(f,
          "usage: fp3 run --model FILE [--integrator NAME] [--literal]\n"
          "               [--set NAME=VALUE ...] [--steps N] [--engine rtl|iss] [--json]\n"
          "       fp3 compile --model FILE [--integrator NAME] [--literal] [-o OUT.s]\n"
          "\n"
          "  --model FILE      a model file (.fp3m, docs/models.md; models/ has examples)\n"
          "  --integrator I    %s (default rk4; symeuler needs `position`\n"
          "                    and `velocity` lines)\n"
          "  --literal         the integrator exactly as docs/models.md writes it, bit for\n"
          "                    bit (default: folded: parameter-only divisions become\n"
          "                    products with the host's reciprocal, zero terms removed)\n"
          "  --set NAME=VALUE  h, every param and every state variable's initial value\n"
          "                    (binary32; each one required)\n"
          "  --steps N         integrations (default %u)\n"
          "  --engine E        rtl (default) or iss\n"
          "  --json            one JSON object: results[0] has every state variable by\n"
          "                    name and NAME_ref, its GSL reference value\n",
          fp3_model_integrators(), DEFAULT_STEPS);
}

typedef struct margs {
  const char *file, *integ, *engine, *out;
  int literal, json;
  uint32_t steps;
  const char *set[2 * FP3_MODEL_MAX_VARS + 8];
  int nset;
} margs;

static int parse_args(int argc, char **argv, const char *cmd, margs *a) {
  memset(a, 0, sizeof *a);
  a->integ = "rk4";
  a->engine = "rtl";
  a->steps = DEFAULT_STEPS;
  for (int i = 1; i < argc; i++) {
    const char *v;
    int r;
    if (fp3_is_help(argv[i])) {
      usage(stdout);
      return 1;
    }
    if ((r = fp3_opt_value(argc, argv, &i, cmd, "--model", &v)) != 0) {
      if (r < 0) return -1;
      a->file = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, cmd, "--integrator", &v)) != 0) {
      if (r < 0) return -1;
      a->integ = v;
    } else if (strcmp(cmd, "run") == 0 &&
               (r = fp3_opt_value(argc, argv, &i, cmd, "--engine", &v)) != 0) {
      if (r < 0) return -1;
      if (strcmp(v, "rtl") != 0 && strcmp(v, "iss") != 0) {
        fprintf(stderr, "fp3 %s: --engine wants rtl or iss, got '%s'\n", cmd, v);
        return -1;
      }
      a->engine = v;
    } else if (strcmp(cmd, "run") == 0 &&
               (r = fp3_opt_value(argc, argv, &i, cmd, "--steps", &v)) != 0) {
      unsigned long long s;
      if (r < 0) return -1;
      if (fp3_parse_count(v, 1, UINT32_MAX, &s)) {
        fprintf(stderr, "fp3 %s: --steps '%s': want 1..%" PRIu32 "\n", cmd, v, UINT32_MAX);
        return -1;
      }
      a->steps = (uint32_t)s;
    } else if (strcmp(cmd, "run") == 0 &&
               (r = fp3_opt_value(argc, argv, &i, cmd, "--set", &v)) != 0) {
      if (r < 0) return -1;
      if (a->nset == (int)(sizeof a->set / sizeof a->set[0])) {
        fprintf(stderr, "fp3 %s: too many --set\n", cmd);
        return -1;
      }
      a->set[a->nset++] = v;
    } else if (strcmp(cmd, "compile") == 0 &&
               ((r = fp3_opt_value(argc, argv, &i, cmd, "-o", &v)) != 0 ||
                (r = fp3_opt_value(argc, argv, &i, cmd, "--output", &v)) != 0)) {
      if (r < 0) return -1;
      a->out = v;
    } else if (strcmp(argv[i], "--literal") == 0) {
      a->literal = 1;
    } else if (strcmp(cmd, "run") == 0 && strcmp(argv[i], "--json") == 0) {
      a->json = 1;
    } else {
      fprintf(stderr, "fp3 %s: '%s' does not go with --model (see fp3 %s --model x --help)\n",
              cmd, argv[i], cmd);
      return -1;
    }
  }
  if (!a->file || !a->file[0]) {
    fprintf(stderr, "fp3 %s: --model needs a file\n", cmd);
    return -1;
  }
  return 0;
}

/* Compile the model for a's integrator (folded: params zero in this
 * object, zero[], removed). */
static fp3_compiled *compile_for(const fp3_model *m, const margs *a, const unsigned char *zero,
                                 const char *cmd) {
  fp3_compile_opts o;
  fp3_compile_defaults(&o);
  o.fold = o.drop_zero = !a->literal;
  fp3_compiled *c = NULL;
  char msg[512];
  if (!fp3_model_integrator_known(a->integ)) {
    fprintf(stderr, "fp3 %s: unknown integrator '%s' for a model (%s)\n", cmd, a->integ,
            fp3_model_integrators());
    return NULL;
  }
  if (fp3_compile_model(m, a->integ, &o, zero, &c, msg, sizeof msg)) {
    fprintf(stderr, "fp3 %s: %s: %s\n", cmd, m->file, msg);
    return NULL;
  }
  return c;
}

int fp3_cmd_compile_model(int argc, char **argv) {
  margs a;
  int r = parse_args(argc, argv, "compile", &a);
  if (r) return r > 0 ? 0 : EXIT_USAGE;
  fp3_model *m = malloc(sizeof *m);
  char msg[512];
  if (!m) return EXIT_FAIL;
  if (fp3_model_load(a.file, m, msg, sizeof msg)) {
    fprintf(stderr, "fp3 compile: %s\n", msg);
    free(m);
    return EXIT_USAGE;
  }
  fp3_compiled *c = compile_for(m, &a, NULL, "compile");
  int rc = c ? 0 : EXIT_USAGE;
  if (c && a.out && fp3_compiled_write(c, a.out, msg, sizeof msg)) {
    fprintf(stderr, "fp3 compile: %s\n", msg);
    rc = EXIT_FAIL;
  } else if (c && !a.out) {
    fputs(fp3_compiled_text(c), stdout);
  }
  if (c && a.out && rc == 0) {
    const fp3_compile_stats *s = fp3_compiled_stats(c);
    fprintf(stderr, "fp3 compile: %s: model %s, %s %s: %u instructions per integration, "
            "prologue %u, %u registers, about %u cycles per integration (one object)\n",
            a.out, m->name, a.integ, a.literal ? "literal" : "folded", s->body_insns,
            s->prologue_insns, s->regs, s->est_cycles_later);
  }
  fp3_compiled_free(c);
  free(m);
  return rc;
}

/* ---- run ------------------------------------------------------------------ */

typedef struct runobs {
  unsigned nstate, reg[FP3_MODEL_MAX_VARS];
  uint32_t steps;
  uint32_t *v;
  unsigned char *seen;
  uint64_t cyc_first, cyc_last;
  uint32_t endis;
} runobs;

static void on_write(void *ctx, unsigned reg, uint32_t value, uint32_t k) {
  runobs *o = ctx;
  if (!o->v || k < 1 || k > o->steps) return;
  for (unsigned i = 0; i < o->nstate; i++)
    if (o->reg[i] == reg) {
      o->v[(size_t)(k - 1) * o->nstate + i] = value;
      o->seen[(size_t)(k - 1) * o->nstate + i] = 1;
    }
}

static void on_endi(void *ctx, uint32_t k, uint64_t cycle) {
  runobs *o = ctx;
  if (k == 1) o->cyc_first = cycle;
  o->cyc_last = cycle;
  o->endis = k;
}

/* --set NAME=VALUE into in[] (params) or y0[] (states). */
static int apply_set(const fp3_model *m, const char *arg, float *in, float *y0,
                     unsigned char *given) {
  const char *eq = strchr(arg, '=');
  if (!eq || eq == arg) {
    fprintf(stderr, "fp3 run: --set wants NAME=VALUE, got '%s'\n", arg);
    return -1;
  }
  char name[FP3_MODEL_NAME_LEN];
  size_t len = (size_t)(eq - arg);
  if (len >= sizeof name) len = sizeof name - 1;
  memcpy(name, arg, len);
  name[len] = '\0';
  char *end;
  float v = strtof(eq + 1, &end);
  if (!eq[1] || *end || !isfinite(v)) {
    fprintf(stderr, "fp3 run: --set %s: '%s' is not a finite number\n", name, eq + 1);
    return -1;
  }
  int k = fp3_model_param(m, name);
  if (k >= 0) {
    in[k] = v;
    given[k] = 1;
    return 0;
  }
  k = fp3_model_state(m, name);
  if (k >= 0) {
    y0[k] = v;
    given[m->nparam + (unsigned)k] = 1;
    return 0;
  }
  fprintf(stderr, "fp3 run: --set %s: model %s (%s) has no param or state '%s'\n", name,
          m->name, m->file, name);
  return -1;
}

int fp3_cmd_run_model(int argc, char **argv) {
  margs a;
  int r = parse_args(argc, argv, "run", &a);
  if (r) return r > 0 ? 0 : EXIT_USAGE;
  fp3_model *m = malloc(sizeof *m);
  char msg[512];
  int rc = EXIT_USAGE;
  fp3_compiled *c = NULL;
  fp3_engine *e = NULL;
  runobs ob;
  memset(&ob, 0, sizeof ob);
  if (!m) return EXIT_FAIL;
  if (fp3_model_load(a.file, m, msg, sizeof msg)) {
    fprintf(stderr, "fp3 run: %s\n", msg);
    goto out;
  }
  float in[FP3_MODEL_MAX_VARS] = {0}, y0[FP3_MODEL_MAX_VARS] = {0};
  unsigned char given[2 * FP3_MODEL_MAX_VARS] = {0};
  for (int i = 0; i < a.nset; i++)
    if (apply_set(m, a.set[i], in, y0, given)) goto out;
  for (unsigned k = 0; k < m->nparam + m->nstate; k++)
    if (!given[k]) {
      int st = k >= m->nparam;
      const char *nm = st ? m->state[k - m->nparam] : m->param[k];
      fprintf(stderr, "fp3 run: %s:%d: %s '%s' has no value: give --set %s=VALUE\n", m->file,
              st ? m->state_line[k - m->nparam] : m->param_line[k] ? m->param_line[k] : 1,
              st ? "state variable" : k == 0 ? "the step" : "param", nm, nm);
      goto out;
    }
  if (!(in[0] > 0.0f)) {
    fprintf(stderr, "fp3 run: --set h=%g: the step must be above 0\n", (double)in[0]);
    goto out;
  }
  unsigned char zero[FP3_MODEL_MAX_VARS] = {0};
  for (unsigned k = 0; k < m->nparam; k++) zero[k] = in[k] == 0.0f;
  if (!(c = compile_for(m, &a, zero, "run"))) goto out;
  rc = EXIT_FAIL;
  e = fp3_engine_new(a.engine);
  if (!e || fp3_engine_error(e)[0]) {
    fprintf(stderr, "fp3 run: cannot create the %s engine%s%s\n", a.engine, e ? ": " : "",
            e ? fp3_engine_error(e) : "");
    goto out;
  }
  unsigned regs[4 * FP3_MODEL_MAX_VARS];
  uint32_t vals[4 * FP3_MODEL_MAX_VARS];
  size_t nw = fp3_compiled_model_start(c, in, y0, regs, vals, 4 * FP3_MODEL_MAX_VARS);
  const fp3_image *img = fp3_compiled_image(c);
  int erc = fp3_engine_load(e, img->words, img->n);
  for (size_t w = 0; w < nw && erc == 0; w++) erc = fp3_engine_write_reg(e, regs[w], vals[w]);
  ob.nstate = m->nstate;
  ob.steps = a.steps;
  for (unsigned i = 0; i < m->nstate; i++) ob.reg[i] = fp3_compiled_state_reg(c, i);
  if ((uint64_t)a.steps * m->nstate <= MAX_CHECKED) {
    ob.v = calloc((size_t)a.steps * m->nstate, sizeof *ob.v);
    ob.seen = calloc((size_t)a.steps * m->nstate, 1);
    if (!ob.v || !ob.seen) {
      fprintf(stderr, "fp3 run: out of memory\n");
      goto out;
    }
  }
  fp3_status st;
  memset(&st, 0, sizeof st);
  if (erc == 0) {
    fp3_observer obs = {.ctx = &ob, .on_write = on_write, .on_endi = on_endi};
    erc = fp3_engine_run(e, a.steps, &obs, &st);
  }
  if (erc) {
    fprintf(stderr, "fp3 run: %s engine: %s\n", a.engine, fp3_engine_error(e));
    goto out;
  }
  uint32_t done = st.steps_done < a.steps ? st.steps_done : a.steps;
  /* the bit-for-bit check, every integration; the first non-finite value */
  uint32_t cur[FP3_MODEL_MAX_VARS], mism_k = 0, nonfinite_k = 0;
  unsigned mism_i = 0, nonfinite_i = 0;
  uint64_t mismatches = 0;
  float g[FP3_MODEL_MAX_VARS], gl[FP3_MODEL_MAX_VARS] = {0};
  uint32_t gwant = 0, ggot = 0;
  for (unsigned i = 0; i < m->nstate; i++) cur[i] = fpref_bits(y0[i]);
  for (uint32_t k = 1; k <= done; k++) {
    fp3_compiled_model_step(c, g);
    for (unsigned i = 0; i < m->nstate; i++) {
      size_t q = (size_t)(k - 1) * m->nstate + i;
      if (ob.v && ob.seen[q]) cur[i] = ob.v[q];
      if (!ob.v && k == done) fp3_engine_read_reg(e, ob.reg[i], &cur[i]);
      if ((ob.v || k == done) && cur[i] != fpref_bits(g[i])) {
        if (!mismatches++) {
          mism_k = k, mism_i = i, ggot = cur[i], gwant = fpref_bits(g[i]);
        }
      }
      if (!nonfinite_k && !isfinite(g[i])) nonfinite_k = k, nonfinite_i = i;
    }
  }
  for (unsigned i = 0; i < m->nstate; i++) gl[i] = g[i];
  /* the references */
  double din[FP3_MODEL_MAX_VARS], dy0[FP3_MODEL_MAX_VARS], ref[FP3_MODEL_MAX_VARS];
  double ex[FP3_MODEL_MAX_VARS];
  int have_ref = 0, have_exact = 0;
  for (unsigned k = 0; k < m->nparam; k++) din[k] = in[k];
  for (unsigned k = 0; k < m->nstate; k++) dy0[k] = y0[k];
  char rmsg[256] = "";
  if (done > 0 && !nonfinite_k)
    have_ref = fp3_model_gsl(m, din, dy0, done, NULL, NULL, ref, rmsg, sizeof rmsg) == 0;
  for (unsigned i = 0; i < m->nstate; i++)
    have_exact |= fp3_model_exact(m, i, din, dy0, (double)done * din[0], &ex[i]) == 0;
  double cyc_per = ob.endis >= 2 ? (double)(ob.cyc_last - ob.cyc_first) / (ob.endis - 1) : NAN;
  int ok = st.error == FP3_ERR_NONE && done == a.steps && mismatches == 0 && !nonfinite_k;
  const fp3_compile_stats *cs = fp3_compiled_stats(c);
  char flags[96];
  fp3_flags_text(st.flags, flags, sizeof flags);
  if (a.json) {
    printf("{\"engine\": ");
    fp3_json_string(stdout, a.engine);
    printf(", \"model\": ");
    fp3_json_string(stdout, m->name);
    printf(", \"program\": ");
    fp3_json_string(stdout, m->file);
    printf(", \"words\": %zu, \"body_insns\": %u", img->n, cs->body_insns);
    printf(", \"steps\": %" PRIu32 ", \"steps_done\": %" PRIu32, a.steps, st.steps_done);
    printf(", \"error\": \"%s\", \"fault_pc\": %" PRIu32, fp3_error_name(st.error), st.fault_pc);
    printf(", \"cycles\": %" PRIu64 ", \"issued\": %" PRIu64 ", \"stalls\": %" PRIu64,
           st.cycles, st.issued, st.stalls);
    printf(", \"cycles_first_step\": ");
    if (ob.endis >= 1) printf("%" PRIu64, ob.cyc_first + 1); else printf("null");
    printf(", \"cycles_per_step\": ");
    fp3_json_double(stdout, cyc_per);
    printf(", \"golden_mismatches\": %" PRIu64, mismatches);
    if (mismatches)
      printf(", \"first_mismatch\": {\"integration\": %" PRIu32 ", \"result\": \"%s\", "
             "\"got\": \"0x%08" PRIX32 "\", \"want\": \"0x%08" PRIX32 "\"}",
             mism_k, m->state[mism_i], ggot, gwant);
    else
      printf(", \"first_mismatch\": null");
    printf(", \"flags\": \"%s\", \"flags_bits\": %" PRIu32, flags, st.flags);
    printf(", \"round\": \"rne\", \"ftz\": false, \"params\": {");
    for (unsigned k = 0; k < m->nparam; k++) {
      printf("%s\"%s\": ", k ? ", " : "", m->param[k]);
      fp3_json_float(stdout, in[k]);
    }
    for (unsigned k = 0; k < m->nstate; k++) {
      printf(", \"%s0\": ", m->state[k]);
      fp3_json_float(stdout, y0[k]);
    }
    printf("}, \"results\": [{");
    for (unsigned k = 0; k < m->nstate; k++) {
      printf("%s\"%s\": ", k ? ", " : "", m->state[k]);
      fp3_json_float(stdout, fpref_float(cur[k]));
      printf(", \"%s_golden\": ", m->state[k]);
      fp3_json_float(stdout, gl[k]);
      printf(", \"%s_ref\": ", m->state[k]);
      fp3_json_double(stdout, have_ref ? ref[k] : NAN);
      if (have_exact) {
        printf(", \"%s_exact\": ", m->state[k]);
        fp3_json_double(stdout, m->exact[k] >= 0 ? ex[k] : NAN);
      }
    }
    printf("}], \"integrator\": ");
    fp3_json_string(stdout, a.integ);
    printf(", \"literal\": %s", a.literal ? "true" : "false");
    printf(", \"nonfinite_from\": ");
    if (nonfinite_k) printf("{\"integration\": %" PRIu32 ", \"variable\": \"%s\"}", nonfinite_k,
                            m->state[nonfinite_i]);
    else printf("null");
    printf(", \"pass\": %s}\n", ok ? "true" : "false");
  } else {
    printf("FP3 run: engine %s, model %s (%s), integrator %s %s, %" PRIu32 " integrations\n",
           a.engine, m->name, m->file, a.integ, a.literal ? "literal" : "folded", a.steps);
    printf("program: %zu words, %u instructions per integration, %u registers\n", img->n,
           cs->body_insns, cs->regs);
    printf("\n%-12s %16s %16s %22s %12s\n", "state", "value", "golden", "reference (GSL)", "error");
    for (unsigned k = 0; k < m->nstate; k++) {
      printf("%-12s %16.9g %16.9g", m->state[k], (double)fpref_float(cur[k]), (double)gl[k]);
      if (have_ref) printf(" %22.15g %12.3g", ref[k], (double)fpref_float(cur[k]) - ref[k]);
      printf("\n");
    }
    if (!have_ref && rmsg[0]) printf("reference: %s\n", rmsg);
    if (have_exact && have_ref) {
      printf("exact solution (the model's `exact` lines) against GSL:");
      for (unsigned k = 0; k < m->nstate; k++)
        if (m->exact[k] >= 0) printf(" %s %.3g", m->state[k], ex[k] - ref[k]);
      printf("\n");
    }
    printf("golden model: %" PRIu64 " mismatches in %" PRIu32 " integrations%s\n", mismatches,
           done, ob.v ? " (every state variable, bit for bit)" : " (the final state only)");
    if (mismatches)
      printf("  first at integration %" PRIu32 ": %s = 0x%08" PRIX32 ", golden 0x%08" PRIX32 "\n",
             mism_k, m->state[mism_i], ggot, gwant);
    if (ob.endis >= 1) {
      printf("cycles: first integration %" PRIu64, ob.cyc_first + 1);
      if (ob.endis >= 2) printf(", later %.2f per integration", cyc_per);
      printf("; total %" PRIu64 "\n", st.cycles);
    }
    printf("flags: %s\n", flags);
    if (nonfinite_k)
      printf("NON-FINITE: state variable %s is not finite after integration %" PRIu32
             " (flags: %s)\n", m->state[nonfinite_i], nonfinite_k, flags);
    if (st.error != FP3_ERR_NONE)
      printf("run error: %s at pc %" PRIu32 "\n", fp3_error_name(st.error), st.fault_pc);
    printf("%s\n", ok ? "PASS: bit-exact with the golden model" : "FAIL");
  }
  if (nonfinite_k)
    fprintf(stderr, "fp3 run: %s: state variable %s is not finite after integration %" PRIu32
            " of %s\n", m->file, m->state[nonfinite_i], nonfinite_k, a.integ);
  rc = ok ? 0 : EXIT_FAIL;
out:
  free(ob.v);
  free(ob.seen);
  fp3_engine_free(e);
  fp3_compiled_free(c);
  free(m);
  return rc;
}
