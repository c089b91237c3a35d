/*
 * device.h -- how many lanes an FPGA holds: the devices `fp3 configure
 * --device` knows and a lane cost model measured on the chip build.
 *
 * The model counts the resources of a build of N lanes as a fixed part
 * and a cost per lane, as Yosys mapped the chip build's shape for the
 * LFE5U-85F with four write-back ports (WB_PORTS = 4, the register file
 * `fp3 configure` builds: its latencies differ; 16 contexts x 8 lanes, 32
 * registers a context, the build for clock rate with the multiplier in
 * MULT18X18D; docs/lanes.md "One write-back port", `bash scripts/synth.sh
 * DIR fp3_axil ecp5 NUM_CONTEXTS=16 NUM_LANES=8 ADD_LATENCY=9
 * MUL_LATENCY=9 FMAX_PIPE=1 HAS_DIV=0 HAS_SQRT=0 -keep fp3_top -keep
 * fp3_lane rtl/[a-z]*.v`, LUTs counting a CCU2C as two LUT4s):
 *
 *   fixed      scheduler, host port, write-back tags, sticky flags and the
 *              AXI4-Lite wrapper: 13,240 LUT4s, 3 EBR
 *   lane 0     13,429 LUT4s (register bank, busy flags and live value
 *              table of the 512 registers, FP cores), 4 MULT18X18D, 8 EBR
 *   lane 1 ..  3,962 LUT4s (register bank, FP cores, broadcast stages), 4 MULT18X18D, 8 EBR
 *
 * Scaled to the build asked for: lane 0's busy flags and live value
 * table (its LUTs beyond another lane's, 9,467) are one entry a register
 * of every context, so they scale with NUM_CONTEXTS x NUM_REGS against
 * the chip build's 512; each lane's 8 EBR hold 512 registers, so a lane
 * takes 8 x ceil(registers / 512).  The fixed part is the chip build's
 * 16-context scheduler (with the sticky flags of its 8 lanes), kept for
 * every build: it is an upper bound below 16 contexts and 8 lanes, and
 * optimistic above.
 *
 * A device's limit is not its LUT4 count but what nextpnr-ecp5 routes:
 * that 8-lane build of 54,403 LUT4s, 65 % of the LFE5U-85F's, routed on
 * 8 seeds (docs/lanes.md "Chip build"), so the model allows LUTs up to 65.1 %
 * of the device's, and all of its MULT18X18D and EBR.  It is measured on
 * the LFE5U-85F only; the other ECP5 parts are the same fabric, with the
 * family data sheet's resource counts.
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

/* The share of a device's LUT4s the model lets a build use, in per
 * mille: the chip build's, the most that routed (see above). */
#define FP3_DEVICE_ROUTABLE_PERMILLE 651u

/* What a build of some lanes costs on a device, and which limit binds. */
typedef struct fp3_device_fit {
  unsigned max_lanes;       /* the most lanes within every limit (0: not  */
                            /* even one)                                  */
  unsigned luts_fixed;      /* the fixed part's LUT4s                     */
  unsigned luts_lane0;      /* lane 0's LUT4s (scaled)                    */
  unsigned luts_lane;       /* each further lane's LUT4s                  */
  unsigned ebr_fixed;       /* the fixed part's EBR                       */
  unsigned ebr_lane;        /* EBR a lane (scaled)                        */
  unsigned dsp_lane;        /* MULT18X18D a lane (0 without a multiplier) */
  unsigned luts_allowed;    /* FP3_DEVICE_ROUTABLE_PERMILLE of the LUT4s  */
  const char *limit;        /* "LUT4s (routing)", "MULT18X18D" or "EBR":  */
                            /* the resource that stops one more lane      */
} fp3_device_fit;

/* The device named name (exact, e.g. "ecp5-85"), or NULL. */
const fp3_device *fp3_device_find(const char *name);

/* The names fp3_device_find knows, comma separated, for messages. */
const char *fp3_device_names(void);

/* The most lanes of a build of num_contexts x num_regs registers (a
 * multiplier in each lane when has_mul) that fit device d under the model
 * above, and the costs it used (*fit).  Returns fit->max_lanes. */
unsigned fp3_device_lanes(const fp3_device *d, unsigned num_contexts, unsigned num_regs,
                          int has_mul, fp3_device_fit *fit);

#endif /* FP3_DEVICE_H */
