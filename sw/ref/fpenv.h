/*
 * fpenv.h -- run host float arithmetic in an FP core configuration.
 *
 * The golden models are plain C float code.  To follow the RTL's core
 * options they run between fpenv_enter() and fpenv_leave(), which set the
 * host's dynamic rounding mode (C11 <fenv.h>: FE_TONEAREST for RNE,
 * FE_TOWARDZERO for RTZ) and, for FTZ, the x86 SSE MXCSR bits FTZ (15,
 * flush tiny results to zero) and DAZ (6, read subnormal inputs as zero) --
 * the behaviour fp_add/fp_mul implement with FTZ = 1 (checked against the
 * host by tests/test_fpu.c).  Code run in between must be compiled with
 * -frounding-math (the Makefile's CFLAGS) so that the compiler does not
 * fold operations at build time in the default mode.
 */
#ifndef FP3_FPENV_H
#define FP3_FPENV_H

#include "fpref.h"

/* The host state that fpenv_leave() restores. */
typedef struct fpenv_saved {
  int round;     /* fegetround() */
  unsigned csr;  /* MXCSR, where there is one */
} fpenv_saved;

/* 1 if this host can run float code in `mode` (FTZ needs x86 SSE). */
int fpenv_supported(fpref_mode mode);

/* Enter `mode`, saving the current state.  Returns 0, or -1 (state
 * unchanged) when the host cannot run in that mode. */
int fpenv_enter(fpref_mode mode, fpenv_saved *saved);

/* Restore the state saved by fpenv_enter(). */
void fpenv_leave(const fpenv_saved *saved);

/* "rne" / "rtz", "" / "+ftz": names of a mode for reports. */
const char *fpenv_round_name(fpref_mode mode);

#endif /* FP3_FPENV_H */
