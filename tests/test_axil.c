/*
 * test_axil.c -- the AXI4-Lite wrapper (rtl/fp3_axil.v) driven by real
 * AXI4-Lite transactions from a C master (sim/fp3_axil_model.h), in both
 * of its builds: default parameters, and the build for clock rate
 * (FMAX_PIPE: a read takes 5 cycles on the host port instead of 1).
 * Every test runs on both builds but test_ship_cycles (default only).
 *
 * The master keeps a queue of writes and a queue of reads and runs all
 * five channels independently, cycle by cycle: a VALID, once raised, is
 * held with a stable payload until its handshake; READYs of B and R may
 * rise and fall at will.  A policy gives the per-cycle chance of raising a
 * VALID and of holding a READY (100 %: back to back).  Every cycle the
 * master checks the slave against the protocol: B and R stay valid with a
 * stable payload until taken, no B before its AW and W, no R before its
 * AR.  It also counts the situations the wrapper must survive (VALID
 * before READY on AW/W/AR, READY before VALID on B/R, W before AW and AW
 * before W) and the random test asserts that each one happened.
 *
 *  - ID and INFO through the bus;
 *  - the ship program loaded, started, polled and read back through the
 *    bus: final registers, status and counters equal to the ISS and to
 *    the host-port RTL model, v and s equal to the golden model, bit for
 *    bit; with back-to-back and with random handshakes;
 *  - back-to-back writes and reads at the wrapper's full rate;
 *  - random delays on every channel, many seeds, against a model of the
 *    register window;
 *  - every word address read and written: OKAY exactly where the access
 *    column of FP3_HOSTREGS (sw/isa/fp3_isa.h) has the access, SLVERR with
 *    no effect for every access the core ignores;
 *  - all contexts running the ship at once, each against the golden model.
 */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "asm.h"
#include "engine.h"
#include "fp3_axil_model.h"
#include "fp3_isa.h"
#include "fp3_model.h"
#include "fpref.h"
#include "compile.h"
#include "objects.h"
#include "image.h"
#include "model.h"

#define RESP_OKAY   0u
#define RESP_SLVERR 2u
#define BYTE(word_addr) ((uint32_t)(word_addr) * 4u)
#define MAX_REGS 256

/* The processors of the FMAX and lanes builds' parameters behind the plain
 * host port (RTL_CFG_fmax and RTL_CFG_l4 of mk/rtl.mk). */
extern const fp3_model_ops fp3_model_fmax, fp3_model_l4;

/* One build of the wrapper and the parameters it reports. */
typedef struct build {
  fp3_axil_variant variant;
  const fp3_model_ops *core; /* fp3_top of the same parameters */
  unsigned num_contexts, add_latency, mul_latency, fmax_pipe, num_lanes;
} build;

static build build_default = {FP3_AXIL_DEFAULT, &fp3_model_rne, FP3_DEFAULT_NUM_CONTEXTS,
                              FP3_DEFAULT_ADD_LATENCY, FP3_DEFAULT_MUL_LATENCY, 0, 1};
static build build_fmax = {FP3_AXIL_FMAX, &fp3_model_fmax, 8, 9, 10, 1, 1};
static build build_lanes = {FP3_AXIL_LANES, &fp3_model_l4, 8, FP3_DEFAULT_ADD_LATENCY,
                            FP3_DEFAULT_MUL_LATENCY, 0, 4};

/* Cycles from a read's address on the host port to its data: fp3_top's
 * (FP3_HOST_READ_CYCLES), and with FMAX_PIPE the wrapper registers the
 * address in front of it. */
static unsigned read_latency(const build *bd) {
  return FP3_HOST_READ_CYCLES(bd->fmax_pipe, bd->num_lanes) + bd->fmax_pipe;
}

/* ---- the AXI4-Lite master ---------------------------------------------------- */

typedef struct axi_wr {
  uint32_t addr, data; /* byte address */
  unsigned strb;
  unsigned resp;       /* filled in */
} axi_wr;

typedef struct axi_rd {
  uint32_t addr;
  uint32_t data;       /* filled in */
  unsigned resp;       /* filled in */
} axi_rd;

enum { ORDER_ANY, ORDER_AW_FIRST, ORDER_W_FIRST };

typedef struct axi_policy {
  unsigned p_valid; /* % chance per cycle of raising a pending VALID      */
  unsigned p_ready; /* % chance per cycle of BREADY / RREADY being high   */
  int order;        /* ORDER_*: which of AW and W of a write goes first   */
} axi_policy;

static const axi_policy FAST = {100, 100, ORDER_ANY};
static const axi_policy RANDOM = {50, 50, ORDER_ANY};

typedef struct axi_stats {
  unsigned long aw_wait, w_wait, ar_wait;   /* VALID high, READY low          */
  unsigned long b_early, r_early;           /* READY high, VALID low          */
  unsigned long b_stall, r_stall;           /* VALID high, READY low (master) */
  unsigned long w_before_aw, aw_before_w;   /* first half of a write          */
  unsigned long cycles;
} axi_stats;

typedef struct bus {
  fp3_axil_model *m;
  uint32_t rng;
  axi_policy pol;
  axi_stats st;
  fp3_axil_out last; /* outputs of the most recent cycle */
} bus;

static unsigned rnd(bus *b) {
  uint32_t x = b->rng;
  x ^= x << 13;
  x ^= x >> 17;
  x ^= x << 5;
  b->rng = x;
  return x;
}

static int chance(bus *b, unsigned pct) { return pct >= 100 || rnd(b) % 100 < pct; }

