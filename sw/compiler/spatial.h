/*
 * spatial.h -- the spatial back end (`fp3 spatial`, docs/spatial.md): a
 * compiled model's integration step (compile.h, its IR) as one fully
 * pipelined Verilog module that takes one object per cycle.
 *
 * Every live operation of the IR gets its own core (rtl/fp_add.v for add
 * and sub, fp_mul, fp_div, fp_sqrt, fp_sign for abs, neg, min and max;
 * rtl/fp_scaleb.v for a multiply by a constant +-2^k, an exponent
 * adjustment with the same results and flags as fp_mul and no multiplier),
 * so the module computes exactly the operations of the golden model
 * fp3_compiled_model_step, and its results equal it bit for bit.  The
 * loop invariants the processor computes once in its prologue are
 * computed again for every object and step here (they are a function of
 * the object's inputs, which travel with it), so the step is a DAG with
 * no state of its own.
 *
 * Schedule: as soon as possible.  A module input (an input of the
 * program, a value the host computes, a carried value) is available in
 * cycle 0, a constant in every cycle; an operation starts when its last
 * operand is available and its result is available `latency` cycles
 * later (the core's LATENCY).  The pipeline's latency L is the latest
 * result's cycle (at least 1); every carried value leaves at L.
 *
 * Balancing: a value available in cycle t and read in cycle s > t passes
 * s - t register stages.  Each value has one delay line, as long as its
 * latest reader needs, and every reader taps it where it needs it (the
 * line is a chain of segments between the taps), so a value's line holds
 * 32 x (its longest delay) bits however many readers it has.  (One RAM per
 * reader instead would hold the sum of the readers' delays, and cost as
 * many block RAMs as a chain of segments.)
 *
 * Delay segments: each segment of D stages takes the form that costs
 * least for its length (the width is always 32 bits), measured with Yosys
 * 0.23 `synth_ecp5` of one 32-bit segment (rtl/fp_pipe.v WIDTH=32, and
 * rtl/fp_delay.v WIDTH=32 STYLE 1 or 2, `hierarchy -chparam ...;
 * synth_ecp5`), and nextpnr-ecp5's packing of a TRELLIS_DPR16X4 LUT-RAM
 * cell into 6 LUT4 sites (4 of RAM, 2 of its write port: 8 cells and 7
 * LUT4s of a 16-stage line placed as 57 TRELLIS_COMB); block RAM through
 * scripts/synth.sh ecp5 (FP3_ECP5_EBR: the block's output register), a
 * CCU2C counted as two LUT4s:
 *
 *   D     flip-flops (fp_pipe)   LUT RAM (STYLE 1)            block RAM (STYLE 2)
 *   4     128 FF                 8 DPR16X4 + 3 LUT4 + 36 FF   1 EBR + 3 LUT4 + 2 FF
 *   16    512 FF                 8 DPR16X4 + 7 LUT4 + 40 FF   1 EBR + 7 LUT4 + 4 FF
 *   32    1,024 FF               16 DPR16X4 + 43 LUT4 + 42 FF 1 EBR + 10 LUT4 + 5 FF
 *   64    2,048 FF               32 DPR16X4 + 144 LUT4 + 44 FF 1 EBR + 12 LUT4 + 6 FF
 *   512   16,384 FF              -                            1 EBR + 18 LUT4 + 9 FF
 *
 * The rule: D <= FP3_SPATIAL_FF_MAX (3) flip-flops (96 FFs, against about
 * 91 cells of LUT RAM: the break-even, and a flip-flop is the fastest
 * form); D <= FP3_SPATIAL_LUTRAM_MAX (16) LUT RAM (one bank of 16 words:
 * about 55 LUT4 sites and 40 FFs, no read multiplexer); longer block RAM
 * (one EBR holds up to 513 stages; LUT RAM would cost about 4.5 LUT4
 * sites a stage more: 140 LUT4s at 32 stages, 0.17 % of the LFE5U-85F's
 * LUT4s, against one of its 208 EBRs, 0.48 %, but the lanes' and spatial
 * builds run out of LUT4s first).
 */

/* The delay-segment rule (see above): stages up to which a segment is
 * flip-flops, and up to which it is LUT RAM; longer: block RAM. */
#define FP3_SPATIAL_FF_MAX 3u
#define FP3_SPATIAL_LUTRAM_MAX 16u
#ifndef FP3_SPATIAL_H
#define FP3_SPATIAL_H

