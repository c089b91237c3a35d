/*
 * fpenv.c -- host float environment for a core configuration (fpenv.h).
 */
#include "fpenv.h"

#include <fenv.h>

#if defined(__SSE2__) || defined(__x86_64__)
#include <xmmintrin.h>
#define FPENV_MXCSR 1
#define MXCSR_FTZ 0x8000u /* flush to zero: bit 15 */
#define MXCSR_DAZ 0x0040u /* denormals are zero: bit 6 */
#else
#define FPENV_MXCSR 0
#endif

int fpenv_supported(fpref_mode mode) { return !mode.ftz || FPENV_MXCSR; }

int fpenv_enter(fpref_mode mode, fpenv_saved *saved) {
  if (!fpenv_supported(mode)) return -1;
  saved->round = fegetround();
  saved->csr = 0;
  if (fesetround(mode.round == FPREF_RTZ ? FE_TOWARDZERO : FE_TONEAREST) != 0) {
    fesetround(saved->round);
    return -1;
  }
#if FPENV_MXCSR
  saved->csr = _mm_getcsr();
  unsigned csr = saved->csr & ~(MXCSR_FTZ | MXCSR_DAZ);
  if (mode.ftz) csr |= MXCSR_FTZ | MXCSR_DAZ;
  _mm_setcsr(csr);
#endif
  return 0;
}

void fpenv_leave(const fpenv_saved *saved) {
#if FPENV_MXCSR
  _mm_setcsr(saved->csr);
#endif
  fesetround(saved->round);
}

const char *fpenv_round_name(fpref_mode mode) {
  return mode.round == FPREF_RTZ ? "rtz" : "rne";
}
