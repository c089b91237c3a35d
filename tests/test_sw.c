/*
 * test_sw.c -- the C library without hardware: assembler, disassembler,
 * program image and .hex files, instruction-set simulator, golden model
 * and exact solution (cmocka).  Run from the repository root.
 */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#include "asm.h"
#include "compile.h"
#include "disasm.h"
#include "engine.h"
#include "fp3_isa.h"
#include "fpref.h"
#include "objects.h"
#include "image.h"
#include "model.h"
#include "progress.h"

#define SHIP "programs/ship_rk4.s"

/* ---- helpers -------------------------------------------------------------- */

static uint32_t fbits(float f) { return fpref_bits(f); }

/* Assemble or fail the test with the messages. */
static void assemble(const char *src, fp3_image *img) {
  char *err = NULL;
  int rc = fp3_asm_string(src, "t.s", img, &err);
  if (rc != 0) fail_msg("assembly failed:\n%s", err ? err : "?");
  free(err);
}

/* Assemble expecting failure; returns the messages (caller frees). */
static char *assemble_fails(const char *src) {
  fp3_image img;
  char *err = NULL;
  int rc = fp3_asm_string(src, "t.s", &img, &err);
  if (rc == 0) fail_msg("assembly of <<%s>> should fail", src);
  assert_non_null(err);
  return err;
}

static void expect_error(const char *src, const char *want) {
  char *err = assemble_fails(src);
  if (!strstr(err, want))
    fail_msg("error for <<%s>>:\n%s\ndoes not contain '%s'", src, err, want);
  free(err);
}

static uint64_t W(unsigned opc, unsigned rd, unsigned ra, unsigned rb,
                  uint32_t imm) {
  return fp3_insn_make(opc, rd, ra, rb, imm);
}

/* Run capture: every write and endi. */
#define MAXW 4096
typedef struct capture {
  unsigned n;
  unsigned reg[MAXW];
  uint32_t val[MAXW], tag[MAXW];
  unsigned nendi;
  uint32_t endi_k[MAXW];
  uint64_t endi_cyc[MAXW];
} capture;

static void cap_write(void *ctx, unsigned reg, uint32_t value, uint32_t k) {
  capture *c = ctx;
  if (c->n < MAXW) {
    c->reg[c->n] = reg;
    c->val[c->n] = value;
    c->tag[c->n] = k;
  }
  c->n++;
}

static void cap_endi(void *ctx, uint32_t k, uint64_t cycle) {
  capture *c = ctx;
  if (c->nendi < MAXW) {
    c->endi_k[c->nendi] = k;
    c->endi_cyc[c->nendi] = cycle;
  }
  c->nendi++;
}

/* Load and run an image on a fresh ISS. */
static fp3_engine *run_iss(const fp3_image *img, uint32_t steps, capture *cap,
                           fp3_status *st) {
  fp3_engine *e = fp3_engine_iss_new();
  assert_non_null(e);
  assert_int_equal(fp3_engine_load(e, img->words, img->n), 0);
  fp3_observer obs = {.ctx = cap, .on_write = cap_write, .on_endi = cap_endi};
  if (cap) memset(cap, 0, sizeof *cap);
  assert_int_equal(fp3_engine_run(e, steps, cap ? &obs : NULL, st), 0);
  return e;
}

static uint32_t reg_of(fp3_engine *e, unsigned r) {
  uint32_t v = 0;
  assert_int_equal(fp3_engine_read_reg(e, r, &v), 0);
  return v;
}

/* ---- assembler ------------------------------------------------------------ */

static void test_asm_instructions(void **state) {
  (void)state;
  fp3_image img;
  assemble("; a comment line\n"
           "# another\n"
           "        li   r1, 1.5      ; trailing comment\n"
           "        li   r31, 0x3E2AAAAB # hash comment\n"
           "loop:   add  r2, r1, r31\n"
           "        SUB  r3, r2, r1\n"
           "        mul  r4, r3, r3\n"
           "        mov  r5, r4\n"
           "        nop\n"
           "        endi loop\n"
           "        halt\n",
           &img);
  assert_int_equal(img.n, 9);
  assert_true(img.words[0] == W(FP3_OP_LI, 1, 0, 0, 0x3FC00000u));
  assert_true(img.words[1] == W(FP3_OP_LI, 31, 0, 0, 0x3E2AAAABu));
  assert_true(img.words[2] == W(FP3_OP_ADD, 2, 1, 31, 0));
  assert_true(img.words[3] == W(FP3_OP_SUB, 3, 2, 1, 0));
  assert_true(img.words[4] == W(FP3_OP_MUL, 4, 3, 3, 0));
  assert_true(img.words[5] == W(FP3_OP_MOV, 5, 4, 0, 0));
  assert_true(img.words[6] == W(FP3_OP_NOP, 0, 0, 0, 0));
  assert_true(img.words[7] == W(FP3_OP_ENDI, 0, 0, 0, 2));
  assert_true(img.words[8] == W(FP3_OP_HALT, 0, 0, 0, 0));
  /* source lines */
  assert_int_equal(img.line[0], 3);
  assert_int_equal(img.line[2], 5);
  assert_int_equal(img.line[8], 11);
  /* field layout of the ISA table */
  assert_true(W(FP3_OP_ADD, 2, 1, 31, 0) == 0x0102011F00000000ull);
  assert_int_equal(img.nbind_in + img.nbind_out, 0);
}

static void test_asm_labels(void **state) {
  (void)state;
  fp3_image img;
  /* forward reference, label alone on a line, two labels, label at end */
  assemble("        endi fwd\n"
           "a: b:   nop\n"
           "fwd:\n"
           "        nop\n"
           "        endi a\n"
           "        endi b\n"
           "        endi end_\n"
           "        endi 0x10\n"
           "end_:\n",
           &img);
  assert_int_equal(img.n, 7);
  assert_int_equal(fp3_insn_imm(img.words[0]), 2);
  assert_int_equal(fp3_insn_imm(img.words[3]), 1);
  assert_int_equal(fp3_insn_imm(img.words[4]), 1);
  assert_int_equal(fp3_insn_imm(img.words[5]), 7);
  assert_int_equal(fp3_insn_imm(img.words[6]), 16);
}

static void test_asm_bindings(void **state) {
  (void)state;
  fp3_image img;
  assemble(".reg thrust r1\n"
           ".reg drag, r2\n"
           ".reg x r10\n"
           ".in T, thrust\n"
           ".in C, drag\n"
           ".in m, r3\n"
           ".in minv, r4\n"
           ".in h, r5\n"
           ".in v0, r6\n"
           ".in s0, r7\n"
           ".out v, r6\n"
           ".out s, r7\n"
           "  add x, thrust, drag\n"
           "  .word 0xFF00000000000001\n"
           "  .word 0x1\n",
           &img);
  /* in program order, names as written, aliases resolved */
  static const char *const in_names[] = {"T", "C", "m", "minv", "h", "v0", "s0"};
  assert_int_equal(img.nbind_in, 7);
  for (unsigned i = 0; i < 7; i++) {
    assert_string_equal(img.bind_in[i].name, in_names[i]);
    assert_int_equal(img.bind_in[i].reg, (int)i + 1);
    assert_int_equal(img.bind_in[i].line, (int)i + 4);
  }
  assert_int_equal(img.nbind_out, 2);
  assert_string_equal(img.bind_out[0].name, "v");
  assert_int_equal(img.bind_out[0].reg, 6);
  assert_string_equal(img.bind_out[1].name, "s");
  assert_int_equal(img.bind_out[1].reg, 7);
  assert_int_equal(img.n, 3);
  assert_true(img.words[0] == W(FP3_OP_ADD, 10, 1, 2, 0));
  assert_true(img.words[1] == 0xFF00000000000001ull); /* raw, unchecked */
  assert_true(img.words[2] == 1);
}

static void test_asm_literals(void **state) {
  (void)state;
  static const struct {
    const char *text;
    uint32_t bits;
  } ok[] = {
      {"0.16666667", 0x3E2AAAABu}, {"-2.5e3", 0xC51C4000u},
      {"inf", 0x7F800000u},        {"-inf", 0xFF800000u},
      {"Infinity", 0x7F800000u},   {"nan", 0x7FC00000u},
      {"0x3E2AAAAB", 0x3E2AAAABu}, {"0x7fc00001", 0x7FC00001u},
      {"0x1", 0x00000001u},        {"1e-45", 0x00000001u},
      {"-0.0", 0x80000000u},       {"0", 0x00000000u},
      {"3", 0x40400000u},          {"0.1", 0x3DCCCCCDu},
      {"3.4028235e38", 0x7F7FFFFFu}, {"+1.0", 0x3F800000u},
      {"0.016666668", 0x3C888889u},
  };
  for (size_t i = 0; i < sizeof ok / sizeof ok[0]; i++) {
    uint32_t b = 0;
    char why[128];
    if (fp3_asm_literal(ok[i].text, &b, why, sizeof why))
      fail_msg("literal %s: %s", ok[i].text, why);
    if (b != ok[i].bits)
      fail_msg("literal %s: 0x%08X, want 0x%08X", ok[i].text, b, ok[i].bits);
  }
  static const char *const bad[] = {"1.2.3", "0x123456789", "1e39", "abc",
                                    "", "0x", "1.0f", "- 1", "0xG1"};
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    uint32_t b;
    char why[128];
    if (fp3_asm_literal(bad[i], &b, why, sizeof why) == 0)
      fail_msg("literal '%s' accepted", bad[i]);
    assert_non_null(strstr(why, "bad literal"));
  }
  /* 1/60 as the CLI's default h */
  assert_int_equal(fbits(1.0f / 60.0f), 0x3C888889u);
}

