// spatial_shim.cpp -- extern "C" shim over one Verilated pipeline written
// by `fp3 spatial` (sw/compiler/spatial.h), built into the shared object
// that the spatial engine loads with dlopen (sw/compiler/engine_spatial.c
// builds it; docs/spatial.md "The spatial engine").
//
// Built with -DSPATIAL_HASH=0x...ULL (FNV-1a 64 of the module's text, the
// value the frame's HASH register holds), -DSPATIAL_NIN=N (32-bit words
// of in_i) and -DSPATIAL_NC=N (words of y_i and y_o); the Verilated class
// is Vspatial (--prefix Vspatial).  A clock cycle is two calls: read the
// outputs (fp3_spatial_shim_out), then drive the inputs and clock
// (fp3_spatial_shim_clock), so the host can feed an object in the cycle
// its previous result leaves.  A cycle evaluates the model twice: the
// clock low with the new inputs, then the rising edge.
#include <cstdint>
#include <new>

#include "Vspatial.h"
#include "verilated.h"

namespace {

// 32-bit word k of a port, whatever type Verilator gives its width: one
// word an IData, two a QData, more a VlWide.
void set_word(IData &p, unsigned k, uint32_t v) {
  (void)k;
  p = v;
}
void set_word(QData &p, unsigned k, uint32_t v) {
  p = (p & ~(0xFFFFFFFFull << (32 * k))) | (static_cast<QData>(v) << (32 * k));
}
template <std::size_t N>
void set_word(VlWide<N> &p, unsigned k, uint32_t v) {
  p[k] = v;
}
uint32_t get_word(IData p, unsigned k) {
  (void)k;
  return p;
}
uint32_t get_word(QData p, unsigned k) { return static_cast<uint32_t>(p >> (32 * k)); }
template <std::size_t N>
uint32_t get_word(const VlWide<N> &p, unsigned k) {
  return p[k];
}

struct dut {
  VerilatedContext ctx;
  Vspatial *top = nullptr;
  uint64_t cycles = 0;
};

void edge(dut *d, int clk) {
  d->top->clk_i = clk;
  d->top->eval();
  d->ctx.timeInc(1);
}

}  // namespace

extern "C" {

// The hash of the module text this object was built from, and its shape.
uint64_t fp3_spatial_shim_hash(void) { return SPATIAL_HASH; }
unsigned fp3_spatial_shim_inputs(void) { return SPATIAL_NIN; }
unsigned fp3_spatial_shim_carried(void) { return SPATIAL_NC; }

// rst_i high for four clock cycles, then low with the clock low; the
// cycle count starts again at 0.
void fp3_spatial_shim_reset(void *h) {
  dut *d = static_cast<dut *>(h);
  d->top->valid_i = 0;
  d->top->rst_i = 1;
  for (int k = 0; k < 4; k++) {
    edge(d, 0);
    edge(d, 1);
  }
  d->top->rst_i = 0;
  edge(d, 0);
  d->cycles = 0;
}

// A new pipeline, reset; nullptr when out of memory.
void *fp3_spatial_shim_new(void) {
  dut *d = new (std::nothrow) dut;
  if (!d) return nullptr;
  d->top = new (std::nothrow) Vspatial{&d->ctx};
  if (!d->top) {
    delete d;
    return nullptr;
  }
  d->top->clk_i = 0;
  fp3_spatial_shim_reset(d);
  return d;
}

void fp3_spatial_shim_free(void *h) {
  dut *d = static_cast<dut *>(h);
  if (!d) return;
  d->top->final();
  delete d->top;
  delete d;
}

// valid_o, and when it is 1 the SPATIAL_NC words of y_o into y[], as the
// last rising edge left them: the generator's outputs are registers (a
// core's result or a delay stage), so no evaluation is needed.
int fp3_spatial_shim_out(void *h, uint32_t *y) {
  dut *d = static_cast<dut *>(h);
  if (!d->top->valid_o) return 0;
  for (unsigned w = 0; w < SPATIAL_NC; w++) y[w] = get_word(d->top->y_o, w);
  return 1;
}

// Drive valid_i, in_i (SPATIAL_NIN words of in[]) and y_i (SPATIAL_NC
// words of y[]), then one rising edge: one clock cycle more.
void fp3_spatial_shim_clock(void *h, int valid, const uint32_t *in, const uint32_t *y) {
  dut *d = static_cast<dut *>(h);
  d->top->valid_i = valid ? 1 : 0;
  for (unsigned k = 0; k < SPATIAL_NIN; k++) set_word(d->top->in_i, k, in[k]);
  for (unsigned w = 0; w < SPATIAL_NC; w++) set_word(d->top->y_i, w, y[w]);
  edge(d, 0);
  edge(d, 1);
  d->cycles++;
}

uint64_t fp3_spatial_shim_cycles(void *h) { return static_cast<dut *>(h)->cycles; }

}  // extern "C"
