// fp3_axil_shim.cpp -- extern "C" shim over the Verilator model of
// rtl/fp3_axil.v (sim/fp3_axil_model.h).  It owns the VerilatedContext, the
// model and an optional VCD writer and moves values between the C structs
// and the ports; it has no AXI logic (that is the C test's master).
#include "fp3_axil_model.h"

#include <cstdio>
#include <new>

#include "Vfp3_axil.h"
#include "verilated.h"
#include "verilated_vcd_c.h"

struct fp3_axil_model {
  VerilatedContext *ctx;
  Vfp3_axil *top;
  VerilatedVcdC *vcd;  // nullptr: no waveform
};

static void half_cycle(fp3_axil_model *m, int clk) {
  m->top->clk_i = clk;
  m->top->eval();
  if (m->vcd) m->vcd->dump(m->ctx->time());
  m->ctx->timeInc(1);
}

static void destroy(fp3_axil_model *m) {
  if (m->vcd) {
    m->vcd->close();
    delete m->vcd;
  }
  delete m->top;
  delete m->ctx;
  delete m;
}

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
  fp3_axil_model *m = nullptr;
  try {
    m = new fp3_axil_model{new VerilatedContext, nullptr, nullptr};
    if (trace_path) m->ctx->traceEverOn(true);
    m->top = new Vfp3_axil{m->ctx};
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
  apply(m->top, nullptr);
  m->top->rst_i = 1;
  for (int i = 0; i < 2; i++) {
    half_cycle(m, 0);
    half_cycle(m, 1);
  }
  m->top->rst_i = 0;
  half_cycle(m, 0);
  return m;
}

extern "C" void fp3_axil_model_free(fp3_axil_model *m) {
  if (!m) return;
  m->top->final();
  destroy(m);
}

extern "C" void fp3_axil_model_cycle(fp3_axil_model *m, const fp3_axil_in *in,
                                     fp3_axil_out *out) {
  Vfp3_axil *t = m->top;
  apply(t, in);
  half_cycle(m, 0);  // inputs settle with the clock low
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
  half_cycle(m, 1);  // the rising edge
}