/* Run the writes and the reads concurrently to completion. */
static void axi_do(bus *b, axi_wr *wr, size_t nw, axi_rd *rd, size_t nr) {
  size_t aw = 0, w = 0, bi = 0, ar = 0, ri = 0;
  int aw_on = 0, w_on = 0, ar_on = 0;
  int prev_b_wait = 0, prev_r_wait = 0;
  fp3_axil_out prev = {0};
  const unsigned long limit = 1000 + 200 * (unsigned long)(nw + nr);
  for (unsigned long cyc = 0; bi < nw || ri < nr; cyc++) {
    if (cyc > limit) fail_msg("AXI hang: %zu/%zu writes, %zu/%zu reads answered", bi, nw, ri, nr);
    fp3_axil_in in = {0};
    /* A raised VALID stays raised until its handshake. */
    if (!aw_on && aw < nw && chance(b, b->pol.p_valid) &&
        !(b->pol.order == ORDER_W_FIRST && w <= aw))
      aw_on = 1;
    if (!w_on && w < nw && chance(b, b->pol.p_valid) &&
        !(b->pol.order == ORDER_AW_FIRST && aw <= w))
      w_on = 1;
    if (!ar_on && ar < nr && chance(b, b->pol.p_valid)) ar_on = 1;
    if (aw_on) {
      in.awvalid = 1;
      in.awaddr = wr[aw].addr;
    }
    if (w_on) {
      in.wvalid = 1;
      in.wdata = wr[w].data;
      in.wstrb = wr[w].strb;
    }
    if (ar_on) {
      in.arvalid = 1;
      in.araddr = rd[ar].addr;
    }
    in.bready = chance(b, b->pol.p_ready);
    in.rready = chance(b, b->pol.p_ready);

    fp3_axil_out out;
    fp3_axil_model_cycle(b->m, &in, &out);
    b->st.cycles++;

    /* Protocol: a response not taken stays, unchanged. */
    if (prev_b_wait && (!out.bvalid || out.bresp != prev.bresp))
      fail_msg("B dropped or changed while waiting for BREADY (cycle %lu)", cyc);
    if (prev_r_wait && (!out.rvalid || out.rresp != prev.rresp || out.rdata != prev.rdata))
      fail_msg("R dropped or changed while waiting for RREADY (cycle %lu)", cyc);
    if (out.bvalid && in.bready) {
      if (bi >= aw || bi >= w) fail_msg("B response before its AW and W (write %zu)", bi);
      if (bi >= nw) fail_msg("B response without a write");
      wr[bi].resp = out.bresp;
      bi++;
    }
    if (out.rvalid && in.rready) {
      if (ri >= ar || ri >= nr) fail_msg("R response before its AR (read %zu)", ri);
      rd[ri].data = out.rdata;
      rd[ri].resp = out.rresp;
      ri++;
    }
    if (out.bvalid && (out.bresp & 1u)) fail_msg("BRESP %u is not OKAY/SLVERR", out.bresp);
    if (out.rvalid && (out.rresp & 1u)) fail_msg("RRESP %u is not OKAY/SLVERR", out.rresp);
    prev_b_wait = out.bvalid && !in.bready;
    prev_r_wait = out.rvalid && !in.rready;
    b->st.b_early += in.bready && !out.bvalid;
    b->st.r_early += in.rready && !out.rvalid;
    b->st.b_stall += prev_b_wait;
    b->st.r_stall += prev_r_wait;

    /* Request handshakes at this edge. */
    if (aw_on) {
      if (out.awready) {
        if (w <= aw) b->st.aw_before_w++;
        aw_on = 0;
        aw++;
      } else {
        b->st.aw_wait++;
      }
    }
    if (w_on) {
      if (out.wready) {
        if (aw <= w) b->st.w_before_aw++;  /* aw already counts this edge */
        w_on = 0;
        w++;
      } else {
        b->st.w_wait++;
      }
    }
    if (ar_on) {
      if (out.arready) {
        ar_on = 0;
        ar++;
      } else {
        b->st.ar_wait++;
      }
    }
    prev = out;
    b->last = out;
  }
}

static unsigned axil_write(bus *b, uint32_t word_addr, uint32_t data) {
  axi_wr w = {BYTE(word_addr), data, 0xF, 99};
  axi_do(b, &w, 1, NULL, 0);
  return w.resp;
}

static unsigned axil_read(bus *b, uint32_t word_addr, uint32_t *data) {
  axi_rd r = {BYTE(word_addr), 0, 99};
  axi_do(b, NULL, 0, &r, 1);
  *data = r.data;
  return r.resp;
}

static uint32_t rd_ok(bus *b, uint32_t word_addr) {
  uint32_t v;
  unsigned resp = axil_read(b, word_addr, &v);
  if (resp != RESP_OKAY) fail_msg("read of 0x%03X answered %u", word_addr, resp);
  return v;
}

static void wr_ok(bus *b, uint32_t word_addr, uint32_t data) {
  unsigned resp = axil_write(b, word_addr, data);
  if (resp != RESP_OKAY) fail_msg("write of 0x%03X answered %u", word_addr, resp);
}

static void bus_open(bus *b, const build *bd, uint32_t seed, axi_policy pol) {
  memset(b, 0, sizeof *b);
  b->m = fp3_axil_model_new(bd->variant, getenv("FP3_AXIL_TRACE"));
  assert_non_null(b->m);
  b->rng = seed ? seed : 1;
  b->pol = pol;
}

static void bus_close(bus *b) { fp3_axil_model_free(b->m); }

/* ---- ID and configuration ---------------------------------------------------- */

static void test_id_info(void **state) {
  const build *bd = *state;
  bus b;
  bus_open(&b, bd, 1, RANDOM);
  assert_int_equal(rd_ok(&b, FP3_HR_ID), FP3_ID_VALUE);
  uint32_t info0 = rd_ok(&b, FP3_HR_INFO0), info1 = rd_ok(&b, FP3_HR_INFO1);
  uint32_t info2 = rd_ok(&b, FP3_HR_INFO2);
  assert_int_equal(info0 & 0xFFFF, FP3_DEFAULT_NUM_REGS);
  assert_int_equal(info0 >> 16, FP3_DEFAULT_IMEM_DEPTH);
  assert_int_equal(info1 & 0xFF, bd->add_latency);
  assert_int_equal((info1 >> 8) & 0xFF, bd->mul_latency);
  assert_int_equal((info1 >> 16) & 7, bd->fmax_pipe << 2); /* ROUND 0, FTZ 0, FMAX_PIPE */
  assert_int_equal(info1 >> 19, FP3_DEFAULT_DIV_LATENCY);   /* DIV_LATENCY */
  assert_int_equal(info2 & 0xFFFF, bd->num_contexts);
  /* HAS_ADD, HAS_SUB, HAS_MUL, HAS_DIV, HAS_SQRT, HAS_SIGN: every unit */
  assert_int_equal((info2 >> 16) & 0x3F, 0x3F);
  assert_int_equal(info2 >> 24, bd->num_lanes);   /* NUM_LANES */
  assert_int_equal(rd_ok(&b, FP3_HR_STATUS), 0);
  bus_close(&b);
}

/* ---- the ship program through the bus ----------------------------------------- */

typedef struct run_result {
  uint32_t regs[MAX_REGS];
  fp3_status st;
} run_result;

/* Load, initialise, run `steps` integrations and read everything back, all
 * through AXI4-Lite. */
