/*
 * cpu_ship.h -- the ship's RK4 step (paper Equations (1), the operation
 * order of the ship model's literal rk4se, programs/ship_rk4.s) on this
 * machine's CPU, timed: the
 * reference the FP3 chip build is compared with (make bench-chip).
 *
 * cpu_ship.c is compiled apart, with -O3 -march=native -ffp-contract=off
 * (no fused multiply-add, so every operation rounds as binary32 as on
 * FP3), so that the compiler may vectorize the array form over ships.
 */
#ifndef FP3_CPU_SHIP_H
#define FP3_CPU_SHIP_H

#include <stddef.h>
#include <stdint.h>

/* Ships in arrays (structure of arrays): T, C, minv, h, v, s of n ships. */
typedef struct cpu_ships {
  float *T, *C, *minv, *h, *v, *s;
  size_t n;
} cpu_ships;

/* steps RK4 steps of every ship in a (all ships one step, then the next:
 * the loop over ships is the inner one, independent ships, vectorizable). */
void cpu_ship_steps_array(cpu_ships *a, uint32_t steps);

/* steps RK4 steps of ship i of a alone (each step waits for the last:
 * the latency of one dependent chain). */
void cpu_ship_steps_scalar(cpu_ships *a, size_t i, uint32_t steps);

/* The compiler flags cpu_ship.c was built with (CPU_SHIP_FLAGS), for the
 * report. */
const char *cpu_ship_flags(void);

#endif /* FP3_CPU_SHIP_H */