static void test_asm_errors(void **state) {
  (void)state;
  expect_error("nop\nfoo r1, r2, r3\n", "t.s:2: unknown mnemonic 'foo'");
  expect_error("add r1, r2, x9\n", "t.s:1: bad register 'x9'");
  expect_error("nop\nnop\nadd r1, r2, r32\n", "t.s:3: register out of range: r32");
  expect_error("li r300, 1\n", "t.s:1: register out of range: r300");
  expect_error("li r1, 1.2.3\n", "t.s:1: bad literal '1.2.3'");
  expect_error("li r1, 1e40\n", "t.s:1: bad literal '1e40': out of binary32");
  expect_error("li r1, 0x100000000\n", "t.s:1: bad literal '0x100000000'");
  expect_error("nop\nendi nowhere\n", "t.s:2: undefined label 'nowhere'");
  expect_error("a: nop\n\na: nop\n", "t.s:3: duplicate label 'a' (first defined at line 1)");
  expect_error("add r1, r2\n", "t.s:1: wrong operand count: add takes 3 (rd, ra, rb), got 2");
  expect_error("halt r1\n", "t.s:1: wrong operand count: halt takes 0 (none), got 1");
  expect_error("li r1\n", "t.s:1: wrong operand count: li takes 2 (rd, imm), got 1");
  expect_error("mov r1, r2, r3\n", "t.s:1: wrong operand count: mov takes 2");
  expect_error("endi\n", "t.s:1: wrong operand count: endi takes 1");
  expect_error("add r1, , r3\n", "t.s:1: empty operand");
  expect_error("add r1 r2, r3\n", "t.s:1: bad operand 'r1 r2' (missing comma?)");
  expect_error(".bogus 1\n", "t.s:1: unknown directive '.bogus'");
  expect_error(".in 3x, r1\n", "t.s:1: bad .in name '3x'");
  expect_error(".out -v, r1\n", "t.s:1: bad .out name '-v'");
  expect_error(".in a.b, r1\n", "t.s:1: bad .in name 'a.b'");
  expect_error(".model ship.fp3m\n", "t.s:1: .model takes one file name in double quotes");
  expect_error(".integrator\n", "t.s:1: .integrator takes one integrator name");
  expect_error(".in T, r1\n.in T, r2\n", "t.s:2: duplicate .in T");
  expect_error(".in T, r1\n.in C, r1\n", "t.s:2: r1 is already bound by .in T");
  expect_error(".in T\n", "t.s:1: wrong operand count: .in takes 2");
  expect_error(".in T, r99\n", "t.s:1: register out of range: r99");
  expect_error(".reg a r1\n.reg a r2\n", "t.s:2: duplicate register alias 'a'");
  expect_error(".reg r5 r1\n", "t.s:1: bad register alias name 'r5'");
  expect_error(".reg a\n", "t.s:1: wrong operand count: .reg");
  expect_error(".reg a r40\n", "t.s:1: register out of range: r40");
  /* .regs N: a program for a build with NUM_REGS >= N */
  expect_error(".regs 64\nadd r1, r2, r64\n", "t.s:2: register out of range: r64 (registers are r0..r63)");
  expect_error("add r1, r2, r3\n.regs 64\n", "t.s:2: .regs must come before the first register");
  expect_error(".regs 1\n", "t.s:1: .regs takes a register count 2..256");
  expect_error(".regs 257\n", "t.s:1: .regs takes a register count 2..256");
  expect_error(".regs 4x\n", "t.s:1: .regs takes a register count 2..256");
  {
    fp3_image img;
    char *errs = NULL;
    assert_int_equal(fp3_asm_string(".regs 256\nadd r255, r40, r32\nendi 0\n", "t.s", &img, &errs), 0);
    free(errs);
    assert_int_equal(fp3_insn_rd(img.words[0]), 255);
    assert_int_equal(fp3_insn_ra(img.words[0]), 40);
    assert_int_equal(fp3_insn_rb(img.words[0]), 32);
  }
  expect_error("add y, r1, r2\n.reg y r3\n", "t.s:1: bad register 'y'");
  expect_error(".word 12\n", "t.s:1: bad literal '12'");
  expect_error("endi 1x\n", "t.s:1: bad address '1x'");
  expect_error("endi 300\n", "t.s:1: endi target 300 outside the 256-entry instruction memory");
  expect_error(": nop\n", "t.s:1: bad label");
  expect_error("nop\nbeq r1, r2, 1\n", "t.s:2: beq target 1 is not ahead of the beq (at 1)");
  expect_error("back: nop\nbeq r1, r2, back\n", "t.s:2: beq target 'back' (address 0) is not ahead");
  expect_error("beq r1, r2, 300\n", "t.s:1: beq target 300 outside the 256-entry");
  expect_error("beq r1, end\nend: halt\n", "t.s:1: wrong operand count: beq takes 3 (ra, rb, imm)");

  /* every error is collected, each with its line */
  char *err = assemble_fails("foo\nadd r1, r2\nnop\nli r1, zz\nendi none\n");
  assert_non_null(strstr(err, "t.s:1: unknown mnemonic"));
  assert_non_null(strstr(err, "t.s:2: wrong operand count"));
  assert_non_null(strstr(err, "t.s:4: bad literal 'zz'"));
  assert_non_null(strstr(err, "t.s:5: undefined label 'none'"));
  assert_null(strstr(err, "t.s:3:"));
  free(err);

  /* the return value counts the errors */
  fp3_image img;
  char *e2 = NULL;
  assert_int_equal(fp3_asm_string("foo\nbar\n", "t.s", &img, &e2), 2);
  free(e2);
  assert_int_equal(fp3_asm_string("nop\n", "t.s", &img, NULL), 0);
  assert_int_equal(fp3_asm_string("foo\n", "t.s", &img, NULL), 1);
}

static void test_asm_too_large(void **state) {
  (void)state;
  size_t n = FP3_DEFAULT_IMEM_DEPTH;
  char *src = malloc((n + 2) * 5 + 1);
  assert_non_null(src);
  src[0] = '\0';
  for (size_t i = 0; i < n; i++) strcat(src, "nop\n");
  fp3_image img;
  assemble(src, &img); /* exactly the memory: fine */
  assert_int_equal(img.n, n);
  strcat(src, "nop\nnop\n");
  char *err = assemble_fails(src);
  char want[64];
  snprintf(want, sizeof want, "t.s:%zu: program larger than the instruction memory (%d words)",
           n + 1, FP3_DEFAULT_IMEM_DEPTH);
  if (!strstr(err, want)) fail_msg("%s", err);
  assert_null(strstr(strstr(err, want) + strlen(want), "program larger")); /* once */
  free(err);
  free(src);
}

static void test_asm_file(void **state) {
  (void)state;
  fp3_image img;
  char *err = NULL;
  assert_int_equal(fp3_asm_file(SHIP, &img, &err), 0);
  assert_null(err);
  assert_int_equal(fp3_image_validate(&img, (char[64]){0}, 64), 0);
  assert_int_not_equal(fp3_asm_file("/nonexistent/x.s", &img, &err), 0);
  assert_non_null(strstr(err, "/nonexistent/x.s: "));
  free(err);
}

/* ---- disassembler --------------------------------------------------------- */

static void roundtrip(const fp3_image *img) {
  char *text = fp3_disasm_image(img);
  assert_non_null(text);
  fp3_image back;
  char *err = NULL;
  if (fp3_asm_string(text, "disasm.s", &back, &err) != 0)
    fail_msg("disassembly does not assemble:\n%s\n%s", err, text);
  assert_int_equal(back.n, img->n);
  for (size_t i = 0; i < img->n; i++)
    if (back.words[i] != img->words[i])
      fail_msg("word %zu: %016llx -> %016llx\n%s", i,
               (unsigned long long)img->words[i],
               (unsigned long long)back.words[i], text);
  assert_int_equal(back.nbind_in, img->nbind_in);
  assert_int_equal(back.nbind_out, img->nbind_out);
  for (unsigned i = 0; i < img->nbind_in + img->nbind_out; i++) {
    const fp3_binding *a = i < img->nbind_in ? &img->bind_in[i] : &img->bind_out[i - img->nbind_in];
    const fp3_binding *b = i < img->nbind_in ? &back.bind_in[i] : &back.bind_out[i - img->nbind_in];
    assert_string_equal(a->name, b->name);
    assert_int_equal(a->reg, b->reg);
  }
  free(text);
}

static void test_disasm_roundtrip(void **state) {
  (void)state;
  fp3_image img;
  char *err = NULL;
  assert_int_equal(fp3_asm_file(SHIP, &img, &err), 0);
  roundtrip(&img);
  /* awkward immediates, illegal words, endi outside the program */
  assemble(".in h, r9\n.out s, r3\n"
           "li r1, 0x7FC00001\n li r1, 0xFFC00000\n li r1, nan\n"
           "li r2, -0.0\n li r2, 1e-45\n li r2, 0x007FFFFF\n li r2, -inf\n"
           "li r2, 0.1\n li r2, 3.4028235e38\n li r2, 0.16666667\n"
           "top: mov r31, r0\n"
           ".word 0x0F00000000000000\n .word 0x0100000000000001\n"
           ".word 0x0120000000000000\n"
           "endi top\n .word 0x060000000000012C\n endi end\n nop\n halt\nend:\n",
           &img);
  roundtrip(&img);
  /* random words */
  srand(7);
  fp3_image_init(&img);
  for (size_t i = 0; i < FP3_DEFAULT_IMEM_DEPTH; i++) {
    uint64_t w = ((uint64_t)(unsigned)rand() << 33) ^ ((uint64_t)(unsigned)rand() << 11) ^
                 (uint64_t)(unsigned)rand();
    if (i % 2) { /* mostly legal */
      w = W((unsigned)(rand() % 15), 0, 0, 0, 0);
      int uses = fp3_opc_uses(fp3_insn_opc(w));
      w = W(fp3_insn_opc(w), uses & FP3_USES_RD ? (unsigned)rand() % 32 : 0,
            uses & FP3_USES_RA ? (unsigned)rand() % 32 : 0,
            uses & FP3_USES_RB ? (unsigned)rand() % 32 : 0,
            uses & FP3_USES_IMM ? (uint32_t)rand() * 2654435761u : 0);
    }
    img.words[i] = w;
  }
  img.n = FP3_DEFAULT_IMEM_DEPTH;
  roundtrip(&img);
}

