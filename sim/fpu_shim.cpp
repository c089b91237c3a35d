// fpu_shim.cpp -- extern "C" shim over the Verilated fpu_top (sim/fpu_model.h).
//
// Compiled once per built configuration with
//   -DFPU_NAME=rne -DFPU_PREFIX=Vfpu_rne -DFPU_ROUND=0 -DFPU_FTZ=0
//   -DFPU_ADD_LATENCY=4 -DFPU_MUL_LATENCY=3 -DFPU_DIV_LATENCY=8
// giving fpu_model_new_<name>() and fpu_model_info_<name>, and once with
//   -DFPU_SHIM_COMMON -DFPU_MODELS="X(rne) X(rtz) ..."
// giving the C functions of fpu_model.h, which dispatch through the virtual
// methods of struct fpu_model.  The only C++ of the FP-core unit.
#include "fpu_model.h"

#include <cstdint>
#include <cstring>

struct fpu_model {
  fpu_model_info info;
  uint64_t cycles = 0;
  virtual ~fpu_model() {}
  virtual void set_add(int valid, int sub, uint32_t a, uint32_t b) = 0;
  virtual void set_mul(int valid, uint32_t a, uint32_t b) = 0;
  virtual void set_div(int valid, uint32_t a, uint32_t b) = 0;
  virtual void set_sqrt(int valid, uint32_t a) = 0;
  virtual void set_sign(int valid, unsigned op, uint32_t a, uint32_t b) = 0;
  virtual void set_rst(int rst) = 0;
  virtual void clock() = 0;
  virtual int add_out(uint32_t *y, unsigned *flags) const = 0;
  virtual int mul_out(uint32_t *y, unsigned *flags) const = 0;
  virtual int div_out(uint32_t *y, unsigned *flags) const = 0;
  virtual int sqrt_out(uint32_t *y, unsigned *flags) const = 0;
  virtual int sign_out(uint32_t *y, unsigned *flags) const = 0;
  virtual int run(fpu_op op, size_t n, const uint32_t *a, const uint32_t *b,
                  uint32_t *y, uint8_t *flags) = 0;
};

#define FPU_CAT2(a, b) a##b
#define FPU_CAT(a, b) FPU_CAT2(a, b)
#define FPU_STR2(x) #x
#define FPU_STR(x) FPU_STR2(x)

#ifndef FPU_SHIM_COMMON
// ---- one configuration -----------------------------------------------------
#include "verilated.h"
#include FPU_STR(FPU_PREFIX.h)

namespace {

struct Impl final : fpu_model {
  VerilatedContext ctx;
  FPU_PREFIX *top;

