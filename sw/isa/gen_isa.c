/*
 * gen_isa.c -- print rtl/fp3_isa.vh, the Verilog view of sw/isa/fp3_isa.h, or
 * (with --markdown) the instruction and host-port tables of docs/isa.md.
 *
 * Usage: gen_isa > rtl/fp3_isa.vh
 *        gen_isa --markdown
 * The committed header must equal this program's output and docs/isa.md
 * must contain the tables verbatim; tests/test_isa_sync.sh checks both.
 */
#include <stdio.h>
#include <string.h>

#include "fp3_isa.h"

static const char *unit_name(int unit) {
  switch (unit) {
    case FP3_UNIT_ADD: return "add";
    case FP3_UNIT_MUL: return "mul";
    case FP3_UNIT_MOV: return "move";
    case FP3_UNIT_DIV: return "div/sqrt";
    default: return "—";
  }
}

/* Assembly operands from the fields an opcode uses. */
static void operands(int uses, char *out, size_t n) {
  out[0] = '\0';
  const char *sep = " ";
  if (uses & FP3_USES_RD) { strncat(out, " rd", n - strlen(out) - 1); sep = ", "; }
  if (uses & FP3_USES_RA) { strncat(out, sep, n - strlen(out) - 1); strncat(out, "ra", n - strlen(out) - 1); sep = ", "; }
  if (uses & FP3_USES_RB) { strncat(out, sep, n - strlen(out) - 1); strncat(out, "rb", n - strlen(out) - 1); sep = ", "; }
  if (uses & FP3_USES_IMM) { strncat(out, sep, n - strlen(out) - 1); strncat(out, "imm", n - strlen(out) - 1); }
}

static void markdown(void) {
  char ops[32];
  printf("| opcode | assembly | unit | meaning |\n| --- | --- | --- | --- |\n");
#define X(name, code, mnem, uses, unit, desc)                                  \
  operands(uses, ops, sizeof ops);                                             \
  printf("| 0x%02X | `%s%s` | %s | %s |\n", code, mnem, ops, unit_name(unit), desc);
  FP3_OPCODES(X)
#undef X
  printf("\n| word address | name | access | meaning |\n| --- | --- | --- | --- |\n");
#define X(name, addr, acc, desc) printf("| 0x%03X | `%s` | %s | %s |\n", addr, #name, acc, desc);
  FP3_HOSTREGS(X)
#undef X
}