static void test_disasm_word(void **state) {
  (void)state;
  char buf[96];
  fp3_disasm_word(W(FP3_OP_MUL, 1, 2, 3, 0), buf, sizeof buf);
  assert_string_equal(buf, "mul r1, r2, r3");
  fp3_disasm_word(W(FP3_OP_LI, 7, 0, 0, 0x3E2AAAABu), buf, sizeof buf);
  assert_string_equal(buf, "li r7, 0.166666672");
  fp3_disasm_word(W(FP3_OP_LI, 7, 0, 0, 0x7FC00001u), buf, sizeof buf);
  assert_string_equal(buf, "li r7, 0x7FC00001");
  fp3_disasm_word(W(FP3_OP_MOV, 4, 5, 0, 0), buf, sizeof buf);
  assert_string_equal(buf, "mov r4, r5");
  fp3_disasm_word(W(FP3_OP_ENDI, 0, 0, 0, 3), buf, sizeof buf);
  assert_string_equal(buf, "endi 3");
  fp3_disasm_word(W(FP3_OP_HALT, 0, 0, 0, 0), buf, sizeof buf);
  assert_string_equal(buf, "halt");
  fp3_disasm_word(W(FP3_OP_BEQ, 0, 5, 24, 9), buf, sizeof buf);
  assert_string_equal(buf, "beq r5, r24, 9");
  fp3_disasm_word(0x0F00000000000000ull, buf, sizeof buf);
  assert_string_equal(buf, ".word 0x0F00000000000000");
  /* the whole image: labels, bindings, hex comments */
  fp3_image img;
  assemble(".in T, r1\nli r2, 2.0\nb: add r3, r1, r2\nendi b\n", &img);
  char *t = fp3_disasm_image(&img);
  assert_non_null(t);
  assert_non_null(strstr(t, ".in T, r1\n"));
  assert_non_null(strstr(t, "L1:\n"));
  assert_non_null(strstr(t, "endi L1"));
  assert_non_null(strstr(t, "li r2, 2"));
  assert_non_null(strstr(t, "imm 0x40000000"));
  assert_non_null(strstr(t, "0402000040000000"));
  free(t);
  assemble("beq r1, r2, skip\nli r3, 1.0\nskip: halt\n", &img);
  assert_true(img.words[0] == W(FP3_OP_BEQ, 0, 1, 2, 2));
  t = fp3_disasm_image(&img);
  assert_non_null(t);
  assert_non_null(strstr(t, "L2:\n"));
  assert_non_null(strstr(t, "beq r1, r2, L2"));
  free(t);
}

/* ---- instruction words and images ---------------------------------------- */

