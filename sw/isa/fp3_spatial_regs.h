/*
 * fp3_spatial_regs.h -- the register map of a spatial chip: the AXI4-Lite
 * slave (rtl/fp3_spatial_axil.v) of the frame (rtl/fp3_spatial_frame.v)
 * around N copies of a model's step module, as `fp3 spatial --pipelines N`
 * writes it (fp3_spatial_MODEL_INTEGRATOR_top.v; docs/spatial.md "The
 * frame").  The host (the spatial engine, a board, MPI) drives the chip
 * through these addresses only.
 *
 * Addresses: 32-bit words at word addresses; the AXI byte address is the
 * word address x 4 (FP3S_BYTE).  The slave decodes byte-address bits
 * [FP3S_ADDR_BITS-1:2]; bits [1:0] and those above are not decoded (an
 * interconnect decodes the base address).
 *
 * Access: R read only, W write only, RW both.  Every access is answered
 * OKAY, or SLVERR with no effect (read data 0) for
 *   - a write to a read-only or unmapped address, a read of a write-only
 *     or unmapped address;
 *   - a write whose WSTRB is not 4'b1111;
 *   - a write to STEPS or COUNT, and any access (read or write) to the
 *     awake list, the state or the input window, while a run is in
 *     progress (STATUS.RUNNING: the frame's memories are the pipelines'
 *     then);
 *   - a write to COUNT of a value above MAXOBJ;
 *   - in a window: an object or entry number >= MAXOBJ, a word at or
 *     beyond the object's carried values (inputs) within its stride;
 *   - a write to the awake list of a value other than FP3S_AWAKE_NONE that
 *     is >= MAXOBJ or whose bank differs from the entry's (below).
 * CTRL is always writable; START while running is ignored.
 *
 * Objects and banks.  The chip holds MAXOBJ = M objects (M a multiple of
 * N).  Object o lives in bank o mod N at row o / N; pipeline p reads and
 * writes only bank p, one object a cycle.  Each object has `carried`
 * state words (the step module's y_i: the state variables and, for
 * rk4comp, their compensations; its header lists them) and `inputs`
 * input words (its in_i: the params and the host's values the program
 * binds, such as h and folded products, listed in the module's header;
 * fp3 spatial --vectors writes them per object).
 *
 * The awake list: entries 0 .. COUNT-1.  A run of STEPS steps integrates
 * the objects the list names, STEPS times each; the others are not read
 * or written.  The list is fed in rounds: round r hands entry r*N + p to
 * pipeline p (p = 0 .. N-1), so entry i must name an object of bank
 * i mod N (o mod N == i mod N), or be FP3S_AWAKE_NONE, an empty slot (a
 * bubble).  A step takes ceil(COUNT / N) rounds, one a cycle, but never
 * fewer cycles than the pipeline's latency plus the frame's
 * (docs/spatial.md gives the run's cycles).  With every object of
 * 0 .. n-1 awake the list is the identity, entry i = i; fp3s_awake_list
 * below builds it for any set.  An object named twice is stepped twice a
 * step or once, depending on where: the list must name each object at
 * most once.
 *
 * A run: write the input and state windows, the awake list, COUNT and
 * STEPS, then CTRL.START; STATUS.RUNNING is 1 until the last step's last
 * object is written back, then STATUS.DONE is 1 (until the next START)
 * and CYCLES_LO/HI hold the run's cycles, from the second cycle after
 * START's write (START reaches the frame through a register) to the cycle
 * DONE rises.  A START with STEPS = 0 or COUNT = 0
 * runs no step.  The state window then holds the new states.
 */
#ifndef FP3_SPATIAL_REGS_H
#define FP3_SPATIAL_REGS_H

#include <stddef.h>
#include <stdint.h>

/* AXI byte-address bits the slave decodes (its ADDR_WIDTH). */
#define FP3S_ADDR_BITS 24

/* The byte address of word address w. */
#define FP3S_BYTE(w) ((uint32_t)(w) * 4u)

/*
 * Scalar registers.  X(NAME, word address, access, description)
 */
