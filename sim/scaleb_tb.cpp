// scaleb_tb.cpp -- rtl/fp_scaleb.v against the C reference: every result
// and flag of the sixteen configurations of sim/scaleb_top.v (RNE, RTZ,
// each with and without FTZ, at LATENCY 1, 2, 3 and 4) must equal
// fpref_mul(a, b) (sw/ref/fpref.h, the reference fp_mul equals) in that
// rounding and FTZ, bit for bit, with valid_o exactly LATENCY cycles after
// valid_i.
//
// Operands, one pair per cycle (bubbles between, every 7th cycle):
//   directed: a from a list of edge cases (zeros, the smallest and largest
//     subnormals, the smallest normal and its neighbours, the largest
//     finite number, infinities, quiet and signalling NaNs, subnormals
//     whose scaled value is a rounding tie, the last bits of a tie's
//     neighbours) times every b = +-2^k, k = -126 to 127;
//   random: N pairs (argument, default 4,000,000): a's exponent field
//     uniform over 0 to 255, or near 0 or near 255, and a random fraction
//     and sign; b = +-2^k with k uniform over -126 to 127, or in -30 to 30.
// Run:   Vscaleb_tb [N] [SEED]
// Exit status: 0 all equal, 1 a difference (the first 10 printed).
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <vector>

#include "Vscaleb_top.h"
#include "verilated.h"

#include "fpref.h" // built as C++ with this harness (tests/test_scaleb.sh)

static uint64_t rng_state = 88172645463325252ull;
static uint64_t rnd() { // xorshift64 (Marsaglia)
  rng_state ^= rng_state << 13;
  rng_state ^= rng_state >> 7;
  rng_state ^= rng_state << 17;
  return rng_state;
}

struct pending {
  uint64_t cycle;
  uint32_t a, b;
};

int main(int argc, char **argv) {
  const uint64_t nrand = argc > 1 ? strtoull(argv[1], nullptr, 0) : 4000000ull;
  if (argc > 2) rng_state = strtoull(argv[2], nullptr, 0) | 1;
  Verilated::commandArgs(argc, argv);
  Vscaleb_top top;
  std::vector<std::pair<uint32_t, uint32_t>> ops;
  const uint32_t edge[] = {
      0x00000000, 0x00000001, 0x00000002, 0x00000003, 0x00000005, 0x00000006, 0x00000007,
      0x007FFFFF, 0x007FFFFE, 0x00400000, 0x00400001, 0x00400003, 0x00555555, 0x00000100,
      0x00800000, 0x00800001, 0x00FFFFFF, 0x01000000, 0x00C00000, 0x00A00001, 0x3F800000,
      0x3F800001, 0x3FFFFFFF, 0x7F7FFFFF, 0x7F000000, 0x7E800000, 0x7F800000, 0x7FC00000,
      0x7FC00001, 0x7F800001, 0x7FA00000, 0x7FFFFFFF, 0x0C000003, 0x0B800001, 0x0D7FFFFF,
      0x04FFFFFF, 0x03800001, 0x34000001, 0x34800003};
  for (uint32_t a : edge)
    for (uint32_t e = 1; e <= 254; e++)
      for (uint32_t s = 0; s < 4; s++)
        ops.push_back({a ^ ((s & 1) << 31), ((s >> 1) << 31) | (e << 23)});
  const size_t ndirected = ops.size();
  uint64_t bad = 0, checked = 0, cyc = 0;
  std::deque<pending> inflight;
  size_t next = 0;
  uint64_t made = 0;
  const fpref_mode modes[4] = {{FPREF_RNE, 0}, {FPREF_RTZ, 0}, {FPREF_RNE, 1}, {FPREF_RTZ, 1}};
  top.rst_i = 1;
  top.clk_i = 0;
  top.eval();
  top.clk_i = 1;
  top.eval();
  top.rst_i = 0;
  for (;;) {
    const bool more = next < ndirected || made < nrand;
    if (!more && inflight.empty()) break;
    // the inputs of this cycle
    uint32_t a = (uint32_t)rnd(), b = 0x3F800000;
    bool valid = more && cyc % 7 != 6;
    if (valid) {
      if (next < ndirected) {
        a = ops[next].first;
        b = ops[next].second;
        next++;
      } else {
        uint64_t r = rnd();
        uint32_t ea;
        switch (r & 3) {
        case 0: ea = (uint32_t)((r >> 2) % 256); break;
        case 1: ea = (uint32_t)((r >> 2) % 40); break;   // subnormal, tiny results
        case 2: ea = 255 - (uint32_t)((r >> 2) % 40); break; // overflow, inf, NaN
        default: ea = 100 + (uint32_t)((r >> 2) % 56); break;
        }
        uint64_t r2 = rnd();
        a = (uint32_t)(r2 & 0x807FFFFFu) | (ea << 23);
        if ((r2 >> 40) % 8 == 0) a &= 0xFFFFFFF0u; // more ties and exact cases
        int k = (r2 >> 32) & 1 ? (int)((r2 >> 33) % 254) - 126 : (int)((r2 >> 33) % 61) - 30;
        b = (uint32_t)(((r2 >> 50) & 1) << 31) | ((uint32_t)(k + 127) << 23);
        made++;
      }
    }
    top.valid_i = valid;
    top.a_i = a;
    top.b_i = b;
    top.clk_i = 0;
    top.eval();
    // outputs of this cycle: instance j at LATENCY j / 4 + 1
    for (int j = 0; j < 16; j++) {
      const unsigned lat = (unsigned)(j / 4 + 1);
      const bool vo = (top.valid_o >> j) & 1;
      const pending *p = nullptr;
      for (const pending &q : inflight)
        if (q.cycle + lat == cyc) p = &q;
      if (vo != (p != nullptr)) {
        if (bad++ < 10) printf("instance %d: valid_o %d in cycle %" PRIu64 ", want %d\n", j, vo,
                               cyc, p != nullptr);
        continue;
      }
      if (!p) continue;
      unsigned want_f = 0;
      const uint32_t want = fpref_mul(p->a, p->b, modes[j % 4], &want_f);
      const uint32_t got = top.y_o[j];
      const unsigned lo = 5 * (unsigned)j; // flags_o is 80 bits: three words
      const uint64_t two = top.flags_o[lo / 32] |
                           (lo / 32 + 1 < 3 ? (uint64_t)top.flags_o[lo / 32 + 1] << 32 : 0);
      const unsigned got_f = (unsigned)(two >> (lo % 32)) & 31;
      checked++;
      if (got != want || got_f != want_f) {
        if (bad++ < 10)
          printf("instance %d (%s%s, latency %u): %08X * %08X = %08X flags %02X, want %08X "
                 "flags %02X\n",
                 j, j % 2 ? "rtz" : "rne", (j / 2) % 2 ? " ftz" : "", lat, p->a, p->b, got,
                 got_f, want, want_f);
      }
    }
    while (!inflight.empty() && inflight.front().cycle + 4 <= cyc) inflight.pop_front();
    if (valid) inflight.push_back({cyc, a, b});
    top.clk_i = 1;
    top.eval();
    cyc++;
  }
  printf("%s: fp_scaleb: %zu directed and %" PRIu64 " random operand pairs, %" PRIu64
         " results of 16 configurations checked against fpref_mul, %" PRIu64 " differ\n",
         bad ? "FAIL" : "PASS", ndirected, made, checked, bad);
  return bad ? 1 : 0;
}
