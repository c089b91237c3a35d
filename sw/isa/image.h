/*
 * image.h -- an FP3 program image: instruction words plus the host
 * bindings of the program by name (which register receives which of the
 * model's params or initial values before a run, which register holds
 * which state variable), validation of a word
 * against the ISA table, and the .hex image file.
 *
 * The .hex file is text that Verilog's $readmemh reads: one 64-bit word
 * per line as 16 hex digits, `//` comments.  The bindings travel in
 * comment lines that $readmemh ignores and fp3_image_read() recovers:
 *
 *   // .in T r1
 *   // .out v r5
 *   0401000000000000  // @0 line 12
 *
 * The trailing `// @ADDR line N` records the source line of the word.
 */
#ifndef FP3_IMAGE_H
#define FP3_IMAGE_H

#include <stddef.h>
#include <stdint.h>

#include "fp3_isa.h"

/* Bindings by name (`.in NAME, rN` / `.out NAME, rN`), in program order.
 * A name is an identifier, an `.in` name may carry a leading '-' (the
 * value with its sign bit flipped).  The model binder
 * (fp3_compile_bind, compile.h) resolves them against a model: a param,
 * a state variable (or NAME0, its initial value), a parameter-only let. */
#define FP3_MAX_BINDINGS 64
#define FP3_BIND_NAME_LEN 32
typedef struct fp3_binding {
  char name[FP3_BIND_NAME_LEN];
  int reg;
  int line; /* source line, 0: unknown (read from an image file) */
} fp3_binding;

/* A program image: its words and its bindings by name. */
typedef struct fp3_image {
  uint64_t words[FP3_DEFAULT_IMEM_DEPTH];
  int line[FP3_DEFAULT_IMEM_DEPTH]; /* source line of each word, 0: unknown */
  size_t n;                         /* words used                          */
  fp3_binding bind_in[FP3_MAX_BINDINGS], bind_out[FP3_MAX_BINDINGS];
  unsigned nbind_in, nbind_out;
  char model[256];     /* `.model "FILE"`: the model the program integrates
                          (a path as the program's reader opens it), or "" */
  char integrator[32]; /* `.integrator NAME`: the model integrator whose
                          literal golden model the program computes, or "" */
} fp3_image;

/* 1 if name is a binding's name: an identifier ([A-Za-z_][A-Za-z0-9_]*),
 * an input's (is_in) also with a leading '-'; else 0. */
int fp3_image_binding_name_ok(int is_in, const char *name);

/* Record binding `name` -> reg (is_in: an input, else a result).  0, or -1 with the reason in why: a name that is none
 * (fp3_image_binding_name_ok), a name given twice, a register bound twice
 * on the same side, more than FP3_MAX_BINDINGS. */
int fp3_image_bind(fp3_image *img, int is_in, const char *name, int reg, int line,
                   char *why, size_t n);

/* An empty image: no words, nothing bound. */
void fp3_image_init(fp3_image *img);

/* Whether the program can end: 1 if one of its n words is an endi or a
 * halt, else 0 (an empty image, or one whose PC can only run off the end
 * of the instruction memory, a fault: fp3_scheduler.v).  A program the
 * CLI assembles must pass (fp3 asm, fp3 run). */
int fp3_image_ends(const fp3_image *img);

/* Instruction word fields. */
static inline unsigned fp3_insn_opc(uint64_t w) {
  return (unsigned)(w >> FP3_OPC_LSB) & ((1u << FP3_OPC_WIDTH) - 1u);
}
static inline unsigned fp3_insn_rd(uint64_t w) {
  return (unsigned)(w >> FP3_RD_LSB) & ((1u << FP3_REG_WIDTH) - 1u);
}
static inline unsigned fp3_insn_ra(uint64_t w) {
  return (unsigned)(w >> FP3_RA_LSB) & ((1u << FP3_REG_WIDTH) - 1u);
}
static inline unsigned fp3_insn_rb(uint64_t w) {
  return (unsigned)(w >> FP3_RB_LSB) & ((1u << FP3_REG_WIDTH) - 1u);
}
static inline uint32_t fp3_insn_imm(uint64_t w) {
  return (uint32_t)(w >> FP3_IMM_LSB);
}
/* Pack a word (unused fields must be passed as 0). */
uint64_t fp3_insn_make(unsigned opc, unsigned rd, unsigned ra, unsigned rb,
                       uint32_t imm);

/* ISA table lookups: fields used (FP3_USES_*) or -1 for an unknown opcode;
 * mnemonic or NULL; opcode of a mnemonic or -1. */
int fp3_opc_uses(unsigned opc);
/* Execution unit of an opcode (FP3_UNIT_*; NONE for an unknown one). */
unsigned fp3_opc_unit(unsigned opc);
const char *fp3_opc_mnemonic(unsigned opc);
int fp3_opc_lookup(const char *mnemonic);

/* Check one word against the ISA table, a register count and an
 * instruction memory depth (pass FP3_DEFAULT_NUM_REGS and
 * FP3_DEFAULT_IMEM_DEPTH for the default build): the same rules as the
 * RTL decoder (rtl/fp3_scheduler.v), including an endi target inside the
 * memory.  Returns 0 if legal, -1 if not, with the reason ("unknown opcode
 * 0x09", "rb field 3 set but unused by add", "rd r40 >= 32 registers") in
 * reason[0..n). */
int fp3_insn_check(uint64_t w, unsigned num_regs, unsigned imem_depth,
                   char *reason, size_t n);
/* fp3_insn_check for the word at address pc, with the one rule that
 * depends on where a word sits: a beq must branch ahead (imm > pc). */
int fp3_insn_check_at(uint64_t w, uint32_t pc, unsigned num_regs, unsigned imem_depth,
                      char *reason, size_t n);
/* 1 if opcode opc's imm is an instruction address (endi, beq), else 0. */
int fp3_opc_has_target(unsigned opc);

/* Check every word of an image and the bindings.  Returns 0 or -1 with
 * "word 5: unknown opcode 0x09" in msg. */
int fp3_image_validate(const fp3_image *img, char *msg, size_t n);

/* Write the image as .hex, atomically (FILE.tmp, then rename): on any
 * error no output file (and no FILE.tmp) remains.  source: name shown in
 * the header comment (may be NULL).  Returns 0 or -1 with a message. */
int fp3_image_write(const fp3_image *img, const char *path,
                    const char *source, char *msg, size_t n);

/* Read a .hex file into img.  Words are not validated (see
 * fp3_image_validate).  Returns 0 or -1 with "FILE:LINE: reason". */
int fp3_image_read(const char *path, fp3_image *img, char *msg, size_t n);

#endif /* FP3_IMAGE_H */