#define FP3S_REGS(X)                                                           \
  X(ID,        0x000, "R",  "0x46503353: 'FP3S', a spatial chip")              \
  X(HASH,      0x001, "R",  "low 32 bits of the step module's hash: FNV-1a "   \
                            "64 of its file's text (fp3 spatial report.txt "   \
                            "'hash:', the top's header and HASH parameter)")   \
  X(INFO,      0x002, "R",  "[7:0] pipelines N, [15:8] inputs per object, "    \
                            "[23:16] carried values per object")              \
  X(LATENCY,   0x003, "R",  "the step module's latency L, cycles")            \
  X(MAXOBJ,    0x004, "R",  "objects the chip holds, M (a multiple of N)")    \
  X(STRIDES,   0x005, "R",  "[7:0] log2 of the state window's object stride, " \
                            "[15:8] log2 of the input window's")              \
  X(CTRL,      0x008, "W",  "bit0 START a run (ignored while running)")      \
  X(STATUS,    0x009, "R",  "bit0 RUNNING, bit1 DONE (the last run ended; "   \
                            "cleared by START)")                              \
  X(STEPS,     0x00A, "RW", "steps a run makes, K (reset 0)")                 \
  X(COUNT,     0x00B, "RW", "entries of the awake list a run feeds, "         \
                            "0 .. MAXOBJ (reset 0)")                          \
  X(CYCLES_LO, 0x00C, "R",  "cycles of the last run, low word")               \
  X(CYCLES_HI, 0x00D, "R",  "cycles of the last run, high word")              \
  X(FLAGS,     0x00E, "R",  "IEEE 754 exception flags the cores raised on "   \
                            "the last run's objects, sticky (cleared by "     \
                            "START): fp3_isa.h FP3_FLAG_* bits")

/*
 * Windows.  X(NAME, base word address, access, description)
 * Each spans FP3S_WINDOW_WORDS words from its base.
 */
#define FP3S_WINDOWS(X)                                                        \
  X(AWAKE, 0x100000, "RW", "awake list entry i at AWAKE + i, i < MAXOBJ: "     \
                           "an object number or FP3S_AWAKE_NONE")             \
  X(STATE, 0x200000, "RW", "object o's carried value w at STATE + "           \
                           "o * state stride + w")                            \
  X(INPUT, 0x300000, "RW", "object o's input k at INPUT + "                   \
                           "o * input stride + k")

#define FP3S_WINDOW_WORDS 0x100000u

#define FP3S_ID_VALUE     0x46503353u /* 'F' 'P' '3' 'S' */
#define FP3S_CTRL_START   0x1u
#define FP3S_STATUS_RUNNING 0x1u
#define FP3S_STATUS_DONE  0x2u
#define FP3S_AWAKE_NONE   0xFFFFFFFFu /* an empty slot of the awake list */

/* INFO's fields. */
#define FP3S_INFO_PIPELINES(v) ((unsigned)(v)&0xFFu)
#define FP3S_INFO_INPUTS(v)    (((unsigned)(v) >> 8) & 0xFFu)
#define FP3S_INFO_CARRIED(v)   (((unsigned)(v) >> 16) & 0xFFu)

/* STRIDES' fields: the strides in words (a power of two, at least the
 * object's carried values, inputs; at least 1). */
#define FP3S_STATE_STRIDE(v) (1u << ((unsigned)(v)&0xFFu))
#define FP3S_INPUT_STRIDE(v) (1u << (((unsigned)(v) >> 8) & 0xFFu))

/* The most pipelines, inputs and carried values a chip may have (INFO's
 * 8-bit fields), and the most objects: a window holds MAXOBJ x stride
 * words. */
#define FP3S_MAX_PIPELINES 255u
#define FP3S_MAX_WORDS     255u

enum fp3s_reg {
#define X(name, addr, acc, desc) FP3S_##name = addr,
  FP3S_REGS(X)
#undef X
};

enum fp3s_window {
#define X(name, addr, acc, desc) FP3S_##name##_BASE = addr,
  FP3S_WINDOWS(X)
#undef X
};

/* The awake list for the objects o < m with awake[o] != 0 on a chip of n
 * pipelines (n >= 1): each bank's awake objects in increasing order, bank
 * p's j-th at entry j * n + p, the slots of the banks with fewer awake
 * objects FP3S_AWAKE_NONE.  Writes the entries to list[] (room for m + n
 * entries: at most n * ceil(m / n)) and returns their number, COUNT; its
 * rounds, ceil(COUNT / n), are the most awake objects of any bank.  With
 * objects 0 .. k-1 awake it is the identity, k entries. */
static inline size_t fp3s_awake_list(const unsigned char *awake, size_t m, unsigned n,
                                     uint32_t *list) {
  size_t rounds = 0;
  for (unsigned p = 0; p < n; p++) {
    size_t j = 0;
    for (size_t o = p; o < m; o += n)
      if (awake[o]) list[j++ * n + p] = (uint32_t)o;
    if (j > rounds) rounds = j;
  }
  /* empty slots: bank p's entries from its own count to the rounds */
  for (unsigned p = 0; p < n; p++) {
    size_t j = 0;
    for (size_t o = p; o < m; o += n)
      if (awake[o]) j++;
    for (; j < rounds; j++) list[j * n + p] = FP3S_AWAKE_NONE;
  }
  /* the last round's trailing empty slots are not fed */
  size_t count = rounds * n;
  while (count > 0 && list[count - 1] == FP3S_AWAKE_NONE) count--;
  return count;
}

#endif /* FP3_SPATIAL_REGS_H */
