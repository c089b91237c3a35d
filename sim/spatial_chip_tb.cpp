// spatial_chip_tb.cpp -- Verilator harness of a spatial chip top
// (`fp3 spatial --pipelines N --objects M`, sw/compiler/spatial_top.h),
// driven only through its AXI4-Lite slave and the register map of
// sw/isa/fp3_spatial_regs.h, checked against the golden model's vectors
// (`fp3 spatial --vectors M --steps S`: each object's inputs, initial
// carried values and carried values after every step).
//
// Build: verilator --cc --top-module MODULE_top --prefix Vchip -Irtl -y rtl
//        TOP.v STEP.v, with this file and -Isw/isa (tests/test_spatial.sh)
// Run:   Vchip VECTORS.txt N M HASH
//          N, M  the pipelines and objects the top was generated for
//          HASH  the step module's hash (report.txt "hash:", hexadecimal)
//
// Checks, each reported as "FAIL: <check>: ..." (exit 1 if any fails):
//   id       ID, HASH, INFO, LATENCY, MAXOBJ and STRIDES read as expected
//   load     every object's inputs and carried values written through the
//            windows (AW before W, W before AW, both together) read back;
//            a write and a read of another row presented together
//   slverr   the SLVERR cases of the map answer SLVERR and change nothing,
//            and the OKAY ones OKAY
//   run      runs of K steps over an awake list: afterwards every object's
//            carried values equal the golden model's after the steps it
//            was awake for, bit for bit (a sleeping one is unchanged), and
//            its inputs are unchanged
//   cycles   CYCLES = (K - 1) * max(R, L + 3) + R + L + 4, R = ceil(COUNT / N)
//   flags    FLAGS after a run: inexact (the ship's steps round, nothing
//            else), none after a run of no step (START clears it)
//   busy     while running: STATUS.RUNNING, SLVERR for STEPS, COUNT and the
//            windows, START ignored; a window read performed right after
//            START answers SLVERR
//   rate     back-to-back reads (a scalar register, a window word) answer
//            every 8th cycle and writes every 2nd (docs/spatial.md)
// The runs: a few objects awake (n < L: a step is bubbles but for n / N
// cycles), most awake (n > N * L when M allows), 0 steps.
#include <cinttypes>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "Vchip.h"
#include "fp3_isa.h"
#include "fp3_spatial_regs.h"
#include "spatial_vectors.h"
#include "verilated.h"

static Vchip *top;
static uint64_t cycle;
static unsigned failures;

static void fail(const char *check, const std::string &what) {
  if (failures++ < 20) std::fprintf(stderr, "FAIL: %s: %s\n", check, what.c_str());
}

// One clock: inputs are set while the clock is low, sampled at the edge.
static void tick() {
  top->clk_i = 0;
  top->eval();
  top->clk_i = 1;
  top->eval();
  cycle++;
}

// The AW and W channels' inputs (valid bits, address of word wa, data and
// strobes), and the AR channel's (valid bit, address of word ra).
static void set_write(bool aw, bool w, uint32_t wa, uint32_t data, unsigned strb) {
  top->s_axil_awvalid_i = aw;
  top->s_axil_awaddr_i = FP3S_BYTE(wa);
  top->s_axil_awprot_i = 0;
  top->s_axil_wvalid_i = w;
  top->s_axil_wdata_i = data;
  top->s_axil_wstrb_i = strb;
}
static void set_read(bool ar, uint32_t ra) {
  top->s_axil_arvalid_i = ar;
  top->s_axil_araddr_i = FP3S_BYTE(ra);
  top->s_axil_arprot_i = 0;
}

// The write channels' and the read channels' handshakes in this cycle
// (inputs set, clock low, the model evaluated).
struct write_hs {
  bool aw, w, b;
  unsigned bresp;
};
struct read_hs {
  bool ar, r;
  unsigned rresp;
  uint32_t rdata;
};
static write_hs sample_write() {
  return {top->s_axil_awvalid_i && top->s_axil_awready_o,
          top->s_axil_wvalid_i && top->s_axil_wready_o, (bool)top->s_axil_bvalid_o,
          (unsigned)top->s_axil_bresp_o};
}
static read_hs sample_read() {
  return {top->s_axil_arvalid_i && top->s_axil_arready_o, (bool)top->s_axil_rvalid_o,
          (unsigned)top->s_axil_rresp_o, (uint32_t)top->s_axil_rdata_o};
}
static write_hs eval_write() {
  top->eval();
  return sample_write();
}
static read_hs eval_read() {
  top->eval();
  return sample_read();
}