static void axil_run(bus *b, const fp3_image *img, const uint32_t *init, uint32_t steps,
                     run_result *res) {
  static axi_wr w[2 * FP3_DEFAULT_IMEM_DEPTH + FP3_DEFAULT_NUM_REGS + 2];
  size_t n = 0;
  for (unsigned i = 0; i < FP3_DEFAULT_IMEM_DEPTH; i++) {
    uint64_t word = i < img->n ? img->words[i] : 0;
    w[n++] = (axi_wr){BYTE(FP3_HR_IMEM_BASE + 2 * i), (uint32_t)word, 0xF, 99};
    w[n++] = (axi_wr){BYTE(FP3_HR_IMEM_BASE + 2 * i + 1), (uint32_t)(word >> 32), 0xF, 99};
  }
  for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS; r++)
    w[n++] = (axi_wr){BYTE(FP3_HR_REG_BASE + r), init[r], 0xF, 99};
  w[n++] = (axi_wr){BYTE(FP3_HR_STEPS), steps, 0xF, 99};
  w[n++] = (axi_wr){BYTE(FP3_HR_CTRL), FP3_CTRL_START, 0xF, 99};
  axi_do(b, w, n, NULL, 0);
  for (size_t i = 0; i < n; i++) {
    if (w[i].resp != RESP_OKAY) fail_msg("write %zu (0x%X) answered %u", i, w[i].addr, w[i].resp);
  }
  /* Poll STATUS until the run is over; the side band must agree. */
  uint32_t status;
  unsigned long polls = 0;
  do {
    status = rd_ok(b, FP3_HR_STATUS);
    if (++polls > 100000ul + 100ul * steps) fail_msg("run does not end (STATUS 0x%X)", status);
  } while (status & FP3_STATUS_RUNNING);
  assert_true(b->last.done);
  assert_false(b->last.running);

  memset(res, 0, sizeof *res);
  res->st.done = (status & FP3_STATUS_DONE) != 0;
  res->st.error = (status >> FP3_STATUS_ERROR_LSB) & 0xF;
  axi_rd r[FP3_DEFAULT_NUM_REGS + 10];
  unsigned scal[] = {FP3_HR_FAULT_PC, FP3_HR_STEPS_DONE, FP3_HR_FLAGS, FP3_HR_CYCLES_LO,
                     FP3_HR_CYCLES_HI, FP3_HR_ISSUED_LO, FP3_HR_ISSUED_HI, FP3_HR_STALLS_LO,
                     FP3_HR_STALLS_HI, FP3_HR_STEPS};
  size_t nr = 0;
  for (unsigned i = 0; i < FP3_DEFAULT_NUM_REGS; i++)
    r[nr++] = (axi_rd){BYTE(FP3_HR_REG_BASE + i), 0, 99};
  for (size_t i = 0; i < sizeof scal / sizeof scal[0]; i++)
    r[nr++] = (axi_rd){BYTE(scal[i]), 0, 99};
  axi_do(b, NULL, 0, r, nr);
  for (size_t i = 0; i < nr; i++) {
    if (r[i].resp != RESP_OKAY) fail_msg("read %zu (0x%X) answered %u", i, r[i].addr, r[i].resp);
  }
  for (unsigned i = 0; i < FP3_DEFAULT_NUM_REGS; i++) res->regs[i] = r[i].data;
  const axi_rd *s = &r[FP3_DEFAULT_NUM_REGS];
  res->st.fault_pc = s[0].data;
  res->st.steps_done = s[1].data;
  res->st.flags = s[2].data;
  res->st.cycles = s[3].data | (uint64_t)s[4].data << 32;
  res->st.issued = s[5].data | (uint64_t)s[6].data << 32;
  res->st.stalls = s[7].data | (uint64_t)s[8].data << 32;
  assert_int_equal(s[9].data, steps); /* STEPS reads back */
  wr_ok(b, FP3_HR_CTRL, FP3_CTRL_CLEAR);
}

static void engine_run(fp3_engine *e, const fp3_image *img, const uint32_t *init, uint32_t steps,
                       run_result *res) {
  if (fp3_engine_load(e, img->words, img->n) != 0) fail_msg("%s", fp3_engine_error(e));
  for (unsigned r = 0; r < e->config.num_regs; r++)
    assert_int_equal(fp3_engine_write_reg(e, r, init[r]), 0);
  if (fp3_engine_run(e, steps, NULL, &res->st) != 0) fail_msg("%s", fp3_engine_error(e));
  for (unsigned r = 0; r < e->config.num_regs; r++)
    assert_int_equal(fp3_engine_read_reg(e, r, &res->regs[r]), 0);
}

/* programs/ship_rk4.s, bound by name to models/ship.fp3m (its golden
 * model: the literal rk4se); sp->c is freed by ship_free. */
typedef struct ship_prog {
  fp3_compiled *c;
  unsigned vreg, sreg; /* the registers of v and s */
} ship_prog;

static void load_ship(ship_prog *sp) {
  static fp3_model m;
  static int loaded;
  char msg[300];
  if (!loaded && fp3_model_load("models/ship.fp3m", &m, msg, sizeof msg)) fail_msg("%s", msg);
  loaded = 1;
  fp3_compile_opts o;
  fp3_compile_defaults(&o);
  if (fp3_compile_bind_file(&m, "programs/ship_rk4.s", &o, &sp->c, msg, sizeof msg))
    fail_msg("%s", msg);
  sp->vreg = fp3_compiled_state_reg(sp->c, 0);
  sp->sreg = fp3_compiled_state_reg(sp->c, 1);
}

static void ship_free(ship_prog *sp) { fp3_compiled_free(sp->c); }

/* The register bank the host writes for ship p (init[MAX_REGS], zeroed
 * first), and the golden model started on it. */
static void ship_init(ship_prog *sp, const fp3_ship_params *p, uint32_t *init) {
  const float in[4] = {p->h, p->T, p->C, p->m}, y0[2] = {p->v0, p->s0};
  unsigned reg[16];
  uint32_t val[16];
  memset(init, 0, MAX_REGS * sizeof *init);
  const size_t nw = fp3_compiled_model_start(sp->c, in, y0, reg, val, 16);
  for (size_t w = 0; w < nw; w++) init[reg[w]] = val[w];
}

