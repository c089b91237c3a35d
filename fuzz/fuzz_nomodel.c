/*
 * fuzz_nomodel.c -- the Verilated models' entry points for the fuzz
 * harnesses, which link no RTL.
 *
 * Library files a harness needs also hold code that drives a Verilated
 * model (objects.c reaches engine_rtl.c; testfloat.c runs vectors through
 * a core when given one).  The harnesses never take those paths, but the
 * linker needs the symbols: here each entry point stops the process with a
 * message, so that a harness that did reach a model would fail loudly
 * instead of testing something other than the parser.
 */
#include <stdio.h>
#include <stdlib.h>

#include "fp3_model.h"
#include "fpu_model.h"

static void no_model(const char *what) {
  fprintf(stderr, "fuzz: %s reached: the fuzz harnesses link no Verilated model\n", what);
  abort();
}

static fp3_model *no_create(const char *trace_path) {
  (void)trace_path;
  no_model("fp3_model_ops.create");
  return NULL;
}

/* Without a created model the other operations cannot be called. */
#define FUZZ_NO_MODEL(name, round, ftz) \
  const fp3_model_ops fp3_model_##name = {no_create, NULL, NULL, NULL};
FP3_MODEL_CONFIGS(FUZZ_NO_MODEL)
#undef FUZZ_NO_MODEL

fpu_model *fpu_model_new(int round, int ftz, unsigned add_latency, unsigned mul_latency) {
  (void)round, (void)ftz, (void)add_latency, (void)mul_latency;
  no_model("fpu_model_new");
  return NULL;
}

void fpu_model_free(fpu_model *m) {
  (void)m;
  no_model("fpu_model_free");
}

int fpu_model_run(fpu_model *m, fpu_op op, size_t n, const uint32_t *a, const uint32_t *b,
                  uint32_t *y, uint8_t *flags) {
  (void)m, (void)op, (void)n, (void)a, (void)b, (void)y, (void)flags;
  no_model("fpu_model_run");
  return -1;
}
