/*
 * fp3_model.h -- the Verilated FP3 processor (rtl/fp3_top.v) as plain C.
 *
 * An opaque handle over the Verilator-generated C++ model; sim/fp3_shim.cpp
 * is the only C++ of the processor harness.  Each call of fp3_model_cycle() is one
 * clock cycle: inputs are applied away from the rising edge, the trace
 * outputs of the cycle are sampled before the edge, and the registered
 * host read data (for the address given in this cycle) after it.
 */
#ifndef FP3_MODEL_H
#define FP3_MODEL_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fp3_model fp3_model;

/* Host-port inputs of one cycle (rtl/fp3_top.v host_*_i). */
typedef struct fp3_model_in {
  int we;          /* write enable                       */
  uint16_t addr;   /* 12-bit word address (FP3_HR_*)      */
  uint32_t wdata;  /* write data                          */
} fp3_model_in;

/* Lanes a model may have (FP3_MAX_LANES of sw/isa/fp3_isa.h). */
#define FP3_MODEL_MAX_LANES 64

/* Write-back ports of the trace port (fp3_top tr_{add,mul,mov,div}_*). */
#define FP3_MODEL_WB_PORTS 4

/* Outputs of one cycle. */
typedef struct fp3_model_out {
  uint32_t rdata;       /* host read data for this cycle's addr   */
  int running, done;    /* run status pins (before the edge)      */
  int issue;            /* an instruction issued                  */
  unsigned issue_ctx;   /* ... by this context                    */
  unsigned issue_unit;  /* its unit, FP3_UNIT_*                   */
  int endi;             /* the issued instruction is an endi      */
  int wb_valid[FP3_MODEL_WB_PORTS];  /* write-back ports: 0 add, 1 mul, 2 move,
                                        3 div/sqrt (port u: unit u + 1) */
  unsigned wb_ctx[FP3_MODEL_WB_PORTS];
  unsigned wb_reg[FP3_MODEL_WB_PORTS];
  uint32_t wb_data[FP3_MODEL_WB_PORTS][FP3_MODEL_MAX_LANES]; /* [port][lane]: the
                                        model's NUM_LANES lanes are filled */
} fp3_model_out;

/*
 * The model is built once per FP core configuration (parameters ROUND and
 * FTZ of rtl/fp3_top.v); X(name, ROUND, FTZ).  Each build exports its
 * operations as `fp3_model_<name>`.
 */
#define FP3_MODEL_CONFIGS(X) \
  X(rne, 0, 0)               \
  X(rtz, 1, 0)               \
  X(ftz, 0, 1)               \
  X(rtz_ftz, 1, 1)

typedef struct fp3_model_ops {
  /* A new model, held in reset for two cycles.  trace_path: a VCD
   * waveform of every signal to write, or NULL; the file is complete once
   * destroy has closed it (the RTL engine gives a temporary name here and
   * renames the file after a finished run: engine.h).  Returns NULL if out
   * of memory or if the trace file cannot be opened (message on stderr). */
  fp3_model *(*create)(const char *trace_path);
  void (*destroy)(fp3_model *m);
  /* One clock cycle; `in` may be NULL (no host access), `out` may be
   * NULL. */
  void (*cycle)(fp3_model *m, const fp3_model_in *in, fp3_model_out *out);
  /* Waveform window: from now on, write only the `count` cycles that
   * start `first` cycles after this call (first 0: the next cycle;
   * first UINT64_MAX: none; count UINT64_MAX: no end).  Without a call,
   * every cycle is written. */
  void (*trace_window)(fp3_model *m, uint64_t first, uint64_t count);
} fp3_model_ops;

#define FP3_MODEL_DECLARE(name, round, ftz) extern const fp3_model_ops fp3_model_##name;
FP3_MODEL_CONFIGS(FP3_MODEL_DECLARE)
#undef FP3_MODEL_DECLARE

#ifdef __cplusplus
}
#endif
#endif /* FP3_MODEL_H */