int main(int argc, char **argv) {
  if (argc > 1 && strcmp(argv[1], "--markdown") == 0) {
    markdown();
    return 0;
  }
  printf("// fp3_isa.vh -- GENERATED from sw/isa/fp3_isa.h by sw/isa/gen_isa.c; do not edit.\n");
  printf("// The instruction set, flag bits, error codes and host-port map of FP3,\n");
  printf("// shared by the RTL and the C host.  `include inside a module body.\n");
  printf("// Each module uses a few of these constants, never all of them, so the\n");
  printf("// unused-parameter lint is waived for this header only.\n");
  printf("/* verilator lint_off UNUSEDPARAM */\n\n");

  printf("// Instruction word fields: [msb:lsb]\n");
  printf("localparam integer ISA_INSN_BITS = %d;\n", FP3_INSN_BITS);
  printf("localparam integer ISA_OPC_LSB   = %d;\n", FP3_OPC_LSB);
  printf("localparam integer ISA_RD_LSB    = %d;\n", FP3_RD_LSB);
  printf("localparam integer ISA_RA_LSB    = %d;\n", FP3_RA_LSB);
  printf("localparam integer ISA_RB_LSB    = %d;\n", FP3_RB_LSB);
  printf("localparam integer ISA_OPC_WIDTH = %d;\n", FP3_OPC_WIDTH);
  printf("localparam integer ISA_REG_WIDTH = %d;\n", FP3_REG_WIDTH);
  printf("localparam integer ISA_IMM_WIDTH = %d;\n\n", FP3_IMM_WIDTH);

  printf("// Opcodes and the operand fields each one uses\n");
  printf("// (bit 0 rd, bit 1 ra, bit 2 rb, bit 3 imm; unused fields must be 0).\n");
  printf("// Unit: 0 none, 1 add/sub core, 2 mul core, 3 move path (and sign group),\n");
  printf("// 4 div/sqrt unit.\n");
#define X(name, code, mnem, uses, unit, desc)                                  \
  printf("localparam [7:0] OP_%-4s = 8'h%02X; localparam [3:0] OPUSES_%-4s = " \
         "4'h%X; localparam [2:0] OPUNIT_%-4s = 3'd%d; // %s: %s\n",           \
         #name, code, #name, uses, #name, unit, mnem, desc);
  FP3_OPCODES(X)
#undef X
  printf("\n// Decode an opcode: {known, unit[2:0], uses[3:0]}; 0 for an unknown one.\n");
  printf("function [7:0] isa_decode;\n  input [7:0] opc;\n  begin\n    case (opc)\n");
#define X(name, code, mnem, uses, unit, desc)                                  \
  printf("      OP_%-4s: isa_decode = {1'b1, OPUNIT_%-4s, OPUSES_%-4s};\n",    \
         #name, #name, #name);
  FP3_OPCODES(X)
#undef X
  printf("      default: isa_decode = 8'd0;\n    endcase\n  end\nendfunction\n");
  /* The issue path's unit field (scheduler, tag lines, trace port,
   * arith): the decode's 3-bit unit, as it is. */
  printf("localparam [2:0] UNIT_NONE = 3'd%d, UNIT_ADD = 3'd%d, UNIT_MUL = 3'd%d, "
         "UNIT_MOV = 3'd%d, UNIT_DIV = 3'd%d;\n\n",
         FP3_UNIT_NONE, FP3_UNIT_ADD, FP3_UNIT_MUL, FP3_UNIT_MOV, FP3_UNIT_DIV);

  printf("// Build configuration defaults\n");
#define X(name, def) printf("localparam integer DEFAULT_%s = %d;\n", #name, def);
  FP3_CONFIG(X)
#undef X
  printf("localparam integer MAX_CONTEXTS = %d, MAX_LANES = %d;\n", FP3_MAX_CONTEXTS,
         FP3_MAX_LANES);

  printf("\n// Exception flags (Berkeley SoftFloat bit order)\n");
#define X(name, bit) printf("localparam [4:0] FLAG_%s = 5'h%02X;\n", #name, bit);
  FP3_FLAGS(X)
#undef X

  printf("\n// Run error codes (STATUS[11:8])\n");
#define X(name, code, desc)                                                    \
  printf("localparam [3:0] ERR_%s = 4'd%d; // %s\n", #name, code, desc);
  FP3_ERRORS(X)
#undef X

  printf("\n// Host port: 12-bit word addresses\n");
#define X(name, addr, acc, desc)                                               \
  printf("localparam [11:0] HR_%s = 12'h%03X; // %s %s\n", #name, addr, acc, desc);
  FP3_HOSTREGS(X)
#undef X
  printf("localparam [31:0] STATUS_RUNNING = 32'h%X, STATUS_DONE = 32'h%X;\n",
         FP3_STATUS_RUNNING, FP3_STATUS_DONE);
  printf("localparam integer STATUS_ERROR_LSB = %d;\n", FP3_STATUS_ERROR_LSB);
  printf("localparam [31:0] CTRL_START = 32'h%X, CTRL_CLEAR = 32'h%X;\n",
         FP3_CTRL_START, FP3_CTRL_CLEAR);
  printf("localparam [31:0] ID_VALUE = 32'h%08X;\n", FP3_ID_VALUE);
  printf("/* verilator lint_on UNUSEDPARAM */\n");
  return 0;
}
