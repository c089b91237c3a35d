/*
 * fp3_isa.h -- the one source of truth for the FP3 instruction set,
 * build configuration, exception flags, error codes and host-port map.
 *
 * Every table here is an X-macro list.  The C side (assembler, ISS,
 * engines, CLI) expands them directly; `build/gen_isa` expands them into
 * rtl/fp3_isa.vh, the Verilog header the RTL includes.  The test
 * `tests/test_isa_sync.sh` regenerates that header and fails if it differs
 * from the committed one, so the two sides cannot drift apart.
 *
 * Instruction word: 64 bits, one per instruction memory entry.
 *
 *   63      56 55    48 47    40 39    32 31                       0
 *  +----------+--------+--------+--------+--------------------------+
 *  |  opcode  |   rd   |   ra   |   rb   |          imm             |
 *  +----------+--------+--------+--------+--------------------------+
 *
 * A field an opcode does not use must be zero, a register field must be
 * below FP3_NUM_REGS; anything else is an illegal instruction (error
 * ILLEGAL_INSN, with the faulting PC), both in the RTL and in the ISS.
 */
#ifndef FP3_ISA_H
#define FP3_ISA_H

/* Field positions (lsb) and widths of the instruction word. */
#define FP3_INSN_BITS   64
#define FP3_OPC_LSB     56
#define FP3_RD_LSB      48
#define FP3_RA_LSB      40
#define FP3_RB_LSB      32
#define FP3_IMM_LSB     0
#define FP3_OPC_WIDTH   8
#define FP3_REG_WIDTH   8
#define FP3_IMM_WIDTH   32

/* Operand fields an opcode uses (bit set = field used). */
#define FP3_USES_RD  0x1
#define FP3_USES_RA  0x2
#define FP3_USES_RB  0x4
#define FP3_USES_IMM 0x8

/* Execution unit an opcode is sent to. */
#define FP3_UNIT_NONE 0   /* no register result: nop, endi, halt          */
#define FP3_UNIT_ADD  1   /* FP add/sub core, ADD_LATENCY cycles          */
#define FP3_UNIT_MUL  2   /* FP mul core, MUL_LATENCY cycles              */
#define FP3_UNIT_MOV  3   /* move/immediate path and sign group, latency 1 */
#define FP3_UNIT_DIV  4   /* FP div/sqrt unit, DIV_LATENCY cycles          */
#define FP3_NUM_UNITS 5   /* units counted per run (fp3_status.unit_issued) */

/* Cycles from issue to the operands leaving the register file (the
 * block-RAM read stage).  A dependent instruction issues FP3_READ_CYCLES +
 * latency cycles after its producer: the unit's latency (ADD_LATENCY,
 * MUL_LATENCY, 1 for the move path) plus this.  The same with FMAX_PIPE
 * (rtl/fp3_top.v: two pick stages and four read stages, but
 * write-backs announced earlier) for latencies of at least
 * FP3_FMAX_PIPE_FULL_LEAD_LATENCY, which shorter ones and the move path
 * count as. */
#define FP3_READ_CYCLES 1

/* FMAX_PIPE's pick stages (rtl/fp3_top.v PICK, fp3_scheduler.v
 * PICK_STAGES): an instruction issues this many cycles after the
 * scheduler grants it, and the move path takes this many cycles more
 * (fp3_top.v MOV_LATENCY = 1 + PICK; ADD_LATENCY with WB_PORTS = 1);
 * ADD_LATENCY and MUL_LATENCY must exceed it. */
#define FP3_FMAX_PIPE_PICK_STAGES 2

/* FMAX_PIPE's fetch stages (fp3_scheduler.v FETCH_STAGE): the fetch grant
 * registered before the instruction memory, the word in the memory's
 * output register and registered again after it, so a word joins its
 * queue this many cycles later. */
#define FP3_FMAX_PIPE_FETCH_STAGES 3

/* FMAX_PIPE starts the contexts a cycle after START (fp3_scheduler.v
 * start_now, from the registered START): the first fetch is this many
 * cycles later than without. */
#define FP3_FMAX_PIPE_START_STAGES 1

/* A context's instruction queue holds FP3_QUEUE_WORDS words
 * (fp3_scheduler.v: two slots); a slot is free again in the cycle after
 * its word's grant.  The context fetches one word at a time, only with a
 * slot free, at most every FP3_FETCH_SPACING cycles (the fetch grant, the
 * word arriving; with FMAX_PIPE, FP3_FMAX_PIPE_FETCH_SPACING). */