/* v and s (bits) after `steps` golden integrations of ship p. */
static void ship_golden(ship_prog *sp, const fp3_ship_params *p, uint32_t steps, uint32_t *v,
                        uint32_t *s) {
  uint32_t init[MAX_REGS];
  float y[2 * FP3_MODEL_MAX_VARS];
  ship_init(sp, p, init);
  for (uint32_t i = 0; i < steps; i++) fp3_compiled_model_step(sp->c, y);
  *v = fpref_bits(y[0]);
  *s = fpref_bits(y[1]);
}

static void check_ship(const build *bd, const fp3_ship_params *p, uint32_t steps, axi_policy pol,
                       uint32_t seed) {
  ship_prog sp;
  load_ship(&sp);
  const fp3_image img = *fp3_compiled_image(sp.c);
  uint32_t init[MAX_REGS];
  ship_init(&sp, p, init);

  bus b;
  bus_open(&b, bd, seed, pol);
  run_result ax, is, hp;
  axil_run(&b, &img, init, steps, &ax);
  bus_close(&b);

  fp3_engine *iss = fp3_engine_iss_new(), *rtl = fp3_engine_rtl_new_model(bd->core, NULL);
  assert_non_null(iss);
  assert_non_null(rtl);
  engine_run(iss, &img, init, steps, &is);
  engine_run(rtl, &img, init, steps, &hp);
  fp3_engine_free(iss);
  fp3_engine_free(rtl);

  assert_true(ax.st.done);
  assert_int_equal(ax.st.error, FP3_ERR_NONE);
  assert_int_equal(ax.st.steps_done, steps);
  /* Architectural state: the ISS. */
  assert_int_equal(ax.st.steps_done, is.st.steps_done);
  assert_int_equal(ax.st.flags, is.st.flags);
  assert_int_equal(ax.st.issued, is.st.issued);
  for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS; r++) {
    if (ax.regs[r] != is.regs[r])
      fail_msg("r%u: AXI 0x%08X, ISS 0x%08X", r, ax.regs[r], is.regs[r]);
  }
  /* Timing: the same core behind the plain host port. */
  assert_int_equal(ax.st.cycles, hp.st.cycles);
  assert_int_equal(ax.st.stalls, hp.st.stalls);
  /* v and s: the golden model. */
  uint32_t gv, gs;
  ship_golden(&sp, p, steps, &gv, &gs);
  uint32_t v = ax.regs[sp.vreg], s = ax.regs[sp.sreg];
  if (v != gv || s != gs)
    fail_msg("after %u integrations: AXI v=0x%08X s=0x%08X, golden v=0x%08X s=0x%08X", steps, v, s,
             gv, gs);
  ship_free(&sp);
}

static void test_ship_back_to_back(void **state) {
  fp3_ship_params p;
  fp3_ship_default(&p);
  check_ship(*state, &p, 300, FAST, 1);
}

static void test_ship_random_handshakes(void **state) {
  fp3_ship_params p = {-30.0f, 12.0f, 0.75f, 0.02f, 4.0f, 0.0f}; /* dinghy reversing */
  check_ship(*state, &p, 200, RANDOM, 7);
  fp3_ship_params q = {2.0e6f, 1.0e5f, 3.0e8f, 0.5f, 3.0f, 1000.0f}; /* tanker */
  check_ship(*state, &q, 50, (axi_policy){30, 20, ORDER_W_FIRST}, 11);
}

/* Cycles per integration through the bus: the paper's figure of merit.
 * Default build only: the bound is the default pipeline's; check_ship
 * compares every build's cycle counts exactly with its fp3_top. */
static void test_ship_cycles(void **state) {
  (void)state;
  ship_prog sp;
  load_ship(&sp);
  const fp3_image img = *fp3_compiled_image(sp.c);
  uint32_t init[MAX_REGS];
  fp3_ship_params p;
  fp3_ship_default(&p);
  ship_init(&sp, &p, init);
  ship_free(&sp);
  bus b;
  bus_open(&b, &build_default, 3, FAST);
  run_result r1, r2, r10;
  axil_run(&b, &img, init, 1, &r1);
  axil_run(&b, &img, init, 2, &r2);
  axil_run(&b, &img, init, 10, &r10);
  bus_close(&b);
  uint64_t per = r2.st.cycles - r1.st.cycles;
  assert_int_equal(r10.st.cycles - r2.st.cycles, 8 * per);
  print_message("ship_rk4 via AXI4-Lite: 1 integration %llu cycles START..DONE, then %llu per "
                "integration\n", (unsigned long long)r1.st.cycles, (unsigned long long)per);
  assert_true(per > 0 && per <= 130);
}

/* ---- back to back ------------------------------------------------------------- */

static void test_back_to_back(void **state) {
  const build *bd = *state;
  bus b;
  bus_open(&b, bd, 5, FAST);
  enum { N = 32 };
  axi_wr w[N];
  axi_rd r[N];
  for (unsigned i = 0; i < N; i++)
    w[i] = (axi_wr){BYTE(FP3_HR_REG_BASE + i), 0xA5000000u + i * 0x01010101u, 0xF, 99};
  axi_do(&b, w, N, NULL, 0);
  unsigned long wcycles = b.st.cycles;
  /* AW and W together in cycle 0, the host port in cycle 1, B in cycle 2,
   * when the next AW and W are taken: one write every second cycle, the
   * last B in cycle 2N. */
  assert_int_equal(wcycles, 2 * N + 1);
  for (unsigned i = 0; i < N; i++) {
    assert_int_equal(w[i].resp, RESP_OKAY);
    r[i] = (axi_rd){BYTE(FP3_HR_REG_BASE + (N - 1 - i)), 0, 99};
  }
  axi_do(&b, NULL, 0, r, N);
  unsigned long rcycles = b.st.cycles - wcycles;
  /* AR in cycle 0, the address on the host port in cycle 1, R valid L
   * cycles later (L = read_latency) and taken at once; the next address
   * goes out when no read is pending, in the cycle R is taken: a read every
   * L + 1 cycles, the last R in cycle N (L + 1) + 1. */
  const unsigned lat = read_latency(bd);
  assert_int_equal(rcycles, N * (lat + 1) + 2);
  for (unsigned i = 0; i < N; i++) {
    assert_int_equal(r[i].resp, RESP_OKAY);
    assert_int_equal(r[i].data, 0xA5000000u + (N - 1 - i) * 0x01010101u);
  }
  /* Writes and reads at once, on different registers: both complete. */
  for (unsigned i = 0; i < N; i++) {
    w[i] = (axi_wr){BYTE(FP3_HR_REG_BASE + (i % 16)), 0x5A000000u + i, 0xF, 99};
    r[i] = (axi_rd){BYTE(i % 2 ? FP3_HR_ID : FP3_HR_REG_BASE + 16 + (i % 16)), 0, 99};
  }
  axi_do(&b, w, N, r, N);
  for (unsigned i = 0; i < N; i++) {
    assert_int_equal(w[i].resp, RESP_OKAY);
    assert_int_equal(r[i].resp, RESP_OKAY);
    uint32_t want = i % 2 ? FP3_ID_VALUE : 0xA5000000u + (16 + i % 16) * 0x01010101u;
    assert_int_equal(r[i].data, want);
  }
  for (unsigned i = 0; i < 16; i++) assert_int_equal(rd_ok(&b, FP3_HR_REG_BASE + i), 0x5A000010u + i);
  print_message("back to back: %d writes in %lu cycles, %d reads in %lu cycles (read latency %u)\n",
                N, wcycles, N, rcycles, lat);
  bus_close(&b);
}

