// fp3_isa.vh -- GENERATED from sw/isa/fp3_isa.h by sw/isa/gen_isa.c; do not edit.
// The instruction set, flag bits, error codes and host-port map of FP3,
// shared by the RTL and the C host.  `include inside a module body.
// Each module uses a few of these constants, never all of them, so the
// unused-parameter lint is waived for this header only.
/* verilator lint_off UNUSEDPARAM */

// Instruction word fields: [msb:lsb]
localparam integer ISA_INSN_BITS = 64;
localparam integer ISA_OPC_LSB   = 56;
localparam integer ISA_RD_LSB    = 48;
localparam integer ISA_RA_LSB    = 40;
localparam integer ISA_RB_LSB    = 32;
localparam integer ISA_OPC_WIDTH = 8;
localparam integer ISA_REG_WIDTH = 8;
localparam integer ISA_IMM_WIDTH = 32;

// Opcodes and the operand fields each one uses
// (bit 0 rd, bit 1 ra, bit 2 rb, bit 3 imm; unused fields must be 0).
// Unit: 0 none, 1 add/sub core, 2 mul core, 3 move path (and sign group),
// 4 div/sqrt unit.
localparam [7:0] OP_NOP  = 8'h00; localparam [3:0] OPUSES_NOP  = 4'h0; localparam [2:0] OPUNIT_NOP  = 3'd0; // nop: no operation
localparam [7:0] OP_ADD  = 8'h01; localparam [3:0] OPUSES_ADD  = 4'h7; localparam [2:0] OPUNIT_ADD  = 3'd1; // add: rd = ra + rb (binary32)
localparam [7:0] OP_SUB  = 8'h02; localparam [3:0] OPUSES_SUB  = 4'h7; localparam [2:0] OPUNIT_SUB  = 3'd1; // sub: rd = ra - rb (binary32)
localparam [7:0] OP_MUL  = 8'h03; localparam [3:0] OPUSES_MUL  = 4'h7; localparam [2:0] OPUNIT_MUL  = 3'd2; // mul: rd = ra * rb (binary32)
localparam [7:0] OP_LI   = 8'h04; localparam [3:0] OPUSES_LI   = 4'h9; localparam [2:0] OPUNIT_LI   = 3'd3; // li: rd = imm (32-bit pattern)
localparam [7:0] OP_MOV  = 8'h05; localparam [3:0] OPUSES_MOV  = 4'h3; localparam [2:0] OPUNIT_MOV  = 3'd3; // mov: rd = ra (bit copy)
localparam [7:0] OP_ENDI = 8'h06; localparam [3:0] OPUSES_ENDI = 4'h8; localparam [2:0] OPUNIT_ENDI = 3'd0; // endi: end of integration; loop to imm unless the last
localparam [7:0] OP_HALT = 8'h07; localparam [3:0] OPUSES_HALT = 4'h0; localparam [2:0] OPUNIT_HALT = 3'd0; // halt: stop issuing; the run ends when results drain
localparam [7:0] OP_BEQ  = 8'h08; localparam [3:0] OPUSES_BEQ  = 4'hE; localparam [2:0] OPUNIT_BEQ  = 3'd0; // beq: continue at imm (ahead) if ra, rb are bit-identical in every lane of the context
localparam [7:0] OP_DIV  = 8'h09; localparam [3:0] OPUSES_DIV  = 4'h7; localparam [2:0] OPUNIT_DIV  = 3'd4; // div: rd = ra / rb (binary32)
localparam [7:0] OP_SQRT = 8'h0A; localparam [3:0] OPUSES_SQRT = 4'h3; localparam [2:0] OPUNIT_SQRT = 3'd4; // sqrt: rd = sqrt(ra) (binary32; sqrt(-0) = -0)
localparam [7:0] OP_ABS  = 8'h0B; localparam [3:0] OPUSES_ABS  = 4'h3; localparam [2:0] OPUNIT_ABS  = 3'd3; // abs: rd = ra with bit 31 cleared (quiet)
localparam [7:0] OP_NEG  = 8'h0C; localparam [3:0] OPUSES_NEG  = 4'h3; localparam [2:0] OPUNIT_NEG  = 3'd3; // neg: rd = ra with bit 31 flipped (quiet)
localparam [7:0] OP_MIN  = 8'h0D; localparam [3:0] OPUSES_MIN  = 4'h7; localparam [2:0] OPUNIT_MIN  = 3'd3; // min: rd = minimum(ra, rb), IEEE 754-2019 9.6 (-0 < +0)
localparam [7:0] OP_MAX  = 8'h0E; localparam [3:0] OPUSES_MAX  = 4'h7; localparam [2:0] OPUNIT_MAX  = 3'd3; // max: rd = maximum(ra, rb), IEEE 754-2019 9.6 (-0 < +0)

