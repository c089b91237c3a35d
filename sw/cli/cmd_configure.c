/*
 * cmd_configure.c -- `fp3 configure SCENE`: the RTL parameters sized to a
 * scene (cmd_configure.h, configure.h).
 */
#include "cmd_configure.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cliopt.h"
#include "configure.h"
#include "device.h"
#include "fpenv.h"
#include "model.h"
#include "mscene.h"
#include "cmd_model.h"
#include "runsetup.h"
#include "report.h"

#define EXIT_FAIL 1
#define EXIT_USAGE 2
#define MAX_STEPS 10000000u

static void usage(FILE *f) {
  fprintf(f,
          "usage: fp3 configure SCENE [--integrator NAME] [--literal]\n"
          "                     [--error-budget REL] [--steps N] [--context-per-object]\n"
          "                     [--max-lanes L] [--device NAME] [--wb-ports P]\n"
          "                     [-o FILE] [--json]\n"
          "\n"
          "Derive the RTL parameters of a processor sized to the scene: compile the\n"
          "scene as fp3 run --scene does, then\n"
          "  HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV, HAS_SQRT, HAS_SIGN  1 when the\n"
          "                   program has an add (or sub), a sub, a mul, a div, a\n"
          "                   sqrt, an abs/neg/min/max (a missing unit is an\n"
          "                   illegal instruction)\n"
          "  NUM_REGS         the fewest registers the compiler fits the program\n"
          "                   into without losing a cycle (at least 4)\n"
          "  NUM_CONTEXTS     the fewest that keep the issue slot busy: ceil(cycles\n"
          "                   of one object's integration / its instructions), at\n"
          "                   most the objects (more objects run in batches);\n"
          "                   --context-per-object: min(objects, 64)\n"
          "  NUM_LANES        the rest of the scene in flight: ceil(objects /\n"
          "                   NUM_CONTEXTS), at most L (--max-lanes, default %d;\n"
          "                   a lane is an adder, a multiplier and a register\n"
          "                   bank, no scheduler logic) and at most what the\n"
          "                   --device holds: LUT4s up to the share that routes\n"
          "                   (%u per mille with one write-back port, %u with\n"
          "                   four), MULT18X18D and EBR, by lane costs measured\n"
          "                   on the chip build (docs/lanes.md)\n"
          "  WB_PORTS, ADD_LATENCY, MUL_LATENCY  one write-back port a lane, both\n"
          "                   latencies %u, when the program has no div and no\n"
          "                   sqrt: no two write-backs meet, so a lane's register\n"
          "                   file needs no live value table (about two thirds of\n"
          "                   a lane); the program is compiled for those latencies\n"
          "                   and NUM_CONTEXTS grows to keep the issue slot busy.\n"
          "                   Otherwise four ports, latencies %u and %u\n"
          "  ROUND, FTZ       the cheapest FP core mode (xc2v LUTs of the cores the\n"
          "                   program needs) whose error stays within the budget:\n"
          "                   the program's golden model in RNE, RTZ, RNE+FTZ and\n"
          "                   RTZ+FTZ against the model's GSL reference (rk8pd,\n"
          "                   1e-12), every object, N integrations; error = max\n"
          "                   over objects and state variables x of\n"
          "                   max|x - ref| / max(max|ref|, 1).\n"
          "                   RNE (the default build) is always allowed, another\n"
          "                   mode when it adds at most REL to each object's RNE\n"
          "                   error (the integrator's own error is not the mode's).\n"
          "\n"
          "  --integrator I   %s\n"
          "                   (default rk4; a ship scene: rk4se)\n"
          "  --literal        no folding, no zero-term removal (fp3 compile --literal)\n"
          "  --error-budget R relative error a mode may add to RNE's (default 1e-4)\n"
          "  --steps N        integrations of the accuracy check (default 1000)\n"
          "  --context-per-object  NUM_CONTEXTS = min(objects, 64)\n"
          "  --max-lanes L    NUM_LANES at most L, 1 .. %d (default %d)\n"
          "  --device NAME    the FPGA the build is for: %s (default: none)\n"
          "  --wb-ports P     1 or 4 write-back ports a lane (default: 1 when the\n"
          "                   program allows it, else 4)\n"
          "  -o FILE          write the line to FILE (atomically) instead of stdout\n"
          "  --json           the parameters and the reasons as JSON on stdout\n"
          "\n"
          "Output: one line of make variables, e.g.\n"
          "  NUM_CONTEXTS=8 NUM_LANES=2 NUM_REGS=16 HAS_ADD=1 HAS_SUB=0 HAS_MUL=1\n"
          "  HAS_DIV=0 HAS_SQRT=0 HAS_SIGN=0 ROUND=0 FTZ=1 ADD_LATENCY=4 MUL_LATENCY=4\n"
          "  WB_PORTS=1\n"
          "and the reason for each parameter on standard error.  `make synth-scene\n"
          "SCENE=FILE` synthesizes the full and the sized build and compares.\n"
          "Exit status: 0 derived; 2 bad arguments, scene, integrator or budget,\n"
          "--wb-ports 1 for a program with div or sqrt, a device without room;\n"
          "1 the output could not be written.\n",
          FP3_CONFIGURE_MAX_LANES, FP3_DEVICE_ROUTABLE_PERMILLE_WB1,
          FP3_DEVICE_ROUTABLE_PERMILLE_WB4,
          FP3_DEFAULT_ADD_LATENCY > FP3_DEFAULT_MUL_LATENCY ? FP3_DEFAULT_ADD_LATENCY
                                                            : FP3_DEFAULT_MUL_LATENCY,
          FP3_DEFAULT_ADD_LATENCY, FP3_DEFAULT_MUL_LATENCY, fp3_model_integrators(),
          FP3_MAX_LANES, FP3_CONFIGURE_MAX_LANES, fp3_device_names());
}