static void test_insn_check(void **state) {
  (void)state;
  char why[160];
  const unsigned R = FP3_DEFAULT_NUM_REGS;
  assert_int_equal(fp3_insn_check(W(FP3_OP_ADD, 31, 30, 29, 0), R, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why), 0);
  assert_int_equal(fp3_insn_check(W(FP3_OP_LI, 0, 0, 0, 0xFFFFFFFFu), R, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why), 0);
  assert_int_equal(fp3_insn_check(0, R, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why), 0); /* nop */
  static const struct {
    uint64_t w;
    const char *why;
  } bad[] = {
      {0x0F00000000000000ull, "unknown opcode 0x0f"},
      {0x0800010200000300ull, "beq target 768 outside the 256-entry"},
      {0x0801010200000003ull, "rd field is 1 but beq does not use it"},
      {0xFF00000000000000ull, "unknown opcode 0xff"},
      {0x0000000000000001ull, "imm field is 0x00000001 but nop does not use it"},
      {0x0001000000000000ull, "rd field is 1 but nop does not use it"},
      {0x0100000000000000ull | (1ull << FP3_IMM_LSB), "imm field"},
      {0x0500000100000000ull, "rb field is 1 but mov does not use it"},
      {0x0400010000000000ull, "ra field is 1 but li does not use it"},
      {0x0601000000000000ull, "rd field is 1 but endi does not use it"},
      {0x0700000000000004ull, "halt does not use it"},
      {0x0120000000000000ull, "rd is r32, not below 32 registers"},
      {0x0100FF0000000000ull, "ra is r255"},
      {0x0300002000000000ull, "rb is r32"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    if (fp3_insn_check(bad[i].w, R, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why) == 0)
      fail_msg("word %016llx accepted", (unsigned long long)bad[i].w);
    if (!strstr(why, bad[i].why))
      fail_msg("word %016llx: '%s', want '%s'", (unsigned long long)bad[i].w,
               why, bad[i].why);
  }
  /* beq: only ahead of itself */
  assert_int_equal(fp3_insn_check_at(W(FP3_OP_BEQ, 0, 1, 2, 6), 5, R, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why), 0);
  assert_int_not_equal(fp3_insn_check_at(W(FP3_OP_BEQ, 0, 1, 2, 5), 5, R, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why), 0);
  assert_non_null(strstr(why, "beq target 5 is not ahead of the beq (at 5)"));
  assert_int_equal(fp3_insn_check_at(W(FP3_OP_ENDI, 0, 0, 0, 0), 5, R, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why), 0);
  /* a smaller register file */
  assert_int_not_equal(fp3_insn_check(W(FP3_OP_MOV, 8, 0, 0, 0), 8, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why), 0);
  /* every opcode of the table is known, in both directions */
#define X(name, code, mnem, uses, unit, desc)                 \
  assert_int_equal(fp3_opc_lookup(mnem), code);               \
  assert_string_equal(fp3_opc_mnemonic(code), mnem);          \
  assert_int_equal(fp3_opc_uses(code), uses);
  FP3_OPCODES(X)
#undef X
  assert_int_equal(fp3_opc_lookup("fma"), -1);
  assert_null(fp3_opc_mnemonic(0x42));
}

static void test_image_validate(void **state) {
  (void)state;
  fp3_image img;
  char msg[256];
  assemble("nop\nadd r1, r2, r3\n.word 0x0F00000000000000\nnop\n", &img);
  assert_int_equal(fp3_image_validate(&img, msg, sizeof msg), -1);
  assert_string_equal(msg, "word 2: unknown opcode 0x0f");
  img.words[2] = W(FP3_OP_NOP, 0, 0, 0, 0);
  assert_int_equal(fp3_image_validate(&img, msg, sizeof msg), 0);
  img.words[3] = 0x0100000000000007ull;
  assert_int_equal(fp3_image_validate(&img, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "word 3: imm field"));
  img.words[3] = 0;
  char why[160];
  assert_int_equal(fp3_image_bind(&img, 1, "T", 40, 1, why, sizeof why), 0);
  assert_int_equal(img.bind_in[img.nbind_in - 1].reg, 40);
  assert_int_equal(fp3_image_validate(&img, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, ".in T: register r40 out of range"));
}

static char tmpdir[64];

static int make_tmpdir(void **state) {
  (void)state;
  snprintf(tmpdir, sizeof tmpdir, "/tmp/fp3_test_sw.XXXXXX");
  return mkdtemp(tmpdir) ? 0 : -1;
}

static int remove_tmpdir(void **state) {
  (void)state;
  char cmd[128];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
  return system(cmd) == 0 ? 0 : -1;
}

static int file_exists(const char *p) {
  struct stat sb;
  return stat(p, &sb) == 0;
}

static void write_file(const char *name, const char *text) {
  char path[160];
  snprintf(path, sizeof path, "%s/%s", tmpdir, name);
  FILE *f = fopen(path, "w");
  assert_non_null(f);
  fputs(text, f);
  fclose(f);
}

/* .include: in place, beside the including file, errors naming the file. */
static void test_asm_include(void **state) {
  (void)state;
  char top[160], *err = NULL;
  fp3_image img;
  mkdir(strcat(strcpy(top, tmpdir), "/sub"), 0700);
  write_file("sub/regs.inc", ".reg x r3\n.include \"consts.inc\"\n");
  write_file("sub/consts.inc", "li x, 2.0\n");
  write_file("sub/top.s", "nop\n.include \"regs.inc\" ; registers\nb: add x, x, x\nendi b\n");
  snprintf(top, sizeof top, "%s/sub/top.s", tmpdir);
  assert_int_equal(fp3_asm_file(top, &img, &err), 0);
  assert_int_equal(img.n, 4);
  assert_true(img.words[1] == W(FP3_OP_LI, 3, 0, 0, 0x40000000u));
  assert_true(img.words[3] == W(FP3_OP_ENDI, 0, 0, 0, 2));
  assert_int_equal(img.line[1], 2); /* the top file's .include line */
  /* an error inside an included file names it and its line */
  write_file("sub/bad.inc", "nop\nmul x, x\nendi nowhere\n");
  write_file("sub/bad.s", ".reg x r1\n.include \"bad.inc\"\n");
  snprintf(top, sizeof top, "%s/sub/bad.s", tmpdir);
  assert_int_not_equal(fp3_asm_file(top, &img, &err), 0);
  assert_non_null(strstr(err, "sub/bad.inc:2: wrong operand count"));
  assert_non_null(strstr(err, "sub/bad.inc:3: undefined label 'nowhere'"));
  free(err);
  /* a missing file, a bad operand, a file including itself */
  expect_error(".include \"no/such.inc\"\n", "t.s:1: cannot include 'no/such.inc'");
  expect_error(".include regs.inc\n", "t.s:1: .include takes one file name in double quotes");
  write_file("loop.inc", ".include \"loop.inc\"\n");
  snprintf(top, sizeof top, "%s/loop.inc", tmpdir);
  assert_int_not_equal(fp3_asm_file(top, &img, &err), 0);
  assert_non_null(strstr(err, "nested more than 8 deep"));
  free(err);
  /* a file including another ten times, which includes a third ten
   * times: refused after 64 reads (without the bound, a file including
   * itself ten times would be read 10^8 times within the nesting limit) */
  write_file("fan1.inc", ".include \"fan2.inc\"\n.include \"fan2.inc\"\n.include \"fan2.inc\"\n"
                         ".include \"fan2.inc\"\n.include \"fan2.inc\"\n.include \"fan2.inc\"\n"
                         ".include \"fan2.inc\"\n.include \"fan2.inc\"\n.include \"fan2.inc\"\n"
                         ".include \"fan2.inc\"\n");
  write_file("fan2.inc", ".include \"fan3.inc\"\n.include \"fan3.inc\"\n.include \"fan3.inc\"\n"
                         ".include \"fan3.inc\"\n.include \"fan3.inc\"\n.include \"fan3.inc\"\n"
                         ".include \"fan3.inc\"\n.include \"fan3.inc\"\n.include \"fan3.inc\"\n"
                         ".include \"fan3.inc\"\n");
  write_file("fan3.inc", "nop\n");
  snprintf(top, sizeof top, "%s/fan1.inc", tmpdir);
  assert_int_not_equal(fp3_asm_file(top, &img, &err), 0);
  assert_non_null(strstr(err, "more than 64 .include directives in one program"));
  free(err);
}

static void test_hex_roundtrip(void **state) {
  (void)state;
  fp3_image img, back;
  char path[128], msg[256];
  char *err = NULL;
  assert_int_equal(fp3_asm_file(SHIP, &img, &err), 0);
  snprintf(path, sizeof path, "%s/ship.hex", tmpdir);
  assert_int_equal(fp3_image_write(&img, path, SHIP, msg, sizeof msg), 0);
  assert_false(file_exists(strcat(strcpy((char[160]){0}, path), ".tmp")));
  assert_int_equal(fp3_image_read(path, &back, msg, sizeof msg), 0);
  assert_int_equal(back.n, img.n);
  assert_memory_equal(back.words, img.words, img.n * sizeof img.words[0]);
  assert_memory_equal(back.line, img.line, img.n * sizeof img.line[0]);
  /* the bindings by name, the model and the integrator travel too */
  assert_int_equal(back.nbind_in, img.nbind_in);
  assert_int_equal(back.nbind_out, img.nbind_out);
  for (unsigned i = 0; i < img.nbind_in; i++) {
    assert_string_equal(back.bind_in[i].name, img.bind_in[i].name);
    assert_int_equal(back.bind_in[i].reg, img.bind_in[i].reg);
  }
  assert_string_equal(back.model, img.model);
  assert_string_equal(back.integrator, "rk4se");
  assert_non_null(strstr(img.model, "models/ship.fp3m"));

  /* the file is what $readmemh reads: comments, then 16 hex digits a line */
  FILE *f = fopen(path, "r");
  assert_non_null(f);
  char line[256];
  int words = 0, in = 0, out = 0;
  while (fgets(line, sizeof line, f)) {
    if (strncmp(line, "//", 2) == 0) {
      if (strncmp(line, "// .in ", 7) == 0) in++;
      if (strncmp(line, "// .out ", 8) == 0) out++;
      continue;
    }
    assert_int_equal(strspn(line, "0123456789abcdef"), 16);
    assert_true(line[16] == ' ' || line[16] == '\n');
    words++;
  }
  fclose(f);
  assert_int_equal(words, (int)img.n);
  assert_int_equal(in, 6);
  assert_int_equal(out, 2);

  /* a hand-written file: blank lines, comments, upper-case digits */
  snprintf(path, sizeof path, "%s/hand.hex", tmpdir);
  f = fopen(path, "w");
  assert_non_null(f);
  fputs("// hand made\n\n   // .in  h   r4\n0400010000000000\n"
        "  0A00000000000000   // @1 line 9\n// .out v r2\n", f);
  fclose(f);
  assert_int_equal(fp3_image_read(path, &back, msg, sizeof msg), 0);
  assert_int_equal(back.n, 2);
  assert_true(back.words[1] == 0x0A00000000000000ull); /* read, not checked */
  assert_int_equal(back.line[1], 9);
  assert_int_equal(back.nbind_in, 1);
  assert_string_equal(back.bind_in[0].name, "h");
  assert_int_equal(back.bind_in[0].reg, 4);
  assert_int_equal(back.nbind_out, 1);
  assert_string_equal(back.bind_out[0].name, "v");
  assert_int_equal(back.bind_out[0].reg, 2);
}

static void test_hex_read_errors(void **state) {
  (void)state;
  static const struct {
    const char *text;
    const char *want;
  } bad[] = {
      {"0000\n", ":1: expected one word of 16 hex digits"},
      {"// x\n00000000000000000\n", ":2: expected one word"},
      {"000000000000000g\n", ":1: expected one word"},
      {"0000000000000000 0000000000000000\n", ":1: expected one word"},
      {"// .in 1X r1\n", ":1: bad .in name '1X'"},
      {"// .in -v r1\n// .in T r1\n", ":2: r1 is already bound by .in -v"},
      {"// .in T r77\n", ":1: malformed binding"},
      {"// .out v r1\n// .out v r2\n", ":2: duplicate .out v"},
  };
  char path[128], msg[256];
  snprintf(path, sizeof path, "%s/bad.hex", tmpdir);
  fp3_image img;
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(bad[i].text, f);
    fclose(f);
    assert_int_equal(fp3_image_read(path, &img, msg, sizeof msg), -1);
    if (!strstr(msg, bad[i].want)) fail_msg("'%s': %s", bad[i].text, msg);
  }
  /* more words than the memory holds */
  FILE *f = fopen(path, "w");
  assert_non_null(f);
  for (int i = 0; i <= FP3_DEFAULT_IMEM_DEPTH; i++) fputs("0000000000000000\n", f);
  fclose(f);
  assert_int_equal(fp3_image_read(path, &img, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "more than 256 words"));
  assert_int_equal(fp3_image_read("/nonexistent/a.hex", &img, msg, sizeof msg), -1);
  assert_non_null(strstr(msg, "/nonexistent/a.hex"));
}

static void test_hex_write_fails_cleanly(void **state) {
  (void)state;
  fp3_image img;
  char path[160], tmp[170], msg[256];
  assemble("nop\n", &img);
  /* directory missing: nothing at all */
  snprintf(path, sizeof path, "%s/no/such/dir/x.hex", tmpdir);
  assert_int_equal(fp3_image_write(&img, path, NULL, msg, sizeof msg), -1);
  assert_false(file_exists(path));
  /* the target is a directory: FILE.tmp is written, the rename fails, and
   * FILE.tmp must be gone */
  snprintf(path, sizeof path, "%s/adir", tmpdir);
  assert_int_equal(mkdir(path, 0700), 0);
  assert_int_equal(fp3_image_write(&img, path, NULL, msg, sizeof msg), -1);
  snprintf(tmp, sizeof tmp, "%s.tmp", path);
  assert_false(file_exists(tmp));
  assert_non_null(strstr(msg, "rename"));
  /* a full device */
  if (file_exists("/dev/full")) {
    assert_int_equal(symlink("/dev/full", strcat(strcpy(tmp, tmpdir), "/full.hex.tmp")), 0);
    snprintf(path, sizeof path, "%s/full.hex", tmpdir);
    assert_int_equal(fp3_image_write(&img, path, NULL, msg, sizeof msg), -1);
    assert_false(file_exists(path));
    struct stat sb;
    assert_int_not_equal(lstat(tmp, &sb), 0);
  }
  /* an old file is replaced only by a complete new one */
  snprintf(path, sizeof path, "%s/old.hex", tmpdir);
  assert_int_equal(fp3_image_write(&img, path, NULL, msg, sizeof msg), 0);
  assert_true(file_exists(path));
}

/* ---- instruction-set simulator --------------------------------------------- */

