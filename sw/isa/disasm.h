/*
 * disasm.h -- program image to assembly text that re-assembles to the
 * same words and bindings.
 */
#ifndef FP3_DISASM_H
#define FP3_DISASM_H

#include <stddef.h>
#include <stdint.h>

#include "image.h"

/* One word as an instruction, without labels: "add r1, r2, r3",
 * "li r7, 0.5", "endi 3", or ".word 0x..." for an illegal word.  The float
 * of li is printed with %.9g (the shortest form that reads back to the
 * same bits; the hex pattern when no decimal form does, e.g. NaN
 * payloads).  Returns the length snprintf would have written. */
int fp3_disasm_word(uint64_t w, char *buf, size_t n);

/* The whole image: a header comment, the .in/.out bindings, a label
 * "L<addr>:" at every endi target inside the program, one instruction per
 * line with "; [addr] 0xWORD" comments and the bit pattern of li
 * immediates.  Returns a malloc'd string (NULL when out of memory). */
char *fp3_disasm_image(const fp3_image *img);

#endif /* FP3_DISASM_H */
