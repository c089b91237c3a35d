/*
 * device.h -- how many lanes an FPGA holds: the devices `fp3 configure
 * --device` knows and two lane cost models measured on the chip build.
 *
 * A model counts the resources of a build of N lanes as a fixed part and
 * a cost per lane, as Yosys mapped the chip build's shape for the
 * LFE5U-85F (16 contexts, 32 registers a context, the build for clock
 * rate with the multiplier in MULT18X18D, no div/sqrt unit; `bash
 * scripts/synth.sh DIR fp3_axil ecp5 NUM_CONTEXTS=16 NUM_LANES=N
 * ADD_LATENCY=9 MUL_LATENCY=9 FMAX_PIPE=1 HAS_DIV=0 HAS_SQRT=0
 * [WB_PORTS=1] -keep fp3_top -keep fp3_lane rtl/[a-z]*.v`, LUTs counting
 * a CCU2C as two LUT4s; docs/lanes.md "One write-back port" and "Chip
 * build"):
 *
 *  four write-back ports (WB_PORTS = 4), 8 lanes:
 *   fixed      scheduler, host port, write-back tags, sticky flags and the
 *              AXI4-Lite wrapper: 13,240 LUT4s (at 8 lanes), 3 EBR
 *   lane 0     13,429 LUT4s (register bank, busy flags and live value
 *              table of the 512 registers, FP cores), 4 MULT18X18D, 8 EBR
 *   lane 1 ..  3,962 LUT4s (register bank, FP cores, broadcast stages),
 *              4 MULT18X18D, 8 EBR (eight RAMs of 512 x 32, two a port)
 *  one write-back port (WB_PORTS = 1), 8 and 16 lanes:
 *   fixed      10,281 LUT4s + 348 a lane (the trace port, host read and
 *              flags multiplexers grow with the lanes: fp3_top and
 *              fp3_axil are 13,070 LUT4s at 8 lanes, 15,849 at 16), 3 EBR
 *   lane 0     4,080 LUT4s (register bank and busy flags of the 512
 *              registers, no live value table, FP cores), 4 MULT18X18D,
 *              2 EBR
 *   lane 1 ..  2,646 LUT4s, 4 MULT18X18D, 2 EBR (two RAMs of 512 x 32)
 *  (measured at latencies 9 and 9; the chip build's latencies 10 and 10
 *  with the multiplier's feed register, MUL_FEED=1, synthesize to 58,968
 *  LUT4s at 16 lanes, lane 0 4,048, a lane 2,598, fp3_top 15,712: within
 *  1.1 % of the model)
 *
 * Scaled to the build asked for: lane 0's busy flags (and, with four
 * ports, live value table) -- its LUTs beyond another lane's, 9,467 or
 * 1,434 -- are one entry a register of every context, so they scale with
 * NUM_CONTEXTS x NUM_REGS against the chip build's 512; a lane's EBR hold
 * 512 registers, so a lane takes its EBR x ceil(registers / 512).  The
 * fixed part is the chip build's 16-context scheduler, kept for every
 * build: it is an upper bound below 16 contexts, and optimistic above.
 *
 * A device's limit is not its LUT4 count but what nextpnr-ecp5 routes:
 * the largest build of each kind that routed on every seed placed (four
 * ports: 8 lanes, 54,403 LUT4s, 65.0 % of the LFE5U-85F's, 8 seeds of 8;
 * one port: 16 lanes, 59,619 LUT4s, 71.3 %), so a model allows LUTs up to
 * that share of the device's (rounded up to the next per mille), and all
 * of its MULT18X18D and EBR.  The models are measured on the LFE5U-85F
 * only; the other ECP5 parts are the same fabric, with the family data
 * sheet's resource counts.
 */
#ifndef FP3_DEVICE_H
#define FP3_DEVICE_H

#include <stddef.h>

/* An FPGA the lane model knows. */
typedef struct fp3_device {
  const char *name;  /* as --device takes it, e.g. "ecp5-85"            */
  const char *part;  /* the part, e.g. "LFE5U-85F"                      */
  unsigned luts;     /* LUT4s                                           */
  unsigned dsps;     /* MULT18X18D multipliers                          */
  unsigned ebrs;     /* DP16KD block RAMs (18 kbit)                     */
} fp3_device;

/* The share of a device's LUT4s a model lets a build use, in per mille:
 * the largest build of its kind that routed (see above), four write-back
 * ports and one. */
#define FP3_DEVICE_ROUTABLE_PERMILLE_WB4 651u
#define FP3_DEVICE_ROUTABLE_PERMILLE_WB1 713u

/* What a build of some lanes costs on a device, and which limit binds. */
typedef struct fp3_device_fit {
  unsigned max_lanes;       /* the most lanes within every limit (0: not  */
                            /* even one)                                  */
  unsigned wb_ports;        /* the model used: 4 or 1 write-back ports    */
  unsigned luts_fixed;      /* the fixed part's LUT4s (its share of each  */
                            /* lane counted in that lane)                 */
  unsigned luts_lane0;      /* lane 0's LUT4s (scaled)                    */
  unsigned luts_lane;       /* each further lane's LUT4s                  */
  unsigned ebr_fixed;       /* the fixed part's EBR                       */
  unsigned ebr_lane;        /* EBR a lane (scaled)                        */
  unsigned dsp_lane;        /* MULT18X18D a lane (0 without a multiplier) */
  unsigned routable_permille; /* FP3_DEVICE_ROUTABLE_PERMILLE_WB4 or _WB1 */
  unsigned luts_allowed;    /* that share of the device's LUT4s           */
  const char *limit;        /* "LUT4s (routing)", "MULT18X18D" or "EBR":  */
                            /* the resource that stops one more lane      */
} fp3_device_fit;

/* The device named name (exact, e.g. "ecp5-85"), or NULL. */
const fp3_device *fp3_device_find(const char *name);

/* The names fp3_device_find knows, comma separated, for messages. */
const char *fp3_device_names(void);

/* The most lanes of a build of num_contexts x num_regs registers (a
 * multiplier in each lane when has_mul) with wb_ports write-back ports (1;
 * anything else: 4) that fit device d under the model above, and the
 * costs it used (*fit).  Returns fit->max_lanes. */
unsigned fp3_device_lanes(const fp3_device *d, unsigned num_contexts, unsigned num_regs,
                          int has_mul, unsigned wb_ports, fp3_device_fit *fit);

#endif /* FP3_DEVICE_H */
