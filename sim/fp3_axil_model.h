/*
 * fp3_axil_model.h -- the Verilated AXI4-Lite wrapper (rtl/fp3_axil.v) as
 * plain C.
 *
 * An opaque handle over the Verilator-generated C++ model; the only C++ of
 * this model is sim/fp3_axil_shim.cpp.  Each call of fp3_axil_model_cycle()
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

/* A new model, held in reset for two cycles.  trace_path: a VCD waveform
 * to write, or NULL.  NULL if out of memory or the file cannot be opened. */
fp3_axil_model *fp3_axil_model_new(const char *trace_path);
void fp3_axil_model_free(fp3_axil_model *m);
/* One clock cycle; `in` may be NULL (all master signals 0). */
void fp3_axil_model_cycle(fp3_axil_model *m, const fp3_axil_in *in, fp3_axil_out *out);

#ifdef __cplusplus
}
#endif
#endif /* FP3_AXIL_MODEL_H */