#define FP3_QUEUE_WORDS 2
#define FP3_FETCH_SPACING 2

/* FMAX_PIPE's registered issue stages (fp3_scheduler.v "The issue
 * loop's registered stages"): a context's readiness is registered, and so
 * is the arbiter's decision, so a word is granted this many cycles later
 * after it joins its queue, and a write-back reaches the readiness this
 * many cycles later unless it is announced that much earlier
 * (FP3_FMAX_PIPE_FULL_LEAD_LATENCY). */
#define FP3_FMAX_PIPE_GRANT_STAGES 2

/* With FMAX_PIPE a context is granted at most once every
 * FP3_FMAX_PIPE_ISSUE_SPACING cycles (the grant of the cycle before is
 * not yet known where the next is decided); two or more contexts still
 * issue every cycle between them. */
#define FP3_FMAX_PIPE_ISSUE_SPACING 3

/* With FMAX_PIPE a unit of at least this latency (ADD_LATENCY,
 * MUL_LATENCY) announces its write-backs early enough for the registered
 * issue stages: its dependent instruction issues FP3_READ_CYCLES +
 * latency after it, as on the default build.  A shorter one (and the move
 * path, of latency 1 + FP3_FMAX_PIPE_PICK_STAGES) counts as this latency:
 * its announcement passes the write-back tag line's pick taps
 * (rtl/fp3_wb_tag.v) only when the line is long enough. */
#define FP3_FMAX_PIPE_FULL_LEAD_LATENCY (FP3_FMAX_PIPE_PICK_STAGES + FP3_FMAX_PIPE_GRANT_STAGES + 1)

/* Cycles FMAX_PIPE = 1 (the build for clock rate, INFO1 bit 18) adds to a
 * beq (FP3_BEQ_CYCLES): the two pick stages, the three more
 * operand-read stages, the fetch stages (FP3_FMAX_PIPE_FETCH_STAGES) and
 * the registered issue stages (FP3_FMAX_PIPE_GRANT_STAGES).  Its
 * host-port reads take 4 cycles instead of 1. */
#define FP3_FMAX_PIPE_CYCLES (5 + FP3_FMAX_PIPE_FETCH_STAGES + FP3_FMAX_PIPE_GRANT_STAGES)

/* With FMAX_PIPE a context fetches at most every FP3_FMAX_PIPE_FETCH_SPACING
 * cycles (grant, read, word registered, queued), so one context runs
 * straight-line code no faster than that; with several contexts the
 * fetches interleave, one per cycle. */
#define FP3_FMAX_PIPE_FETCH_SPACING (FP3_FETCH_SPACING + FP3_FMAX_PIPE_FETCH_STAGES)

/* A context issues at most once every FP3_ISSUE_SPACING cycles (its
 * readiness is decided a cycle ahead, for the instruction at the head of
 * its queue; with FMAX_PIPE, FP3_FMAX_PIPE_ISSUE_SPACING); two or more
 * contexts issue every cycle between them. */
#define FP3_ISSUE_SPACING 2

/* Cycles from START to the first issue: the first instruction is
 * fetched (in cycle 0, the first after START), lands in its context's
 * queue, and is found ready; so also the fewest cycles from a word's
 * fetch to its issue.  FMAX_PIPE adds FP3_FMAX_PIPE_FETCH_STAGES,
 * FP3_FMAX_PIPE_GRANT_STAGES and FP3_FMAX_PIPE_PICK_STAGES (and, from
 * START, FP3_FMAX_PIPE_START_STAGES). */
#define FP3_START_CYCLES 3

/* Cycles from a beq's issue to the next issue of its context: operands
 * read (1), compared and the outcome registered (1), the next word's
 * address presented (1), the word read (1), queued (1) and found ready
 * (1). */
#define FP3_BEQ_CYCLES 6

/* Cycles a build with lanes (NUM_LANES > 1) adds to a beq, and to the
 * end of a run: the lanes run FP3_LANES_STAGE_CYCLES behind the scheduler
 * (the broadcast stages at their inputs, rtl/fp3_lane.v), and each
 * registers its beq compare (one more cycle for a beq only). */
