/*
 * mpishard.c -- fp3-mpi's ranks (mpishard.h): the sharding rule, the
 * sharded runs of many objects and of frames, the gathering on rank 0,
 * and the faults a test may inject (FP3_MPI_FAULT).
 *
 * Every rank parses the same command line, reads the same scene and
 * compiles the same program (cheap beside the runs), so only results
 * travel: per rank a fixed-size record of counts and messages (the ranks
 * run one build of fp3-mpi on machines of one kind, so the record goes as
 * bytes) and the objects' final states or register banks.
 */
#include "mpishard.h"

#include <inttypes.h>
#include <limits.h>
#include <mpi.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "report.h"
#include "runsetup.h"

#define HOST_LEN 64
#define MSG_LEN 512

static int g_rank, g_size = 1;
static char (*g_host)[HOST_LEN]; /* every rank's host name */

/* FP3_MPI_FAULT=KIND:OBJECT (mpishard.h) */
enum { FAULT_NONE, FAULT_ENGINE, FAULT_GOLDEN, FAULT_KILL };
static int g_fault = FAULT_NONE;
static size_t g_fault_obj;

static int parse_fault(void) {
  const char *v = getenv("FP3_MPI_FAULT");
  if (!v || !*v) return 0;
  static const char *const kinds[] = {"", "engine", "golden", "kill"};
  const char *colon = strchr(v, ':');
  char *end = NULL;
  for (int k = FAULT_ENGINE; colon && k <= FAULT_KILL; k++)
    if ((size_t)(colon - v) == strlen(kinds[k]) && strncmp(v, kinds[k], (size_t)(colon - v)) == 0) {
      unsigned long long o = strtoull(colon + 1, &end, 10);
      if (colon[1] >= '0' && colon[1] <= '9' && end && !*end) {
        g_fault = k;
        g_fault_obj = (size_t)o;
        return 0;
      }
    }
  fprintf(stderr, "fp3-mpi: FP3_MPI_FAULT='%s': not KIND:OBJECT, KIND one of engine, golden, "
          "kill, OBJECT a scene object's index\n", v);
  return -1;
}