/* ---- random delays on every channel --------------------------------------------- */

static void test_random_stalls(void **state) {
  static const axi_policy pols[] = {
      {50, 50, ORDER_ANY}, {20, 80, ORDER_ANY}, {90, 10, ORDER_ANY},
      {100, 30, ORDER_ANY}, {40, 100, ORDER_W_FIRST}, {40, 60, ORDER_AW_FIRST},
  };
  axi_stats tot = {0};
  for (uint32_t seed = 1; seed <= 24; seed++) {
    bus b;
    bus_open(&b, *state, seed * 2654435761u, pols[seed % (sizeof pols / sizeof pols[0])]);
    uint32_t model[32];
    for (unsigned i = 0; i < 32; i++) {
      model[i] = rnd(&b);
      wr_ok(&b, FP3_HR_REG_BASE + i, model[i]);
    }
    /* Writes go to r0..r15, reads to r16..r31 and the ID: no order
     * between the two queues is needed to know every answer. */
    enum { N = 64 };
    axi_wr w[N];
    axi_rd r[N];
    unsigned ridx[N];
    for (unsigned i = 0; i < N; i++) {
      unsigned reg = rnd(&b) % 16;
      w[i] = (axi_wr){BYTE(FP3_HR_REG_BASE + reg), rnd(&b), 0xF, 99};
      ridx[i] = 16 + rnd(&b) % 17; /* 32: the ID register */
      r[i] = (axi_rd){BYTE(ridx[i] == 32 ? FP3_HR_ID : FP3_HR_REG_BASE + ridx[i]), 0, 99};
    }
    axi_do(&b, w, N, r, N);
    for (unsigned i = 0; i < N; i++) {
      assert_int_equal(w[i].resp, RESP_OKAY);
      assert_int_equal(r[i].resp, RESP_OKAY);
      model[w[i].addr / 4 - FP3_HR_REG_BASE] = w[i].data;
      uint32_t want = ridx[i] == 32 ? FP3_ID_VALUE : model[ridx[i]];
      if (r[i].data != want) fail_msg("seed %u read %u: 0x%08X, want 0x%08X", seed, i, r[i].data, want);
    }
    for (unsigned i = 0; i < 32; i++) assert_int_equal(rd_ok(&b, FP3_HR_REG_BASE + i), model[i]);
    tot.aw_wait += b.st.aw_wait;
    tot.w_wait += b.st.w_wait;
    tot.ar_wait += b.st.ar_wait;
    tot.b_early += b.st.b_early;
    tot.r_early += b.st.r_early;
    tot.b_stall += b.st.b_stall;
    tot.r_stall += b.st.r_stall;
    tot.w_before_aw += b.st.w_before_aw;
    tot.aw_before_w += b.st.aw_before_w;
    bus_close(&b);
  }
  print_message("coverage: valid before ready AW %lu W %lu AR %lu; ready before valid B %lu R %lu;"
                " B/R held %lu/%lu; W first %lu, AW first %lu\n",
                tot.aw_wait, tot.w_wait, tot.ar_wait, tot.b_early, tot.r_early, tot.b_stall,
                tot.r_stall, tot.w_before_aw, tot.aw_before_w);
  assert_true(tot.aw_wait > 0 && tot.w_wait > 0 && tot.ar_wait > 0);
  assert_true(tot.b_early > 0 && tot.r_early > 0 && tot.b_stall > 0 && tot.r_stall > 0);
  assert_true(tot.w_before_aw > 0 && tot.aw_before_w > 0);
}

/* A write whose W comes many cycles before its AW, and the reverse. */
static void test_split_write(void **state) {
  bus b;
  bus_open(&b, *state, 9, FAST);
  for (int first = 0; first < 2; first++) {
    uint32_t data = 0x12345678u + (uint32_t)first;
    fp3_axil_in in = {0};
    fp3_axil_out out;
    if (first == 0) { in.wvalid = 1; in.wdata = data; in.wstrb = 0xF; }
    else { in.awvalid = 1; in.awaddr = BYTE(FP3_HR_REG_BASE + 7); }
    fp3_axil_model_cycle(b.m, &in, &out);
    assert_true(first == 0 ? out.wready : out.awready);
    memset(&in, 0, sizeof in);
    in.bready = 1;
    for (int i = 0; i < 6; i++) {
      fp3_axil_model_cycle(b.m, &in, &out);
      assert_false(out.bvalid); /* half a write: no response */
      assert_false(first == 0 ? out.wready : out.awready); /* one held */
    }
    if (first == 0) { in.awvalid = 1; in.awaddr = BYTE(FP3_HR_REG_BASE + 7); }
    else { in.wvalid = 1; in.wdata = data; in.wstrb = 0xF; }
    fp3_axil_model_cycle(b.m, &in, &out);
    assert_true(first == 0 ? out.awready : out.wready);
    memset(&in, 0, sizeof in);
    int got = 0;
    for (int i = 0; i < 8 && !got; i++) {
      in.bready = i >= 4; /* B waits 4 cycles for BREADY */
      fp3_axil_model_cycle(b.m, &in, &out);
      if (out.bvalid && in.bready) {
        assert_int_equal(out.bresp, RESP_OKAY);
        got = 1;
      }
    }
    assert_true(got);
    assert_int_equal(rd_ok(&b, FP3_HR_REG_BASE + 7), data);
  }
  bus_close(&b);
}

/* ---- the register map, from the one table ---------------------------------------- */

typedef struct hostreg {
  const char *name;
  unsigned addr;
  const char *acc; /* "R", "W" or "RW" */
} hostreg;

