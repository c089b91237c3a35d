// spatial_shim.cpp -- extern "C" shim over one Verilated spatial chip top
// (`fp3 spatial --pipelines N --objects M`: the frame around a model's
// step module behind its AXI4-Lite slave, sw/compiler/spatial_top.h),
// built into the shared object that the spatial engine loads with dlopen
// (sw/compiler/engine_spatial.c builds it; docs/spatial.md "The spatial
// engine").  The host reaches the chip only as a board's host would:
// AXI4-Lite writes and reads of one word, each with its response, at the
// addresses of sw/isa/fp3_spatial_regs.h.  The Verilated class is
// Vspatial (--prefix Vspatial).
//
// The top has its trace port (fp3_spatial_top with trace): at every
// clock cycle, before the rising edge, each write-back it shows is handed
// to the callback that fp3_spatial_shim_trace sets, so the host observes
// a run of K steps while the model runs freely, with no AXI transfer
// (DESIGN.md "Observe, don't stop").
#include <cstddef>
#include <cstdint>
#include <new>

#include "Vspatial.h"
#include "verilated.h"

namespace {

// Clock cycles one transfer may wait for its handshake or response.
constexpr int kAxiTimeout = 1000;

// The host's callback for one write-back: object obj's nc new carried
// values y[0 .. nc-1], in the clock cycle `cycle` (the shim's count).
typedef void (*trace_fn)(void *ctx, uint32_t obj, const uint32_t *y, unsigned nc,
                         uint64_t cycle);

// The widest carried state the shim copies for the callback (the
// generator's limit, FP3S_MAX_WORDS, is below it).
constexpr unsigned kMaxCarried = 256;

struct dut {
  VerilatedContext ctx;
  Vspatial *top = nullptr;
  uint64_t cycles = 0;
  trace_fn fn = nullptr;
  void *fn_ctx = nullptr;
  unsigned pipelines = 0, carried = 0;
};

// Word i (32 bits) of an output port, as Verilator types it by width:
// an integer up to 64 bits, a VlWide array beyond.
template <typename T>
uint32_t word_of(const T &v, unsigned i) {
  return i < (sizeof v + 3) / 4 ? static_cast<uint32_t>(static_cast<uint64_t>(v) >> (32 * i)) : 0;
}
template <std::size_t N>
uint32_t word_of(const VlWide<N> &v, unsigned i) {
  return i < N ? v[i] : 0;
}

// The write-backs of this cycle (the inputs evaluated, before the edge)
// to the callback.
void observe(dut *d) {
  Vspatial *t = d->top;
  uint32_t y[kMaxCarried];
  for (unsigned p = 0; p < d->pipelines; p++) {
    if (!((word_of(t->trace_v_o, p / 32) >> (p % 32)) & 1u)) continue;
    for (unsigned w = 0; w < d->carried; w++) y[w] = word_of(t->trace_y_o, p * d->carried + w);
    d->fn(d->fn_ctx, word_of(t->trace_obj_o, p), y, d->carried, d->cycles);
  }
}

// One clock cycle: the inputs as set, the clock low (the trace observed),
// then the rising edge.
void tick(dut *d) {
  d->top->clk_i = 0;
  d->top->eval();
  if (d->fn) observe(d);
  d->top->clk_i = 1;
  d->top->eval();
  d->cycles++;
}

}  // namespace