static void test_iss_opcodes(void **state) {
  (void)state;
  fp3_image img;
  assemble("li r1, 1.5\n"
           "li r2, -0.25\n"
           "add r3, r1, r2\n"  /* 1.25 */
           "sub r4, r1, r2\n"  /* 1.75 */
           "mul r5, r1, r2\n"  /* -0.375 */
           "mov r6, r5\n"
           "nop\n"
           "li r7, 0x7FC00001\n"
           "mov r8, r7\n"     /* bit copy of a NaN */
           "halt\n"
           "li r9, 1.0\n",    /* not reached */
           &img);
  fp3_status st;
  capture cap;
  fp3_engine *e = run_iss(&img, 1, &cap, &st);
  assert_int_equal(st.error, FP3_ERR_NONE);
  assert_int_equal(st.done, 1);
  assert_int_equal(st.steps_done, 0);
  assert_int_equal(st.flags, 0); /* all exact */
  assert_int_equal(st.cycles, 10);
  assert_int_equal(st.issued, 10);
  assert_int_equal(st.stalls, 0);
  assert_int_equal(reg_of(e, 3), fbits(1.25f));
  assert_int_equal(reg_of(e, 4), fbits(1.75f));
  assert_int_equal(reg_of(e, 5), fbits(-0.375f));
  assert_int_equal(reg_of(e, 6), fbits(-0.375f));
  assert_int_equal(reg_of(e, 8), 0x7FC00001u);
  assert_int_equal(reg_of(e, 9), 0);
  assert_int_equal(cap.n, 8); /* li li add sub mul mov li mov */
  assert_int_equal(cap.nendi, 0);
  assert_string_equal(e->ops->name, "iss");
  fp3_engine_free(e);
}

static void test_iss_flags(void **state) {
  (void)state;
  fp3_image img;
  fp3_status st;
  /* inexact */
  assemble("li r1, 1.0\nli r2, 0.1\nadd r3, r1, r2\nhalt\n", &img);
  fp3_engine *e = run_iss(&img, 1, NULL, &st);
  assert_int_equal(st.flags, FP3_FLAG_INEXACT);
  assert_int_equal(reg_of(e, 3), fbits(1.0f + 0.1f));
  fp3_engine_free(e);
  /* overflow */
  assemble("li r1, 3e38\nmul r2, r1, r1\nhalt\n", &img);
  e = run_iss(&img, 1, NULL, &st);
  assert_int_equal(st.flags, FP3_FLAG_OVERFLOW | FP3_FLAG_INEXACT);
  assert_int_equal(reg_of(e, 2), 0x7F800000u);
  fp3_engine_free(e);
  /* invalid: inf - inf gives the default NaN; flags are sticky */
  assemble("li r1, inf\nsub r2, r1, r1\nli r3, 1e-30\nmul r4, r3, r3\nhalt\n", &img);
  e = run_iss(&img, 1, NULL, &st);
  assert_int_equal(reg_of(e, 2), 0xFFC00000u);
  assert_int_equal(st.flags, FP3_FLAG_INVALID | FP3_FLAG_UNDERFLOW | FP3_FLAG_INEXACT);
  fp3_engine_free(e);
}

/* div, sqrt, abs, neg, min, max: bit-exact results and their flags. */
static void test_iss_divsqrt_sign(void **state) {
  (void)state;
  fp3_image img;
  fp3_status st;
  assemble("li r1, 1.0\nli r2, 3.0\nli r3, -0.0\nli r4, 2.25\n"
           "div r5, r1, r2\n"   /* 1/3: inexact */
           "sqrt r6, r4\n"      /* 1.5: exact */
           "sqrt r7, r3\n"      /* sqrt(-0) = -0 */
           "abs r8, r3\n"       /* +0 */
           "neg r9, r2\n"       /* -3 */
           "min r10, r3, r8\n"  /* -0 < +0 */
           "max r11, r8, r3\n"  /* +0 */
           "min r12, r2, r1\n"  /* 1 */
           "halt\n",
           &img);
  fp3_engine *e = run_iss(&img, 1, NULL, &st);
  assert_int_equal(st.error, FP3_ERR_NONE);
  assert_int_equal(reg_of(e, 5), fbits(1.0f / 3.0f));
  assert_int_equal(reg_of(e, 6), fbits(1.5f));
  assert_int_equal(reg_of(e, 7), 0x80000000u);
  assert_int_equal(reg_of(e, 8), 0x00000000u);
  assert_int_equal(reg_of(e, 9), fbits(-3.0f));
  assert_int_equal(reg_of(e, 10), 0x80000000u);
  assert_int_equal(reg_of(e, 11), 0x00000000u);
  assert_int_equal(reg_of(e, 12), fbits(1.0f));
  assert_int_equal(st.flags, FP3_FLAG_INEXACT);
  assert_int_equal(st.unit_issued[FP3_UNIT_DIV], 3);
  assert_int_equal(st.unit_issued[FP3_UNIT_MOV], 4 + 5);
  fp3_engine_free(e);
  /* x/0: divide by zero (INFINITE); sqrt(-1): invalid, the default NaN;
   * min with a signalling NaN: invalid, the NaN quieted; abs of a
   * signalling NaN: quiet, only the sign bit changes */
  assemble("li r1, 1.0\nli r2, 0.0\nli r3, -1.0\nli r4, 0xFF800001\n"
           "div r5, r1, r2\nsqrt r6, r3\nmin r7, r4, r1\nabs r8, r4\nhalt\n", &img);
  e = run_iss(&img, 1, NULL, &st);
  assert_int_equal(reg_of(e, 5), 0x7F800000u);
  assert_int_equal(reg_of(e, 6), 0xFFC00000u);
  assert_int_equal(reg_of(e, 7), 0xFFC00001u);
  assert_int_equal(reg_of(e, 8), 0x7F800001u);
  assert_int_equal(st.flags, FP3_FLAG_INFINITE | FP3_FLAG_INVALID);
  fp3_engine_free(e);
  /* the disassembler prints them back */
  char buf[64];
  fp3_disasm_word(W(FP3_OP_DIV, 1, 2, 3, 0), buf, sizeof buf);
  assert_string_equal(buf, "div r1, r2, r3");
  fp3_disasm_word(W(FP3_OP_SQRT, 4, 5, 0, 0), buf, sizeof buf);
  assert_string_equal(buf, "sqrt r4, r5");
  fp3_disasm_word(W(FP3_OP_MAX, 6, 7, 8, 0), buf, sizeof buf);
  assert_string_equal(buf, "max r6, r7, r8");
}

static void test_iss_endi_loop(void **state) {
  (void)state;
  fp3_image img;
  assemble("    li r1, 1.0\n"
           "    li r2, 0.0\n"
           "b:  add r2, r2, r1\n"
           "    mov r3, r2\n"
           "    endi b\n"
           "    li r4, 9\n", /* after the last endi: never */
           &img);
  for (uint32_t n = 1; n <= 7; n++) {
    fp3_status st;
    capture cap;
    fp3_engine *e = run_iss(&img, n, &cap, &st);
    assert_int_equal(st.error, FP3_ERR_NONE);
    assert_int_equal(st.steps_done, n);
    assert_int_equal(reg_of(e, 2), fbits((float)n));
    assert_int_equal(reg_of(e, 4), 0);
    assert_int_equal(st.cycles, 2 + 3 * n);
    assert_int_equal(cap.nendi, n);
    for (uint32_t k = 0; k < n; k++) {
      assert_int_equal(cap.endi_k[k], k + 1);
      assert_int_equal(cap.endi_cyc[k], 4 + 3 * k); /* index of the endi */
    }
    /* integration tags: prologue writes belong to integration 1 */
    assert_int_equal(cap.n, 2 + 2 * n);
    assert_int_equal(cap.tag[0], 1);
    assert_int_equal(cap.tag[1], 1);
    for (uint32_t k = 0; k < n; k++) {
      assert_int_equal(cap.reg[2 + 2 * k], 2);
      assert_int_equal(cap.tag[2 + 2 * k], k + 1);
      assert_int_equal(cap.val[2 + 2 * k], fbits((float)(k + 1)));
      assert_int_equal(cap.reg[3 + 2 * k], 3);
      assert_int_equal(cap.tag[3 + 2 * k], k + 1);
    }
    fp3_engine_free(e);
  }
}

static void test_iss_halt(void **state) {
  (void)state;
  fp3_image img;
  fp3_status st;
  capture cap;
  /* halt inside the loop body, after two integrations' worth of endi */
  assemble("b: li r1, 1.0\n endi c\nc: endi b2\nb2: halt\n", &img);
  fp3_engine *e = run_iss(&img, 10, &cap, &st);
  assert_int_equal(st.error, FP3_ERR_NONE);
  assert_int_equal(st.done, 1);
  assert_int_equal(st.steps_done, 2);
  assert_int_equal(st.cycles, 4);
  assert_int_equal(cap.nendi, 2);
  fp3_engine_free(e);
  /* the last endi wins over a later halt; a halt first wins */
  assemble("halt\nendi 0\n", &img);
  e = run_iss(&img, 1, &cap, &st);
  assert_int_equal(st.steps_done, 0);
  assert_int_equal(st.cycles, 1);
  fp3_engine_free(e);
}

