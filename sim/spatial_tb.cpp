// spatial_tb.cpp -- Verilator harness of a module written by `fp3 spatial`
// (sw/compiler/spatial.h): streams objects through the pipeline and checks
// every object's carried values after every step, bit for bit, against the
// golden model's (the vectors `fp3 spatial --vectors N --steps K` writes).
//
// Build: verilator --cc --exe --build --top-module MODULE --prefix Vspatial
//        -Irtl DIR/MODULE.v sim/spatial_tb.cpp  (tests/test_spatial.sh)
// Run:   Vspatial VECTORS.txt
//
// Streaming: the objects are fed in turn, one per cycle; an object is fed
// its next step as soon as its previous result has left the pipeline
// (valid_o), its own new state as the input (the RTL's, not the golden
// model's), so with more objects than the latency every cycle carries an
// object, and with fewer the cycles between are bubbles (valid_i = 0)
// whose inputs are random words, so that a value read in the wrong cycle
// is wrong even for a lone object.
// Each result must leave exactly LATENCY cycles after its object entered.
// Exit status: 0 every value matches, 1 a mismatch or a timing error, 2 a
// bad vectors file.
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <vector>

#include "Vspatial.h"
#include "spatial_vectors.h"
#include "verilated.h"

// 32-bit word k of a port, whatever type Verilator gives its width.
static void set_word(IData &p, unsigned k, uint32_t v) { (void)k; p = v; }
static void set_word(QData &p, unsigned k, uint32_t v) {
  p = (p & ~(0xFFFFFFFFull << (32 * k))) | ((QData)v << (32 * k));
}
template <std::size_t N> static void set_word(VlWide<N> &p, unsigned k, uint32_t v) { p[k] = v; }
static uint32_t get_word(IData p, unsigned k) { (void)k; return p; }
static uint32_t get_word(QData p, unsigned k) { return (uint32_t)(p >> (32 * k)); }
template <std::size_t N> static uint32_t get_word(const VlWide<N> &p, unsigned k) { return p[k]; }

// The words of a bubble: xorshift32 (Marsaglia).
static uint32_t junk(uint32_t *x) {
  *x ^= *x << 13;
  *x ^= *x >> 17;
  *x ^= *x << 5;
  return *x;
}

int main(int argc, char **argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s VECTORS.txt\n", argv[0]);
    return 2;
  }
  spatial_vectors v;
  if (spatial_vectors_read(argv[1], &v)) return 2;
  const unsigned long nobj = v.nobj, steps = v.steps, nin = v.nin, nc = v.nc, lat = v.lat;
  const std::vector<uint32_t> &in = v.in, &want = v.gold;
  std::vector<uint32_t> y = v.y0;

  Verilated::commandArgs(argc, argv);
  Vspatial top;
  top.clk_i = 0;
  top.rst_i = 1;
  top.valid_i = 0;
  for (int k = 0; k < 4; k++) {
    top.clk_i = 0;
    top.eval();
    top.clk_i = 1;
    top.eval();
  }
  top.rst_i = 0;

  struct issued {
    unsigned long obj;
    uint64_t cycle;
  };
  std::deque<issued> flight;                   // in the pipeline, in order
  std::vector<unsigned long> done(nobj, 0);    // steps finished per object
  std::vector<char> busy(nobj, 0);             // in the pipeline now
  unsigned long next = 0, finished = 0, mismatches = 0, bubbles = 0, fed = 0;
  const unsigned long total = nobj * steps;
  uint64_t cycle = 0;
  uint32_t rng = 0x2545F491u;
  const uint64_t limit = (uint64_t)(total + 2) * (lat + 4) + 100;
  while (finished < total && cycle < limit) {
    top.clk_i = 0;
    top.eval();
    // a result leaving this cycle
    if (top.valid_o) {
      if (flight.empty()) {
        std::fprintf(stderr, "cycle %" PRIu64 ": valid_o with no object in flight\n", cycle);
        return 1;
      }
      issued x = flight.front();
      flight.pop_front();
      if (cycle - x.cycle != lat) {
        std::fprintf(stderr, "object %lu: result after %" PRIu64 " cycles, latency %lu\n", x.obj,
                     cycle - x.cycle, lat);
        return 1;
      }
      const unsigned long s = done[x.obj];
      for (unsigned long w = 0; w < nc; w++) {
        const uint32_t got = get_word(top.y_o, (unsigned)w);
        const uint32_t exp = want[(s * nobj + x.obj) * nc + w];
        if (got != exp && mismatches++ < 10)
          std::fprintf(stderr, "object %lu step %lu value %lu: RTL %08X, golden %08X\n", x.obj,
                       s + 1, w, got, exp);
        y[x.obj * nc + w] = got; // the RTL's own state goes round again
      }
      done[x.obj]++;
      busy[x.obj] = 0;
      finished++;
    } else if (!flight.empty() && cycle - flight.front().cycle >= lat) {
      std::fprintf(stderr, "object %lu: no result %lu cycles after it entered\n",
                   flight.front().obj, lat);
      return 1;
    }
    // the next object in turn, if its previous step has left
    top.valid_i = 0;
    if (fed < total) {
      const unsigned long o = next;
      if (!busy[o] && done[o] < steps) {
        for (unsigned long k = 0; k < nin; k++) set_word(top.in_i, (unsigned)k, in[o * nin + k]);
        for (unsigned long w = 0; w < nc; w++) set_word(top.y_i, (unsigned)w, y[o * nc + w]);
        top.valid_i = 1;
        busy[o] = 1;
        flight.push_back({o, cycle});
        next = (next + 1) % nobj;
        fed++;
      } else {
        bubbles++;
      }
    }
    if (!top.valid_i) { // a bubble carries junk: a read at the wrong cycle shows
      for (unsigned long k = 0; k < nin; k++) set_word(top.in_i, (unsigned)k, junk(&rng));
      for (unsigned long w = 0; w < nc; w++) set_word(top.y_i, (unsigned)w, junk(&rng));
    }
    top.eval();
    top.clk_i = 1;
    top.eval();
    cycle++;
  }
  top.final();
  if (finished < total) {
    std::fprintf(stderr, "only %lu of %lu object-steps left the pipeline\n", finished, total);
    return 1;
  }
  std::printf("%s: %lu objects x %lu steps, latency %lu: %lu cycles, %lu bubbles, "
              "%lu values differ\n",
              mismatches ? "FAIL" : "PASS", nobj, steps, lat, (unsigned long)cycle, bubbles,
              mismatches);
  return mismatches ? 1 : 0;
}