// Decode an opcode: {known, unit[2:0], uses[3:0]}; 0 for an unknown one.
function [7:0] isa_decode;
  input [7:0] opc;
  begin
    case (opc)
      OP_NOP : isa_decode = {1'b1, OPUNIT_NOP , OPUSES_NOP };
      OP_ADD : isa_decode = {1'b1, OPUNIT_ADD , OPUSES_ADD };
      OP_SUB : isa_decode = {1'b1, OPUNIT_SUB , OPUSES_SUB };
      OP_MUL : isa_decode = {1'b1, OPUNIT_MUL , OPUSES_MUL };
      OP_LI  : isa_decode = {1'b1, OPUNIT_LI  , OPUSES_LI  };
      OP_MOV : isa_decode = {1'b1, OPUNIT_MOV , OPUSES_MOV };
      OP_ENDI: isa_decode = {1'b1, OPUNIT_ENDI, OPUSES_ENDI};
      OP_HALT: isa_decode = {1'b1, OPUNIT_HALT, OPUSES_HALT};
      OP_BEQ : isa_decode = {1'b1, OPUNIT_BEQ , OPUSES_BEQ };
      OP_DIV : isa_decode = {1'b1, OPUNIT_DIV , OPUSES_DIV };
      OP_SQRT: isa_decode = {1'b1, OPUNIT_SQRT, OPUSES_SQRT};
      OP_ABS : isa_decode = {1'b1, OPUNIT_ABS , OPUSES_ABS };
      OP_NEG : isa_decode = {1'b1, OPUNIT_NEG , OPUSES_NEG };
      OP_MIN : isa_decode = {1'b1, OPUNIT_MIN , OPUSES_MIN };
      OP_MAX : isa_decode = {1'b1, OPUNIT_MAX , OPUSES_MAX };
      default: isa_decode = 8'd0;
    endcase
  end
endfunction
localparam [2:0] UNIT_NONE = 3'd0, UNIT_ADD = 3'd1, UNIT_MUL = 3'd2, UNIT_MOV = 3'd3, UNIT_DIV = 3'd4;

// Build configuration defaults
localparam integer DEFAULT_NUM_CONTEXTS = 8;
localparam integer DEFAULT_NUM_LANES = 1;
localparam integer DEFAULT_NUM_REGS = 32;
localparam integer DEFAULT_IMEM_DEPTH = 256;
localparam integer DEFAULT_ADD_LATENCY = 4;
localparam integer DEFAULT_MUL_LATENCY = 3;
localparam integer DEFAULT_HAS_ADD = 1;
localparam integer DEFAULT_HAS_SUB = 1;
localparam integer DEFAULT_HAS_MUL = 1;
localparam integer DEFAULT_HAS_DIV = 1;
localparam integer DEFAULT_HAS_SQRT = 1;
localparam integer DEFAULT_HAS_SIGN = 1;
localparam integer DEFAULT_DIV_LATENCY = 8;
localparam integer MAX_CONTEXTS = 64, MAX_LANES = 64;

// Exception flags (Berkeley SoftFloat bit order)
localparam [4:0] FLAG_INEXACT = 5'h01;
localparam [4:0] FLAG_UNDERFLOW = 5'h02;
localparam [4:0] FLAG_OVERFLOW = 5'h04;
localparam [4:0] FLAG_INFINITE = 5'h08;
localparam [4:0] FLAG_INVALID = 5'h10;

// Run error codes (STATUS[11:8])
localparam [3:0] ERR_NONE = 4'd0; // no error
localparam [3:0] ERR_ILLEGAL_INSN = 4'd1; // illegal instruction
localparam [3:0] ERR_PC_OVERFLOW = 4'd2; // PC ran past the end of instruction memory
localparam [3:0] ERR_BAD_STEPS = 4'd3; // run started with STEPS = 0
localparam [3:0] ERR_BAD_CONTEXTS = 4'd4; // run started with CONTEXTS = 0 or > NUM_CONTEXTS

// Host port: 12-bit word addresses
localparam [11:0] HR_CTRL = 12'h000; // W bit0 START a run (clears counters, flags), bit1 CLEAR the DONE and ERROR status
localparam [11:0] HR_STATUS = 12'h001; // R bit0 RUNNING, bit1 DONE, bit2 some context has an error, bits 11:8 ERROR of context CTX
localparam [11:0] HR_STEPS = 12'h002; // RW integrations to run
localparam [11:0] HR_STEPS_DONE = 12'h003; // R integrations completed by context CTX
localparam [11:0] HR_FAULT_PC = 12'h004; // R PC of the instruction that raised context CTX's ERROR
localparam [11:0] HR_FLAGS = 12'h005; // R sticky exception flags of context CTX, lane LANE in the last run
localparam [11:0] HR_CYCLES_LO = 12'h006; // R cycles from START to DONE, low word
localparam [11:0] HR_CYCLES_HI = 12'h007; // R cycles, high word
localparam [11:0] HR_ISSUED_LO = 12'h008; // R instructions issued, low word
localparam [11:0] HR_ISSUED_HI = 12'h009; // R instructions issued, high word
localparam [11:0] HR_STALLS_LO = 12'h00A; // R cycles an instruction waited on a hazard, low
localparam [11:0] HR_STALLS_HI = 12'h00B; // R stall cycles, high word
localparam [11:0] HR_INFO0 = 12'h00C; // R NUM_REGS[15:0], IMEM_DEPTH[31:16]
localparam [11:0] HR_INFO1 = 12'h00D; // R ADD_LATENCY[7:0], MUL_LATENCY[15:8], ROUND[16], FTZ[17], FMAX_PIPE[18], DIV_LATENCY[26:19]
localparam [11:0] HR_ID = 12'h00E; // R 0x46503301: 'FP3', version 1
localparam [11:0] HR_CTX = 12'h00F; // RW context selected for STATUS.ERROR, STEPS_DONE, FAULT_PC and the register window
localparam [11:0] HR_CONTEXTS = 12'h010; // RW contexts a START runs, 1 .. NUM_CONTEXTS (reset value 1)
localparam [11:0] HR_INFO2 = 12'h011; // R NUM_CONTEXTS[15:0], HAS_ADD[16], HAS_SUB[17], HAS_MUL[18], HAS_DIV[19], HAS_SQRT[20], HAS_SIGN[21], ONE_WB_PORT[22], NUM_LANES[31:24]
localparam [11:0] HR_LANE = 12'h012; // RW lane selected for FLAGS and the register window, 0 .. NUM_LANES-1 (a larger value: ignored; SLVERR over AXI)
localparam [11:0] HR_REG_BASE = 12'h100; // RW register r of context CTX, lane LANE at REG_BASE + r (stopped only)
localparam [11:0] HR_IMEM_BASE = 12'h800; // W instruction i: low word at IMEM_BASE + 2i, high word at IMEM_BASE + 2i + 1 (writing the high word stores both halves)
localparam [31:0] STATUS_RUNNING = 32'h1, STATUS_DONE = 32'h2;
localparam integer STATUS_ERROR_LSB = 8;
localparam [31:0] CTRL_START = 32'h1, CTRL_CLEAR = 32'h2;
localparam [31:0] ID_VALUE = 32'h46503301;
/* verilator lint_on UNUSEDPARAM */