static const hostreg hostregs[] = {
#define X(name, addr, acc, desc) {#name, addr, acc},
    FP3_HOSTREGS(X)
#undef X
};

static const hostreg *hostreg_at(unsigned addr) {
  for (size_t i = 0; i < sizeof hostregs / sizeof hostregs[0]; i++)
    if (hostregs[i].addr == addr) return &hostregs[i];
  return NULL;
}

/* The answer the wrapper owes to an access of word address `a` while the
 * machine is stopped (writes of 0): from the access column of
 * FP3_HOSTREGS for the scalar registers, from the windows' sizes for the
 * register and program windows (the core decodes a 256-word register
 * window and the whole upper half as the program window). */
static unsigned expected(unsigned a, int write, unsigned num_regs, unsigned imem_depth) {
  const char *acc;
  int inside;
  if (a < FP3_HR_REG_BASE) {
    const hostreg *h = hostreg_at(a);
    acc = h ? h->acc : "";
    inside = h != NULL;
  } else if (a < FP3_HR_REG_BASE + 0x100) {
    acc = hostreg_at(FP3_HR_REG_BASE)->acc;
    inside = a - FP3_HR_REG_BASE < num_regs;
  } else if (a >= FP3_HR_IMEM_BASE) {
    acc = hostreg_at(FP3_HR_IMEM_BASE)->acc;
    inside = (a - FP3_HR_IMEM_BASE) / 2 < imem_depth;
  } else {
    acc = "";
    inside = 0;
  }
  return inside && strchr(acc, write ? 'W' : 'R') ? RESP_OKAY : RESP_SLVERR;
}

/* Every word address, read and written: OKAY exactly where the table
 * says the access exists. */
static void test_register_map(void **state) {
  bus b;
  bus_open(&b, *state, 17, FAST);
  unsigned num_regs = rd_ok(&b, FP3_HR_INFO0) & 0xFFFF, imem_depth = rd_ok(&b, FP3_HR_INFO0) >> 16;
  enum { NA = 0x1000 };
  static axi_rd r[NA];
  static axi_wr w[NA];
  for (unsigned a = 0; a < NA; a++) r[a] = (axi_rd){BYTE(a), 0xFFFFFFFFu, 99};
  axi_do(&b, NULL, 0, r, NA);
  unsigned okay_r = 0, okay_w = 0;
  for (unsigned a = 0; a < NA; a++) {
    unsigned want = expected(a, 0, num_regs, imem_depth);
    if (r[a].resp != want) fail_msg("read of 0x%03X answered %u, want %u", a, r[a].resp, want);
    if (want == RESP_SLVERR && r[a].data != 0) fail_msg("SLVERR read of 0x%03X gave data", a);
    okay_r += want == RESP_OKAY;
  }
  /* The writes twice: back to back, then with AW first and W and BREADY
   * late, so that the next write's AW waits on the bus while the wrapper
   * holds an address (whose answer must stay its own). */
  static const axi_policy late_w = {60, 40, ORDER_AW_FIRST};
  for (int pass = 0; pass < 2; pass++) {
    b.pol = pass ? late_w : FAST;
    for (unsigned a = 0; a < NA; a++) w[a] = (axi_wr){BYTE(a), 0, 0xF, 99};
    axi_do(&b, w, NA, NULL, 0);
    okay_w = 0;
    for (unsigned a = 0; a < NA; a++) {
      unsigned want = expected(a, 1, num_regs, imem_depth);
      if (w[a].resp != want)
        fail_msg("write of 0x%03X answered %u, want %u (pass %d)", a, w[a].resp, want, pass);
      okay_w += want == RESP_OKAY;
    }
  }
  print_message("register map: AW waiting behind a held address in %lu cycles\n", b.st.aw_wait);
  print_message("register map: %u readable, %u writable word addresses of %d\n", okay_r, okay_w, NA);
  assert_int_equal(rd_ok(&b, FP3_HR_STATUS) & FP3_STATUS_RUNNING, 0);
  bus_close(&b);
}

/* ---- error responses -------------------------------------------------------------- */

