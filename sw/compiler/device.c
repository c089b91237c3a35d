/*
 * device.c -- how many lanes an FPGA holds (device.h).
 */
#include "device.h"

#include <stdio.h>
#include <string.h>

/* ECP5 family data sheet (FPGA-DS-02012), table 1.1: LUT4s, 18x18
 * multipliers, EBR SRAM blocks. */
static const fp3_device devices[] = {
    {"ecp5-25", "LFE5U-25F", 24288, 28, 56},
    {"ecp5-45", "LFE5U-45F", 43848, 72, 108},
    {"ecp5-85", "LFE5U-85F", 83640, 156, 208},
};
#define NDEV (sizeof devices / sizeof devices[0])

/* The chip build's figures (device.h), per write-back ports. */
typedef struct lane_model {
  unsigned fixed_luts;  /* fixed part, less its share of each lane     */
  unsigned fixed_lane;  /* the fixed part's LUT4s a lane               */
  unsigned lane0_luts;  /* lane 0 at CHIP_REGS registers               */
  unsigned lane_luts;   /* a further lane                              */
  unsigned lane_ebr;    /* EBR a lane per CHIP_REGS registers          */
  unsigned permille;    /* LUT4s that route, per mille of the device's */
} lane_model;
/* four ports: fp3_top alone 13,087 + fp3_axil alone 153 at 8 lanes */
static const lane_model model_wb4 = {13240u, 0u, 13429u, 3962u, 8u,
                                     FP3_DEVICE_ROUTABLE_PERMILLE_WB4};
/* one port: fp3_top + fp3_axil 13,070 at 8 lanes, 15,611 + 238 at 16 */
static const lane_model model_wb1 = {10281u, 348u, 4080u, 2646u, 2u,
                                     FP3_DEVICE_ROUTABLE_PERMILLE_WB1};
#define FIXED_EBR 3u
#define LANE_DSP 4u        /* a binary32 product in MULT18X18D */
#define CHIP_REGS 512u     /* 16 contexts x 32 registers */

const fp3_device *fp3_device_find(const char *name) {
  for (size_t i = 0; i < NDEV; i++)
    if (strcmp(devices[i].name, name) == 0) return &devices[i];
  return NULL;
}

const char *fp3_device_names(void) {
  static char names[NDEV * 16];  /* "name, name, ...", built from devices[] once */
  if (!names[0]) {
    size_t at = 0;
    for (size_t i = 0; i < NDEV; i++)
      at += (size_t)snprintf(names + at, sizeof names - at, "%s%s", i ? ", " : "",
                             devices[i].name);
  }
  return names;
}

/* x * num / den rounded up */
static unsigned scale_up(unsigned x, unsigned long long num, unsigned long long den) {
  return (unsigned)(((unsigned long long)x * num + den - 1) / den);
}

unsigned fp3_device_lanes(const fp3_device *d, unsigned num_contexts, unsigned num_regs,
                          int has_mul, unsigned wb_ports, fp3_device_fit *fit) {
  const lane_model *m = wb_ports == 1 ? &model_wb1 : &model_wb4;
  const unsigned long long regs = (unsigned long long)num_contexts * num_regs;
  fit->wb_ports = wb_ports == 1 ? 1 : 4;
  fit->luts_fixed = m->fixed_luts;
  fit->luts_lane = m->lane_luts + m->fixed_lane;
  fit->luts_lane0 = fit->luts_lane + scale_up(m->lane0_luts - m->lane_luts, regs, CHIP_REGS);
  fit->ebr_fixed = FIXED_EBR;
  fit->ebr_lane = m->lane_ebr * (unsigned)((regs + CHIP_REGS - 1) / CHIP_REGS);
  fit->dsp_lane = has_mul ? LANE_DSP : 0;
  fit->routable_permille = m->permille;
  fit->luts_allowed = (unsigned)((unsigned long long)d->luts * m->permille / 1000);
  unsigned n = 0;
  for (;;) { /* one more lane, while every limit holds */
    const unsigned long long k = n + 1;
    const unsigned long long luts = fit->luts_fixed + fit->luts_lane0 + (k - 1) * fit->luts_lane;
    if (luts > fit->luts_allowed) { fit->limit = "LUT4s (routing)"; break; }
    if (k * fit->dsp_lane > d->dsps) { fit->limit = "MULT18X18D"; break; }
    if (fit->ebr_fixed + k * fit->ebr_lane > d->ebrs) { fit->limit = "EBR"; break; }
    n++;
  }
  fit->max_lanes = n;
  return n;
}