static const char *const unit_name[FP3_CONFIGURE_UNITS] = {"add", "sub", "mul", "div", "sqrt",
                                                             "abs/neg/min/max"};

static void mode_name(fpref_mode m, char *buf, size_t n) {
  snprintf(buf, n, "%s%s", m.round == FPREF_RTZ ? "RTZ" : "RNE", m.ftz ? "+FTZ" : "");
}

static void print_json(const char *scene, const char *integ, const fp3_configure_opts *o,
                       const fp3_configure_result *r, const char *line) {
  printf("{\"scene\": ");
  fp3_json_string(stdout, scene);
  printf(", \"objects\": %zu, \"integrator\": ", r->objects);
  fp3_json_string(stdout, integ);
  printf(", \"literal\": %s, \"error_budget\": %.17g, \"steps\": %u", o->literal ? "true" : "false",
         o->budget, o->steps);
  printf(", \"context_per_object\": %s, \"contexts_issue\": %u",
         o->context_per_object ? "true" : "false", r->contexts_issue);
  printf(", \"lanes_scene\": %u, \"max_lanes\": %u, \"device\": ", r->lanes_scene,
         o->max_lanes);
  if (o->device) {
    fp3_json_string(stdout, o->device->name);
    printf(", \"device_max_lanes\": %u, \"device_limit\": ", r->fit.max_lanes);
    fp3_json_string(stdout, r->fit.limit);
  } else {
    printf("null, \"device_max_lanes\": null, \"device_limit\": null");
  }
  printf(", \"make\": ");
  fp3_json_string(stdout, line);
  printf(", \"params\": {\"NUM_CONTEXTS\": %u, \"NUM_LANES\": %u, \"NUM_REGS\": %u, "
         "\"HAS_ADD\": %u, \"HAS_SUB\": %u, \"HAS_MUL\": %u, \"HAS_DIV\": %u, "
         "\"HAS_SQRT\": %u, \"HAS_SIGN\": %u, \"ROUND\": %d, \"FTZ\": %d, "
         "\"ADD_LATENCY\": %u, \"MUL_LATENCY\": %u, \"WB_PORTS\": %u}",
         r->cfg.num_contexts, r->cfg.num_lanes, r->cfg.num_regs, r->cfg.has_add, r->cfg.has_sub,
         r->cfg.has_mul, r->cfg.has_div, r->cfg.has_sqrt, r->cfg.has_sign,
         r->cfg.mode.round == FPREF_RTZ, r->cfg.mode.ftz ? 1 : 0, r->cfg.add_latency,
         r->cfg.mul_latency, r->cfg.wb_ports);
  printf(", \"unit_pc\": {");
  for (int u = 0; u < FP3_CONFIGURE_UNITS; u++) {
    printf("%s\"%s\": ", u ? ", " : "", unit_name[u]);
    if (r->unit_pc[u] >= 0) printf("%d", r->unit_pc[u]);
    else printf("null");
  }
  printf("}, \"insns_per_step\": %u, \"est_cycles_first_step\": %u, \"est_cycles_per_step\": %u",
         r->body_insns, r->est_first, r->est_later);
  printf(", \"regs_default\": %u, \"regs_used\": %u", r->regs_default, r->regs_used);
  printf(", \"modes\": [");
  for (int m = 0; m < FP3_CONFIGURE_MODES; m++) {
    char name[16];
    mode_name(r->mode[m], name, sizeof name);
    printf("%s{\"mode\": \"%s\", \"error\": ", m ? ", " : "", name);
    fp3_json_double(stdout, r->err[m]);
    fp3_json_member_double(stdout, "added_error", r->added[m]);
    printf(", \"allowed\": %s, \"fp_core_luts_xc2v\": %u}", r->allowed[m] ? "true" : "false",
           r->luts[m]);
  }
  char chosen[16];
  mode_name(r->cfg.mode, chosen, sizeof chosen);
  printf("], \"chosen_mode\": \"%s\"}\n", chosen);
}