#include <stddef.h>
#include <stdint.h>

#include "compile.h"
#include "model.h"

/* The cores' configuration. */
typedef struct fp3_spatial_opts {
  unsigned add_latency;  /* fp_add LATENCY (add, sub)                    */
  unsigned mul_latency;  /* fp_mul LATENCY                               */
  int mul_feed;          /* 1: fp_mul FEED = 1, a fabric register in
                            front of its MULT18X18D (mul_latency 7 to
                            10: the DSP product with the blocks' own
                            registers, then this one); 0: none          */
  unsigned mul_blocks;   /* fp_mul MULT_BLOCKS: the MULT18X18D per
                            product, 4 (12 x 12-bit pieces) or 3 (18 x 18,
                            two 18 x 6, the 6 x 6 piece in LUTs: for
                            chips the multiplier blocks bound); 3 needs
                            the DSP product (mul_latency less the feed
                            register at most 9)                         */
  unsigned div_latency;  /* fp_div and fp_sqrt LATENCY                   */
  unsigned sign_latency; /* fp_sign LATENCY (abs, neg, min, max)         */
  unsigned scaleb_latency; /* fp_scaleb LATENCY                          */
  int scaleb;            /* 1: a multiply by a constant +-2^k (k = -126
                            to 127) is an fp_scaleb core (an exponent
                            adjustment, the same results and flags as
                            fp_mul, no MULT18X18D); 0: fp_mul           */
  int rtz;               /* 1: every core rounds toward zero, 0: RNE     */
  int ftz;               /* 1: flush-to-zero cores (FTZ = 1)             */
} fp3_spatial_opts;

/* The latencies of the processor's default build (fp3_compile_defaults),
 * fp_sign 1, fp_scaleb 2 (on), no feed register, RNE, subnormals
 * supported. */
void fp3_spatial_defaults(fp3_spatial_opts *o);

/* The cores of the chip builds, for clock rate (`fp3 spatial --clock-cores`,
 * `make pnr-spatial`, `make bench-chip`, `make spatial-table`): fp_add 9
 * and fp_div / fp_sqrt 34 (every register place), fp_mul 10 with its feed
 * register (the product in MULT18X18D with the blocks' registers, and a
 * fabric register in front: on a full chip the route into a MULT18X18D is
 * the longest otherwise, docs/spatial.md), fp_scaleb 4 (every place),
 * fp_sign 1; o's rounding, FTZ and scaleB choice are kept. */
void fp3_spatial_clock_cores(fp3_spatial_opts *o);

/* What a generated pipeline holds. */
typedef struct fp3_spatial_stats {
  unsigned latency;              /* L: cycles from an object's inputs to
                                    its new carried values              */
  unsigned cores[FP3_IR_KINDS];  /* core instances per operation kind
                                    (FP3_IR_MUL: fp_mul only)           */
  unsigned scaleb;               /* fp_scaleb cores (multiplies by +-2^k) */
  unsigned ncores;               /* all of them                          */
  unsigned inputs;               /* 32-bit inputs per object (in_i)      */
  unsigned carried;              /* carried values per object (y_i, y_o) */
  unsigned delay_lines;          /* values with a delay line             */
  unsigned delay_stages;         /* their stages, summed                 */
  unsigned longest_delay;        /* the longest delay line, stages       */
  unsigned ff_segments;          /* segments of flip-flops (fp_pipe)     */
  unsigned ff_stages;            /* their stages                         */
  unsigned delay_ffs;            /* their flip-flops: 32 per stage       */
  unsigned lutram_segments;      /* segments in LUT RAM (fp_delay 1)     */
  unsigned lutram_stages;        /* their stages                         */
  unsigned lutram_cells;         /* their TRELLIS_DPR16X4 (16 x 4 bits)  */
  unsigned ebr_segments;         /* segments in block RAM (fp_delay 2)   */
  unsigned ebr_stages;           /* their stages                         */
  unsigned ebr_blocks;           /* their DP16KD (512 x 36 each)         */
  /* The area estimate of one pipeline on the LFE5U-85F (spatial.c's table
   * of per-core costs measured with Yosys synth_ecp5, plus the delay
   * segments and the valid bit's line; LUT4s as nextpnr's TRELLIS_COMB
   * sites: a LUT4, two per CCU2C, six per TRELLIS_DPR16X4). */
  unsigned est_lut4;             /* LUT4 sites                           */
  unsigned est_ff;               /* flip-flops                           */
  unsigned est_mult;             /* MULT18X18D                           */
  unsigned est_ebr;              /* DP16KD (the delay segments')         */
  unsigned est_inexact;          /* cores whose configuration is not in
                                    the table (the nearest one counted)  */
  unsigned fit;                  /* pipelines that fit the device within
                                    FP3_SPATIAL_BUDGET_* (0: not one)    */
  const char *limit;             /* the resource that limits `fit`       */
} fp3_spatial_stats;