static void test_slverr(void **state) {
  bus b;
  bus_open(&b, *state, 13, RANDOM);
  unsigned num_ctx = rd_ok(&b, FP3_HR_INFO2) & 0xFFFF;
  wr_ok(&b, FP3_HR_REG_BASE + 3, 0x11111111u);
  /* A partial write is refused whole. */
  axi_wr pw = {BYTE(FP3_HR_REG_BASE + 3), 0x22222222u, 0x3, 99};
  axi_do(&b, &pw, 1, NULL, 0);
  assert_int_equal(pw.resp, RESP_SLVERR);
  assert_int_equal(rd_ok(&b, FP3_HR_REG_BASE + 3), 0x11111111u);
  /* A context the build does not have: refused, CTX unchanged. */
  assert_int_equal(axil_write(&b, FP3_HR_CTX, num_ctx), RESP_SLVERR);
  assert_int_equal(rd_ok(&b, FP3_HR_CTX), 0);
  /* ... nor a lane: refused, LANE unchanged; the last lane taken. */
  unsigned num_lanes = rd_ok(&b, FP3_HR_INFO2) >> 24;
  assert_true(num_lanes >= 1);
  assert_int_equal(axil_write(&b, FP3_HR_LANE, num_lanes), RESP_SLVERR);
  assert_int_equal(axil_write(&b, FP3_HR_LANE, 0xFFFFFFFFu), RESP_SLVERR);
  assert_int_equal(rd_ok(&b, FP3_HR_LANE), 0);
  assert_int_equal(axil_write(&b, FP3_HR_LANE, num_lanes - 1), RESP_OKAY);
  assert_int_equal(rd_ok(&b, FP3_HR_LANE), num_lanes - 1);
  assert_int_equal(axil_write(&b, FP3_HR_LANE, 0), RESP_OKAY);
  /* Byte addresses: the word address times 4; byte offsets ignored. */
  axi_rd rr = {BYTE(FP3_HR_ID) + 2, 0, 99};
  axi_do(&b, NULL, 0, &rr, 1);
  assert_int_equal(rr.data, FP3_ID_VALUE);

  /* While running: STEPS, CONTEXTS, CTX, LANE, registers and program are
   * refused, CTRL is not. */
  char *errors = NULL;
  fp3_image img;
  fp3_image_init(&img);
  assert_int_equal(fp3_asm_string("body:\n add r2, r2, r3\n endi body\n", "t.s", &img, &errors), 0);
  for (unsigned i = 0; i < img.n; i++) {
    wr_ok(&b, FP3_HR_IMEM_BASE + 2 * i, (uint32_t)img.words[i]);
    wr_ok(&b, FP3_HR_IMEM_BASE + 2 * i + 1, (uint32_t)(img.words[i] >> 32));
  }
  wr_ok(&b, FP3_HR_STEPS, 2000);
  wr_ok(&b, FP3_HR_CTRL, FP3_CTRL_START);
  assert_true(rd_ok(&b, FP3_HR_STATUS) & FP3_STATUS_RUNNING);
  assert_true(b.last.running);
  assert_int_equal(axil_write(&b, FP3_HR_REG_BASE + 3, 0x33333333u), RESP_SLVERR);
  assert_int_equal(axil_write(&b, FP3_HR_STEPS, 5), RESP_SLVERR);
  assert_int_equal(axil_write(&b, FP3_HR_CONTEXTS, 2), RESP_SLVERR);
  assert_int_equal(axil_write(&b, FP3_HR_CTX, 0), RESP_SLVERR);
  assert_int_equal(axil_write(&b, FP3_HR_LANE, 0), RESP_SLVERR);
  assert_int_equal(axil_write(&b, FP3_HR_IMEM_BASE, 0), RESP_SLVERR);
  assert_int_equal(axil_write(&b, FP3_HR_IMEM_BASE + 1, 0), RESP_SLVERR);
  assert_int_equal(axil_write(&b, FP3_HR_CTRL, FP3_CTRL_START), RESP_OKAY);
  assert_true(rd_ok(&b, FP3_HR_STATUS) & FP3_STATUS_RUNNING);
  assert_int_equal(rd_ok(&b, FP3_HR_STEPS), 2000);
  assert_int_equal(rd_ok(&b, FP3_HR_CONTEXTS), 1);
  unsigned long polls = 0;
  while (rd_ok(&b, FP3_HR_STATUS) & FP3_STATUS_RUNNING) assert_true(++polls < 100000);
  assert_int_equal(rd_ok(&b, FP3_HR_STEPS_DONE), 2000);
  assert_int_equal(rd_ok(&b, FP3_HR_REG_BASE + 3), 0x11111111u); /* untouched */
  /* The program survived: a second run does the same. */
  wr_ok(&b, FP3_HR_CTRL, FP3_CTRL_CLEAR);
  wr_ok(&b, FP3_HR_STEPS, 3);
  wr_ok(&b, FP3_HR_CTRL, FP3_CTRL_START);
  while (rd_ok(&b, FP3_HR_STATUS) & FP3_STATUS_RUNNING) assert_true(++polls < 200000);
  assert_int_equal(rd_ok(&b, FP3_HR_STEPS_DONE), 3);
  assert_int_equal(rd_ok(&b, FP3_HR_ISSUED_LO), 6);
  bus_close(&b);
}

/* ---- the words of context CTX, read right after CTX is written -------------------- */

/* Every context runs one program; its data send the even contexts to an
 * illegal word (ILLEGAL_INSN at FAULT_PC 3, no integration done) and the
 * odd ones through STEPS integrations, of which those with c % 4 == 1 add
 * a value that does not fit (the inexact flag).  Then, back to back, CTX
 * is written and one of STATUS, STEPS_DONE, FAULT_PC, FLAGS read at once,
 * for contexts taken in turn: a read that sees another context's word
 * differs. */
static void test_context_words(void **state) {
  const build *bd = *state;
  bus b;
  bus_open(&b, bd, 31, FAST);
  const unsigned nctx = bd->num_contexts;
  char *errors = NULL;
  fp3_image img;
  fp3_image_init(&img);
  assert_int_equal(fp3_asm_string("body:\n beq r0, r1, bad\n add r2, r2, r3\n endi body\n"
                                  "bad:\n halt\n", "t.s", &img, &errors), 0);
  img.words[3] = 0xFFull << FP3_OPC_LSB; /* `bad`: an opcode the ISA does not have */
  for (unsigned i = 0; i < img.n; i++) {
    wr_ok(&b, FP3_HR_IMEM_BASE + 2 * i, (uint32_t)img.words[i]);
    wr_ok(&b, FP3_HR_IMEM_BASE + 2 * i + 1, (uint32_t)(img.words[i] >> 32));
  }
  const uint32_t steps = 5;
  for (unsigned c = 0; c < nctx; c++) {
    wr_ok(&b, FP3_HR_CTX, c);
    wr_ok(&b, FP3_HR_REG_BASE + 0, c);
    wr_ok(&b, FP3_HR_REG_BASE + 1, c % 2 ? c + 1 : c);
    wr_ok(&b, FP3_HR_REG_BASE + 2, fpref_bits(1.0f));
    wr_ok(&b, FP3_HR_REG_BASE + 3, fpref_bits(c % 4 == 1 ? 1.0e-8f : 0.5f));
  }
  wr_ok(&b, FP3_HR_CONTEXTS, nctx);
  wr_ok(&b, FP3_HR_STEPS, steps);
  wr_ok(&b, FP3_HR_CTRL, FP3_CTRL_START);
  unsigned long polls = 0;
  while (rd_ok(&b, FP3_HR_STATUS) & FP3_STATUS_RUNNING) assert_true(++polls < 100000);
  static const uint32_t words[] = {FP3_HR_STATUS, FP3_HR_STEPS_DONE, FP3_HR_FAULT_PC,
                                   FP3_HR_FLAGS};
  unsigned reads = 0;
  for (unsigned w = 0; w < 4; w++) {
    for (unsigned k = 0; k < 2 * nctx; k++) {
      unsigned c = (k * 3 + w) % nctx; /* each context, after a different one */
      wr_ok(&b, FP3_HR_CTX, c);
      uint32_t got = rd_ok(&b, words[w]);
      int bad = c % 2 == 0;
      uint32_t want = 0;
      switch (words[w]) {
      case FP3_HR_STATUS:
        want = FP3_STATUS_DONE | FP3_STATUS_ANY_ERROR |
               (bad ? (uint32_t)FP3_ERR_ILLEGAL_INSN << FP3_STATUS_ERROR_LSB : 0);
        break;
      case FP3_HR_STEPS_DONE: want = bad ? 0 : steps; break;
      case FP3_HR_FAULT_PC:   want = bad ? 3 : 0; break;
      default:                want = c % 4 == 1 ? FP3_FLAG_INEXACT : 0; break;
      }
      if (got != want)
        fail_msg("word 0x%03X of context %u: 0x%08X, want 0x%08X", words[w], c, got, want);
      reads++;
    }
  }
  print_message("%u reads of a context's word right after CTX was written, all right\n", reads);
  bus_close(&b);
}

