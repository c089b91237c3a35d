// vmodel.h -- what every FP3 Verilator shim shares: the VerilatedContext,
// the model, an optional VCD writer with a window of cycles, reset and
// half clock cycles.  Header-only C++, a template over the Verilated
// class; the shims that include it are the project's only C++.
#ifndef FP3_VMODEL_H
#define FP3_VMODEL_H

#include <cstdint>
#include <cstdio>
#include <new>

#include "verilated.h"
#include "verilated_vcd_c.h"

template <class Top>
struct vmodel {
  VerilatedContext *ctx = nullptr;
  Top *top = nullptr;
  VerilatedVcdC *vcd = nullptr;  // nullptr: no waveform
  // Cycles since creation; the waveform holds cycles win_lo .. win_hi-1.
  // One clock cycle is two time units in the waveform.
  uint64_t cyc = 0, win_lo = 0, win_hi = UINT64_MAX;

  // A new model (inputs as Verilator leaves them: zero), writing a VCD of
  // every signal to trace_path unless it is null.  nullptr when out of
  // memory or when the file cannot be opened (message on stderr).
  static vmodel *create(const char *trace_path) {
    vmodel *m = nullptr;
    try {
      m = new vmodel;
      m->ctx = new VerilatedContext;
      if (trace_path) m->ctx->traceEverOn(true);
      m->top = new Top{m->ctx};
      if (trace_path) {
        m->vcd = new VerilatedVcdC;
        m->top->trace(m->vcd, 99);
        m->vcd->open(trace_path);
        if (!m->vcd->isOpen()) {
          std::fprintf(stderr, "fp3: cannot open trace file %s\n", trace_path);
          m->destroy();
          return nullptr;
        }
      }
    } catch (const std::bad_alloc &) {
      if (m) m->destroy();
      return nullptr;
    }
    return m;
  }

  // clk_i = clk, evaluate, dump (inside the window), advance time.
  void half_cycle(int clk) {
    top->clk_i = clk;
    top->eval();
    if (vcd && cyc >= win_lo && cyc < win_hi) vcd->dump(ctx->time());
    ctx->timeInc(1);
    if (clk) cyc++;
  }

  // rst_i high for two clock cycles, then low with the clock low.
  void reset() {
    top->rst_i = 1;
    for (int i = 0; i < 2; i++) {
      half_cycle(0);
      half_cycle(1);
    }
    top->rst_i = 0;
    half_cycle(0);
  }

  // Dump only cycles first .. first+count-1 counted from now (saturating).
  void window(uint64_t first, uint64_t count) {
    win_lo = first > UINT64_MAX - cyc ? UINT64_MAX : cyc + first;
    win_hi = count > UINT64_MAX - win_lo ? UINT64_MAX : win_lo + count;
  }

  // final() the model, close the waveform, free everything.
  void finish() {
    top->final();
    destroy();
  }

  void destroy() {
    if (vcd) {
      vcd->close();
      delete vcd;
    }
    delete top;
    delete ctx;
    delete this;
  }
};

#endif  // FP3_VMODEL_H
