/*
 * mpishard.h -- fp3-mpi: a scene's objects sharded across MPI ranks, each
 * rank with an engine of its own, rank 0 gathering (docs/cluster.md).
 * Compiled only into build/fp3-mpi (-DFP3_MPI, mpicc's flags); build/fp3
 * has none of it.
 *
 * Sharding rule.  A scene of n objects runs in B = ceil(n / S) batches of
 * S = contexts x lanes objects (fp3_config_slots), batch b holding objects
 * bS .. bS+S-1, as in one process.  Rank r of N runs the whole batches
 * floor(rB/N) .. floor((r+1)B/N)-1: every rank's engine is full except
 * in the scene's last batch, and each batch holds the same objects as in
 * one process, so every count (batches, cycles, issued, per-object
 * results) adds up to the one-process run's, bit for bit.  Frame by frame
 * (fp3 frames) the same rule applies each frame to the batches of that
 * frame's awake objects: rank 0 keeps every object's register bank and
 * the golden models, scatters the banks of each rank's batches, gathers
 * them back, and sleeping objects are sent nowhere.
 *
 * Output.  Only rank 0 writes standard output (the other ranks' stdout
 * goes to /dev/null), so a report or --json is the one-process run's.  On
 * standard error rank 0 adds one line per rank (its objects,
 * object-steps and seconds) and one line per failing rank naming the
 * rank, its host and the object.
 *
 * Faults.  A rank whose engine fails (an error from the engine, a golden
 * mismatch, a run error) makes the command exit 1, with the message
 * naming rank, host and object; nothing is printed on standard output
 * when a rank's engine fails.  A rank that dies ends the job through
 * mpirun (Open MPI aborts every rank), before rank 0 has printed.  For
 * tests, FP3_MPI_FAULT=KIND:OBJECT makes the rank holding scene object
 * OBJECT fail on purpose: KIND `engine` (its engine reports a failure
 * when the batch holding OBJECT starts, as a board that does not
 * answer), `golden` (OBJECT's state after each integration differs from
 * the golden model's in its lowest bit) or `kill` (the rank kills itself
 * with SIGKILL when that batch starts, as a crashed process).
 */
#ifndef FP3_MPISHARD_H
#define FP3_MPISHARD_H

#include <mpi.h>
#include <stddef.h>
#include <stdint.h>

#include "engine.h"
#include "fpref.h"
#include "model.h"
#include "mscene.h"

/* MPI_Init (the process exits 1 when it fails); standard output of every
 * rank but 0 to /dev/null; FP3_MPI_FAULT read.  Returns 0, or -1 with the
 * reason on stderr (a bad FP3_MPI_FAULT); fp3_mpi_finish is called
 * either way. */
int fp3_mpi_init(int *argc, char ***argv);

/* The job's exit status from every rank's rc (the largest), then
 * MPI_Finalize.  Returns that status. */
int fp3_mpi_finish(int rc);

/* This process's rank, and the number of ranks (MPI_COMM_WORLD). */
int fp3_mpi_rank(void);
int fp3_mpi_size(void);

/* The sharding rule above: rank r of `size` runs objects [*lo, *hi) of
 * nobj in batches of `slots` (empty when the scene has fewer batches than
 * ranks). */
void fp3_mpi_shard(size_t nobj, unsigned slots, int rank, int size, size_t *lo, size_t *hi);

/* fp3_run_state_objects (mscene.h), sharded: every rank calls it with the
 * same arguments, runs its shard on e, and rank 0 gets the whole scene's
 * result in *res, equal to one process's (the other ranks get their
 * shard's).  Returns 0, or -1 on every rank when a rank failed; on rank 0
 * msg then names each failing rank, its host and objects. */
int fp3_mpi_run_state_objects(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                              uint32_t steps, fpref_mode mode, const fp3_state_golden *golden,
                              fp3_state_result *res, char *msg, size_t n);

/* The GSL reference (want_ref 0: none; rank 0's value counts) and the
 * exact solution of every object of sc after `steps` integrations
 * (fp3_run_references, runsetup.h), each rank computing those of the
 * objects fp3_mpi_shard gives it (batches of `slots`), rank 0 gathering
 * them all into ref[] and ex[] (objects x state variables; the other
 * ranks' hold their shard's). */
void fp3_mpi_scene_references(const fp3_model *m, const fp3_mscene *sc, unsigned slots,
                              uint32_t steps, int want_ref, double *ref, double *ex);

/* fp3_run_state_frames (mscene.h), sharded frame by frame: every rank
 * calls it with the same arguments; every rank returns the whole scene's
 * result, equal to one process's.  Returns 0, or -1 on every rank with the
 * reason (naming the failing rank, host and objects) in msg. */
int fp3_mpi_run_state_frames(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                             uint32_t frames, int rest_skip, const fp3_state_wake *wake,
                             fpref_mode mode, const fp3_state_stepper *golden,
                             fp3_state_frames_result *res, char *msg, size_t n);

#endif /* FP3_MPISHARD_H */