/* ---- many objects: every context runs the ship, each its own scene ------------------ */

static void test_ship_contexts(void **state) {
  static const fp3_ship_params scenes[] = {
      {50000.0f, 5000.0f, 10000.0f, 1.0f / 60.0f, 0.0f, 0.0f},
      {2000.0f, 0.0f, 1000.0f, 0.01f, 1.0f, -5.0f},
      {2.0e6f, 1.0e5f, 3.0e8f, 0.5f, 3.0f, 1000.0f},
      {-30.0f, 12.0f, 0.75f, 0.02f, 4.0f, 0.0f},
      {0.0f, 300.0f, 5000.0f, 0.1f, 12.5f, 100.0f},
      {1000.0f, 100.0f, 100.0f, 2.5f, 0.0f, 0.0f},
  };
  const unsigned nscenes = sizeof scenes / sizeof scenes[0];
  ship_prog sp;
  load_ship(&sp);
  const fp3_image img = *fp3_compiled_image(sp.c);
  bus b;
  bus_open(&b, *state, 21, RANDOM);
  unsigned nctx = rd_ok(&b, FP3_HR_INFO2) & 0xFFFF, nl = rd_ok(&b, FP3_HR_INFO2) >> 24;
  assert_true(nctx >= 1 && nl >= 1);
  /* 1 context 40 integrations, all contexts 40, all contexts 80; every
   * lane of a context runs, lane l with the scene of slot c + l x nctx
   * and its v0 raised by l (every object different). */
  uint64_t cycles[3] = {0, 0, 0};
  for (int pass = 0; pass < 3; pass++) {
    unsigned run_ctx = pass == 0 ? 1 : nctx;
    const uint32_t steps = pass == 2 ? 80 : 40;
    for (unsigned i = 0; i < img.n; i++) {
      wr_ok(&b, FP3_HR_IMEM_BASE + 2 * i, (uint32_t)img.words[i]);
      wr_ok(&b, FP3_HR_IMEM_BASE + 2 * i + 1, (uint32_t)(img.words[i] >> 32));
    }
    for (unsigned k = 0; k < run_ctx * nl; k++) {
      const unsigned c = k % run_ctx, l = k / run_ctx;
      fp3_ship_params p = scenes[(c + l * nctx) % nscenes];
      p.v0 += (float)l;
      uint32_t init[MAX_REGS];
      ship_init(&sp, &p, init);
      wr_ok(&b, FP3_HR_CTX, c);
      wr_ok(&b, FP3_HR_LANE, l);
      for (unsigned r = 0; r < FP3_DEFAULT_NUM_REGS; r++) wr_ok(&b, FP3_HR_REG_BASE + r, init[r]);
    }
    wr_ok(&b, FP3_HR_CONTEXTS, run_ctx);
    wr_ok(&b, FP3_HR_STEPS, steps);
    wr_ok(&b, FP3_HR_CTRL, FP3_CTRL_START);
    unsigned long polls = 0;
    while (rd_ok(&b, FP3_HR_STATUS) & FP3_STATUS_RUNNING) assert_true(++polls < 1000000);
    assert_int_equal(rd_ok(&b, FP3_HR_STATUS) & 0xF07u, FP3_STATUS_DONE);
    cycles[pass] = rd_ok(&b, FP3_HR_CYCLES_LO) | (uint64_t)rd_ok(&b, FP3_HR_CYCLES_HI) << 32;
    for (unsigned k = 0; k < run_ctx * nl; k++) {
      const unsigned c = k % run_ctx, l = k / run_ctx;
      fp3_ship_params p = scenes[(c + l * nctx) % nscenes];
      p.v0 += (float)l;
      uint32_t gv, gs;
      ship_golden(&sp, &p, steps, &gv, &gs);
      wr_ok(&b, FP3_HR_CTX, c);
      wr_ok(&b, FP3_HR_LANE, l);
      assert_int_equal(rd_ok(&b, FP3_HR_STEPS_DONE), steps);
      uint32_t v = rd_ok(&b, FP3_HR_REG_BASE + sp.vreg);
      uint32_t s = rd_ok(&b, FP3_HR_REG_BASE + sp.sreg);
      if (v != gv || s != gs)
        fail_msg("context %u lane %u: AXI v=0x%08X s=0x%08X, golden v=0x%08X s=0x%08X", c, l,
                 v, s, gv, gs);
    }
    wr_ok(&b, FP3_HR_CTRL, FP3_CTRL_CLEAR);
    wr_ok(&b, FP3_HR_CTX, 0);
    wr_ok(&b, FP3_HR_LANE, 0);
  }
  /* Every object-step costs the same once the schedule is periodic. */
  double per_step = (double)(cycles[2] - cycles[1]) / (40.0 * nctx * nl);
  print_message("ship_rk4 via AXI4-Lite, 40 integrations: 1 context %llu cycles, %u contexts "
                "%llu cycles; steady state %.2f cycles per object-step\n",
                (unsigned long long)cycles[0], nctx, (unsigned long long)cycles[1], per_step);
  assert_true(cycles[1] < cycles[0] * nctx); /* contexts overlap */
  wr_ok(&b, FP3_HR_CONTEXTS, 1);
  bus_close(&b);
  ship_free(&sp);
}

/* A test on each build: state is the build, cmocka prints "test (build)". */
#define ON_BOTH(f) {#f " (default)", f, NULL, NULL, &build_default}, \
                   {#f " (fmax)", f, NULL, NULL, &build_fmax}
/* ... and on the lanes build too */
#define ON_ALL(f) ON_BOTH(f), {#f " (lanes)", f, NULL, NULL, &build_lanes}

int main(void) {
  const struct CMUnitTest tests[] = {
      ON_ALL(test_id_info),
      ON_BOTH(test_back_to_back),
      ON_BOTH(test_split_write),
      ON_BOTH(test_random_stalls),
      ON_ALL(test_register_map),
      ON_ALL(test_slverr),
      ON_BOTH(test_context_words),
      ON_ALL(test_ship_contexts),
      ON_BOTH(test_ship_back_to_back),
      ON_BOTH(test_ship_random_handshakes),
      cmocka_unit_test(test_ship_cycles),
  };
  return cmocka_run_group_tests(tests, NULL, NULL);
}