#define FP3_LANES_STAGE_CYCLES 2
#define FP3_LANES_BEQ_CYCLES (FP3_LANES_STAGE_CYCLES + 1)

/* Cycles a build with lanes adds to a host-port read (1 + 3 FMAX_PIPE
 * without): the lanes after lane 0 see the host's address a cycle after
 * it, so that lane 0's LVT choice reaches them through a register. */
#define FP3_LANES_HOST_READ_CYCLES 1

/* Cycles from a host-port read's address to its data (rtl/fp3_top.v
 * "Host port"), for a build of FMAX_PIPE fmax_pipe and num_lanes lanes. */
#define FP3_HOST_READ_CYCLES(fmax_pipe, num_lanes) \
  (1 + 3 * (fmax_pipe) + ((num_lanes) > 1 ? FP3_LANES_HOST_READ_CYCLES : 0))

/*
 * X(NAME, opcode, mnemonic, fields used, unit, description)
 *
 * endi: end of integration.  Increments the integration counter; if it
 * reached the requested count the run stops issuing (in-flight results
 * still drain), otherwise the PC jumps to imm, the first instruction of the
 * loop body.  Everything before the body is the prologue, run once.
 */
#define FP3_OPCODES(X)                                                         \
  X(NOP,  0x00, "nop",  0,                                                     \
    FP3_UNIT_NONE, "no operation")                                             \
  X(ADD,  0x01, "add",  FP3_USES_RD | FP3_USES_RA | FP3_USES_RB,               \
    FP3_UNIT_ADD,  "rd = ra + rb (binary32)")                                  \
  X(SUB,  0x02, "sub",  FP3_USES_RD | FP3_USES_RA | FP3_USES_RB,               \
    FP3_UNIT_ADD,  "rd = ra - rb (binary32)")                                  \
  X(MUL,  0x03, "mul",  FP3_USES_RD | FP3_USES_RA | FP3_USES_RB,               \
    FP3_UNIT_MUL,  "rd = ra * rb (binary32)")                                  \
  X(LI,   0x04, "li",   FP3_USES_RD | FP3_USES_IMM,                            \
    FP3_UNIT_MOV,  "rd = imm (32-bit pattern)")                                \
  X(MOV,  0x05, "mov",  FP3_USES_RD | FP3_USES_RA,                             \
    FP3_UNIT_MOV,  "rd = ra (bit copy)")                                       \
  X(ENDI, 0x06, "endi", FP3_USES_IMM,                                          \
    FP3_UNIT_NONE, "end of integration; loop to imm unless the last")          \
  X(HALT, 0x07, "halt", 0,                                                     \
    FP3_UNIT_NONE, "stop issuing; the run ends when results drain")         \
  X(BEQ,  0x08, "beq",  FP3_USES_RA | FP3_USES_RB | FP3_USES_IMM,              \
    FP3_UNIT_NONE, "continue at imm (ahead) if ra, rb are bit-identical "     \
                   "in every lane of the context")                            \
  X(DIV,  0x09, "div",  FP3_USES_RD | FP3_USES_RA | FP3_USES_RB,               \
    FP3_UNIT_DIV,  "rd = ra / rb (binary32)")                                  \
  X(SQRT, 0x0A, "sqrt", FP3_USES_RD | FP3_USES_RA,                             \
    FP3_UNIT_DIV,  "rd = sqrt(ra) (binary32; sqrt(-0) = -0)")                  \
  X(ABS,  0x0B, "abs",  FP3_USES_RD | FP3_USES_RA,                             \
    FP3_UNIT_MOV,  "rd = ra with bit 31 cleared (quiet)")                      \
  X(NEG,  0x0C, "neg",  FP3_USES_RD | FP3_USES_RA,                             \
    FP3_UNIT_MOV,  "rd = ra with bit 31 flipped (quiet)")                      \
  X(MIN,  0x0D, "min",  FP3_USES_RD | FP3_USES_RA | FP3_USES_RB,               \
    FP3_UNIT_MOV,  "rd = minimum(ra, rb), IEEE 754-2019 9.6 (-0 < +0)")        \
  X(MAX,  0x0E, "max",  FP3_USES_RD | FP3_USES_RA | FP3_USES_RB,               \
    FP3_UNIT_MOV,  "rd = maximum(ra, rb), IEEE 754-2019 9.6 (-0 < +0)")

