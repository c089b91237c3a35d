/*
 * spatial_top.h -- the chip top of the spatial back end (`fp3 spatial
 * --pipelines N [--objects M]`, docs/spatial.md "The frame"): N copies of
 * a generated step module (spatial.h) in the frame (rtl/fp3_spatial_frame.v:
 * object memory, feeder, write-back, runs of K steps) behind its AXI4-Lite
 * slave (rtl/fp3_spatial_axil.v, register map sw/isa/fp3_spatial_regs.h).
 */
#ifndef FP3_SPATIAL_TOP_H
#define FP3_SPATIAL_TOP_H

#include <stddef.h>
#include <stdint.h>

#include "spatial.h"

/* FNV-1a 64 (Fowler, Noll, Vo): h continued over the n bytes at p; start
 * from FP3_FNV1A64_BASIS.  The hash of the step module (below) and of the
 * spatial engine's cache entries. */
#define FP3_FNV1A64_BASIS 0xcbf29ce484222325ull
uint64_t fp3_fnv1a64(uint64_t h, const void *p, size_t n);

/* The step module's hash: FNV-1a 64 (offset basis 0xcbf29ce484222325,
 * prime 0x100000001b3; Fowler, Noll, Vo) of its text, the bytes of the
 * file `fp3 spatial` writes.  The chip's HASH register holds its low 32
 * bits. */
uint64_t fp3_spatial_hash(const fp3_spatial *s);

/* The default objects of a chip of `pipelines` pipelines: 512 per
 * pipeline (one ECP5 block RAM's rows at 36 bits). */
unsigned fp3_spatial_default_objects(unsigned pipelines);

/* The object strides of the windows, log2 of words (the next power of two
 * of the carried values, of the inputs). */
unsigned fp3_spatial_state_log(const fp3_spatial *s);
unsigned fp3_spatial_input_log(const fp3_spatial *s);

/* The chip top's module name (fp3_spatial_MODEL_INTEGRATOR_top, into the n
 * bytes of name) and Verilog text (malloc'd into *text) for `pipelines`
 * pipelines (1 .. FP3S_MAX_PIPELINES) and `objects` objects (a multiple of
 * pipelines, at least 2 per pipeline, and objects x stride <= 2^20 words
 * in either window).  With trace nonzero the top has a trace port:
 * trace_v_o, trace_obj_o and trace_y_o show each write-back of an
 * object's new carried values as the state memory takes it (one per
 * awake object a step), for a simulation to observe a run of K steps
 * without reading states back; without it (the board's and placement's
 * top) the ports do not exist, so they cost no pins and no logic.  0, or
 * -1 with a message naming the bad value (and *text NULL). */
int fp3_spatial_top(const fp3_spatial *s, unsigned pipelines, unsigned objects, int trace,
                    char *name, size_t namelen, char **text, char *msg, size_t n);

#endif /* FP3_SPATIAL_TOP_H */