  Impl() {
    info.name = FPU_STR(FPU_NAME);
    info.round = FPU_ROUND;
    info.ftz = FPU_FTZ;
    info.add_latency = FPU_ADD_LATENCY;
    info.mul_latency = FPU_MUL_LATENCY;
    info.div_latency = FPU_DIV_LATENCY;
    top = new FPU_PREFIX(&ctx, "fpu");
    top->clk_i = 0;
    top->rst_i = 0;
    top->add_valid_i = 0;
    top->add_sub_i = 0;
    top->add_a_i = 0;
    top->add_b_i = 0;
    top->mul_valid_i = 0;
    top->mul_a_i = 0;
    top->mul_b_i = 0;
    top->div_valid_i = 0;
    top->div_a_i = 0;
    top->div_b_i = 0;
    top->sqrt_valid_i = 0;
    top->sqrt_a_i = 0;
    top->sign_valid_i = 0;
    top->sign_op_i = 0;
    top->sign_a_i = 0;
    top->sign_b_i = 0;
    top->eval();
  }
  ~Impl() override {
    top->final();
    delete top;
  }
  void set_add(int valid, int sub, uint32_t a, uint32_t b) override {
    top->add_valid_i = valid ? 1 : 0;
    top->add_sub_i = sub ? 1 : 0;
    top->add_a_i = a;
    top->add_b_i = b;
  }
  void set_mul(int valid, uint32_t a, uint32_t b) override {
    top->mul_valid_i = valid ? 1 : 0;
    top->mul_a_i = a;
    top->mul_b_i = b;
  }
  void set_div(int valid, uint32_t a, uint32_t b) override {
    top->div_valid_i = valid ? 1 : 0;
    top->div_a_i = a;
    top->div_b_i = b;
  }
  void set_sqrt(int valid, uint32_t a) override {
    top->sqrt_valid_i = valid ? 1 : 0;
    top->sqrt_a_i = a;
  }
  void set_sign(int valid, unsigned op, uint32_t a, uint32_t b) override {
    top->sign_valid_i = valid ? 1 : 0;
    top->sign_op_i = op & 3u;
    top->sign_a_i = a;
    top->sign_b_i = b;
  }
  void set_rst(int rst) override { top->rst_i = rst ? 1 : 0; }
  void clock() override {
    top->clk_i = 1;
    top->eval();
    top->clk_i = 0;
    top->eval();
    ++cycles;
  }
  int add_out(uint32_t *y, unsigned *flags) const override {
    if (y) *y = top->add_y_o;
    if (flags) *flags = top->add_flags_o;
    return top->add_valid_o;
  }
  int mul_out(uint32_t *y, unsigned *flags) const override {
    if (y) *y = top->mul_y_o;
    if (flags) *flags = top->mul_flags_o;
    return top->mul_valid_o;
  }
  int div_out(uint32_t *y, unsigned *flags) const override {
    if (y) *y = top->div_y_o;
    if (flags) *flags = top->div_flags_o;
    return top->div_valid_o;
  }
  int sqrt_out(uint32_t *y, unsigned *flags) const override {
    if (y) *y = top->sqrt_y_o;
    if (flags) *flags = top->sqrt_flags_o;
    return top->sqrt_valid_o;
  }
  int sign_out(uint32_t *y, unsigned *flags) const override {
    if (y) *y = top->sign_y_o;
    if (flags) *flags = top->sign_flags_o;
    return top->sign_valid_o;
  }
  // Drive the inputs of op's core: valid, operands (b unused by sqrt).
  void drive(fpu_op op, int valid, uint32_t a, uint32_t b) {
    switch (op) {
    case FPU_OP_ADD:
    case FPU_OP_SUB: set_add(valid, op == FPU_OP_SUB, a, b); break;
    case FPU_OP_MUL: set_mul(valid, a, b); break;
    case FPU_OP_DIV: set_div(valid, a, b); break;
    case FPU_OP_SQRT: set_sqrt(valid, a); break;
    default: set_sign(valid, (unsigned)(op - FPU_OP_ABS), a, b); break;
    }
  }
  int out(fpu_op op, uint32_t *y, unsigned *flags) const {
    switch (op) {
    case FPU_OP_ADD:
    case FPU_OP_SUB: return add_out(y, flags);
    case FPU_OP_MUL: return mul_out(y, flags);
    case FPU_OP_DIV: return div_out(y, flags);
    case FPU_OP_SQRT: return sqrt_out(y, flags);
    default: return sign_out(y, flags);
    }
  }
  int run(fpu_op op, size_t n, const uint32_t *a, const uint32_t *b,
          uint32_t *y, uint8_t *flags) override {
    const size_t lat = op == FPU_OP_MUL ? FPU_MUL_LATENCY
                     : op == FPU_OP_DIV || op == FPU_OP_SQRT ? FPU_DIV_LATENCY
                     : op >= FPU_OP_ABS ? FPU_SIGN_LATENCY
                     : FPU_ADD_LATENCY;
    int bad = 0;
    for (size_t k = 0; k < n + lat; ++k) {
      // Cycle k: issue operation k (if any), then read the outputs, which
      // belong to operation k - lat.
      if (k < n)
        drive(op, 1, a[k], op == FPU_OP_SQRT ? 0 : b[k]);
      else
        drive(op, 0, 0, 0);
      uint32_t yk;
      unsigned fk;
      const int v = out(op, &yk, &fk);
      if (k >= lat) {
        const size_t j = k - lat;
        if (!v) bad = 1;
        y[j] = yk;
        if (flags) flags[j] = (uint8_t)fk;
      } else if (v) {
        bad = 1;
      }
      // The edge ending cycle k (after the last read this leaves a bubble
      // on the outputs, so the model is idle for the next call).
      clock();
    }
    drive(op, 0, 0, 0);
    return bad ? -1 : 0;
  }
};

}  // namespace

extern "C" {
fpu_model *FPU_CAT(fpu_model_new_, FPU_NAME)(void);
extern const fpu_model_info FPU_CAT(fpu_model_info_, FPU_NAME);

const fpu_model_info FPU_CAT(fpu_model_info_, FPU_NAME) = {
    FPU_STR(FPU_NAME), FPU_ROUND, FPU_FTZ, FPU_ADD_LATENCY, FPU_MUL_LATENCY,
    FPU_DIV_LATENCY};

fpu_model *FPU_CAT(fpu_model_new_, FPU_NAME)(void) {
  try {
    return new Impl();
  } catch (...) {
    return nullptr;
  }
}
}