/*
 * Build configuration: X(NAME, default).  The RTL top takes these as
 * parameters with these defaults; the C side reads the values a model was
 * built with back from the INFO host registers.
 */
#define FP3_CONFIG(X)                                                          \
  X(NUM_CONTEXTS, 8)   /* contexts: instruction streams (1 .. 64)      */      \
  X(NUM_LANES,    1)   /* lanes per context (1 .. 64); objects in      */      \
                       /* flight: NUM_CONTEXTS x NUM_LANES             */      \
  X(NUM_REGS,    32)   /* registers per context (at most 256)          */      \
  X(IMEM_DEPTH,  256)  /* instruction memory words (at most 1024)      */      \
  X(ADD_LATENCY, 4)    /* add/sub core: operands to result, cycles     */      \
  X(MUL_LATENCY, 3)    /* mul core: operands to result, cycles         */      \
  X(HAS_ADD,     1)    /* 0: no add/sub core (add, sub are illegal)    */      \
  X(HAS_SUB,     1)    /* 0: the adder only adds (sub is illegal)      */      \
  X(HAS_MUL,     1)    /* 0: no mul core (mul is illegal)              */      \
  X(HAS_DIV,     1)    /* 1: a divider (else div is illegal)           */      \
  X(HAS_SQRT,    1)    /* 1: a square root (else sqrt is illegal)      */      \
  X(HAS_SIGN,    1)    /* 1: the sign group (else abs, neg, min, max   */      \
                       /*    are illegal)                              */      \
  X(DIV_LATENCY, 8)    /* div/sqrt unit: operands to result, cycles    */

/* HAS_DIV, HAS_SQRT and HAS_SIGN: the ISS (iss.c) executes div, sqrt, abs,
 * neg, min and max bit-exactly (fpref_div .. fpref_max).  The processor
 * runs the sign group on its move path (rtl/fp3_arith.v, fp_sign; latency
 * 1 like mov) and div and sqrt on a fourth unit of DIV_LATENCY cycles
 * (rtl/fp_div.v, fp_sqrt.v: one write-back port and tag line for both),
 * reported in INFO2 (DIV_LATENCY in INFO1).  A build without one of them
 * has the instruction illegal, and the host refuses a program that uses
 * it before running it, naming the parameter (fp3_config_check_program). */

/* The most contexts a build may have (NUM_CONTEXTS; the trace port carries
 * 6-bit context numbers). */
#define FP3_MAX_CONTEXTS 64

/* The most registers a context may have (NUM_REGS; the register fields of
 * an instruction word are 8 bits wide). */
#define FP3_MAX_REGS 256

/* The most lanes a build may have (NUM_LANES): the trace port carries
 * 32 x NUM_LANES bits per write-back port, and INFO2[31:24] and LANE hold
 * the lane count and number.
 *
 * Lanes (rtl/fp3_lane.v): every instruction a context issues runs on all
 * NUM_LANES lanes of that context at once, each lane with its own
 * register bank and its own add/sub core, mul core and move path; fetch,
 * decode, the scoreboard and the issue arbiter are shared.  Lane l of
 * context c is one object: the C side numbers it as object slot
 * l x NUM_CONTEXTS + c (engine.h).  A beq is taken only when its operands
 * are bit-identical in every lane of the context (all NUM_LANES lanes
 * always execute); else every lane falls through.  Exception flags are
 * kept per lane. */
#define FP3_MAX_LANES 64

/* Exception flags, Berkeley SoftFloat / TestFloat bit order. */
#define FP3_FLAGS(X)                                                           \
  X(INEXACT,   0x01)                                                           \
  X(UNDERFLOW, 0x02)                                                           \
  X(OVERFLOW,  0x04)                                                           \
  X(INFINITE,  0x08)  /* divide by zero: never raised by add/sub/mul */        \
  X(INVALID,   0x10)

/* Run error codes (STATUS.ERROR). */
#define FP3_ERRORS(X)                                                          \
  X(NONE,         0, "no error")                                               \
  X(ILLEGAL_INSN, 1, "illegal instruction")                                    \
  X(PC_OVERFLOW,  2, "PC ran past the end of instruction memory")             \
  X(BAD_STEPS,    3, "run started with STEPS = 0")                              \
  X(BAD_CONTEXTS, 4, "run started with CONTEXTS = 0 or > NUM_CONTEXTS")

/*
 * Host port: 32-bit words at 12-bit word addresses.
 * X(NAME, address, access, description)
 */
