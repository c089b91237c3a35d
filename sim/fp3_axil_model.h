/*
 * fp3_axil_model.h -- the Verilated AXI4-Lite wrapper (rtl/fp3_axil.v) as
 * plain C, in each of its builds (fp3_axil_variant).
 *
 * An opaque handle over a Verilator-generated C++ model; the only C++ of
 * these models is sim/fp3_axil_shim.cpp.  Each call of fp3_axil_model_cycle()
 * is one clock cycle: the master's signals in `in` are applied with the
 * clock low, the slave's signals are sampled after they settle and before
 * the rising edge (so a channel handshakes at this edge exactly when its
 * VALID and READY in this cycle's in/out are both 1), then the edge.
 */
#ifndef FP3_AXIL_MODEL_H
#define FP3_AXIL_MODEL_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fp3_axil_model fp3_axil_model;

/* The builds of the wrapper (mk/axil.mk). */
typedef enum fp3_axil_variant {
  FP3_AXIL_DEFAULT, /* every parameter at its default (FMAX_PIPE 0)        */
  FP3_AXIL_FMAX,    /* the build for clock rate: FMAX_PIPE 1, NUM_CONTEXTS
                       8, ADD_LATENCY 9, MUL_LATENCY 10, the rest default
                       (RTL_CFG_fmax of mk/rtl.mk)                         */
  FP3_AXIL_LANES    /* 8 contexts x 4 lanes, the default latencies
                       (RTL_CFG_l4 of mk/rtl.mk)                           */
} fp3_axil_variant;

/* Master-driven signals of one cycle (s_axil_*_i). */
typedef struct fp3_axil_in {
  uint32_t awaddr; int awvalid;
  uint32_t wdata; unsigned wstrb; int wvalid;
  int bready;
  uint32_t araddr; int arvalid;
  int rready;
} fp3_axil_in;

/* Slave-driven signals of one cycle, before the edge (s_axil_*_o). */
typedef struct fp3_axil_out {
  int awready, wready;
  int bvalid; unsigned bresp;
  int arready;
  int rvalid; unsigned rresp; uint32_t rdata;
  int running, done; /* side band */
} fp3_axil_out;

/* A new model of build `variant`, held in reset for two cycles.
 * trace_path: a VCD waveform to write, or NULL.  NULL if out of memory,
 * if the file cannot be opened (message on stderr) or for an unknown
 * variant. */
fp3_axil_model *fp3_axil_model_new(fp3_axil_variant variant, const char *trace_path);
/* Close the waveform and free the model; m may be NULL. */
void fp3_axil_model_free(fp3_axil_model *m);
/* One clock cycle; `in` may be NULL (all master signals 0), `out` may be
 * NULL. */
void fp3_axil_model_cycle(fp3_axil_model *m, const fp3_axil_in *in, fp3_axil_out *out);

#ifdef __cplusplus
}
#endif
#endif /* FP3_AXIL_MODEL_H */
