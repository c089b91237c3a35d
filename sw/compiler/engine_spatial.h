/*
 * engine_spatial.h -- the spatial engine (`--engine spatial`,
 * docs/spatial.md "The spatial engine"): a compiled model's step as the
 * pipeline `fp3 spatial` writes (spatial.h), Verilated on first use,
 * cached by its hash, loaded with dlopen, behind the fp3_engine
 * interface (engine.h).
 *
 * One interface, honestly: an fp3_engine runs a program image on
 * registers.  A spatial engine is built for one compiled model c (its
 * program, integrator, folding and core options) and runs only c's own
 * image: load_program refuses any other, so a hand-written program or
 * another model's cannot run on it.  Its registers are c's registers: an
 * object slot holds the bank that fp3_compiled_model_start writes (the
 * params, the host's values, the carried values).  The engine keeps the
 * banks on the host and the chip's object memory in step with them: a
 * run writes the inputs and carried values of each slot whose bank the
 * host wrote since (from the registers that hold them, fp3_ir_node_reg,
 * fp3_compiled_state_reg), runs all the steps with one START, and takes
 * every slot's new carried values after every step from the chip's trace
 * port while the model runs freely (DESIGN.md "Observe, don't stop"):
 * each into its registers and to the observer as a write-back of that
 * integration, then an endi.  So every runner of the
 * model path (fp3_run_state_objects, fp3_run_state_frames, fp3 run's one
 * object) drives it unchanged and compares every object with the same
 * golden model after every integration.
 *
 * The chip: the top `fp3 spatial --pipelines 1 --objects
 * FP3_SPATIAL_SLOTS` writes, with its trace port (spatial_top.h: the
 * frame, its object memory and AXI4-Lite slave around one pipeline),
 * driven only through AXI4-Lite transfers at the addresses of
 * fp3_spatial_regs.h, as a board's host would, and observed through the
 * trace port.  On load the engine reads ID, HASH (the low word of the step
 * module's hash, fp3_spatial_hash), INFO, LATENCY and MAXOBJ and refuses
 * a chip that is not this module's.  A run of n slots and K steps writes
 * the awake list 0 .. n-1, COUNT = n, STEPS = K and START once, and
 * polls STATUS until DONE; the trace port meanwhile shows each object's
 * write-backs, the k-th its state after integration k.  After the run
 * every object must have been written back K times (no more, no other
 * object), and the state window, read back to back
 * (fp3_spatial_shim_read_many), must hold each object's last write-back:
 * otherwise the run fails naming the object.  status.cycles is the
 * run's CYCLES register (START to DONE; (K - 1) max(R, L + 3) + R + L +
 * 4 for n objects on N pipelines, R = ceil(n / N), docs/spatial.md);
 * issued counts operations (one per core per object-step); status.flags
 * is the run's FLAGS register, the IEEE 754 flags the cores raised on its
 * objects (a slot's own flags, fp3_ctx_status.flags, are not kept: 0).
 * An AXI error (SLVERR, no response) or a run that never ends
 * fails the run with the address.
 *
 * The cache (FP3_SPATIAL_CACHE_VERSION): DIR/MODULE-KEY/ holds
 * spatial.so and a manifest.  KEY is FNV-1a 64 (hex) of the step
 * module's and the chip top's text, every rtl/ file,
 * sim/spatial_shim.cpp and the Verilator version, so any change builds a
 * new entry.  The manifest records the step's hash and the shared
 * object's size and FNV-1a 64; before loading, the files must match it
 * (a cut or replaced object never reaches dlopen), and after loading the
 * chip's registers must be the module's.  An entry that fails is said to
 * be unusable, removed and built again.  A build happens in
 * DIR/MODULE-KEY.tmp.PID and is renamed into place when done; a
 * concurrent build of the same entry loses the rename and uses the
 * winner's, so readers never see a half-built entry.
 */
#ifndef FP3_ENGINE_SPATIAL_H
#define FP3_ENGINE_SPATIAL_H

#include <stddef.h>
#include <stdint.h>

#include "compile.h"
#include "engine.h"
#include "model.h"
#include "spatial.h"

/* Object slots of a spatial engine of one pipeline
 * (fp3_config.num_contexts): the objects one run streams through the
 * pipelines, as the frame's state memory holds M objects; more objects run
 * in batches.  With N pipelines, rounded up to a multiple of N. */
#define FP3_SPATIAL_SLOTS 1024

/* The cache layout's version, part of every KEY. */
#define FP3_SPATIAL_CACHE_VERSION 3

/* Where the engine finds what it builds with. */
typedef struct fp3_spatial_env {
  const char *root;      /* the FP3 tree: ROOT/rtl/ and ROOT/sim/spatial_shim.cpp */
  const char *cache;     /* the cache folder (made if missing)                    */
  const char *verilator; /* the Verilator command (NULL or "": "verilator")       */
  /* The C++ compiler of the Verilated model (NULL or "": clang++ if it answers
   * --version, else g++).  clang++ -O2 runs the 4-pipeline folded ship
   * chip about 10 % faster than g++ -O2 (Clang 14, GCC 12; make
   * bench-simspeed: 505,923 against 469,933 object-steps per CPU second).
   * Part of the cache key. */
  const char *cxx;
  const char *label;     /* prefix of the messages on stderr ("spatial")          */
  /* The chip's shape: its pipelines N (0: one; at most
   * FP3S_MAX_PIPELINES) and its cores (NULL: fp3_spatial_defaults; `make
   * pnr-spatial` places fp3_spatial_clock_cores'), whose rounding and FTZ
   * the engine's `mode` sets either way.  Slot o is in bank o mod N, and
   * the engine has FP3_SPATIAL_SLOTS slots rounded up to a multiple of N
   * (fp3_config.num_contexts). */
  unsigned pipelines;
  const fp3_spatial_opts *cores;
} fp3_spatial_env;

/* A spatial engine for compiled model c (of model m and integrator
 * integ, compiled with registers: fp3_compile_model or
 * fp3_model_compile_for), its cores rounding and flushing as `mode`
 * says, their latencies env->cores' (fp3_spatial_defaults' without).  Builds the
 * pipeline and its chip top, finds or builds its cache entry (progress on
 * stderr: what it builds, each stage and its time), loads and checks it.  c must outlive the
 * engine.  NULL with the reason in err: a pipeline the generator
 * refuses, no Verilator ("verilator: not found"), a failed build (the
 * log's path and its last lines), a chip that does not load or answer as
 * the module's. */
fp3_engine *fp3_engine_spatial_new(fp3_compiled *c, const fp3_model *m, const char *integ,
                                   fpref_mode mode, const fp3_spatial_env *env, char *err,
                                   size_t n);

/* 1 when e is a spatial engine. */
int fp3_engine_spatial_is(const fp3_engine *e);

/* The pipeline's latency L (cycles) and its cores, of spatial engine e
 * (0 for another engine). */
unsigned fp3_engine_spatial_latency(const fp3_engine *e);
unsigned fp3_engine_spatial_cores(const fp3_engine *e);

#endif /* FP3_ENGINE_SPATIAL_H */