static const char *param_text(const char *name, unsigned v, char *buf, size_t n) {
  snprintf(buf, n, "%s=%u", name, v);
  return buf;
}

static void print_reasons(const char *scene, const char *integ, const char *against,
                          const fp3_configure_opts *o,
                          const fp3_configure_result *r) {
  const fp3_config *c = &r->cfg;
  char p0[32];
  fprintf(stderr,
          "fp3 configure: %s (%zu objects), %s%s: %u instructions per integration, "
          "estimated %u cycles per later integration of one object\n",
          scene, r->objects, integ, o->literal ? " (literal)" : "", r->body_insns, r->est_later);
  if (o->context_per_object)
    fprintf(stderr, "  %-16s one context per object (%zu object%s; at most %d, more run in "
                    "batches)\n", param_text("NUM_CONTEXTS", c->num_contexts, p0, sizeof p0),
            r->objects, r->objects == 1 ? "" : "s", FP3_MAX_CONTEXTS);
  else
    fprintf(stderr, "  %-16s the fewest contexts that keep the issue slot busy: ceil(%u cycles "
                    "/ %u instructions) = %u, at most the %zu object%s\n",
            param_text("NUM_CONTEXTS", c->num_contexts, p0, sizeof p0), r->est_later,
            r->body_insns, r->contexts_issue, r->objects, r->objects == 1 ? "" : "s");
  fprintf(stderr, "  %-16s ceil(%zu object%s / %u contexts) = %u, at most %u (--max-lanes)",
          param_text("NUM_LANES", c->num_lanes, p0, sizeof p0), r->objects,
          r->objects == 1 ? "" : "s", c->num_contexts, r->lanes_scene, o->max_lanes);
  if (o->device)
    fprintf(stderr, " and %u (the %s holds %u: %s)", r->fit.max_lanes, o->device->part,
            r->fit.max_lanes, r->fit.limit);
  fprintf(stderr, ": %u object%s in flight\n", c->num_contexts * c->num_lanes,
          c->num_contexts * c->num_lanes == 1 ? "" : "s");
  if (o->device)
    fprintf(stderr, "  %-16s lane model (%u write-back port%s): %u fixed + %u lane 0 + %u a "
                    "further lane LUT4s <= %u (%u per mille of %u), %u MULT18X18D a lane <= "
                    "%u, %u + %u EBR a lane <= %u\n",
            "", r->fit.wb_ports, r->fit.wb_ports == 1 ? "" : "s", r->fit.luts_fixed,
            r->fit.luts_lane0, r->fit.luts_lane, r->fit.luts_allowed, r->fit.routable_permille,
            o->device->luts, r->fit.dsp_lane, o->device->dsps, r->fit.ebr_fixed,
            r->fit.ebr_lane, o->device->ebrs);
  if (c->wb_ports == 1)
    fprintf(stderr, "  %-16s one write-back port a lane (no live value table): the program "
                    "has no div or sqrt; every unit writes back after %u cycles (ADD_LATENCY=%u "
                    "MUL_LATENCY=%u), the program is compiled for that\n",
            param_text("WB_PORTS", 1, p0, sizeof p0), c->add_latency, c->add_latency,
            c->mul_latency);
  else if (o->wb_ports == 4)
    fprintf(stderr, "  %-16s four write-back ports (--wb-ports 4), the default latencies\n",
            param_text("WB_PORTS", 4, p0, sizeof p0));
  else
    fprintf(stderr, "  %-16s four write-back ports, the default latencies: the program has "
                    "%s (pc %d), whose unit writes back later than the others\n",
            param_text("WB_PORTS", 4, p0, sizeof p0), r->unit_pc[3] >= 0 ? "div" : "sqrt",
            r->unit_pc[3] >= 0 ? r->unit_pc[3] : r->unit_pc[4]);
  if (r->regs_default > FP3_DEFAULT_NUM_REGS)
    fprintf(stderr, "  %-16s the fewest registers the compiler schedules the program into "
                    "(more than the default %u; no spilling)\n",
            param_text("NUM_REGS", c->num_regs, p0, sizeof p0), (unsigned)FP3_DEFAULT_NUM_REGS);
  else
    fprintf(stderr, "  %-16s the fewest registers the program fits without losing a cycle "
                    "(it names %u; compiled for the default %u it names %u)\n",
            param_text("NUM_REGS", c->num_regs, p0, sizeof p0), r->regs_used,
            (unsigned)FP3_DEFAULT_NUM_REGS, r->regs_default);
  const unsigned has[FP3_CONFIGURE_UNITS] = {c->has_add, c->has_sub, c->has_mul,
                                             c->has_div, c->has_sqrt, c->has_sign};
  const char *const param[FP3_CONFIGURE_UNITS] = {"HAS_ADD", "HAS_SUB", "HAS_MUL",
                                                  "HAS_DIV", "HAS_SQRT", "HAS_SIGN"};
  for (int u = 0; u < FP3_CONFIGURE_UNITS; u++) {
    if (r->unit_pc[u] >= 0)
      fprintf(stderr, "  %-16s the program has %s (first at pc %d)\n",
              param_text(param[u], has[u], p0, sizeof p0), unit_name[u], r->unit_pc[u]);
    else if (u == 0 && has[u])
      fprintf(stderr, "  %-16s the program has sub (the adder subtracts)\n",
              param_text(param[u], 1, p0, sizeof p0));
    else
      fprintf(stderr, "  %-16s the program has no %s\n", param_text(param[u], 0, p0, sizeof p0),
              unit_name[u]);
  }
  char chosen[16];
  mode_name(c->mode, chosen, sizeof chosen);
  fprintf(stderr, "  ROUND=%d FTZ=%d    %s: the cheapest mode that adds at most %g to each object's "
                  "RNE error (%s, %u integrations):\n",
          c->mode.round == FPREF_RTZ, c->mode.ftz ? 1 : 0, chosen, o->budget, against, o->steps);
  for (int m = 0; m < FP3_CONFIGURE_MODES; m++) {
    char name[16];
    mode_name(r->mode[m], name, sizeof name);
    fprintf(stderr, "                     %-8s error %-10.4g added %-10.3g %-12s FP cores %4u xc2v LUTs%s\n",
            name, r->err[m], r->added[m], isnan(r->err[m]) ? "(host: no)" : r->allowed[m] ? "allowed" : "over budget",
            r->luts[m], m == r->chosen ? "  <- chosen (fewest LUTs allowed)" : "");
  }
}

