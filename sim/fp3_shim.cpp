// fp3_shim.cpp -- extern "C" shim over the Verilator model of rtl/fp3_top.v:
// moves values between C structs and the model's ports; the model's
// lifecycle (context, VCD window, reset, half cycles) is sim/vmodel.h.
//
// Compiled once per core configuration (FP3_MODEL_CONFIGS in fp3_model.h):
// FP3_CFG names it, the Verilated class is Vfp3_top_<FP3_CFG>, and the
// operations are exported as fp3_model_<FP3_CFG>.
#include "fp3_model.h"

#define FP3_CAT_(a, b) a##b
#define FP3_CAT(a, b) FP3_CAT_(a, b)
#define FP3_STR_(a) #a
#define FP3_STR(a) FP3_STR_(a)
#define VTOP FP3_CAT(Vfp3_top_, FP3_CFG)
#include FP3_STR(FP3_CAT(Vfp3_top_, FP3_CFG).h)
#include "vmodel.h"

namespace {

// The C side's opaque fp3_model is this configuration's model: handles
// are reinterpret_cast between the two, never dereferenced as fp3_model.
using model = vmodel<VTOP>;

model *of(fp3_model *m) { return reinterpret_cast<model *>(m); }

// A write-back port's data, lane l in bits [32l +: 32] (fp3_top trace
// port), into dst[0 .. lanes-1]: Verilator gives one lane as a 32-bit
// IData, two as a 64-bit QData, more as a VlWide of 32-bit words.
void lanes_out(uint32_t *dst, IData v) { dst[0] = v; }
void lanes_out(uint32_t *dst, QData v) {
  dst[0] = static_cast<uint32_t>(v);
  dst[1] = static_cast<uint32_t>(v >> 32);
}
template <std::size_t N>
void lanes_out(uint32_t *dst, const VlWide<N> &v) {
  static_assert(N <= FP3_MODEL_MAX_LANES, "more lanes than fp3_model_out holds");
  for (std::size_t l = 0; l < N; l++) dst[l] = v[l];
}

}  // namespace

static void trace_window(fp3_model *handle, uint64_t first, uint64_t count) {
  of(handle)->window(first, count);
}

static fp3_model *create(const char *trace_path) {
  model *m = model::create(trace_path);
  if (!m) return nullptr;
  m->top->host_we_i = 0;
  m->top->host_addr_i = 0;
  m->top->host_wdata_i = 0;
  m->top->host_wsel_i = 0;  /* HOST_WSEL = 0: the core decodes host_addr_i */
  m->reset();
  return reinterpret_cast<fp3_model *>(m);
}

static void free_model(fp3_model *handle) {
  if (handle) of(handle)->finish();
}

static void cycle(fp3_model *handle, const fp3_model_in *in, fp3_model_out *out) {
  model *m = of(handle);
  VTOP *t = m->top;
  t->host_we_i = in ? (in->we ? 1 : 0) : 0;
  t->host_addr_i = in ? (in->addr & 0xFFFu) : 0;
  t->host_wdata_i = in ? in->wdata : 0;
  m->half_cycle(0);  // inputs settle with the clock low
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
    lanes_out(out->wb_data[0], t->tr_add_data_o);
    out->wb_valid[1] = t->tr_mul_valid_o;
    out->wb_ctx[1] = t->tr_mul_ctx_o;
    out->wb_reg[1] = t->tr_mul_reg_o;
    lanes_out(out->wb_data[1], t->tr_mul_data_o);
    out->wb_valid[2] = t->tr_mov_valid_o;
    out->wb_ctx[2] = t->tr_mov_ctx_o;
    out->wb_reg[2] = t->tr_mov_reg_o;
    lanes_out(out->wb_data[2], t->tr_mov_data_o);
    out->wb_valid[3] = t->tr_div_valid_o;
    out->wb_ctx[3] = t->tr_div_ctx_o;
    out->wb_reg[3] = t->tr_div_reg_o;
    lanes_out(out->wb_data[3], t->tr_div_data_o);
  }
  m->half_cycle(1);  // the rising edge
  if (out) out->rdata = t->host_rdata_o;
}

extern "C" const fp3_model_ops FP3_CAT(fp3_model_, FP3_CFG) = {create, free_model, cycle,
                                                                 trace_window};