extern "C" {

// rst_i high for four clock cycles, the AXI inputs idle; the cycle count
// starts again at 0.
void fp3_spatial_shim_reset(void *h) {
  dut *d = static_cast<dut *>(h);
  Vspatial *t = d->top;
  t->s_axil_awvalid_i = t->s_axil_wvalid_i = t->s_axil_bready_i = 0;
  t->s_axil_arvalid_i = t->s_axil_rready_i = 0;
  t->s_axil_awprot_i = t->s_axil_arprot_i = 0;
  t->s_axil_wstrb_i = 0xF;
  t->rst_i = 1;
  for (int k = 0; k < 4; k++) tick(d);
  t->rst_i = 0;
  tick(d);
  d->cycles = 0;
}

// A new chip, reset; nullptr when out of memory.
void *fp3_spatial_shim_new(void) {
  dut *d = new (std::nothrow) dut;
  if (!d) return nullptr;
  d->top = new (std::nothrow) Vspatial{&d->ctx};
  if (!d->top) {
    delete d;
    return nullptr;
  }
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

// Write `data` to byte address `addr` (WSTRB 4'b1111; AW and W presented
// together): BRESP (0 OKAY, 2 SLVERR), or -1 when no response came within
// kAxiTimeout cycles.
int fp3_spatial_shim_write(void *h, uint32_t addr, uint32_t data) {
  dut *d = static_cast<dut *>(h);
  Vspatial *t = d->top;
  bool aw = true, w = true;
  t->s_axil_awaddr_i = addr;
  t->s_axil_wdata_i = data;
  t->s_axil_wstrb_i = 0xF;
  t->s_axil_bready_i = 1;
  for (int n = 0; n < kAxiTimeout; n++) {
    t->s_axil_awvalid_i = aw;
    t->s_axil_wvalid_i = w;
    t->clk_i = 0;
    t->eval();
    const bool aw_hs = aw && t->s_axil_awready_o, w_hs = w && t->s_axil_wready_o;
    const bool b = t->s_axil_bvalid_o;
    const int resp = t->s_axil_bresp_o;
    tick(d);
    if (aw_hs) aw = false;
    if (w_hs) w = false;
    if (b) {
      t->s_axil_awvalid_i = t->s_axil_wvalid_i = t->s_axil_bready_i = 0;
      return resp;
    }
  }
  t->s_axil_awvalid_i = t->s_axil_wvalid_i = t->s_axil_bready_i = 0;
  return -1;
}

// Read byte address `addr` into *data: RRESP (0 OKAY, 2 SLVERR), or -1
// when no response came within kAxiTimeout cycles.
int fp3_spatial_shim_read(void *h, uint32_t addr, uint32_t *data) {
  dut *d = static_cast<dut *>(h);
  Vspatial *t = d->top;
  bool ar = true;
  t->s_axil_araddr_i = addr;
  t->s_axil_rready_i = 1;
  for (int n = 0; n < kAxiTimeout; n++) {
    t->s_axil_arvalid_i = ar;
    t->clk_i = 0;
    t->eval();
    const bool ar_hs = ar && t->s_axil_arready_o;
    const bool r = t->s_axil_rvalid_o;
    const uint32_t v = t->s_axil_rdata_o;
    const int resp = t->s_axil_rresp_o;
    tick(d);
    if (ar_hs) ar = false;
    if (r) {
      t->s_axil_arvalid_i = t->s_axil_rready_i = 0;
      *data = v;
      return resp;
    }
  }
  t->s_axil_arvalid_i = t->s_axil_rready_i = 0;
  return -1;
}

// Read the n words at byte addresses addr[0 .. n-1] into data[], their
// RRESP into resp[]: the next AR is presented as soon as the last one is
// accepted, so the slave's read channel is kept busy (a read every
// eighth cycle: docs/spatial.md "The register map").  Returns the reads
// answered, n unless one timed out (kAxiTimeout cycles without a
// handshake or a response).
size_t fp3_spatial_shim_read_many(void *h, const uint32_t *addr, size_t n, uint32_t *data,
                                  int *resp) {
  dut *d = static_cast<dut *>(h);
  Vspatial *t = d->top;
  size_t issued = 0, got = 0;
  int idle = 0;
  t->s_axil_rready_i = 1;
  while (got < n && idle < kAxiTimeout) {
    t->s_axil_arvalid_i = issued < n;
    if (issued < n) t->s_axil_araddr_i = addr[issued];
    t->clk_i = 0;
    t->eval();
    const bool ar_hs = t->s_axil_arvalid_i && t->s_axil_arready_o;
    const bool r = t->s_axil_rvalid_o;
    const uint32_t v = t->s_axil_rdata_o;
    const int rr = t->s_axil_rresp_o;
    tick(d);
    idle++;
    if (ar_hs) issued++, idle = 0;
    if (r) {
      data[got] = v;
      resp[got++] = rr;
      idle = 0;
    }
  }
  t->s_axil_arvalid_i = t->s_axil_rready_i = 0;
  return got;
}

// Hand every write-back of the trace port to fn(ctx, ...) from now on
// (fn NULL: no more), the top having `pipelines` pipelines of `carried`
// carried words.  0, or -1 when carried exceeds what the shim copies.
int fp3_spatial_shim_trace(void *h, unsigned pipelines, unsigned carried, trace_fn fn,
                           void *ctx) {
  dut *d = static_cast<dut *>(h);
  if (carried > kMaxCarried) return -1;
  d->fn = fn;
  d->fn_ctx = ctx;
  d->pipelines = pipelines;
  d->carried = carried;
  return 0;
}

// Clock cycles simulated since the last reset (the host's transfers
// included; the chip's CYCLES register counts a run's own).
uint64_t fp3_spatial_shim_cycles(void *h) { return static_cast<dut *>(h)->cycles; }

}  // extern "C"