#define FP3_HOSTREGS(X)                                                        \
  X(CTRL,       0x000, "W",  "bit0 START a run (clears counters, flags), "     \
                             "bit1 CLEAR the DONE and ERROR status")          \
  X(STATUS,     0x001, "R",  "bit0 RUNNING, bit1 DONE, bit2 some context "    \
                             "has an error, bits 11:8 ERROR of context CTX")  \
  X(STEPS,      0x002, "RW", "integrations to run")                           \
  X(STEPS_DONE, 0x003, "R",  "integrations completed by context CTX")         \
  X(FAULT_PC,   0x004, "R",  "PC of the instruction that raised context "     \
                             "CTX's ERROR")                                   \
  X(FLAGS,      0x005, "R",  "sticky exception flags of context CTX, lane "  \
                             "LANE in the last run")                          \
  X(CYCLES_LO,  0x006, "R",  "cycles from START to DONE, low word")           \
  X(CYCLES_HI,  0x007, "R",  "cycles, high word")                             \
  X(ISSUED_LO,  0x008, "R",  "instructions issued, low word")                 \
  X(ISSUED_HI,  0x009, "R",  "instructions issued, high word")                \
  X(STALLS_LO,  0x00A, "R",  "cycles an instruction waited on a hazard, low") \
  X(STALLS_HI,  0x00B, "R",  "stall cycles, high word")                       \
  X(INFO0,      0x00C, "R",  "NUM_REGS[15:0], IMEM_DEPTH[31:16]")             \
  X(INFO1,      0x00D, "R",  "ADD_LATENCY[7:0], MUL_LATENCY[15:8], ROUND[16], FTZ[17], FMAX_PIPE[18], " \
                             "DIV_LATENCY[26:19]")                            \
  X(ID,         0x00E, "R",  "0x46503301: 'FP3', version 1")                  \
  X(CTX,        0x00F, "RW", "context selected for STATUS.ERROR, STEPS_DONE, " \
                             "FAULT_PC and the register window")              \
  X(CONTEXTS,   0x010, "RW", "contexts a START runs, 1 .. NUM_CONTEXTS "       \
                             "(reset value 1)")                               \
  X(INFO2,      0x011, "R",  "NUM_CONTEXTS[15:0], HAS_ADD[16], HAS_SUB[17], HAS_MUL[18], "  \
                             "HAS_DIV[19], HAS_SQRT[20], HAS_SIGN[21], ONE_WB_PORT[22], "   \
                             "NUM_LANES[31:24]")                              \
  X(LANE,       0x012, "RW", "lane selected for FLAGS and the register "      \
                             "window, 0 .. NUM_LANES-1 (a larger value: "      \
                             "ignored; SLVERR over AXI)")                     \
  X(REG_BASE,   0x100, "RW", "register r of context CTX, lane LANE at "       \
                             "REG_BASE + r (stopped only)")                   \
  X(IMEM_BASE,  0x800, "W",  "instruction i: low word at IMEM_BASE + 2i, "    \
                             "high word at IMEM_BASE + 2i + 1 (writing the "  \
                             "high word stores both halves)")

#define FP3_STATUS_RUNNING   0x1u
#define FP3_STATUS_DONE      0x2u
#define FP3_STATUS_ANY_ERROR 0x4u
#define FP3_STATUS_ERROR_LSB 8
#define FP3_CTRL_START       0x1u
#define FP3_CTRL_CLEAR       0x2u
#define FP3_ID_VALUE         0x46503301u

/* ---- C views of the tables ------------------------------------------- */

enum fp3_opcode {
#define X(name, code, mnem, uses, unit, desc) FP3_OP_##name = code,
  FP3_OPCODES(X)
#undef X
};

enum fp3_config_default {
#define X(name, def) FP3_DEFAULT_##name = def,
  FP3_CONFIG(X)
#undef X
};

enum fp3_flag {
#define X(name, bit) FP3_FLAG_##name = bit,
  FP3_FLAGS(X)
#undef X
};

enum fp3_error {
#define X(name, code, desc) FP3_ERR_##name = code,
  FP3_ERRORS(X)
#undef X
};

enum fp3_hostreg {
#define X(name, addr, acc, desc) FP3_HR_##name = addr,
  FP3_HOSTREGS(X)
#undef X
};

#endif /* FP3_ISA_H */