int fp3_parse_configure(int argc, char **argv, fp3_configure_args *a) {
  a->scene = a->out = NULL;
  a->json = 0;
  fp3_configure_defaults(&a->opts);
  fp3_configure_opts *o = &a->opts;
  int given = 0; /* --integrator */
  for (int i = 1; i < argc; i++) {
    const char *v;
    unsigned long long k;
    int r;
    if (fp3_is_help(argv[i])) return FP3_ARGS_HELP;
    if ((r = fp3_opt_output(argc, argv, &i, "configure", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      a->out = v;
    } else if ((r = fp3_opt_value(argc, argv, &i, "configure", "--integrator", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->integrator = v; /* checked by the run step */
      given = 1;
    } else if ((r = fp3_opt_value(argc, argv, &i, "configure", "--error-budget", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      char *end;
      errno = 0;
      double b = strtod(v, &end);
      if (end == v || *end || errno || !(b > 0.0) || !isfinite(b)) {
        fprintf(stderr, "fp3 configure: --error-budget '%s': want a positive relative error, "
                        "e.g. 1e-4\n", v);
        return FP3_ARGS_BAD;
      }
      o->budget = b;
    } else if ((r = fp3_opt_count(argc, argv, &i, "configure", "--steps", 1, MAX_STEPS,
                                  "integrations", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->steps = (uint32_t)k;
    } else if (strcmp(argv[i], "--literal") == 0) {
      o->literal = 1;
    } else if ((r = fp3_opt_count(argc, argv, &i, "configure", "--max-lanes", 1, FP3_MAX_LANES,
                                  "lanes", &k)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->max_lanes = (unsigned)k;
    } else if ((r = fp3_opt_value(argc, argv, &i, "configure", "--device", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      o->device = fp3_device_find(v);
      if (!o->device) {
        fprintf(stderr, "fp3 configure: --device '%s': unknown device (known: %s)\n", v,
                fp3_device_names());
        return FP3_ARGS_BAD;
      }
    } else if ((r = fp3_opt_value(argc, argv, &i, "configure", "--wb-ports", &v)) != 0) {
      if (r < 0) return FP3_ARGS_BAD;
      if (strcmp(v, "1") != 0 && strcmp(v, "4") != 0) {
        fprintf(stderr, "fp3 configure: --wb-ports '%s': want 1 or 4 write-back ports\n", v);
        return FP3_ARGS_BAD;
      }
      o->wb_ports = (unsigned)(v[0] - '0');
    } else if (strcmp(argv[i], "--context-per-object") == 0) {
      o->context_per_object = 1;
    } else if (strcmp(argv[i], "--json") == 0) {
      a->json = 1;
    } else if (fp3_opt_positional("configure", "scene", argv[i], &a->scene)) {
      return FP3_ARGS_BAD;
    }
  }
  if (!a->scene) {
    fprintf(stderr, "fp3 configure: no scene file (see fp3 configure --help)\n");
    return FP3_ARGS_BAD;
  }
  if (fp3_ship_scene_integrator(a->scene, given, &o->integrator, "configure"))
    return FP3_ARGS_BAD;
  return FP3_ARGS_RUN;
}

/* The run step: read the scene, derive the parameters, write, report. */
static int run_configure(const fp3_configure_args *a) {
  const char *scene = a->scene, *outp = a->out;
  const int json = a->json;
  const fp3_configure_opts o = a->opts;
  char msg[512];
  fp3_configure_result res;
  fp3_mscene ms;
  if (fp3_read_scene(scene, &ms, msg, sizeof msg)) {
    fprintf(stderr, "fp3 configure: %s\n", msg);
    return EXIT_USAGE;
  }
  if (!fp3_model_integrator_known(o.integrator)) {
    fprintf(stderr, "fp3 configure: unknown integrator '%s' for a model (%s)\n", o.integrator,
            fp3_model_integrators());
    fp3_mscene_free(&ms);
    return EXIT_USAGE;
  }
  const char *against = "every state variable against the model's GSL reference";
  int rc = fp3_configure_model(&ms, &o, &res, NULL, msg, sizeof msg);
  fp3_mscene_free(&ms);
  if (rc) {
    fprintf(stderr, "fp3 configure: %s: %s\n", scene, msg);
    return EXIT_USAGE;
  }
  char line[288];
  fp3_configure_line(&res.cfg, line, sizeof line);
  if (outp) {
    char text[300];
    snprintf(text, sizeof text, "%s\n", line);
    if (fp3_write_text_atomic(outp, text, msg, sizeof msg)) {
      fprintf(stderr, "fp3 configure: %s\n", msg);
      return EXIT_FAIL;
    }
  }
  if (json) print_json(scene, o.integrator, &o, &res, line);
  else {
    if (!outp) printf("%s\n", line);
    print_reasons(scene, o.integrator, against, &o, &res);
  }
  return 0;
}

int fp3_cmd_configure(int argc, char **argv) {
  fp3_configure_args a;
  int r = fp3_parse_configure(argc, argv, &a);
  return r == FP3_ARGS_RUN ? run_configure(&a) : fp3_args_exit(r, usage);
}