/* The LFE5U-85F (Lattice FPGA-DS-02012 "ECP5 and ECP5-5G Family Data
 * Sheet", table 1.1) and the share of it a pipeline may take: the rest is
 * left for the frame (state and parameter memory, feeder, AXI4-Lite slave)
 * and for routing.  7/8 of the LUT4s and flip-flops: the folded ship chip
 * of 4 pipelines (make pnr-spatial, docs/spatial.md; the estimate 86.6 %
 * of the LUT4s, synthesized 82.9 %, placed 86.8 % of the TRELLIS_COMB,
 * the frame 2.7 % beside them) places and routes; every MULT18X18D (the
 * frame has no multiply); the EBRs less 16 for the frame's state and
 * parameter memory. */
#define FP3_SPATIAL_DEVICE_LUT4 83640u
#define FP3_SPATIAL_DEVICE_FF 83640u
#define FP3_SPATIAL_DEVICE_MULT 156u
#define FP3_SPATIAL_DEVICE_EBR 208u
#define FP3_SPATIAL_BUDGET_LUT4 (FP3_SPATIAL_DEVICE_LUT4 * 7u / 8u)
#define FP3_SPATIAL_BUDGET_FF (FP3_SPATIAL_DEVICE_FF * 7u / 8u)
#define FP3_SPATIAL_BUDGET_MULT FP3_SPATIAL_DEVICE_MULT
#define FP3_SPATIAL_BUDGET_EBR (FP3_SPATIAL_DEVICE_EBR - 16u)

typedef struct fp3_spatial fp3_spatial;

/* Schedule compiled model c (of model m, integrator `integ`, as
 * fp3_compile_model or fp3_compile_model_ir made it) for the cores of o,
 * and write its module.
 * c must outlive the result.  Returns 0 and *out, or -1 with a message
 * (latencies out of range, a model with no input, out of memory). */
int fp3_spatial_build(fp3_compiled *c, const fp3_model *m, const char *integ,
                      const fp3_spatial_opts *o, fp3_spatial **out, char *msg, size_t n);

void fp3_spatial_free(fp3_spatial *s);

/* The Verilog module's name (fp3_spatial_MODEL_INTEGRATOR) and text
 * (one module; it instantiates rtl/fp_*.v and rtl/fp_pipe.v). */
const char *fp3_spatial_module(const fp3_spatial *s);
const char *fp3_spatial_verilog(const fp3_spatial *s);

const fp3_spatial_stats *fp3_spatial_stats_of(const fp3_spatial *s);

/* The IR node (fp3_ir_node_get) whose value is word k of in_i
 * (k < stats.inputs); word w of y_i and y_o is carried value w. */
int fp3_spatial_input_node(const fp3_spatial *s, unsigned k);

/* The report: latency, cores by kind, delay lines and flip-flops, one
 * "name: value" line each (NUL-terminated, owned by s). */
const char *fp3_spatial_report(const fp3_spatial *s);

/* Test vectors for the module (text, malloc'd into *text): `nobj`
 * objects, object 0 with the model's default params and initial state,
 * each other non-h value scaled by its own factor in [0.75, 1.25] from
 * xorshift64 seeded with `seed`; each object's module inputs (in_i's
 * words, as fp3_compiled_model_start computes them) and initial carried
 * values, then its carried values after each of `steps` integrations of
 * the golden model (fp3_compiled_model_step), computed in the cores'
 * rounding (fpenv).  Format: a line "fp3-spatial-vectors OBJECTS STEPS
 * INPUTS CARRIED LATENCY", then per object a line of INPUTS + CARRIED hex
 * words, then per step and object a line of CARRIED hex words.  0, or -1
 * with a message (a rounding mode the host cannot run). */
int fp3_spatial_vectors(fp3_spatial *s, size_t nobj, unsigned steps, uint64_t seed,
                        char **text, char *msg, size_t n);

#endif /* FP3_SPATIAL_H */