static void test_iss_errors(void **state) {
  (void)state;
  fp3_image img;
  fp3_status st;
  capture cap;
  /* illegal instruction: unknown opcode at pc 2 */
  assemble("li r1, 1.0\nnop\n.word 0x0F00000000000000\nhalt\n", &img);
  fp3_engine *e = run_iss(&img, 3, &cap, &st);
  assert_int_equal(st.error, FP3_ERR_ILLEGAL_INSN);
  assert_int_equal(st.fault_pc, 2);
  assert_int_equal(st.done, 1);
  assert_int_equal(st.cycles, 2);
  assert_non_null(strstr(fp3_engine_error(e), "pc 2"));
  fp3_engine_free(e);
  /* illegal: register field out of range, inside the loop's 2nd pass */
  assemble("b: nop\n .word 0x0600000000000003\n endi b\n"
           " .word 0x0120010200000000\n", &img);
  e = run_iss(&img, 3, &cap, &st);
  assert_int_equal(st.error, FP3_ERR_ILLEGAL_INSN);
  assert_int_equal(st.fault_pc, 3);
  assert_int_equal(st.steps_done, 1);
  fp3_engine_free(e);
  /* illegal: unused field set */
  assemble("nop\nnop\nnop\n.word 0x0000000000000001\n", &img);
  e = run_iss(&img, 1, &cap, &st);
  assert_int_equal(st.error, FP3_ERR_ILLEGAL_INSN);
  assert_int_equal(st.fault_pc, 3);
  fp3_engine_free(e);
  /* running off the end: zeros are nops up to the last entry */
  assemble("li r1, 2.0\n", &img);
  e = run_iss(&img, 1, &cap, &st);
  assert_int_equal(st.error, FP3_ERR_PC_OVERFLOW);
  assert_int_equal(st.fault_pc, FP3_DEFAULT_IMEM_DEPTH - 1);
  assert_int_equal(st.cycles, FP3_DEFAULT_IMEM_DEPTH);
  assert_int_equal(reg_of(e, 1), fbits(2.0f));
  fp3_engine_free(e);
  /* endi jumping outside the memory: an illegal word (the assembler
   * refuses `endi 300`, so the word is given raw) */
  assemble("nop\n.word 0x060000000000012C\n", &img);
  e = run_iss(&img, 2, &cap, &st);
  assert_int_equal(st.error, FP3_ERR_ILLEGAL_INSN);
  assert_int_equal(st.fault_pc, 1);
  assert_int_equal(st.steps_done, 0);
  fp3_engine_free(e);
  /* STEPS = 0 */
  assemble("b: endi b\n", &img);
  e = run_iss(&img, 0, &cap, &st);
  assert_int_equal(st.error, FP3_ERR_BAD_STEPS);
  assert_int_equal(st.steps_done, 0);
  assert_int_equal(st.cycles, 0);
  assert_int_equal(cap.n + cap.nendi, 0);
  /* the same engine runs again after an error */
  assert_int_equal(fp3_engine_run(e, 5, NULL, &st), 0);
  assert_int_equal(st.error, FP3_ERR_NONE);
  assert_int_equal(st.steps_done, 5);
  fp3_engine_free(e);
}

static void test_iss_host_access(void **state) {
  (void)state;
  fp3_engine *e = fp3_engine_new("iss");
  assert_non_null(e);
  assert_null(fp3_engine_new("bogus"));
  fp3_engine *r = fp3_engine_new("rtl");
  assert_non_null(r);
  assert_string_equal(r->ops->name, "rtl");
  /* the Verilated RTL and the ISS report every write-back; a board on a
   * serial line is named uart:SPEC, and one that cannot be opened is
   * refused with its name */
  assert_int_equal(fp3_engine_untraced(r), 0);
  assert_int_equal(fp3_engine_untraced(e), 0);
  fp3_engine_free(r);
  assert_true(fp3_engine_is_uart("uart:/dev/ttyUSB0@3000000"));
  assert_true(fp3_engine_is_uart("uart:socket://127.0.0.1:1234"));
  assert_false(fp3_engine_is_uart("uart:"));
  assert_false(fp3_engine_is_uart("rtl"));
  char err[512];
  assert_null(fp3_engine_uart_new("/nonexistent/tty", err, sizeof err));
  assert_non_null(strstr(err, "uart:/nonexistent/tty: cannot open"));
  assert_null(fp3_engine_uart_new("/dev/null@1234", err, sizeof err));
  assert_non_null(strstr(err, "1234 baud is not one of the standard rates"));
  assert_null(fp3_engine_uart_new("/dev/null", err, sizeof err));
  assert_non_null(strstr(err, "uart:/dev/null: not a serial line"));
  assert_null(fp3_engine_uart_new("socket://nohostport", err, sizeof err));
  assert_non_null(strstr(err, "give socket://HOST:PORT"));
  assert_null(fp3_engine_new("uart:/nonexistent/tty"));
  assert_int_equal(e->config.num_regs, FP3_DEFAULT_NUM_REGS);
  assert_int_equal(e->config.imem_depth, FP3_DEFAULT_IMEM_DEPTH);
  uint32_t v = 1;
  assert_int_equal(fp3_engine_read_reg(e, 31, &v), 0);
  assert_int_equal(v, 0);
  assert_int_equal(fp3_engine_write_reg(e, 31, 0xDEADBEEFu), 0);
  assert_int_equal(fp3_engine_read_reg(e, 31, &v), 0);
  assert_int_equal(v, 0xDEADBEEFu);
  assert_int_equal(fp3_engine_write_reg(e, 32, 0), -1);
  assert_non_null(strstr(fp3_engine_error(e), "r32"));
  assert_int_equal(fp3_engine_read_reg(e, 99, &v), -1);
  uint64_t words[FP3_DEFAULT_IMEM_DEPTH + 1] = {0};
  assert_int_equal(fp3_engine_load(e, words, FP3_DEFAULT_IMEM_DEPTH + 1), -1);
  assert_non_null(strstr(fp3_engine_error(e), "does not fit"));
  /* a shorter program replaces a longer one completely */
  words[0] = W(FP3_OP_LI, 1, 0, 0, 1);
  words[1] = W(FP3_OP_LI, 2, 0, 0, 2);
  words[2] = W(FP3_OP_HALT, 0, 0, 0, 0);
  assert_int_equal(fp3_engine_load(e, words, 3), 0);
  uint64_t shorter[1] = {W(FP3_OP_LI, 3, 0, 0, 3)};
  assert_int_equal(fp3_engine_load(e, shorter, 1), 0);
  fp3_status st;
  assert_int_equal(fp3_engine_run(e, 1, NULL, &st), 0);
  assert_int_equal(st.error, FP3_ERR_PC_OVERFLOW); /* the halt is gone */
  fp3_engine_free(e);
  fp3_engine_free(NULL);
}

/* ---- golden model against the ISS running programs/ship_rk4.s -------------- */

typedef struct ship_check {
  int reg[2];
  uint32_t cur[2];
  uint32_t next_k[2];
  uint32_t steps;
  uint32_t *v, *s; /* engine values after each integration, [1..steps] */
} ship_check;

static void sc_write(void *ctx, unsigned reg, uint32_t value, uint32_t k) {
  ship_check *c = ctx;
  for (int w = 0; w < 2; w++)
    if ((int)reg == c->reg[w]) {
      assert_true(k >= c->next_k[w]); /* in order */
      while (c->next_k[w] < k && c->next_k[w] <= c->steps) {
        (w ? c->s : c->v)[c->next_k[w]] = c->cur[w];
        c->next_k[w]++;
      }
      c->cur[w] = value;
    }
}

/* models/ship.fp3m, loaded once. */
static const fp3_model *ship_model(void) {
  static fp3_model m;
  static int loaded;
  char msg[256];
  if (!loaded && fp3_model_load("models/ship.fp3m", &m, msg, sizeof msg)) fail_msg("%s", msg);
  loaded = 1;
  return &m;
}

/* The paper's RK4 program (bound by name to the ship model) on the ISS,
 * v and s after every integration against the model's literal rk4se. */
static void run_ship(const fp3_ship_params *p, uint32_t steps, const char *what) {
  const fp3_model *m = ship_model();
  char msg[256];
  fp3_engine *e = fp3_engine_iss_new();
  assert_non_null(e);
  fp3_compile_opts o;
  fp3_compile_opts_for(&o, &e->config);
  fp3_compiled *bound = NULL;
  if (fp3_compile_bind_file(m, SHIP, &o, &bound, msg, sizeof msg)) fail_msg("%s", msg);
  const fp3_image *img = fp3_compiled_image(bound);
  assert_int_equal(fp3_engine_load(e, img->words, img->n), 0);
  const float in[4] = {p->h, p->T, p->C, p->m};
  float y[4] = {p->v0, p->s0, 0, 0};
  unsigned reg[16];
  uint32_t val[16];
  const size_t nw = fp3_compiled_model_start(bound, in, y, reg, val, 16);
  for (size_t w = 0; w < nw; w++) assert_int_equal(fp3_engine_write_reg(e, reg[w], val[w]), 0);
  ship_check c;
  memset(&c, 0, sizeof c);
  c.steps = steps;
  c.v = calloc(steps + 1, sizeof *c.v);
  c.s = calloc(steps + 1, sizeof *c.s);
  assert_non_null(c.v);
  assert_non_null(c.s);
  for (int w = 0; w < 2; w++) {
    c.reg[w] = (int)fp3_compiled_state_reg(bound, (unsigned)w);
    c.next_k[w] = 1;
    c.cur[w] = reg_of(e, (unsigned)c.reg[w]);
  }
  fp3_compiled_free(bound);
  fp3_observer obs = {.ctx = &c, .on_write = sc_write};
  fp3_status st;
  assert_int_equal(fp3_engine_run(e, steps, &obs, &st), 0);
  assert_int_equal(st.error, FP3_ERR_NONE);
  assert_int_equal(st.steps_done, steps);
  sc_write(&c, (unsigned)c.reg[0], 0, steps + 1);
  sc_write(&c, (unsigned)c.reg[1], 0, steps + 1);
  fp3_model_start_literal(m, "rk4se", in, y);
  for (uint32_t k = 1; k <= steps; k++) {
    assert_int_equal(fp3_model_step_literal(m, "rk4se", in, y), 0);
    if (c.v[k] != fbits(y[0]) || c.s[k] != fbits(y[1]))
      fail_msg("%s: integration %u: ISS v=%08x s=%08x, golden v=%08x s=%08x",
               what, k, c.v[k], c.s[k], fbits(y[0]), fbits(y[1]));
  }
  /* cycles: 3 prologue instructions, then the body */
  assert_int_equal(st.cycles, 3 + 31ull * steps);
  free(c.v);
  free(c.s);
  fp3_engine_free(e);
}

