/*
 * disasm.c -- FP3 disassembler (see disasm.h).
 */
#include "disasm.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "asm.h"
#include "report.h"

/* An li operand that reads back (fp3_asm_literal) to exactly `bits`. */
static void format_imm(uint32_t bits, char *buf, size_t n) {
  float f;
  memcpy(&f, &bits, sizeof f);
  snprintf(buf, n, "%.9g", (double)f);
  uint32_t back;
  char why[8];
  if (fp3_asm_literal(buf, &back, why, sizeof why) != 0 || back != bits)
    snprintf(buf, n, "0x%08X", (unsigned)bits);
}

int fp3_disasm_word(uint64_t w, char *buf, size_t n) {
  char why[8];
  if (fp3_insn_check(w, FP3_DEFAULT_NUM_REGS, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why))
    return snprintf(buf, n, ".word 0x%016llX", (unsigned long long)w);
  unsigned opc = fp3_insn_opc(w);
  const char *mn = fp3_opc_mnemonic(opc);
  unsigned rd = fp3_insn_rd(w), ra = fp3_insn_ra(w), rb = fp3_insn_rb(w);
  uint32_t imm = fp3_insn_imm(w);
  char lit[32];
  switch ((enum fp3_opcode)opc) {
  case FP3_OP_ADD:
  case FP3_OP_SUB:
  case FP3_OP_MUL:
  case FP3_OP_DIV:
  case FP3_OP_MIN:
  case FP3_OP_MAX:
    return snprintf(buf, n, "%s r%u, r%u, r%u", mn, rd, ra, rb);
  case FP3_OP_LI:
    format_imm(imm, lit, sizeof lit);
    return snprintf(buf, n, "%s r%u, %s", mn, rd, lit);
  case FP3_OP_MOV:
  case FP3_OP_SQRT:
  case FP3_OP_ABS:
  case FP3_OP_NEG:
    return snprintf(buf, n, "%s r%u, r%u", mn, rd, ra);
  case FP3_OP_ENDI:
    return snprintf(buf, n, "%s %lu", mn, (unsigned long)imm);
  case FP3_OP_BEQ:
    return snprintf(buf, n, "%s r%u, r%u, %lu", mn, ra, rb, (unsigned long)imm);
  case FP3_OP_NOP:
  case FP3_OP_HALT:
    break;
  }
  return snprintf(buf, n, "%s", mn);
}

/* endi and beq instructions (legal ones) targeting `addr`, addr <= n */
static int is_target(const fp3_image *img, size_t addr) {
  char why[8];
  for (size_t i = 0; i < img->n; i++) {
    uint64_t w = img->words[i];
    if (fp3_opc_has_target(fp3_insn_opc(w)) &&
        fp3_insn_check(w, FP3_DEFAULT_NUM_REGS, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why) == 0 &&
        fp3_insn_imm(w) == addr)
      return 1;
  }
  return 0;
}

char *fp3_disasm_image(const fp3_image *img) {
  fp3_strbuf b = {NULL, 0, 0, 0};
  fp3_strbuf_printf(&b, "; FP3 program, %zu words (disassembled)\n", img->n);
  for (unsigned i = 0; i < img->nbind_in; i++)
    fp3_strbuf_printf(&b, ".in %s, r%d\n", img->bind_in[i].name, img->bind_in[i].reg);
  for (unsigned i = 0; i < img->nbind_out; i++)
    fp3_strbuf_printf(&b, ".out %s, r%d\n", img->bind_out[i].name, img->bind_out[i].reg);
  char text[96], why[8];
  for (size_t i = 0; i <= img->n; i++) {
    if (is_target(img, i)) fp3_strbuf_printf(&b, "L%zu:\n", i);
    if (i == img->n) break;
    uint64_t w = img->words[i];
    int legal = fp3_insn_check(w, FP3_DEFAULT_NUM_REGS, FP3_DEFAULT_IMEM_DEPTH, why, sizeof why) == 0;
    if (legal && fp3_insn_opc(w) == FP3_OP_ENDI && fp3_insn_imm(w) <= img->n)
      snprintf(text, sizeof text, "endi L%lu", (unsigned long)fp3_insn_imm(w));
    else if (legal && fp3_insn_opc(w) == FP3_OP_BEQ && fp3_insn_imm(w) <= img->n)
      snprintf(text, sizeof text, "beq r%u, r%u, L%lu", fp3_insn_ra(w), fp3_insn_rb(w),
               (unsigned long)fp3_insn_imm(w));
    else
      fp3_disasm_word(w, text, sizeof text);
    fp3_strbuf_printf(&b, "    %-28s ; [%3zu] %016llx", text, i, (unsigned long long)w);
    if (legal && fp3_insn_opc(w) == FP3_OP_LI)
      fp3_strbuf_printf(&b, "  imm 0x%08X", (unsigned)fp3_insn_imm(w));
    if (img->line[i] > 0) fp3_strbuf_printf(&b, "  (line %d)", img->line[i]);
    fp3_strbuf_printf(&b, "\n");
  }
  if (b.oom) {
    free(b.s);
    return NULL;
  }
  return b.s;
}
