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
 * params, the host's values, the carried values), and a run feeds each
 * slot's pipeline inputs from the registers that hold them
 * (fp3_ir_node_reg) and writes each new carried value back to its
 * register (fp3_compiled_state_reg), reporting it to the observer as a
 * write-back of that integration, then an endi.  So every runner of the
 * model path (fp3_run_state_objects, fp3_run_state_frames, fp3 run's one
 * object) drives it unchanged and compares every object with the same
 * golden model after every integration.
 *
 * A run: slots 0 .. n-1 are fed in turn, one a cycle; a slot is fed its
 * next step as soon as its previous result has left the pipeline
 * (latency L), so K steps of n objects take about K max(n, L) + L cycles
 * (docs/spatial.md "Objects against latency").  A bubble's inputs are
 * pseudo-random words, so a value read in the wrong cycle shows.  Each
 * result must leave exactly L cycles after its object entered, else the
 * run fails.  status.cycles counts the pipeline's clock cycles from the
 * first object in to the last result out; issued counts operations (one
 * per core per object-step); exception flags are not reported (the
 * pipeline has no flag outputs: flags stays 0, and
 * fp3_engine_spatial_is says which engine it is so callers say so).
 *
 * The cache (FP3_SPATIAL_CACHE_VERSION): DIR/MODULE-KEY/ holds
 * spatial.so, build.log and manifest.  KEY is FNV-1a 64 (hex) of the
 * generated module's text, every rtl/ file, sim/spatial_shim.cpp, the
 * Verilator version and the build commands, so any change rebuilds.  The
 * shared object reports the FNV-1a 64 hash of the module text it was
 * built from (fp3_spatial_shim_hash, the frame's HASH register's value);
 * a mismatch, a file that does not load or a missing symbol makes the
 * entry unusable: it is removed and built again, said on stderr.  A build
 * happens in DIR/tmp.MODULE-KEY.PID and is renamed into place when done;
 * a concurrent build of the same entry loses the rename and uses the
 * winner's, so readers never see a half-built entry.
 */
#ifndef FP3_ENGINE_SPATIAL_H
#define FP3_ENGINE_SPATIAL_H

#include <stddef.h>
#include <stdint.h>

#include "compile.h"
#include "engine.h"
#include "model.h"

/* Object slots of a spatial engine (fp3_config.num_contexts): the
 * objects one run streams through the pipeline, as the frame's state
 * memory holds M objects; more objects run in batches. */
#define FP3_SPATIAL_SLOTS 1024

/* The cache layout's version, part of every KEY. */
#define FP3_SPATIAL_CACHE_VERSION 1

/* Where the engine finds what it builds with. */
typedef struct fp3_spatial_env {
  const char *root;      /* the FP3 tree: ROOT/rtl/ and ROOT/sim/spatial_shim.cpp */
  const char *cache;     /* the cache folder (made if missing)                    */
  const char *verilator; /* the Verilator command (NULL: "verilator")             */
  const char *label;     /* prefix of the messages on stderr ("spatial")          */
} fp3_spatial_env;

/* A spatial engine for compiled model c (of model m and integrator
 * integ, compiled with registers: fp3_compile_model or
 * fp3_model_compile_for), its cores rounding and flushing as `mode`
 * says, the cores' latencies those of fp3_spatial_defaults.  Builds the
 * pipeline, finds or builds its cache entry (progress on stderr: what it
 * builds, each stage and its time), loads it.  c must outlive the
 * engine.  NULL with the reason in err: a pipeline the generator
 * refuses, no Verilator ("verilator: not found"), a failed build (the
 * log's path and its last lines), a shared object that does not load. */
fp3_engine *fp3_engine_spatial_new(fp3_compiled *c, const fp3_model *m, const char *integ,
                                   fpref_mode mode, const fp3_spatial_env *env, char *err,
                                   size_t n);

/* 1 when e is a spatial engine. */
int fp3_engine_spatial_is(const fp3_engine *e);

/* The pipeline's latency L (cycles), cores and cache folder of spatial
 * engine e (0 / NULL for another engine). */
unsigned fp3_engine_spatial_latency(const fp3_engine *e);
unsigned fp3_engine_spatial_cores(const fp3_engine *e);
const char *fp3_engine_spatial_entry(const fp3_engine *e);

/* FNV-1a 64 of the n bytes at p, continuing from h (start: the offset
 * basis 0xcbf29ce484222325). */
uint64_t fp3_fnv1a64(uint64_t h, const void *p, size_t n);

#endif /* FP3_ENGINE_SPATIAL_H */