int fp3_mpi_init(int *argc, char ***argv) {
  if (MPI_Init(argc, argv) != MPI_SUCCESS) { /* no MPI to agree on an exit status with */
    fprintf(stderr, "fp3-mpi: MPI_Init failed\n");
    exit(1);
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &g_rank);
  MPI_Comm_size(MPI_COMM_WORLD, &g_size);
  g_host = calloc((size_t)g_size, sizeof *g_host);
  char me[HOST_LEN + 1] = "";
  int len = 0;
  char name[MPI_MAX_PROCESSOR_NAME];
  if (MPI_Get_processor_name(name, &len) == MPI_SUCCESS) snprintf(me, HOST_LEN, "%.*s", HOST_LEN - 1, name);
  if (!g_host) {
    fprintf(stderr, "fp3-mpi: out of memory\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Allgather(me, HOST_LEN, MPI_CHAR, g_host, HOST_LEN, MPI_CHAR, MPI_COMM_WORLD);
  /* one report: rank 0's */
  if (g_rank != 0 && !freopen("/dev/null", "w", stdout)) {
    fprintf(stderr, "fp3-mpi: rank %d: cannot send standard output to /dev/null\n", g_rank);
    return -1;
  }
  return parse_fault();
}

int fp3_mpi_finish(int rc) {
  int all = rc;
  fflush(stdout);
  MPI_Allreduce(&rc, &all, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  free(g_host);
  return all;
}

/* CPU seconds of this process: a rank's rate that other load on its
 * machine does not change (the wall seconds do). */
static double cpu_seconds(void) {
  struct timespec t;
  return clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t) ? 0.0 : (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int fp3_mpi_rank(void) { return g_rank; }
int fp3_mpi_size(void) { return g_size; }

void fp3_mpi_shard(size_t nobj, unsigned slots, int rank, int size, size_t *lo, size_t *hi) {
  const size_t batches = (nobj + slots - 1) / slots;
  size_t b0 = batches * (size_t)rank / (size_t)size, b1 = batches * (size_t)(rank + 1) / (size_t)size;
  *lo = b0 * slots < nobj ? b0 * slots : nobj;
  *hi = b1 * slots < nobj ? b1 * slots : nobj;
}

/* ---- many objects ---------------------------------------------------------- */

/* The golden model of the rank's shard: object i is scene object lo + i.
 * It notes the last object started (the batch the engine runs next). */
typedef struct shard_golden {
  const fp3_state_golden *g;
  size_t lo, last;
  int flip; /* FP3_MPI_FAULT golden: the object being checked is the one */
} shard_golden;

static size_t shard_start(void *ctx, size_t obj, unsigned *reg, uint32_t *val, size_t max) {
  shard_golden *s = ctx;
  s->last = s->lo + obj;
  s->flip = g_fault == FAULT_GOLDEN && s->last == g_fault_obj;
  return s->g->start(s->g->ctx, s->lo + obj, reg, val, max);
}

static void shard_step(void *ctx, float *y) {
  shard_golden *s = ctx;
  s->g->step(s->g->ctx, y);
  if (s->flip && s->g->nstate) { /* the engine's value then differs in its lowest bit */
    uint32_t b = fpref_bits(y[0]) ^ 1u;
    y[0] = fpref_float(b);
  }
}

/* An engine that forwards to the rank's own, and fails (FP3_MPI_FAULT
 * engine) or dies (kill) when the batch holding the fault object starts. */
typedef struct fault_engine {
  fp3_engine head;
  fp3_engine *in;
  const shard_golden *sh;
} fault_engine;

static fp3_engine *inner(fp3_engine *e) { return ((fault_engine *)e)->in; }
static int pass_err(fp3_engine *e, int rc) {
  if (rc) snprintf(e->error, sizeof e->error, "%s", fp3_engine_error(inner(e)));
  return rc;
}
static int fe_load(fp3_engine *e, const uint64_t *w, size_t n) {
  return pass_err(e, fp3_engine_load(inner(e), w, n));
}
static int fe_write(fp3_engine *e, unsigned c, unsigned r, uint32_t v) {
  return pass_err(e, fp3_engine_write_ctx_reg(inner(e), c, r, v));
}
static int fe_read(fp3_engine *e, unsigned c, unsigned r, uint32_t *v) {
  return pass_err(e, fp3_engine_read_ctx_reg(inner(e), c, r, v));
}
static int fe_run(fp3_engine *e, uint32_t steps, unsigned k, const fp3_observer *obs,
                  fp3_status *st) {
  const size_t last = ((fault_engine *)e)->sh->last; /* the batch: last-k+1 .. last */
  if (g_fault_obj <= last && g_fault_obj + k > last) {
    if (g_fault == FAULT_KILL) raise(SIGKILL);
    snprintf(e->error, sizeof e->error, "the engine does not answer (FP3_MPI_FAULT=engine:%zu)",
             g_fault_obj);
    return -1;
  }
  return pass_err(e, fp3_engine_run_contexts(inner(e), steps, k, obs, st));
}
static int fe_status(fp3_engine *e, unsigned c, fp3_ctx_status *cs) {
  return pass_err(e, fp3_engine_ctx_status(inner(e), c, cs));
}
static void fe_destroy(fp3_engine *e) { (void)e; }
static const fp3_engine_ops fault_ops = {"fault", fe_load, fe_write, fe_read,
                                         fe_run, fe_status, fe_destroy};

/* What a rank tells rank 0 about its shard (sent as bytes). */
typedef struct rank_report {
  int32_t rc;
  char msg[MSG_LEN];
  uint64_t lo, hi;       /* its objects                                  */
  uint64_t work;         /* object-steps (frames: object-frames)         */
  double seconds, cpu;   /* on its engine, golden check included: wall, CPU */
  uint64_t failed_lo, failed_hi; /* the batch that failed (rc != 0)     */
  fp3_state_result r;    /* its result (y not sent in here)              */
} rank_report;

/* One line per rank on stderr (rank 0, after the run): its objects (for
 * frames, which change from frame to frame, none), its work and seconds. */
static void rank_lines(const char *what, const rank_report *rr, int size, int objects) {
  for (int r = 0; r < size; r++) {
    fprintf(stderr, "fp3-mpi: rank %d of %d (host %s): ", r, size, g_host[r]);
    if (objects && rr[r].hi > rr[r].lo)
      fprintf(stderr, "objects %" PRIu64 " .. %" PRIu64 ", ", rr[r].lo, rr[r].hi - 1);
    else if (objects)
      fprintf(stderr, "no objects, ");
    fprintf(stderr, "%" PRIu64 " %s in %.3f s, %.3f s of CPU (%.0f per second, %.0f per CPU "
            "second)\n", rr[r].work, what, rr[r].seconds, rr[r].cpu,
            rr[r].seconds > 0 ? (double)rr[r].work / rr[r].seconds : 0.0,
            rr[r].cpu > 0 ? (double)rr[r].work / rr[r].cpu : 0.0);
  }
}

int fp3_mpi_run_state_objects(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                              uint32_t steps, fpref_mode mode, const fp3_state_golden *golden,
                              fp3_state_result *res, char *msg, size_t n) {
  const unsigned slots = fp3_config_slots(&e->config);
  const unsigned ns = golden->nstate;
  size_t lo, hi;
  fp3_mpi_shard(nobj, slots, g_rank, g_size, &lo, &hi);
  shard_golden sh = {golden, lo, lo, 0};
  const fp3_state_golden sg = {&sh, ns, golden->reg, shard_start, shard_step};
  fault_engine fe = {{&fault_ops, e->config, "", e->progress}, e, &sh};
  fp3_engine *run_on = g_fault == FAULT_ENGINE || g_fault == FAULT_KILL ? &fe.head : e;
  rank_report me;
  memset(&me, 0, sizeof me);
  memset(res, 0, sizeof *res);
  me.lo = lo;
  me.hi = hi;
  double t0 = MPI_Wtime(), c0 = cpu_seconds();
  if (hi > lo) {
    me.rc = fp3_run_state_objects(run_on, words, nwords, hi - lo, steps, mode, &sg, res, me.msg,
                                  sizeof me.msg);
  } else { /* fewer batches than ranks: this one idles */
    res->contexts = e->config.num_contexts;
    res->lanes = e->config.num_lanes ? e->config.num_lanes : 1;
    res->first_object = res->error_object = res->nonfinite_object = SIZE_MAX;
  }
  me.seconds = MPI_Wtime() - t0;
  me.cpu = cpu_seconds() - c0;
  me.work = (uint64_t)(hi - lo) * steps;
  if (me.rc) {
    size_t b0 = sh.last - (sh.last - lo) % slots;
    me.failed_lo = b0;
    me.failed_hi = b0 + slots < hi ? b0 + slots : hi;
  }
  me.r = *res;
  me.r.y = NULL;
  rank_report *rr = NULL;
  if (g_rank == 0 && !(rr = calloc((size_t)g_size, sizeof *rr))) MPI_Abort(MPI_COMM_WORLD, 1);
  MPI_Gather(&me, (int)sizeof me, MPI_BYTE, rr, (int)sizeof me, MPI_BYTE, 0, MPI_COMM_WORLD);
  int bad = me.rc != 0, anybad = 0;
  MPI_Allreduce(&bad, &anybad, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (anybad) { /* no states to gather: every rank returns -1, rank 0 names the failures */
    if (g_rank == 0) {
      size_t at = 0;
      msg[0] = 0;
      for (int r = 0; r < g_size; r++)
        if (rr[r].rc && at < n)
          at += (size_t)snprintf(msg + at, n - at, "%srank %d of %d (host %s), objects %" PRIu64
                                 " .. %" PRIu64 ": %s", at ? "; " : "", r, g_size, g_host[r],
                                 rr[r].failed_lo, rr[r].failed_hi - 1, rr[r].msg);
      free(rr);
    } else {
      snprintf(msg, n, "%s", me.msg[0] ? me.msg : "another rank failed");
    }
    if (hi > lo && !me.rc) fp3_state_result_free(res);
    return -1;
  }
  /* the final states, in object order: rank r's block at lo_r * ns */
  int *counts = NULL, *displs = NULL;
  uint32_t *y = NULL;
  if (g_rank == 0) {
    counts = calloc((size_t)g_size, sizeof *counts);
    displs = calloc((size_t)g_size, sizeof *displs);
    y = calloc(nobj * (ns ? ns : 1), sizeof *y);
    if (!counts || !displs || !y || (double)nobj * ns > INT_MAX) MPI_Abort(MPI_COMM_WORLD, 1);
    for (int r = 0; r < g_size; r++) {
      counts[r] = (int)((rr[r].hi - rr[r].lo) * ns);
      displs[r] = (int)(rr[r].lo * ns);
    }
  }
  MPI_Gatherv(res->y, (int)((hi - lo) * ns), MPI_UINT32_T, y, counts, displs, MPI_UINT32_T, 0,
              MPI_COMM_WORLD);
  free(counts);
  free(displs);
  if (g_rank != 0) return 0;
  /* rank 0: the whole scene's result from the shards, in object order */
  fp3_state_result_free(res);
  memset(res, 0, sizeof *res);
  res->objects = nobj;
  res->contexts = rr[0].r.contexts;
  res->lanes = rr[0].r.lanes;
  res->first_object = res->error_object = res->nonfinite_object = SIZE_MAX;
  res->y = y;
  for (int r = 0; r < g_size; r++) {
    const fp3_state_result *q = &rr[r].r;
    const size_t off = rr[r].lo;
    res->batches += q->batches;
    res->cycles += q->cycles;
    res->issued += q->issued;
    res->stalls += q->stalls;
    for (int u = 0; u < FP3_NUM_UNITS; u++) res->unit_issued[u] += q->unit_issued[u];
    res->flags |= q->flags;
    if (q->error != FP3_ERR_NONE) {
      fprintf(stderr, "fp3-mpi: rank %d of %d (host %s): object %zu: run error %s at pc %" PRIu32
              "\n", r, g_size, g_host[r], off + q->error_object, fp3_error_name(q->error),
              q->error_pc);
      if (res->error == FP3_ERR_NONE) {
        res->error = q->error;
        res->error_object = off + q->error_object;
        res->error_pc = q->error_pc;
      }
    }
    if (q->mismatches) {
      fprintf(stderr, "fp3-mpi: rank %d of %d (host %s): object %zu: %" PRIu64 " golden "
              "mismatches, the first at integration %" PRIu32 "\n", r, g_size, g_host[r],
              off + q->first_object, q->mismatches, q->first_step);
      if (res->mismatches == 0) {
        res->first_object = off + q->first_object;
        res->first_step = q->first_step;
        res->first_var = q->first_var;
        res->first_got = q->first_got;
        res->first_want = q->first_want;
      }
      res->mismatches += q->mismatches;
    }
    if (q->nonfinite_object != SIZE_MAX && res->nonfinite_object == SIZE_MAX) {
      res->nonfinite_object = off + q->nonfinite_object;
      res->nonfinite_step = q->nonfinite_step;
      res->nonfinite_var = q->nonfinite_var;
    }
  }
  rank_lines("object-steps", rr, g_size, 1);
  /* the ranks' records, the states, and the references gathered next
   * (fp3_mpi_scene_references: two doubles a state variable) */
  const double moved =
      (double)g_size * sizeof *rr + (double)nobj * ns * (sizeof *y + 2 * sizeof(double));
  fprintf(stderr, "fp3-mpi: %d ranks, %.0f bytes gathered on rank 0 (%.1f per object)\n", g_size,
          moved, nobj ? moved / (double)nobj : 0.0);
  free(rr);
  return 0;
}

void fp3_mpi_scene_references(const fp3_model *m, const fp3_mscene *sc, unsigned slots,
                              uint32_t steps, int want_ref, double *ref, double *ex) {
  const unsigned np = m->nparam, ns = m->nstate;
  int want = want_ref;
  MPI_Bcast(&want, 1, MPI_INT, 0, MPI_COMM_WORLD);
  size_t lo, hi;
  fp3_mpi_shard(sc->n, slots, g_rank, g_size, &lo, &hi);
  for (size_t o = lo; o < hi; o++) {
    char rmsg[256];
    fp3_run_references(m, sc->in + o * np, sc->y0 + o * ns, steps, want, ref + o * ns,
                       ex + o * ns, rmsg, sizeof rmsg);
  }
  int *cnt = NULL, *dsp = NULL;
  if (g_rank == 0) {
    cnt = calloc((size_t)g_size, sizeof *cnt);
    dsp = calloc((size_t)g_size, sizeof *dsp);
    if (!cnt || !dsp || (double)sc->n * ns > INT_MAX) MPI_Abort(MPI_COMM_WORLD, 1);
    for (int r = 0; r < g_size; r++) {
      size_t a, b;
      fp3_mpi_shard(sc->n, slots, r, g_size, &a, &b);
      cnt[r] = (int)((b - a) * ns), dsp[r] = (int)(a * ns);
    }
  }
  /* in place on rank 0: its own shard is where the gathered one goes */
  const int mine = (int)((hi - lo) * ns);
  MPI_Gatherv(g_rank == 0 ? MPI_IN_PLACE : ref + lo * ns, mine, MPI_DOUBLE, ref, cnt, dsp,
              MPI_DOUBLE, 0, MPI_COMM_WORLD);
  MPI_Gatherv(g_rank == 0 ? MPI_IN_PLACE : ex + lo * ns, mine, MPI_DOUBLE, ex, cnt, dsp,
              MPI_DOUBLE, 0, MPI_COMM_WORLD);
  free(cnt), free(dsp);
}

/* ---- frames ------------------------------------------------------------------ */

/* What travels each frame: rank 0 sends every rank the indices and banks
 * of the awake objects of its batches; each rank sends back the banks,
 * which came back unchanged (stay), and a frame_report. */
typedef struct frame_report {
  int32_t rc;
  char msg[MSG_LEN];
  uint64_t failed_lo, failed_hi; /* scene objects of the batch that failed */
  double seconds, cpu;
  fp3_state_frames_result acc;   /* error_object: an index into its objects */
} frame_report;

typedef struct frames_farm {
  fp3_engine *e;
  unsigned nregs, slots;
  unsigned flip_reg;     /* FP3_MPI_FAULT golden: the register whose low bit flips */
  uint64_t *ids;         /* this frame's objects of this rank              */
  uint32_t *banks;       /* their banks                                    */
  unsigned char *stay;
  size_t cap;            /* objects the three buffers hold                 */
  rank_report *total;    /* rank 0: per rank, objects-frames and seconds   */
  double moved;          /* rank 0: bytes scattered and gathered           */
} frames_farm;

static int farm_room(frames_farm *f, size_t k) {
  if (k <= f->cap) return 0;
  uint64_t *ids = realloc(f->ids, k * sizeof *ids);
  if (ids) f->ids = ids;
  uint32_t *b = realloc(f->banks, k * f->nregs * sizeof *b);
  if (b) f->banks = b;
  unsigned char *s = realloc(f->stay, k);
  if (s) f->stay = s;
  if (!ids || !b || !s) return -1;
  f->cap = k;
  return 0;
}

/* This rank's k objects of the frame (ids, banks in f): run, with the
 * injected faults; the report in *fr. */
static void farm_local(frames_farm *f, size_t k, frame_report *fr) {
  memset(fr, 0, sizeof *fr);
  fr->acc.error_object = SIZE_MAX;
  double t0 = MPI_Wtime(), c0 = cpu_seconds();
  size_t *at = malloc((k ? k : 1) * sizeof *at);
  if (!at) {
    fr->rc = -1;
    snprintf(fr->msg, sizeof fr->msg, "out of memory");
    return;
  }
  for (size_t i = 0; i < k; i++) at[i] = i;
  size_t fault_at = SIZE_MAX;
  for (size_t i = 0; i < k && g_fault != FAULT_NONE; i++)
    if (f->ids[i] == g_fault_obj) fault_at = i;
  if (fault_at != SIZE_MAX && g_fault == FAULT_KILL) raise(SIGKILL);
  if (fault_at != SIZE_MAX && g_fault == FAULT_ENGINE) {
    fr->rc = -1;
    snprintf(fr->msg, sizeof fr->msg, "the engine does not answer (FP3_MPI_FAULT=engine:%zu)",
             g_fault_obj);
    size_t b0 = fault_at - fault_at % f->slots;
    fr->failed_lo = f->ids[b0];
    fr->failed_hi = f->ids[b0 + f->slots < k ? b0 + f->slots - 1 : k - 1] + 1;
  } else if (fp3_frame_batches(f->e, f->banks, at, k, f->stay, &fr->acc, fr->msg,
                               sizeof fr->msg)) {
    fr->rc = -1;
    if (k) fr->failed_lo = f->ids[0], fr->failed_hi = f->ids[k - 1] + 1;
  } else if (fault_at != SIZE_MAX && g_fault == FAULT_GOLDEN) {
    f->banks[fault_at * f->nregs + f->flip_reg] ^= 1u;
  }
  fr->seconds = MPI_Wtime() - t0;
  fr->cpu = cpu_seconds() - c0;
  free(at);
}

#define FRAMES_STOP UINT64_MAX

/* Rank 0's fp3_frames_farm.run: one frame's awake objects across the ranks. */
static int farm_run(void *ctx, uint32_t *bank, const size_t *at, size_t k, unsigned char *stay,
                    fp3_state_frames_result *acc, char *msg, size_t n) {
  frames_farm *f = ctx;
  uint64_t ctl = k;
  MPI_Bcast(&ctl, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
  int *cnt = calloc((size_t)g_size, sizeof *cnt), *dsp = calloc((size_t)g_size, sizeof *dsp);
  int *bcnt = calloc((size_t)g_size, sizeof *bcnt), *bdsp = calloc((size_t)g_size, sizeof *bdsp);
  uint64_t *ids = malloc((k ? k : 1) * sizeof *ids);
  uint32_t *banks = malloc((k ? k : 1) * f->nregs * sizeof *banks);
  frame_report *fr = calloc((size_t)g_size, sizeof *fr);
  if (!cnt || !dsp || !bcnt || !bdsp || !ids || !banks || !fr ||
      (double)k * f->nregs > INT_MAX)
    MPI_Abort(MPI_COMM_WORLD, 1); /* the other ranks wait in this frame's collectives */
  for (int r = 0; r < g_size; r++) {
    size_t lo, hi;
    fp3_mpi_shard(k, f->slots, r, g_size, &lo, &hi);
    cnt[r] = (int)(hi - lo), dsp[r] = (int)lo;
    bcnt[r] = cnt[r] * (int)f->nregs, bdsp[r] = dsp[r] * (int)f->nregs;
  }
  for (size_t i = 0; i < k; i++) {
    ids[i] = at[i];
    memcpy(banks + i * f->nregs, bank + at[i] * f->nregs, f->nregs * sizeof *banks);
  }
  size_t mine = (size_t)cnt[0];
  if (farm_room(f, mine)) MPI_Abort(MPI_COMM_WORLD, 1);
  MPI_Scatterv(ids, cnt, dsp, MPI_UINT64_T, f->ids, cnt[0], MPI_UINT64_T, 0, MPI_COMM_WORLD);
  MPI_Scatterv(banks, bcnt, bdsp, MPI_UINT32_T, f->banks, bcnt[0], MPI_UINT32_T, 0,
               MPI_COMM_WORLD);
  frame_report me;
  farm_local(f, mine, &me);
  MPI_Gather(&me, (int)sizeof me, MPI_BYTE, fr, (int)sizeof me, MPI_BYTE, 0, MPI_COMM_WORLD);
  MPI_Gatherv(f->banks, bcnt[0], MPI_UINT32_T, banks, bcnt, bdsp, MPI_UINT32_T, 0,
              MPI_COMM_WORLD);
  MPI_Gatherv(f->stay, cnt[0], MPI_BYTE, stay, cnt, dsp, MPI_BYTE, 0, MPI_COMM_WORLD);
  int rc = 0;
  size_t put = 0;
  msg[0] = 0;
  for (int r = 0; r < g_size; r++) {
    const fp3_state_frames_result *q = &fr[r].acc;
    f->total[r].work += q->object_frames;
    f->total[r].seconds += fr[r].seconds;
    f->total[r].cpu += fr[r].cpu;
    if (fr[r].rc) {
      rc = -1;
      if (put < n)
        put += (size_t)snprintf(msg + put, n - put, "%srank %d of %d (host %s), objects %" PRIu64
                                " .. %" PRIu64 ": %s", put ? "; " : "", r, g_size, g_host[r],
                                fr[r].failed_lo, fr[r].failed_hi - 1, fr[r].msg);
      continue;
    }
    acc->batches += q->batches;
    acc->cycles += q->cycles;
    acc->issued += q->issued;
    acc->object_frames += q->object_frames;
    acc->host_words += q->host_words;
    if (q->error != FP3_ERR_NONE) {
      size_t o = at[(size_t)dsp[r] + q->error_object];
      fprintf(stderr, "fp3-mpi: rank %d of %d (host %s): object %zu: run error %s at pc %" PRIu32
              "\n", r, g_size, g_host[r], o, fp3_error_name(q->error), q->error_pc);
      if (acc->error == FP3_ERR_NONE) {
        acc->error = q->error;
        acc->error_object = o;
        acc->error_pc = q->error_pc;
      }
    }
  }
  f->moved += (double)k * (sizeof *ids + 2.0 * f->nregs * sizeof *banks + 1.0) +
              (double)g_size * (sizeof ctl + sizeof *fr);
  if (!rc)
    for (size_t i = 0; i < k; i++)
      memcpy(bank + at[i] * f->nregs, banks + i * f->nregs, f->nregs * sizeof *banks);
  free(cnt), free(dsp), free(bcnt), free(bdsp), free(ids), free(banks), free(fr);
  return rc;
}

/* A rank other than 0: its share of each frame until rank 0 says stop. */
static void farm_worker(frames_farm *f, const uint64_t *words, size_t nwords) {
  int loaded = fp3_engine_load(f->e, words, nwords) == 0;
  for (;;) {
    uint64_t k;
    MPI_Bcast(&k, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    if (k == FRAMES_STOP) return;
    size_t lo, hi;
    fp3_mpi_shard((size_t)k, f->slots, g_rank, g_size, &lo, &hi);
    size_t mine = hi - lo;
    if (farm_room(f, mine)) MPI_Abort(MPI_COMM_WORLD, 1);
    MPI_Scatterv(NULL, NULL, NULL, MPI_UINT64_T, f->ids, (int)mine, MPI_UINT64_T, 0,
                 MPI_COMM_WORLD);
    MPI_Scatterv(NULL, NULL, NULL, MPI_UINT32_T, f->banks, (int)(mine * f->nregs),
                 MPI_UINT32_T, 0, MPI_COMM_WORLD);
    frame_report me;
    if (loaded) {
      farm_local(f, mine, &me);
    } else {
      memset(&me, 0, sizeof me);
      me.rc = -1;
      snprintf(me.msg, sizeof me.msg, "%s", fp3_engine_error(f->e));
      if (mine) me.failed_lo = f->ids[0], me.failed_hi = f->ids[mine - 1] + 1;
    }
    MPI_Gather(&me, (int)sizeof me, MPI_BYTE, NULL, 0, MPI_BYTE, 0, MPI_COMM_WORLD);
    MPI_Gatherv(f->banks, (int)(mine * f->nregs), MPI_UINT32_T, NULL, NULL, NULL, MPI_UINT32_T,
                0, MPI_COMM_WORLD);
    MPI_Gatherv(f->stay, (int)mine, MPI_BYTE, NULL, NULL, NULL, MPI_BYTE, 0, MPI_COMM_WORLD);
  }
}

int fp3_mpi_run_state_frames(fp3_engine *e, const uint64_t *words, size_t nwords, size_t nobj,
                             uint32_t frames, int rest_skip, const fp3_state_wake *wake,
                             fpref_mode mode, const fp3_state_stepper *golden,
                             fp3_state_frames_result *res, char *msg, size_t n) {
  frames_farm f;
  memset(&f, 0, sizeof f);
  f.e = e;
  f.nregs = e->config.num_regs;
  f.slots = fp3_config_slots(&e->config);
  f.flip_reg = golden->nstate ? golden->reg[0] : 0;
  int rc = 0;
  if (g_rank == 0) {
    f.total = calloc((size_t)g_size, sizeof *f.total);
    if (!f.total) MPI_Abort(MPI_COMM_WORLD, 1);
    const fp3_frames_farm farm = {&f, farm_run};
    rc = fp3_run_state_frames_farm(e, words, nwords, nobj, frames, rest_skip, wake, mode, golden,
                                   &farm, res, msg, n);
    uint64_t stop = FRAMES_STOP;
    MPI_Bcast(&stop, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    if (!rc) {
      rank_lines("object-frames", f.total, g_size, 0);
      fprintf(stderr, "fp3-mpi: %d ranks, %.0f bytes scattered from and gathered on rank 0 "
              "(%.1f per object-frame run)\n", g_size, f.moved,
              res->object_frames ? f.moved / (double)res->object_frames : 0.0);
    }
    free(f.total);
  } else {
    farm_worker(&f, words, nwords);
  }
  /* every rank reports what rank 0 found */
  int32_t rc32 = g_rank == 0 ? rc : 0;
  MPI_Bcast(&rc32, 1, MPI_INT32_T, 0, MPI_COMM_WORLD);
  MPI_Bcast(res, (int)sizeof *res, MPI_BYTE, 0, MPI_COMM_WORLD);
  MPI_Bcast(msg, (int)n, MPI_CHAR, 0, MPI_COMM_WORLD);
  free(f.ids), free(f.banks), free(f.stay);
  return rc32;
}