static void test_golden_vs_iss(void **state) {
  (void)state;
  fp3_ship_params p;
  fp3_ship_default(&p);
  run_ship(&p, 2000, "default scene");
  p.C = 0.0f; /* no drag: constant acceleration */
  run_ship(&p, 500, "C = 0");
  fp3_ship_default(&p);
  p.m = 3.0e7f; /* a supertanker */
  p.T = 2.0e6f;
  p.C = 1.0e5f;
  run_ship(&p, 500, "large m");
  fp3_ship_default(&p);
  p.m = 0.125f; /* tiny mass: stiff, h near the RK4 stability limit */
  p.C = 20.0f;
  p.h = 0.0125f;
  run_ship(&p, 500, "small m");
  fp3_ship_default(&p);
  p.v0 = 25.0f; /* faster than terminal velocity: decelerating */
  p.s0 = -100.0f;
  p.T = 0.0f;
  run_ship(&p, 500, "coasting");
  fp3_ship_default(&p);
  p.h = 6.0f; /* h = 3 tau > 2.785 tau: RK4 unstable, overflows to inf/NaN */
  run_ship(&p, 300, "unstable h");
  fp3_ship_default(&p);
  p.T = -1.0e-40f; /* subnormal thrust */
  p.C = 1.0e-30f;
  run_ship(&p, 200, "subnormal");
}

static void test_golden_validate(void **state) {
  (void)state;
  fp3_ship_params p;
  char msg[256];
  fp3_ship_default(&p);
  assert_int_equal(fp3_ship_validate(&p, msg, sizeof msg), 0);
  assert_int_equal(p.h, 1.0f / 60.0f);
  p.C = 0.0f;
  assert_int_equal(fp3_ship_validate(&p, msg, sizeof msg), 0);
  static const struct {
    int field;
    float value;
    const char *want;
  } bad[] = {
      {2, 0.0f, "parameter m"},  {2, -1.0f, "parameter m"},
      {3, 0.0f, "parameter h"},  {3, -0.01f, "parameter h"},
      {1, -1.0f, "parameter C"}, {0, NAN, "parameter T"},
      {4, INFINITY, "parameter v0"}, {5, -INFINITY, "parameter s0"},
      {2, NAN, "parameter m"},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    fp3_ship_default(&p);
    float *f[] = {&p.T, &p.C, &p.m, &p.h, &p.v0, &p.s0};
    *f[bad[i].field] = bad[i].value;
    assert_int_equal(fp3_ship_validate(&p, msg, sizeof msg), -1);
    if (!strstr(msg, bad[i].want)) fail_msg("%s: want '%s'", msg, bad[i].want);
  }
  assert_int_equal(fbits(fp3_ship_minv(10000.0f)), fbits(1.0f / 10000.0f));
  assert_int_equal(fbits(fp3_ship_minv(3.0f)), 0x3EAAAAABu);
}

/* The literal rk4se of the ship model at exactly representable numbers
 * without drag: RK4 is exact, v = v0 + a t, and s += h v1. */
static void test_golden_no_drag(void **state) {
  (void)state;
  const fp3_model *m = ship_model();
  const float in[4] = {0.25f, 8.0f, 0.0f, 2.0f}; /* h, T, C, m */
  float y[2] = {1.0f, 0.0f}, s = 0.0f;
  for (int k = 1; k <= 64; k++) {
    assert_int_equal(fp3_model_step_literal(m, "rk4se", in, y), 0);
    float v = 1.0f + 4.0f * 0.25f * (float)k;
    s += 0.25f * v;
    assert_true(y[0] == v);
    assert_true(y[1] == s);
  }
}

/* ---- the ship model's exact solution --------------------------------------------- */

static void ship_exact(double T, double C, double m, double v0, double s0, double t, double *v,
                       double *s) {
  const double in[4] = {1.0 / 60.0, T, C, m}, y0[2] = {v0, s0};
  assert_int_equal(fp3_model_exact(ship_model(), 0, in, y0, t, v), 0);
  assert_int_equal(fp3_model_exact(ship_model(), 1, in, y0, t, s), 0);
}

static void test_analytic_known(void **state) {
  (void)state;
  double v, s;
  /* default scene at t = tau = 2 s: v = 10 (1 - 1/e), s = 20 - 20 (1 - 1/e) */
  ship_exact(50000, 5000, 10000, 0, 0, 2.0, &v, &s);
  assert_true(fabs(v - 10.0 * (1.0 - exp(-1.0))) < 1e-14);
  assert_true(fabs(s - 20.0 * exp(-1.0)) < 1e-13);
  /* t = 0 */
  ship_exact(50000, 5000, 10000, 3, 7, 0.0, &v, &s);
  assert_true(v == 3.0 && s == 7.0);
  /* against the closed form of DESIGN.md (x = 0.3, 3) */
  for (int i = 0; i < 2; i++) {
    double T = 500, C = 0.1 * (i ? 10 : 1), m = 1, v0 = 2, s0 = -1;
    double t = 3.0, tau = m / C, vinf = T / C;
    double ve = vinf + (v0 - vinf) * exp(-t / tau);
    double se = s0 + vinf * t + (v0 - vinf) * tau * (1 - exp(-t / tau));
    ship_exact(T, C, m, v0, s0, t, &v, &s);
    assert_true(fabs(v - ve) <= 1e-12 * fabs(ve));
    assert_true(fabs(s - se) <= 1e-9 * fabs(se));
  }
  /* long after: terminal velocity */
  ship_exact(50000, 5000, 10000, 0, 0, 200.0, &v, &s);
  assert_true(fabs(v - 10.0) < 1e-12);
  assert_true(fabs(s - (2000.0 - 20.0)) < 1e-9);
}

/* Max |error| of the literal rk4se's v and s against the exact solution. */
static void golden_error(const fp3_ship_params *p, double t_end, double *ev, double *es) {
  const fp3_model *m = ship_model();
  const float in[4] = {p->h, p->T, p->C, p->m};
  float y[2] = {p->v0, p->s0};
  uint32_t n = (uint32_t)lround(t_end / (double)p->h);
  *ev = *es = 0;
  for (uint32_t k = 1; k <= n; k++) {
    assert_int_equal(fp3_model_step_literal(m, "rk4se", in, y), 0);
    double v, s;
    ship_exact(p->T, p->C, p->m, p->v0, p->s0, (double)k * (double)p->h, &v, &s);
    if (fabs((double)y[0] - v) > *ev) *ev = fabs((double)y[0] - v);
    if (fabs((double)y[1] - s) > *es) *es = fabs((double)y[1] - s);
  }
}

static void test_analytic_vs_golden(void **state) {
  (void)state;
  fp3_ship_params p;
  fp3_ship_default(&p);
  double ev, es;
  /* h = 1/60: RK4's truncation error is far below binary32 rounding, so v
   * is within a few ulp per step of 10 m/s; s = s + h v1 is first order */
  golden_error(&p, 10.0, &ev, &es);
  assert_true(ev < 2e-5);
  assert_true(es < 0.5 * 10.0 * (double)p.h * 1.1);
  /* the s error is O(h): halving h halves it */
  double ev2, es2;
  p.h = 1.0f / 120.0f;
  golden_error(&p, 10.0, &ev2, &es2);
  assert_true(es2 < 0.6 * es && es2 > 0.4 * es);
  /* v is O(h^4): with h = 0.5 s (tau / 4) the error is visible and
   * shrinks about 16 times when h halves */
  p.h = 0.5f;
  golden_error(&p, 20.0, &ev, &es);
  p.h = 0.25f;
  golden_error(&p, 20.0, &ev2, &es2);
  assert_true(ev > 1e-4);
  assert_true(ev2 < ev / 10 && ev2 > ev / 24);
}

/* ---- the progress line (progress.h) ----------------------------------------- */

static void test_progress_format(void **state) {
  (void)state;
  char b[256];
  /* 123,456 of 10^7 in 3.0864 s: 40,000/s, 246.9 s left */
  size_t len = fp3_progress_format(b, sizeof b, "fp3 run", 123456, 10000000, "integrations",
                                   3.0864);
  assert_string_equal(b, "fp3 run: 123,456 of 10,000,000 integrations (1.2 %), 40,000/s, "
                         "about 4 min left");
  assert_int_equal(len, strlen(b));
  fp3_progress_format(b, sizeof b, "fp3 run", 4294967295u, 4294967295u, "integrations", 1.0);
  assert_string_equal(b, "fp3 run: 4,294,967,295 of 4,294,967,295 integrations (100.0 %), "
                         "4,294,967,295/s");
  /* the percentage rounds down: 100.0 only at the end */
  fp3_progress_format(b, sizeof b, "x", 9999, 10000, "frames", 1.0);
  assert_string_equal(b, "x: 9,999 of 10,000 frames (99.9 %), 9,999/s, about 1 s left");
  /* nothing done yet: no rate, no time left */
  fp3_progress_format(b, sizeof b, "fp3 frames", 0, 600, "frames", 2.5);
  assert_string_equal(b, "fp3 frames: 0 of 600 frames (0.0 %)");
  /* slow rates in three digits; seconds, minutes, hours, days */
  fp3_progress_format(b, sizeof b, "x", 10, 100, "frames", 4.0);
  assert_string_equal(b, "x: 10 of 100 frames (10.0 %), 2.5/s, about 36 s left");
  fp3_progress_format(b, sizeof b, "x", 1000, 1000 + 5400 * 1000, "steps", 1.0);
  assert_string_equal(b, "x: 1,000 of 5,401,000 steps (0.0 %), 1,000/s, about 1.5 h left");
  fp3_progress_format(b, sizeof b, "x", 1000, 1000 + 3 * 86400 * 1000ull, "steps", 1.0);
  assert_string_equal(b, "x: 1,000 of 259,201,000 steps (0.0 %), 1,000/s, about 3.0 days left");
  /* total unknown: count and rate */
  fp3_progress_format(b, sizeof b, "x", 999, 0, "steps", 1.0);
  assert_string_equal(b, "x: 999 steps, 999/s");
  /* a short buffer: cut, terminated */
  len = fp3_progress_format(b, 12, "fp3 run", 123456, 10000000, "integrations", 1.0);
  assert_string_equal(b, "fp3 run: 12");
  assert_int_equal(len, 11);
}

