/*
 * fuzz_model.c -- libFuzzer harness for the model reader (fp3_model_parse,
 * sw/model/model.c: the .fp3m language of docs/models.md).
 *
 * The input is model text.  A model that parses is then used as the CLI
 * uses it: its derivatives are evaluated once (fp3_model_eval_f, every
 * param and state 1.0, so that a node index the parser let through out of
 * range shows as an ASan report), and each variable name is looked up.
 * Its defaults must be as the parser promises: finite, the step's above 0.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include "fuzz_common.h"
#include "model.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  static fp3_model m;
  static float in[FP3_MODEL_MAX_VARS], y[FP3_MODEL_MAX_VARS], f[FP3_MODEL_MAX_VARS];
  static float val[FP3_MODEL_MAX_NODES];
  char msg[512];
  char *src = fuzz_strdup(data, size);
  int rc = fp3_model_parse(src, "fuzz.fp3m", &m, msg, sizeof msg);
  free(src);
  if (rc != 0) return 0;
  if (m.nparam < 1 || m.nparam > FP3_MODEL_MAX_VARS || m.nstate > FP3_MODEL_MAX_VARS ||
      m.nn > FP3_MODEL_MAX_NODES) {
    fprintf(stderr, "fuzz_model: counts out of range (%u params, %u states, %u nodes)\n",
            m.nparam, m.nstate, m.nn);
    abort();
  }
  for (unsigned i = 0; i < FP3_MODEL_MAX_VARS; i++) in[i] = y[i] = 1.0f;
  fp3_model_eval_f(&m, in, y, f, val);
  for (unsigned i = 0; i < m.nparam; i++)
    if (fp3_model_param(&m, m.param[i]) != (int)i) abort();
  for (unsigned i = 0; i < m.nstate; i++)
    if (fp3_model_state(&m, m.state[i]) != (int)i) abort();
  for (unsigned i = 0; i < m.nparam; i++)
    if (m.param_has_def[i] > 1 || (m.param_has_def[i] && !isfinite(m.param_def[i]))) abort();
  for (unsigned i = 0; i < m.nstate; i++)
    if (m.state_has_def[i] > 1 || (m.state_has_def[i] && !isfinite(m.state_def[i]))) abort();
  if (m.param_has_def[0] && !(m.param_def[0] > 0.0f)) abort();
  fp3_model_split(&m);
  return 0;
}
