// fp3_shim.cpp -- extern "C" shim over the Verilator model of rtl/fp3_top.v.
// The only C++ of the processor harness: it owns the VerilatedContext, the
// model and an optional VCD writer, and moves values between C structs and
// the model's ports.  One clock cycle is two time units in the waveform.
//
// Compiled once per core configuration (FP3_MODEL_CONFIGS in fp3_model.h):
// FP3_CFG names it, the Verilated class is Vfp3_top_<FP3_CFG>, and the
// operations are exported as fp3_model_<FP3_CFG>.
#include "fp3_model.h"

#include <cstdint>
#include <cstdio>
#include <new>

#include "verilated.h"
#include "verilated_vcd_c.h"

#define FP3_CAT_(a, b) a##b
#define FP3_CAT(a, b) FP3_CAT_(a, b)
#define FP3_STR_(a) #a
#define FP3_STR(a) FP3_STR_(a)
#define VTOP FP3_CAT(Vfp3_top_, FP3_CFG)
#include FP3_STR(FP3_CAT(Vfp3_top_, FP3_CFG).h)

namespace {

// The C side's opaque fp3_model is this configuration's model: handles
// are reinterpret_cast between the two, never dereferenced as fp3_model.
struct model {
  VerilatedContext *ctx;
  VTOP *top;
  VerilatedVcdC *vcd;  // nullptr: no waveform
  // Cycles since creation; the waveform holds cycles win_lo .. win_hi-1.
  uint64_t cyc = 0, win_lo = 0, win_hi = UINT64_MAX;
};

model *of(fp3_model *m) { return reinterpret_cast<model *>(m); }

}  // namespace

static void half_cycle(model *m, int clk) {
  m->top->clk_i = clk;
  m->top->eval();
  if (m->vcd && m->cyc >= m->win_lo && m->cyc < m->win_hi) m->vcd->dump(m->ctx->time());
  m->ctx->timeInc(1);
  if (clk) m->cyc++;
}

static uint64_t sat_add(uint64_t a, uint64_t b) { return b > UINT64_MAX - a ? UINT64_MAX : a + b; }

static void trace_window(fp3_model *handle, uint64_t first, uint64_t count) {
  model *m = of(handle);
  m->win_lo = sat_add(m->cyc, first);
  m->win_hi = sat_add(m->win_lo, count);
}

static void destroy(model *m) {
  if (m->vcd) {
    m->vcd->close();
    delete m->vcd;
  }
  delete m->top;
  delete m->ctx;
  delete m;
}

static fp3_model *create(const char *trace_path) {
  model *m = nullptr;
  try {
    m = new model{new VerilatedContext, nullptr, nullptr};
    if (trace_path) m->ctx->traceEverOn(true);
    m->top = new VTOP{m->ctx};
    if (trace_path) {
      m->vcd = new VerilatedVcdC;
      m->top->trace(m->vcd, 99);
      m->vcd->open(trace_path);
      if (!m->vcd->isOpen()) {
        std::fprintf(stderr, "fp3: cannot open trace file %s\n", trace_path);
        destroy(m);
        return nullptr;
      }
    }
  } catch (const std::bad_alloc &) {
    if (m) destroy(m);
    return nullptr;
  }
  m->top->host_we_i = 0;
  m->top->host_addr_i = 0;
  m->top->host_wdata_i = 0;
  m->top->rst_i = 1;
  for (int i = 0; i < 2; i++) {
    half_cycle(m, 0);
    half_cycle(m, 1);
  }
  m->top->rst_i = 0;
  half_cycle(m, 0);
  return reinterpret_cast<fp3_model *>(m);
}

static void free_model(fp3_model *handle) {
  if (!handle) return;
  model *m = of(handle);
  m->top->final();
  destroy(m);
}

static void cycle(fp3_model *handle, const fp3_model_in *in, fp3_model_out *out) {
  model *m = of(handle);
  VTOP *t = m->top;
  t->host_we_i = in ? (in->we ? 1 : 0) : 0;
  t->host_addr_i = in ? (in->addr & 0xFFFu) : 0;
  t->host_wdata_i = in ? in->wdata : 0;
  half_cycle(m, 0);  // inputs settle with the clock low
  if (out) {
    out->running = t->running_o;
    out->done = t->done_o;
    out->issue = t->tr_issue_o;
    out->issue_ctx = t->tr_issue_ctx_o;
    out->issue_unit = t->tr_issue_unit_o;
    out->endi = t->tr_endi_o;
    out->wb_valid[0] = t->tr_add_valid_o;
    out->wb_ctx[0] = t->tr_add_ctx_o;
    out->wb_reg[0] = t->tr_add_reg_o;
    out->wb_data[0] = t->tr_add_data_o;
    out->wb_valid[1] = t->tr_mul_valid_o;
    out->wb_ctx[1] = t->tr_mul_ctx_o;
    out->wb_reg[1] = t->tr_mul_reg_o;
    out->wb_data[1] = t->tr_mul_data_o;
    out->wb_valid[2] = t->tr_mov_valid_o;
    out->wb_ctx[2] = t->tr_mov_ctx_o;
    out->wb_reg[2] = t->tr_mov_reg_o;
    out->wb_data[2] = t->tr_mov_data_o;
  }
  half_cycle(m, 1);  // the rising edge
  if (out) out->rdata = t->host_rdata_o;
}

extern "C" const fp3_model_ops FP3_CAT(fp3_model_, FP3_CFG) = {create, free_model, cycle,
                                                                 trace_window};
