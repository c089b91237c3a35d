// fp3_axil_shim.cpp -- extern "C" shim over the Verilator models of
// rtl/fp3_axil.v (sim/fp3_axil_model.h), one per build variant: moves
// values between the C structs and the ports (the model's lifecycle is
// sim/vmodel.h); it has no AXI logic (that is the C test's master).
#include <new>

#include "fp3_axil_model.h"

#include "Vfp3_axil_default.h"
#include "Vfp3_axil_fmax.h"
#include "Vfp3_axil_lanes.h"
#include "vmodel.h"

// The C side's opaque handle: the model of one variant.
struct fp3_axil_model {
  virtual ~fp3_axil_model() = default;
  virtual void cycle(const fp3_axil_in *in, fp3_axil_out *out) = 0;
};

namespace {

template <class Top>
struct axil_model final : fp3_axil_model {
  vmodel<Top> *m;

  explicit axil_model(vmodel<Top> *vm) : m(vm) {}
  ~axil_model() override { m->finish(); }

  void apply(const fp3_axil_in *in) {
    static const fp3_axil_in idle = {};
    if (!in) in = &idle;
    Top *t = m->top;
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

  void cycle(const fp3_axil_in *in, fp3_axil_out *out) override {
    Top *t = m->top;
    apply(in);
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

  static fp3_axil_model *create(const char *trace_path) {
    vmodel<Top> *vm = vmodel<Top>::create(trace_path);
    if (!vm) return nullptr;
    axil_model *h = new (std::nothrow) axil_model(vm);
    if (!h) {
      vm->finish();
      return nullptr;
    }
    h->apply(nullptr);
    vm->reset();
    return h;
  }
};

}  // namespace

extern "C" fp3_axil_model *fp3_axil_model_new(fp3_axil_variant variant, const char *trace_path) {
  switch (variant) {
    case FP3_AXIL_DEFAULT: return axil_model<Vfp3_axil_default>::create(trace_path);
    case FP3_AXIL_FMAX: return axil_model<Vfp3_axil_fmax>::create(trace_path);
    case FP3_AXIL_LANES: return axil_model<Vfp3_axil_lanes>::create(trace_path);
  }
  return nullptr;
}

extern "C" void fp3_axil_model_free(fp3_axil_model *m) { delete m; }

extern "C" void fp3_axil_model_cycle(fp3_axil_model *m, const fp3_axil_in *in,
                                     fp3_axil_out *out) {
  m->cycle(in, out);
}
