/*
 * asm.h -- the FP3 assembler: assembly text (.s) to a program image.
 *
 * Syntax, one statement per line; `;` and `#` start a comment:
 *
 *   name:                      label (address of the next instruction)
 *   add rd, ra, rb             also sub, mul
 *   li rd, IMM                 IMM: float literal rounded to binary32 by
 *                              strtof (0.5, -2.5e3, inf, nan) or a bit
 *                              pattern 0x3E2AAAAB (at most 8 hex digits)
 *   mov rd, ra
 *   endi LABEL                 imm = address of LABEL (or a number)
 *   beq ra, rb, LABEL          LABEL must lie ahead of the beq
 *   halt / nop
 *   .reg NAME rN               register alias (`.reg NAME, rN` too)
 *   .in NAME, rN               the host writes NAME into rN before the
 *                              run: a param of the program's model, a
 *                              state variable's initial value (NAME or
 *                              NAME0), a parameter-only let (minv), or
 *                              -NAME, the same with its sign bit flipped
 *                              (fp3_compile_bind resolves the names)
 *   .out NAME, rN              rN holds state variable NAME after every
 *                              integration
 *   .model "FILE"              the model the program integrates (a
 *                              relative FILE is found beside the program)
 *   .integrator NAME           the model integrator whose literal golden
 *                              model the program computes, operation for
 *                              operation (fp3_model_step_literal)
 *   .regs N                    the program is for a build with NUM_REGS >= N
 *                              (2 .. 256): registers r0 .. r(N-1); before the
 *                              first register named.  Engines check each
 *                              register against their own NUM_REGS
 *   .word 0xHHHHHHHHHHHHHHHH   a raw 64-bit word, not checked (tests)
 *   .include "FILE"            FILE's lines in place (a relative FILE is
 *                              found beside the including file; at most 8
 *                              deep and 64 in all); errors name FILE:LINE.  An image's
 *                              line numbers are the top file's: a word
 *                              from an included file has the line of the
 *                              .include
 *
 * Registers are r0 .. r31 (the default NUM_REGS; after .regs N, r0 ..
 * r(N-1)) or aliases; mnemonics and directives are case
 * insensitive, labels and aliases are not.
 */
#ifndef FP3_ASM_H
#define FP3_ASM_H

#include "image.h"

/* Assemble text `src`; `fname` names it in messages ("prog.s:12: ...").
 * Every error is collected; on failure *errors (if errors != NULL) gets a
 * malloc'd string, one "FILE:LINE: reason" per line, which the caller
 * frees.  Returns 0 on success, else the number of errors (> 0). */
int fp3_asm_string(const char *src, const char *fname, fp3_image *img,
                   char **errors);

/* Same for a file (a read error is reported as "FILE: reason"). */
int fp3_asm_file(const char *path, fp3_image *img, char **errors);

/* Parse an IMM literal as `li` does: 0 and the bit pattern, or -1 with a
 * reason in why[0..n). */
int fp3_asm_literal(const char *text, uint32_t *bits, char *why, size_t n);

#endif /* FP3_ASM_H */