/* A fake clock: each read returns *t, then advances it by step seconds. */
typedef struct fake_clock {
  double t, step;
  unsigned reads;
} fake_clock;

static double fake_read(void *ctx) {
  fake_clock *c = ctx;
  double now = c->t;
  c->t += c->step;
  c->reads++;
  return now;
}

/* Lines drawn in an output text: the '\r'-separated pieces that are not
 * blank (the erase is '\r', spaces, '\r'). */
static unsigned drawn_lines(const char *text) {
  unsigned k = 0;
  for (const char *p = text; *p;) {
    const char *q = strchr(p, '\r');
    size_t len = q ? (size_t)(q - p) : strlen(p);
    int blank = 1;
    for (size_t i = 0; i < len; i++) blank &= p[i] == ' ';
    k += !blank && len > 0;
    p += len + (q != NULL);
  }
  return k;
}

static void test_progress_throttle(void **state) {
  (void)state;
  char *text = NULL;
  size_t size = 0;
  FILE *f = open_memstream(&text, &size);
  assert_non_null(f);
  /* a clock read every 1/16 s of run: the stride stays 1 */
  fake_clock c = {100.0, 0.0625, 0};
  fp3_progress p;
  fp3_progress_start_on(&p, f, "fp3 run", 1000, "integrations", 0, fake_read, &c);
  for (uint64_t k = 1; k <= 31; k++) fp3_progress_update(&p, k);
  fflush(f);
  assert_int_equal(size, 0); /* under FP3_PROGRESS_DELAY: nothing */
  fp3_progress_update(&p, 32);
  fflush(f);
  assert_true(size > 0); /* 2 s: the first line */
  assert_int_equal(text[0], '\r');
  assert_int_equal(text[size - 1], '\r');
  assert_string_equal(text, "\rfp3 run: 32 of 1,000 integrations (3.2 %), 16/s, about 1 min "
                            "left\r");
  /* then one line every FP3_PROGRESS_PERIOD (4 reads of 1/16 s) */
  for (uint64_t k = 33; k <= 140; k++) fp3_progress_update(&p, k);
  fflush(f);
  assert_int_equal(drawn_lines(text), 28);
  assert_non_null(strstr(text, "\rfp3 run: 36 of 1,000"));
  assert_null(strstr(text, "\rfp3 run: 37 of 1,000"));
  assert_non_null(strstr(text, "\rfp3 run: 140 of 1,000 integrations (14.0 %), 16/s, about 54 s "
                               "left\r"));
  /* a shorter line is padded over the longer one before it */
  fp3_progress_update(&p, 1000);
  for (int i = 0; i < 5; i++) fp3_progress_update(&p, 1000);
  fflush(f);
  size_t before = size;
  fp3_progress_finish(&p);
  fflush(f);
  /* finish erases the line: '\r', as many spaces as it had, '\r' */
  const char *erase = text + before;
  assert_non_null(strstr(text, "\rfp3 run: 1,000 of 1,000 integrations (100.0 %), 111/s"
                               "             \r")); /* 13 spaces over the longer line */
  size_t last = strlen("fp3 run: 1,000 of 1,000 integrations (100.0 %), 111/s");
  assert_true(size - before == last + 2);
  assert_int_equal(erase[0], '\r');
  for (size_t i = 1; i <= last; i++) assert_int_equal(erase[i], ' ');
  assert_int_equal(erase[last + 1], '\r');
  fp3_progress_finish(&p); /* twice: nothing more */
  fp3_progress_update(&p, 5);
  fflush(f);
  assert_int_equal(size, before + last + 2);
  fclose(f);
  free(text);

  /* a fast caller: the clock is read far less often than every update */
  f = open_memstream(&text, &size);
  fake_clock fast = {0.0, 1e-4, 0};
  fp3_progress_start_on(&p, f, "x", 0, "steps", 0, fake_read, &fast);
  for (uint64_t k = 1; k <= 10000000; k++) fp3_progress_update(&p, k);
  fp3_progress_finish(&p);
  fclose(f);
  assert_true(fast.reads < 200);
  assert_int_equal(size, 0); /* never 2 s of run: nothing shown */
  free(text);

  /* a line wider than the terminal is cut to its width */
  f = open_memstream(&text, &size);
  fake_clock slow = {0.0, 3.0, 0};
  fp3_progress_start_on(&p, f, "fp3 run", 1000, "integrations", 20, fake_read, &slow);
  fp3_progress_update(&p, 10);
  fflush(f);
  assert_int_equal(size, 22);
  assert_memory_equal(text, "\rfp3 run: 10 of 1,000\r", 22);
  fp3_progress_finish(&p);
  fclose(f);
  free(text);

  /* off: no stream, no label, or not asked for */
  fp3_progress_start_on(&p, NULL, "x", 10, "steps", 0, fake_read, &slow);
  assert_null(p.out);
  fp3_progress_start_on(&p, stderr, NULL, 10, "steps", 0, fake_read, &slow);
  assert_null(p.out);
  fp3_progress_start(&p, "x", 10, "steps", 0);
  assert_null(p.out);
  fp3_progress_start(&p, "x", 10, "steps", 1);
  if (!isatty(fileno(stderr))) assert_null(p.out); /* not a terminal: off */
  fp3_progress_finish(&p);
}

/* An engine run reports its integrations to the observer's progress line. */
static void test_progress_engine_run(void **state) {
  (void)state;
  fp3_image img;
  assemble("    li r1, 1.0\n"
           "b:  add r2, r2, r1\n"
           "    endi b\n", &img);
  fp3_engine *e = fp3_engine_iss_new();
  assert_non_null(e);
  assert_int_equal(fp3_engine_load(e, img.words, img.n), 0);
  char *text = NULL;
  size_t size = 0;
  FILE *f = open_memstream(&text, &size);
  fake_clock c = {0.0, 0.0625, 0};
  fp3_progress p;
  fp3_progress_start_on(&p, f, "fp3 run", 1000, "integrations", 0, fake_read, &c);
  fp3_observer obs = {.progress = &p};
  fp3_status st;
  assert_int_equal(fp3_engine_run(e, 1000, &obs, &st), 0);
  assert_int_equal(st.steps_done, 1000);
  fflush(f);
  assert_non_null(strstr(text, "\rfp3 run: 40 of 1,000 integrations (4.0 %)"));
  assert_non_null(strstr(text, "\rfp3 run: 996 of 1,000 integrations (99.6 %)"));
  assert_non_null(strstr(text, "\rfp3 run: 1,000 of 1,000 integrations (100.0 %)"));
  fp3_progress_finish(&p);
  fclose(f);
  free(text);
  /* the engine's own line: off unless stderr is a terminal */
  fp3_engine_show_progress(e, "fp3 run");
  assert_int_equal(fp3_engine_run(e, 10, NULL, &st), 0);
  assert_int_equal(st.steps_done, 10);
  fp3_engine_free(e);
}

int main(void) {
  const struct CMUnitTest tests[] = {
      cmocka_unit_test(test_asm_instructions),
      cmocka_unit_test(test_asm_labels),
      cmocka_unit_test(test_asm_bindings),
      cmocka_unit_test(test_asm_literals),
      cmocka_unit_test(test_asm_errors),
      cmocka_unit_test(test_asm_too_large),
      cmocka_unit_test(test_asm_file),
      cmocka_unit_test(test_asm_include),
      cmocka_unit_test(test_disasm_roundtrip),
      cmocka_unit_test(test_disasm_word),
      cmocka_unit_test(test_insn_check),
      cmocka_unit_test(test_image_validate),
      cmocka_unit_test(test_hex_roundtrip),
      cmocka_unit_test(test_hex_read_errors),
      cmocka_unit_test(test_hex_write_fails_cleanly),
      cmocka_unit_test(test_iss_opcodes),
      cmocka_unit_test(test_iss_flags),
      cmocka_unit_test(test_iss_divsqrt_sign),
      cmocka_unit_test(test_iss_endi_loop),
      cmocka_unit_test(test_iss_halt),
      cmocka_unit_test(test_iss_errors),
      cmocka_unit_test(test_iss_host_access),
      cmocka_unit_test(test_golden_vs_iss),
      cmocka_unit_test(test_golden_validate),
      cmocka_unit_test(test_golden_no_drag),
      cmocka_unit_test(test_analytic_known),
      cmocka_unit_test(test_analytic_vs_golden),
      cmocka_unit_test(test_progress_format),
      cmocka_unit_test(test_progress_throttle),
      cmocka_unit_test(test_progress_engine_run),
  };
  return cmocka_run_group_tests(tests, make_tmpdir, remove_tmpdir);
}
