// fp3_axil_shim.cpp -- extern "C" shim over the Verilator model of
// rtl/fp3_axil.v (sim/fp3_axil_model.h): moves values between the C structs
// and the ports (the model's lifecycle is sim/vmodel.h); it has no AXI
// logic (that is the C test's master).
#include "fp3_axil_model.h"

#include "Vfp3_axil.h"
#include "vmodel.h"

// The C side's opaque handle is the model: handles are reinterpret_cast
// between the two, never dereferenced as fp3_axil_model.
using model = vmodel<Vfp3_axil>;

static model *of(fp3_axil_model *m) { return reinterpret_cast<model *>(m); }

static void apply(Vfp3_axil *t, const fp3_axil_in *in) {
  static const fp3_axil_in idle = {};
  if (!in) in = &idle;
  t->s_axil_awaddr_i = in->awaddr & 0x3FFFu;
  t->s_axil_awprot_i = 0;
  t->s_axil_awvalid_i = in->awvalid ? 1 : 0;
  t->s_axil_wdata_i = in->wdata;
  t->s_axil_wstrb_i = in->wstrb & 0xFu;
  t->s_axil_wvalid_i = in->wvalid ? 1 : 0;
  t->s_axil_bready_i = in->bready ? 1 : 0;
  t->s_axil_araddr_i = in->araddr & 0x3FFFu;
  t->s_axil_arprot_i = 0;
  t->s_axil_arvalid_i = in->arvalid ? 1 : 0;
  t->s_axil_rready_i = in->rready ? 1 : 0;
}

extern "C" fp3_axil_model *fp3_axil_model_new(const char *trace_path) {
  model *m = model::create(trace_path);
  if (!m) return nullptr;
  apply(m->top, nullptr);
  m->reset();
  return reinterpret_cast<fp3_axil_model *>(m);
}

extern "C" void fp3_axil_model_free(fp3_axil_model *m) {
  if (m) of(m)->finish();
}

extern "C" void fp3_axil_model_cycle(fp3_axil_model *handle, const fp3_axil_in *in,
                                     fp3_axil_out *out) {
  model *m = of(handle);
  Vfp3_axil *t = m->top;
  apply(t, in);
  m->half_cycle(0);  // inputs settle with the clock low
  if (out) {
    out->awready = t->s_axil_awready_o;
    out->wready = t->s_axil_wready_o;
    out->bvalid = t->s_axil_bvalid_o;
    out->bresp = t->s_axil_bresp_o;
    out->arready = t->s_axil_arready_o;
    out->rvalid = t->s_axil_rvalid_o;
    out->rresp = t->s_axil_rresp_o;
    out->rdata = t->s_axil_rdata_o;
    out->running = t->running_o;
    out->done = t->done_o;
  }
  m->half_cycle(1);  // the rising edge
}
