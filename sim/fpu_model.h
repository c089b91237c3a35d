/*
 * fpu_model.h -- C interface to the Verilated FP cores (sim/fpu_top.v: one
 * fp_add and one fp_mul), one model per built configuration.
 *
 * The implementation is sim/fpu_shim.cpp, compiled once per configuration
 * (mk/fpu.mk); link $(FPU_OBJS) $(FPU_LIBS) with g++ to use this header.
 *
 * Cycle model: inputs set with fpu_model_set_add / _mul / _div / _sqrt /
 * _sign are
 * sampled by the next fpu_model_clock() (one rising edge); an operation sampled by
 * edge k shows on the outputs after edge k + LATENCY - 1, i.e. after
 * fpu_model_clock() has been called LATENCY times counting the sampling
 * edge (rtl/fp_add.v "Timing contract").  Inputs stay as set until changed.
 */
#ifndef FP3_FPU_MODEL_H
#define FP3_FPU_MODEL_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* A built configuration of fpu_top. */
typedef struct fpu_model_info {
  const char *name;     /* e.g. "rne", "rtz", "ftz", "rtz_ftz", "lat_1_2" */
  int round;            /* parameter ROUND: 0 RNE, 1 RTZ                   */
  int ftz;              /* parameter FTZ                                  */
  unsigned add_latency; /* parameter ADD_LATENCY                          */
  unsigned mul_latency; /* parameter MUL_LATENCY                          */
  unsigned div_latency; /* parameter DIV_LATENCY (fp_div and fp_sqrt)     */
} fpu_model_info;

/* The operations, for fpu_model_run (sqrt, abs and neg take operand a
 * only; abs .. max run on fp_sign, latency 1). */
typedef enum fpu_op {
  FPU_OP_ADD = 0,
  FPU_OP_SUB = 1,
  FPU_OP_MUL = 2,
  FPU_OP_DIV = 3,
  FPU_OP_SQRT = 4,
  FPU_OP_ABS = 5,
  FPU_OP_NEG = 6,
  FPU_OP_MIN = 7,
  FPU_OP_MAX = 8
} fpu_op;

/* fp_sign's latency in this harness (the processor's move path). */
#define FPU_SIGN_LATENCY 1

typedef struct fpu_model fpu_model; /* opaque */

/* Built configurations: index 0 .. fpu_model_count() - 1. */
size_t fpu_model_count(void);
const fpu_model_info *fpu_model_info_at(size_t i);

/* A new model, reset, of the first built configuration with this rounding
 * and FTZ and (when nonzero) these latencies; NULL if none was built or out
 * of memory. */
fpu_model *fpu_model_new(int round, int ftz, unsigned add_latency,
                         unsigned mul_latency);
/* By name (fpu_model_info.name); NULL if unknown. */
fpu_model *fpu_model_new_named(const char *name);
void fpu_model_free(fpu_model *m);
const fpu_model_info *fpu_model_get_info(const fpu_model *m);

/* Hold rst_i high for one rising edge with the valid inputs low. */
void fpu_model_reset(fpu_model *m);

/* Inputs for the next rising edge. */
void fpu_model_set_add(fpu_model *m, int valid, int sub, uint32_t a,
                       uint32_t b);
void fpu_model_set_mul(fpu_model *m, int valid, uint32_t a, uint32_t b);
void fpu_model_set_div(fpu_model *m, int valid, uint32_t a, uint32_t b);
void fpu_model_set_sqrt(fpu_model *m, int valid, uint32_t a);
/* fp_sign: op 0 abs, 1 neg, 2 min, 3 max (rtl/fp_sign.v op_i). */
void fpu_model_set_sign(fpu_model *m, int valid, unsigned op, uint32_t a,
                        uint32_t b);

/* One clock cycle: rising edge, then falling edge. */
void fpu_model_clock(fpu_model *m);

/* Outputs in the current cycle: returns valid_o, stores y_o and flags_o
 * (either pointer may be NULL). */
int fpu_model_add_out(const fpu_model *m, uint32_t *y, unsigned *flags);
int fpu_model_mul_out(const fpu_model *m, uint32_t *y, unsigned *flags);
int fpu_model_div_out(const fpu_model *m, uint32_t *y, unsigned *flags);
int fpu_model_sqrt_out(const fpu_model *m, uint32_t *y, unsigned *flags);
int fpu_model_sign_out(const fpu_model *m, uint32_t *y, unsigned *flags);

/* Rising edges since creation. */
uint64_t fpu_model_cycles(const fpu_model *m);

/* Stream n operations through one core, a new one every cycle, and collect
 * the n results in order (flags may be NULL; b is not read for sqrt).  The model must be idle (no
 * operation in flight); it is idle again on return.  Returns 0, or -1 if
 * a result came out in the wrong cycle or valid_o misbehaved. */
int fpu_model_run(fpu_model *m, fpu_op op, size_t n, const uint32_t *a,
                  const uint32_t *b, uint32_t *y, uint8_t *flags);

#ifdef __cplusplus
}
#endif

#endif /* FP3_FPU_MODEL_H */