// A write of word address wa; order 0: AW and W together, 1: W three
// cycles before AW, 2: AW three cycles before W.  Returns BRESP.
static unsigned axi_write(uint32_t wa, uint32_t data, unsigned strb = 0xF, int order = 0) {
  int aw_wait = order == 1 ? 3 : 0, w_wait = order == 2 ? 3 : 0;
  bool aw = true, w = true;
  top->s_axil_bready_i = 1;
  for (int n = 0; n < 1000; n++) {
    top->clk_i = 0;
    set_write(aw && aw_wait == 0, w && w_wait == 0, wa, data, strb);
    const write_hs hs = eval_write();
    tick();
    if (hs.aw) aw = false;
    if (hs.w) w = false;
    if (aw_wait) aw_wait--;
    if (w_wait) w_wait--;
    if (hs.b) {
      top->s_axil_awvalid_i = 0;
      top->s_axil_wvalid_i = 0;
      top->s_axil_bready_i = 0;
      if (aw || w) fail("axi", "B before AW and W were accepted");
      return hs.bresp;
    }
  }
  fail("axi", "no write response");
  return 3;
}

// A read of word address wa; *resp its RRESP.
static uint32_t axi_read(uint32_t wa, unsigned *resp) {
  bool ar = true;
  top->s_axil_rready_i = 1;
  for (int n = 0; n < 1000; n++) {
    top->clk_i = 0;
    set_read(ar, wa);
    const read_hs hs = eval_read();
    *resp = hs.rresp;
    tick();
    if (hs.ar) ar = false;
    if (hs.r) {
      top->s_axil_arvalid_i = 0;
      top->s_axil_rready_i = 0;
      return hs.rdata;
    }
  }
  fail("axi", "no read response");
  *resp = 3;
  return 0;
}

static const unsigned OKAY = 0, SLVERR = 2;

// A write of data to wa and a read of ra presented together (AW, W and
// AR in the same cycle, or AR ar_wait cycles later), so that the slave
// performs one right after the other.  Returns the read's word; *bresp,
// *rresp the responses.
static uint32_t axi_write_with_read(uint32_t wa, uint32_t data, uint32_t ra, unsigned *bresp,
                                    unsigned *rresp, int ar_wait = 0) {
  bool aw = true, w = true, ar = true, b = false, r = false;
  uint32_t rdata = 0;
  *bresp = *rresp = 3;
  top->s_axil_bready_i = 1;
  top->s_axil_rready_i = 1;
  for (int n = 0; n < 1000 && !(b && r); n++) {
    top->clk_i = 0;
    set_write(aw, w, wa, data, 0xF);
    set_read(ar && ar_wait == 0, ra);
    top->eval();
    const write_hs wh = sample_write();
    const read_hs rh = sample_read();
    if (ar_wait) ar_wait--;
    if (!b && wh.b) b = true, *bresp = wh.bresp;
    if (!r && rh.r) r = true, *rresp = rh.rresp, rdata = rh.rdata;
    tick();
    if (wh.aw) aw = false;
    if (wh.w) w = false;
    if (rh.ar) ar = false;
  }
  top->s_axil_awvalid_i = top->s_axil_wvalid_i = top->s_axil_arvalid_i = 0;
  top->s_axil_bready_i = top->s_axil_rready_i = 0;
  if (!(b && r)) fail("axi", "no response to a write and a read presented together");
  return rdata;
}