#else
// ---- the C interface -------------------------------------------------------
extern "C" {
#define X(name)                                      \
  fpu_model *fpu_model_new_##name(void);              \
  extern const fpu_model_info fpu_model_info_##name;
FPU_MODELS
#undef X
}

namespace {
struct Entry {
  const fpu_model_info *info;
  fpu_model *(*make)(void);
};
const Entry kModels[] = {
#define X(name) {&fpu_model_info_##name, fpu_model_new_##name},
    FPU_MODELS
#undef X
};
const size_t kNumModels = sizeof kModels / sizeof kModels[0];

fpu_model *make_reset(const Entry &e) {
  fpu_model *m = e.make();
  if (m) fpu_model_reset(m);
  return m;
}
}  // namespace

extern "C" {

size_t fpu_model_count(void) { return kNumModels; }

const fpu_model_info *fpu_model_info_at(size_t i) {
  return i < kNumModels ? kModels[i].info : nullptr;
}

fpu_model *fpu_model_new(int round, int ftz, unsigned add_latency,
                         unsigned mul_latency) {
  for (size_t i = 0; i < kNumModels; ++i) {
    const fpu_model_info *in = kModels[i].info;
    if (in->round == round && in->ftz == (ftz != 0) &&
        (add_latency == 0 || in->add_latency == add_latency) &&
        (mul_latency == 0 || in->mul_latency == mul_latency))
      return make_reset(kModels[i]);
  }
  return nullptr;
}

fpu_model *fpu_model_new_named(const char *name) {
  for (size_t i = 0; i < kNumModels; ++i)
    if (std::strcmp(kModels[i].info->name, name) == 0)
      return make_reset(kModels[i]);
  return nullptr;
}

void fpu_model_free(fpu_model *m) { delete m; }

const fpu_model_info *fpu_model_get_info(const fpu_model *m) {
  return &m->info;
}

void fpu_model_reset(fpu_model *m) {
  m->set_add(0, 0, 0, 0);
  m->set_mul(0, 0, 0);
  m->set_div(0, 0, 0);
  m->set_sqrt(0, 0);
  m->set_sign(0, 0, 0, 0);
  m->set_rst(1);
  m->clock();
  m->set_rst(0);
}

void fpu_model_set_add(fpu_model *m, int valid, int sub, uint32_t a,
                       uint32_t b) {
  m->set_add(valid, sub, a, b);
}

void fpu_model_set_mul(fpu_model *m, int valid, uint32_t a, uint32_t b) {
  m->set_mul(valid, a, b);
}

void fpu_model_set_div(fpu_model *m, int valid, uint32_t a, uint32_t b) {
  m->set_div(valid, a, b);
}

void fpu_model_set_sqrt(fpu_model *m, int valid, uint32_t a) {
  m->set_sqrt(valid, a);
}

void fpu_model_set_sign(fpu_model *m, int valid, unsigned op, uint32_t a,
                        uint32_t b) {
  m->set_sign(valid, op, a, b);
}

void fpu_model_clock(fpu_model *m) { m->clock(); }

int fpu_model_add_out(const fpu_model *m, uint32_t *y, unsigned *flags) {
  return m->add_out(y, flags);
}

int fpu_model_mul_out(const fpu_model *m, uint32_t *y, unsigned *flags) {
  return m->mul_out(y, flags);
}

int fpu_model_div_out(const fpu_model *m, uint32_t *y, unsigned *flags) {
  return m->div_out(y, flags);
}

int fpu_model_sqrt_out(const fpu_model *m, uint32_t *y, unsigned *flags) {
  return m->sqrt_out(y, flags);
}

int fpu_model_sign_out(const fpu_model *m, uint32_t *y, unsigned *flags) {
  return m->sign_out(y, flags);
}

uint64_t fpu_model_cycles(const fpu_model *m) { return m->cycles; }

int fpu_model_run(fpu_model *m, fpu_op op, size_t n, const uint32_t *a,
                  const uint32_t *b, uint32_t *y, uint8_t *flags) {
  return m->run(op, n, a, b, y, flags);
}

}  // extern "C"
#endif