// The slave's transfer rate, cycle-exact: n reads of wa with ARVALID and
// RREADY held high (the next AR presented as soon as one is accepted), or
// n writes of data to wa with AWVALID, WVALID and BREADY held high.
// Returns the cycles from the first response to the last over n - 1 (the
// period), or 0 when a response is missing or not OKAY.
static unsigned axi_read_period(uint32_t wa, unsigned n) {
  unsigned issued = 0, got = 0;
  uint64_t first = 0, last = 0;
  top->s_axil_rready_i = 1;
  for (int k = 0; k < 100 * (int)n && got < n; k++) {
    top->clk_i = 0;
    set_read(issued < n, wa);
    const read_hs hs = eval_read();
    tick();
    if (hs.ar) issued++;
    if (hs.r) {
      if (hs.rresp != OKAY) break;
      (got++ ? last : first) = cycle;
    }
  }
  top->s_axil_arvalid_i = 0;
  top->s_axil_rready_i = 0;
  return got == n && n > 1 ? (unsigned)((last - first) / (n - 1)) : 0;
}
static unsigned axi_write_period(uint32_t wa, uint32_t data, unsigned n) {
  unsigned aw = 0, w = 0, got = 0;
  uint64_t first = 0, last = 0;
  top->s_axil_bready_i = 1;
  for (int k = 0; k < 100 * (int)n && got < n; k++) {
    top->clk_i = 0;
    set_write(aw < n, w < n, wa, data, 0xF);
    const write_hs hs = eval_write();
    tick();
    aw += hs.aw;
    w += hs.w;
    if (hs.b) {
      if (hs.bresp != OKAY) break;
      (got++ ? last : first) = cycle;
    }
  }
  top->s_axil_awvalid_i = 0;
  top->s_axil_wvalid_i = 0;
  top->s_axil_bready_i = 0;
  return got == n && n > 1 ? (unsigned)((last - first) / (n - 1)) : 0;
}

static std::string hex(uint32_t v) {
  char b[16];
  std::snprintf(b, sizeof b, "%08X", v);
  return b;
}

// Expect a read of wa to answer resp and (if OKAY) data want.
static uint32_t expect_read(const char *check, uint32_t wa, unsigned resp, uint32_t want,
                            bool check_data = true) {
  unsigned r;
  const uint32_t v = axi_read(wa, &r);
  if (r != resp) fail(check, "read of " + hex(wa) + ": resp " + std::to_string(r));
  else if (resp == SLVERR && v != 0) fail(check, "SLVERR read of " + hex(wa) + " with data");
  else if (check_data && v != want)
    fail(check, "read of " + hex(wa) + ": " + hex(v) + ", want " + hex(want));
  return v;
}

static void expect_write(const char *check, uint32_t wa, uint32_t data, unsigned resp,
                         unsigned strb = 0xF, int order = 0) {
  const unsigned r = axi_write(wa, data, strb, order);
  if (r != resp)
    fail(check, "write of " + hex(data) + " to " + hex(wa) + ": resp " + std::to_string(r) +
                    ", want " + std::to_string(resp));
}

int main(int argc, char **argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: %s VECTORS.txt N M HASH\n", argv[0]);
    return 2;
  }
  const unsigned N = (unsigned)std::strtoul(argv[2], nullptr, 10);
  const unsigned M = (unsigned)std::strtoul(argv[3], nullptr, 10);
  const uint32_t hash = (uint32_t)std::strtoull(argv[4], nullptr, 16);
  spatial_vectors v;
  if (spatial_vectors_read(argv[1], &v)) return 2;
  if (v.nobj != M || v.steps < 5) {
    std::fprintf(stderr, "%s: vectors of %lu objects and %lu steps, not %u and 5 or more\n",
                 argv[1], v.nobj, v.steps, M);
    return 2;
  }
  const unsigned long nobj = v.nobj, nin = v.nin, nc = v.nc, lat = v.lat;
  const std::vector<uint32_t> &in = v.in, &y0 = v.y0, &gold = v.gold;

  Verilated::commandArgs(argc, argv);
  top = new Vchip;
  top->rst_i = 1;
  for (int k = 0; k < 4; k++) tick();
  top->rst_i = 0;
  tick();

  // ---- id ----
  unsigned slog = 0, ilog = 0;
  while ((1ul << slog) < nc) slog++;
  while ((1ul << ilog) < nin) ilog++;
  expect_read("id", FP3S_ID, OKAY, FP3S_ID_VALUE);
  expect_read("id", FP3S_HASH, OKAY, hash);
  const uint32_t info = expect_read("id", FP3S_INFO, OKAY, 0, false);
  if (FP3S_INFO_PIPELINES(info) != N || FP3S_INFO_INPUTS(info) != nin ||
      FP3S_INFO_CARRIED(info) != nc)
    fail("id", "INFO " + hex(info));
  expect_read("id", FP3S_LATENCY, OKAY, (uint32_t)lat);
  expect_read("id", FP3S_MAXOBJ, OKAY, M);
  const uint32_t strides = expect_read("id", FP3S_STRIDES, OKAY, slog | ilog << 8);
  const uint32_t SS = FP3S_STATE_STRIDE(strides), SI = FP3S_INPUT_STRIDE(strides);
  expect_read("id", FP3S_STATUS, OKAY, 0);

  // ---- rate: back-to-back transfers, as docs/spatial.md gives them ----
  // (a scalar register and one object's words: no division by N)
  const unsigned rp = axi_read_period(FP3S_ID, 8), rpw = axi_read_period(FP3S_STATE_BASE, 8);
  const unsigned wp = axi_write_period(FP3S_STEPS, 0, 8);
  if (rp != 8 || rpw != 8 || wp != 2)
    fail("rate", "a read every " + std::to_string(rp) + " cycles (a window's: " +
                     std::to_string(rpw) + "), a write every " + std::to_string(wp) +
                     "; want 8, 8 and 2");

  // ---- load: every object, the three channel orders in turn ----
  int order = 0;
  for (unsigned o = 0; o < M; o++) {
    for (unsigned k = 0; k < nin; k++)
      expect_write("load", FP3S_INPUT_BASE + o * SI + k, in[o * nin + k], OKAY, 0xF,
                   order++ % 3);
    for (unsigned w = 0; w < nc; w++)
      expect_write("load", FP3S_STATE_BASE + o * SS + w, y0[o * nc + w], OKAY, 0xF,
                   order++ % 3);
  }
  std::vector<unsigned> done(M, 0); // steps each object has made
  // every object's state and inputs against the golden model
  auto check_all = [&](const char *check) {
    for (unsigned o = 0; o < M; o++) {
      for (unsigned w = 0; w < nc; w++) {
        const uint32_t want =
            done[o] ? gold[((done[o] - 1) * nobj + o) * nc + w] : y0[o * nc + w];
        unsigned r;
        const uint32_t v = axi_read(FP3S_STATE_BASE + o * SS + w, &r);
        if (r != OKAY || v != want)
          fail(check, "object " + std::to_string(o) + " (bank " + std::to_string(o % N) +
                          ") after " + std::to_string(done[o]) + " steps, value " +
                          std::to_string(w) + ": " + hex(v) + ", golden " + hex(want));
      }
      for (unsigned k = 0; k < nin; k++) {
        unsigned r;
        const uint32_t v = axi_read(FP3S_INPUT_BASE + o * SI + k, &r);
        if (r != OKAY || v != in[o * nin + k])
          fail(check, "object " + std::to_string(o) + " input " + std::to_string(k) + ": " +
                          hex(v));
      }
    }
  };
  check_all("load");
  // a write and a read presented together, to rows of one bank (objects
  // o and o + N): each performed right after the other, in either order
  // (the arbitration takes turns), the read's word that of its own row.
  // Inputs, whose words differ between objects (the initial carried
  // values may all be zero).
  for (unsigned o = 0; o + N < M && o < 4 * N; o++)
    for (unsigned k = 0; k < nin; k++) {
      unsigned br, rr;
      const uint32_t want = in[(o + N) * nin + k];
      const uint32_t got = axi_write_with_read(FP3S_INPUT_BASE + o * SI + k, in[o * nin + k],
                                               FP3S_INPUT_BASE + (o + N) * SI + k, &br, &rr);
      if (br != OKAY || rr != OKAY || got != want)
        fail("load", "a write to object " + std::to_string(o) + " with a read of object " +
                         std::to_string(o + N) + ", input " + std::to_string(k) + ": " +
                         hex(got) + ", want " + hex(want));
    }
  check_all("load");

  // ---- slverr: each case answers SLVERR and changes nothing ----
  expect_write("slverr", FP3S_ID, 0, SLVERR);
  expect_write("slverr", FP3S_STATUS, 3, SLVERR);
  expect_write("slverr", FP3S_CYCLES_LO, 1, SLVERR);
  expect_write("slverr", 0x006, 1, SLVERR);
  expect_read("slverr", FP3S_CTRL, SLVERR, 0);
  expect_read("slverr", 0x006, SLVERR, 0);
  expect_read("slverr", 0x0FFFFF, SLVERR, 0);
  expect_write("slverr", FP3S_STEPS, 5, OKAY);
  expect_write("slverr", FP3S_STEPS, 7, SLVERR, 0x7); // a byte lane missing
  expect_read("slverr", FP3S_STEPS, OKAY, 5);
  expect_write("slverr", FP3S_COUNT, M, OKAY);
  expect_write("slverr", FP3S_COUNT, M + 1, SLVERR);
  expect_read("slverr", FP3S_COUNT, OKAY, M);
  // windows: beyond M, beyond the object's words
  expect_write("slverr", FP3S_STATE_BASE + M * SS, 1, SLVERR);
  expect_read("slverr", FP3S_STATE_BASE + M * SS, SLVERR, 0);
  expect_write("slverr", FP3S_INPUT_BASE + M * SI, 1, SLVERR);
  expect_write("slverr", FP3S_AWAKE_BASE + M, 0, SLVERR);
  expect_read("slverr", FP3S_AWAKE_BASE + M, SLVERR, 0);
  if (SI > nin) {
    expect_write("slverr", FP3S_INPUT_BASE + (uint32_t)nin, 1, SLVERR);
    expect_read("slverr", FP3S_INPUT_BASE + (uint32_t)nin, SLVERR, 0);
  }
  if (SS > nc) expect_write("slverr", FP3S_STATE_BASE + (uint32_t)nc, 1, SLVERR);
  // the awake list: the empty slot, an object of the entry's bank: OKAY;
  // an object >= M or of another bank: SLVERR, the entry unchanged
  expect_write("slverr", FP3S_AWAKE_BASE + 0, FP3S_AWAKE_NONE, OKAY);
  expect_read("slverr", FP3S_AWAKE_BASE + 0, OKAY, FP3S_AWAKE_NONE);
  expect_write("slverr", FP3S_AWAKE_BASE + 0, N, OKAY);
  expect_read("slverr", FP3S_AWAKE_BASE + 0, OKAY, N);
  expect_write("slverr", FP3S_AWAKE_BASE + 0, M, SLVERR);
  if (N > 1) expect_write("slverr", FP3S_AWAKE_BASE + 0, 1, SLVERR);
  expect_read("slverr", FP3S_AWAKE_BASE + 0, OKAY, N);
  check_all("slverr"); // no SLVERR write reached an object

  // ---- runs ----
  auto run = [&](const std::vector<unsigned char> &awake, unsigned K, bool busy_checks) {
    std::vector<uint32_t> list(M + N);
    const size_t count = fp3s_awake_list(awake.data(), M, N, list.data());
    for (size_t i = 0; i < count; i++) expect_write("run", FP3S_AWAKE_BASE + (uint32_t)i, list[i], OKAY);
    for (size_t i = 0; i < count; i++) expect_read("run", FP3S_AWAKE_BASE + (uint32_t)i, OKAY, list[i]);
    expect_write("run", FP3S_COUNT, (uint32_t)count, OKAY);
    expect_write("run", FP3S_STEPS, K, OKAY);
    if (!busy_checks) expect_write("run", FP3S_CTRL, FP3S_CTRL_START, OKAY);
    if (busy_checks) {
      // START with a window read right behind it (AR a cycle after AW
      // and W, so the write is performed first): the read is performed
      // after START, so it answers as during the run, SLVERR.  (The read
      // before it is of the same object, so that this one needs no
      // division by N and follows START by a cycle or two.)
      unsigned br, rr;
      const unsigned o = M - 1;
      expect_read("busy", FP3S_INPUT_BASE + o * SI, OKAY, in[o * nin]);
      const uint32_t got = axi_write_with_read(FP3S_CTRL, FP3S_CTRL_START,
                                               FP3S_INPUT_BASE + o * SI + nin - 1, &br, &rr, 1);
      if (br != OKAY || rr != SLVERR || got != 0)
        fail("busy", "START with a read of object " + std::to_string(o) + "'s input behind it: resp " +
                         std::to_string(br) + ", read resp " + std::to_string(rr) + " " +
                         hex(got) + ", want SLVERR");
      expect_read("busy", FP3S_STATUS, OKAY, FP3S_STATUS_RUNNING);
      expect_write("busy", FP3S_STEPS, 1, SLVERR);
      expect_write("busy", FP3S_COUNT, 1, SLVERR);
      expect_write("busy", FP3S_STATE_BASE, 0, SLVERR);
      expect_write("busy", FP3S_INPUT_BASE, 0, SLVERR);
      expect_write("busy", FP3S_AWAKE_BASE, FP3S_AWAKE_NONE, SLVERR);
      expect_read("busy", FP3S_STATE_BASE, SLVERR, 0);
      expect_read("busy", FP3S_AWAKE_BASE, SLVERR, 0);
      expect_write("busy", FP3S_CTRL, FP3S_CTRL_START, OKAY); // ignored
      expect_read("busy", FP3S_STEPS, OKAY, K);
    }
    unsigned r, polls = 0;
    uint32_t st;
    while ((st = axi_read(FP3S_STATUS, &r)) & FP3S_STATUS_RUNNING)
      if (++polls > 1000000) {
        fail("run", "never done");
        break;
      }
    if (st != FP3S_STATUS_DONE) fail("run", "STATUS " + hex(st) + " after the run");
    const uint64_t cyc = axi_read(FP3S_CYCLES_LO, &r) |
                         (uint64_t)axi_read(FP3S_CYCLES_HI, &r) << 32;
    const uint64_t R = (count + N - 1) / N;
    const uint64_t P = R > lat + 3 ? R : lat + 3;
    const uint64_t want = K && R ? (K - 1) * P + R + lat + 4 : 0;
    unsigned n = 0;
    for (unsigned o = 0; o < M; o++) n += awake[o] != 0;
    if (cyc != want)
      fail("cycles", std::to_string(K) + " steps, " + std::to_string(R) + " rounds: " +
                         std::to_string(cyc) + " cycles, formula " + std::to_string(want));
    // FLAGS: the cores' flags on this run's objects, cleared by START: the
    // ship's steps round (inexact) and stay normal; a run of no step none
    const uint32_t flags = axi_read(FP3S_FLAGS, &r);
    const uint32_t want_flags = K && R ? FP3_FLAG_INEXACT : 0;
    if (r != OKAY || flags != want_flags)
      fail("flags", std::to_string(K) + " steps: FLAGS " + hex(flags) + ", want " +
                        hex(want_flags));
    std::printf("run: %u of %u objects awake, %zu entries, %u pipelines, latency %lu, "
                "%u steps: %" PRIu64 " cycles (formula %" PRIu64 ")\n",
                n, M, count, N, lat, K, cyc, want);
    for (unsigned o = 0; o < M; o++)
      if (awake[o]) done[o] += K;
    check_all("run");
  };
  // few awake: every third object of the first L (n < L)
  std::vector<unsigned char> awake(M, 0);
  for (unsigned o = 0; o < M && o < lat; o += 3) awake[o] = 1;
  run(awake, 2, false);
  // most awake: all but every ninth (n > N * L when M > 9/8 N L)
  for (unsigned o = 0; o < M; o++) awake[o] = o % 9 != 4;
  run(awake, 3, true);
  // no step
  run(awake, 0, false);

  top->final();
  delete top;
  if (failures) {
    std::printf("FAIL: %u checks failed\n", failures);
    return 1;
  }
  std::printf("PASS: chip of %u pipelines, %u objects, latency %lu: every object bit-exact\n", N,
              M, lat);
  return 0;
}
