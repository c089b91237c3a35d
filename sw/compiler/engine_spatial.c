/*
 * engine_spatial.c -- the spatial engine (engine_spatial.h): the chip of a
 * compiled model's pipeline, Verilated on first use into a cached shared
 * object, loaded with dlopen and driven over AXI4-Lite.
 *
 * Why dlopen: the pipeline is generated at run time, one per model,
 * integrator and core options, so it cannot be linked into build/fp3; a
 * shared object built once and loaded into the process keeps a clock
 * cycle a function call (the Verilated model's speed) and needs no second
 * process or protocol.  The object carries its own Verilator runtime
 * (libverilated.a, built position-independent with it) and is linked
 * with -Bsymbolic and loaded RTLD_LOCAL, so it never binds to the
 * runtime that build/fp3 links for the processor's models.
 */
#define _GNU_SOURCE /* nftw, popen, dlopen's RTLD_* */
#include "engine_spatial.h"

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <glob.h>
#include <inttypes.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "report.h"
#include "fp3_spatial_regs.h"
#include "spatial.h"
#include "spatial_top.h"

extern char **environ;

#define LOG_TAIL 12 /* lines of a failed build's log shown */

/* The shim's entry points (sim/spatial_shim.cpp). */
typedef struct shim {
  void *dl;
  void *(*create)(void);
  void (*destroy)(void *);
  void (*reset)(void *);
  int (*write)(void *, uint32_t, uint32_t);
  int (*read)(void *, uint32_t, uint32_t *);
  size_t (*read_many)(void *, const uint32_t *, size_t, uint32_t *, int *);
  uint64_t (*cycles)(void *);
  int (*trace)(void *, unsigned, unsigned,
               void (*)(void *, uint32_t, const uint32_t *, unsigned, uint64_t), void *);
  void *dut;           /* the chip, once created                          */
  unsigned sstride, istride; /* the windows' object strides (STRIDES)     */
} shim;

typedef struct spatial_engine {
  fp3_engine base;
  fp3_compiled *c;
  fp3_spatial *sp;
  char *top_text;     /* the chip top's Verilog (fp3_spatial_top)       */
  unsigned nin, nc, lat, nregs, ncores;
  unsigned pipelines; /* the chip's pipelines N                        */
  unsigned slots;     /* object slots: FP3_SPATIAL_SLOTS rounded up to a
                         multiple of N (the frame's M)                   */
  int *in_reg;        /* register of each word of in_i                 */
  unsigned *y_reg;    /* register of each carried value                */
  uint32_t *bank;     /* slots x nregs                                 */
  unsigned char *dirty; /* per slot: the host wrote its bank since the
                           chip's copy was last synchronised             */
  uint32_t *steps_done; /* per slot, of the last run                    */
  uint32_t *rd_addr, *rd_data; /* the state window's words of every slot */
  int *rd_resp;
  unsigned awake_n;   /* awake-list entries 0 .. awake_n-1 hold i       */
  uint32_t count_reg, steps_reg; /* COUNT and STEPS as last written     */
  uint64_t ops[FP3_NUM_UNITS]; /* operations per object-step, by unit   */
  char entry[4096];   /* the cache folder of this pipeline             */
  shim sh;
} spatial_engine;

static spatial_engine *of(fp3_engine *e) { return (spatial_engine *)e; }

/* ---- files and commands ------------------------------------------------------ */

/* FNV-1a 64 of a file's bytes into *h; -1 if it cannot be read. */
static int hash_file(uint64_t *h, const char *path) {
  FILE *f = fopen(path, "rb");
  if (!f) return -1;
  char buf[65536];
  size_t k;
  while ((k = fread(buf, 1, sizeof buf, f)) > 0) *h = fp3_fnv1a64(*h, buf, k);
  int bad = ferror(f);
  fclose(f);
  return bad ? -1 : 0;
}

static int rm_one(const char *path, const struct stat *sb, int flag, struct FTW *ftw) {
  (void)sb, (void)flag, (void)ftw;
  return remove(path);
}

/* Remove a folder and everything in it (quietly: what is left is only a
 * stale temporary). */
static void rm_tree(const char *dir) { nftw(dir, rm_one, 16, FTW_DEPTH | FTW_PHYS); }

static double now(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Run argv (searched on PATH) with stdin from /dev/null and stdout and
 * stderr appended to log.  0 when it exits 0; 127 when it cannot be
 * started; else its exit status (or 128 + signal). */
static int run_cmd(char *const argv[], const char *log) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, log, O_WRONLY | O_CREAT | O_APPEND, 0666);
  posix_spawn_file_actions_adddup2(&fa, 1, 2);
  pid_t pid;
  int rc = posix_spawnp(&pid, argv[0], &fa, NULL, argv, environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) return 127;
  int st;
  while (waitpid(pid, &st, 0) < 0)
    if (errno != EINTR) return 127;
  if (WIFEXITED(st)) return WEXITSTATUS(st);
  return 128 + (WIFSIGNALED(st) ? WTERMSIG(st) : 0);
}

/* The first line a command prints on stdout ("" on failure). */
static void cmd_line(const char *cmd, char *out, size_t n) {
  out[0] = '\0';
  FILE *p = popen(cmd, "r");
  if (!p) return;
  if (fgets(out, (int)n, p)) out[strcspn(out, "\n")] = '\0';
  pclose(p);
}

/* The last LOG_TAIL lines of a log, indented, into out. */
static void log_tail(const char *log, char *out, size_t n) {
  out[0] = '\0';
  FILE *f = fopen(log, "r");
  if (!f) return;
  char lines[LOG_TAIL][160];
  unsigned k = 0;
  while (fgets(lines[k % LOG_TAIL], sizeof lines[0], f)) k++;
  fclose(f);
  size_t used = 0;
  for (unsigned i = k > LOG_TAIL ? k - LOG_TAIL : 0; i < k && used < n; i++) {
    int w = snprintf(out + used, n - used, "\n  %s", lines[i % LOG_TAIL]);
    if (w < 0) break;
    used += (size_t)w;
    if (used && used < n && out[used - 1] == '\n') out[--used] = '\0';
  }
}

/* ---- the cache entry ------------------------------------------------------------ */

/* What one entry is built from: the step module, the chip top, the
 * Verilator that builds them. */
typedef struct build {
  const fp3_spatial_env *env;
  const char *module, *verilog; /* the step module                      */
  const char *top, *top_verilog; /* the chip top around it              */
  uint64_t text_hash;            /* FNV-1a 64 of the step's text         */
  unsigned pipelines, nin, nc, lat, objects;
  const char *verilator; /* the Verilator command (fp3_spatial_env.verilator) */
  char vroot[1024]; /* VERILATOR_ROOT */
  char vversion[128];
  char cxx[256]; /* the model's C++ compiler (fp3_spatial_env.cxx)      */
} build;

/* The cache key: the cache version, the Verilator version, the C++
 * compiler, the module's shape and name, the step module's and the chip
 * top's text, the shim, every rtl/ file.  0, or -1 if a file cannot be
 * read. */
static int cache_key(const build *b, uint64_t *key, char *err, size_t n) {
  uint64_t h = FP3_FNV1A64_BASIS;
  char line[512];
  snprintf(line, sizeof line, "fp3-spatial-cache %d|%s|%s|%u|%u|%s", FP3_SPATIAL_CACHE_VERSION,
           b->vversion, b->cxx, b->nin, b->nc, b->module);
  h = fp3_fnv1a64(h, line, strlen(line));
  h = fp3_fnv1a64(h, b->verilog, strlen(b->verilog));
  h = fp3_fnv1a64(h, b->top_verilog, strlen(b->top_verilog));
  char path[4096];
  snprintf(path, sizeof path, "%s/sim/spatial_shim.cpp", b->env->root);
  if (hash_file(&h, path)) {
    snprintf(err, n, "%s: %s", path, strerror(errno));
    return -1;
  }
  /* the cores and everything they instantiate or include: every .v and
   * .vh of rtl/, in glob's sorted order */
  static const char *const pat[] = {"%s/rtl/*.v", "%s/rtl/*.vh"};
  for (size_t p = 0; p < sizeof pat / sizeof pat[0]; p++) {
    glob_t g;
    snprintf(path, sizeof path, pat[p], b->env->root);
    if (glob(path, 0, NULL, &g) != 0) continue; /* no .vh is fine */
    for (size_t i = 0; i < g.gl_pathc; i++) {
      h = fp3_fnv1a64(h, g.gl_pathv[i], strlen(g.gl_pathv[i]) + 1);
      if (hash_file(&h, g.gl_pathv[i])) {
        snprintf(err, n, "%s: %s", g.gl_pathv[i], strerror(errno));
        globfree(&g);
        return -1;
      }
    }
    globfree(&g);
  }
  *key = h;
  return 0;
}

/* An entry's manifest: the cache version, the module, its text's hash,
 * the shared object's size and FNV-1a 64, the module's shape. */
#define MANIFEST                                                                            \
  "fp3-spatial-cache %d\nmodule %s\nhash %016" PRIx64 "\nso_size %lld\nso_hash %016" PRIx64 \
  "\ninputs %u\ncarried %u\n"

/* The manifest of the shared object `so` built for b: its size and
 * FNV-1a 64 with the module's shape (MANIFEST) into text; *size and
 * *so_hash for a message.  0, or -1 with errno when the object cannot be
 * read. */
static int manifest_of(const char *so, const build *b, char *text, size_t n, long long *size,
                       uint64_t *so_hash) {
  struct stat sb;
  *so_hash = FP3_FNV1A64_BASIS;
  if (stat(so, &sb) != 0 || hash_file(so_hash, so)) return -1;
  *size = (long long)sb.st_size;
  snprintf(text, n, MANIFEST, FP3_SPATIAL_CACHE_VERSION, b->module, b->text_hash, *size,
           *so_hash, b->nin, b->nc);
  return 0;
}

/* Check an entry's files before loading anything: its manifest must be
 * the one this module's build writes, the shared object the size and
 * hash the manifest records (a cut or replaced object never reaches
 * dlopen, which may crash on it).  0, or -1 with the reason. */
static int entry_check(const char *entry, const build *b, char *err, size_t n) {
  char path[4400], text[1024], want[1024];
  snprintf(path, sizeof path, "%s/manifest", entry);
  FILE *f = fopen(path, "r");
  if (!f) {
    snprintf(err, n, "no manifest: %s", strerror(errno));
    return -1;
  }
  size_t k = fread(text, 1, sizeof text - 1, f);
  fclose(f);
  text[k] = '\0';
  snprintf(path, sizeof path, "%s/spatial.so", entry);
  uint64_t so_hash;
  long long size;
  if (manifest_of(path, b, want, sizeof want, &size, &so_hash)) {
    snprintf(err, n, "spatial.so: %s", strerror(errno));
    return -1;
  }
  if (strcmp(text, want) != 0) {
    snprintf(err, n, "spatial.so (%lld bytes, FNV-1a %016" PRIx64 ") or the manifest is not "
             "what this module's build wrote", size, so_hash);
    return -1;
  }
  return 0;
}

/* Load the shared object of an entry: every symbol.  0, or -1 with the
 * reason. */
static int shim_load(shim *s, const char *so, char *err, size_t n) {
  memset(s, 0, sizeof *s);
  s->dl = dlopen(so, RTLD_NOW | RTLD_LOCAL);
  if (!s->dl) {
    snprintf(err, n, "dlopen: %s", dlerror());
    return -1;
  }
  struct {
    const char *name;
    void **fn;
  } sym[] = {{"fp3_spatial_shim_new", (void **)&s->create},
             {"fp3_spatial_shim_free", (void **)&s->destroy},
             {"fp3_spatial_shim_reset", (void **)&s->reset},
             {"fp3_spatial_shim_write", (void **)&s->write},
             {"fp3_spatial_shim_read", (void **)&s->read},
             {"fp3_spatial_shim_read_many", (void **)&s->read_many},
             {"fp3_spatial_shim_cycles", (void **)&s->cycles},
             {"fp3_spatial_shim_trace", (void **)&s->trace}};
  for (size_t i = 0; i < sizeof sym / sizeof sym[0]; i++)
    if (!(*sym[i].fn = dlsym(s->dl, sym[i].name))) {
      snprintf(err, n, "no symbol %s", sym[i].name);
      dlclose(s->dl);
      s->dl = NULL;
      return -1;
    }
  return 0;
}

/* One AXI4-Lite transfer of word address wa: 0, or -1 with the chip's
 * answer (SLVERR, none) in err. */
static int ax_write(shim *s, uint32_t wa, uint32_t v, char *err, size_t n) {
  int r = s->write(s->dut, FP3S_BYTE(wa), v);
  if (r == 0) return 0;
  snprintf(err, n, "the chip answered %s to a write of word 0x%06" PRIX32,
           r < 0 ? "nothing" : r == 2 ? "SLVERR" : "an error", wa);
  return -1;
}

static int ax_read(shim *s, uint32_t wa, uint32_t *v, char *err, size_t n) {
  int r = s->read(s->dut, FP3S_BYTE(wa), v);
  if (r == 0) return 0;
  snprintf(err, n, "the chip answered %s to a read of word 0x%06" PRIX32,
           r < 0 ? "nothing" : r == 2 ? "SLVERR" : "an error", wa);
  return -1;
}

/* Create the loaded chip and check what it says it is through its
 * registers: ID, HASH (the step's text hash, low word), INFO (one
 * pipeline, the step's inputs and carried values), LATENCY, MAXOBJ; keep
 * the STRIDES.  0, or -1 with the reason (the chip freed). */
static int chip_check(shim *s, const build *b, char *err, size_t n) {
  if (!(s->dut = s->create())) {
    snprintf(err, n, "out of memory for the Verilated chip");
    return -1;
  }
  uint32_t id, hash, info, lat, maxobj, strides;
  if (ax_read(s, FP3S_ID, &id, err, n) || ax_read(s, FP3S_HASH, &hash, err, n) ||
      ax_read(s, FP3S_INFO, &info, err, n) || ax_read(s, FP3S_LATENCY, &lat, err, n) ||
      ax_read(s, FP3S_MAXOBJ, &maxobj, err, n) || ax_read(s, FP3S_STRIDES, &strides, err, n))
    goto bad;
  if (id != FP3S_ID_VALUE) {
    snprintf(err, n, "its ID is 0x%08" PRIX32 ", not a spatial chip's 0x%08X", id,
             FP3S_ID_VALUE);
    goto bad;
  }
  if (hash != (uint32_t)b->text_hash) {
    snprintf(err, n, "its HASH is %08" PRIx32 ", the module's %08" PRIx32, hash,
             (uint32_t)b->text_hash);
    goto bad;
  }
  if (FP3S_INFO_PIPELINES(info) != b->pipelines || FP3S_INFO_INPUTS(info) != b->nin ||
      FP3S_INFO_CARRIED(info) != b->nc || lat != b->lat || maxobj != b->objects) {
    snprintf(err, n, "its INFO 0x%08" PRIX32 ", LATENCY %" PRIu32 " and MAXOBJ %" PRIu32
             " are not the module's (%u pipelines, %u inputs, %u carried; %u; %u)", info, lat,
             maxobj, b->pipelines, b->nin, b->nc, b->lat, b->objects);
    goto bad;
  }
  s->sstride = FP3S_STATE_STRIDE(strides);
  s->istride = FP3S_INPUT_STRIDE(strides);
  return 0;
bad:
  s->destroy(s->dut);
  s->dut = NULL;
  return -1;
}

/* One build stage: say it, run it, say its time.  0, or -1 with what
 * failed in err. */
static int stage(const build *b, int k, int of_n, const char *what, char *const argv[],
                 const char *log, char *err, size_t n) {
  const double t0 = now();
  fprintf(stderr, "%s:   [%d/%d] %s ...", b->env->label, k, of_n, what);
  fflush(stderr);
  int rc = run_cmd(argv, log);
  if (rc == 0) {
    fprintf(stderr, " %.1f s\n", now() - t0);
    return 0;
  }
  fprintf(stderr, " failed\n");
  if (rc == 127)
    snprintf(err, n, "%s: cannot run %s (not installed? scripts/setup.sh installs it)", what,
             argv[0]);
  else
    snprintf(err, n, "%s failed (exit %d)", what, rc);
  return -1;
}

/* Build the entry into a temporary folder of the cache and rename it to
 * final.  0, or -1 with the reason (the temporary is then removed, the
 * log kept beside the cache as final.failed.log). */
static int build_entry(const build *b, const char *final, char *err, size_t n) {
  const fp3_spatial_env *env = b->env;
  char tmp[4200], obj[4300], vfile[4400], tfile[4400], log[4300], so[4300], man[4300];
  snprintf(tmp, sizeof tmp, "%s.tmp.%ld", final, (long)getpid());
  rm_tree(tmp);
  if (mkdir(tmp, 0777) != 0) {
    snprintf(err, n, "%s: %s", tmp, strerror(errno));
    return -1;
  }
  snprintf(obj, sizeof obj, "%s/obj", tmp);
  snprintf(vfile, sizeof vfile, "%s/%s.v", tmp, b->module);
  snprintf(tfile, sizeof tfile, "%s/%s.v", tmp, b->top);
  snprintf(log, sizeof log, "%s/build.log", tmp);
  snprintf(so, sizeof so, "%s/spatial.so", tmp);
  snprintf(man, sizeof man, "%s/manifest", tmp);
  char rtl[4200], top[200], inc1[1100], inc2[1100], inc3[4400], shimsrc[4200], mkf[64],
      mkdir_obj[4400];
  snprintf(rtl, sizeof rtl, "-I%s/rtl", env->root);
  snprintf(top, sizeof top, "%s", b->top);
  snprintf(inc1, sizeof inc1, "-I%s/include", b->vroot);
  snprintf(inc2, sizeof inc2, "-I%s/include/vltstd", b->vroot);
  snprintf(inc3, sizeof inc3, "-I%s", obj);
  snprintf(shimsrc, sizeof shimsrc, "%s/sim/spatial_shim.cpp", env->root);
  snprintf(mkf, sizeof mkf, "Vspatial.mk");
  snprintf(mkdir_obj, sizeof mkdir_obj, "%s", obj);
  char msg[256];
  if (fp3_write_text_atomic(vfile, b->verilog, msg, sizeof msg) ||
      fp3_write_text_atomic(tfile, b->top_verilog, msg, sizeof msg)) {
    snprintf(err, n, "%s", msg);
    rm_tree(tmp);
    return -1;
  }
  const char *verilator = b->verilator;
  /* --inline-mult 1: Verilator keeps the cores and the step module as
   * modules of their own instead of inlining them into one function of
   * straight-line code, bound by fetching its instructions: the 4-pipeline
   * folded ship chip then runs in about 14 % less CPU time (perf, clang++)
   * and compiles 2 to 5 times faster (g++: 16 s against 91 s). */
  char *verilate[] = {(char *)verilator, "--cc", "-O3", "--inline-mult", "1",
                      "--x-assign", "fast", "--x-initial", "fast", "--noassert",
                      "-Wno-fatal", rtl, "-y", rtl + 2,
                      "--top-module", top, "--prefix", "Vspatial", "--Mdir", obj,
                      "-CFLAGS", "-fPIC", tfile, vfile, NULL};
  char cxx[300], what_cc[320];
  snprintf(cxx, sizeof cxx, "CXX=%s", b->cxx);
  snprintf(what_cc, sizeof what_cc, "compile the model (%s)", b->cxx);
  char *make[] = {"make", "-s", "-C", mkdir_obj, "-f", mkf, "VM_PARALLEL_BUILDS=0", cxx,
                  "OPT_FAST=-O2", "OPT_SLOW=-O1", "OPT_GLOBAL=-O2", "Vspatial__ALL.a",
                  "verilated.o", "verilated_threads.o", NULL};
  char all[4400], rt1[4400], rt2[4400];
  snprintf(all, sizeof all, "%s/Vspatial__ALL.a", obj);
  snprintf(rt1, sizeof rt1, "%s/verilated.o", obj);
  snprintf(rt2, sizeof rt2, "%s/verilated_threads.o", obj);
  char *link[] = {"g++", "-shared", "-fPIC", "-O2", "-std=c++17", "-faligned-new", inc1,
                  inc2, inc3, shimsrc, all, rt1, rt2, "-o", so,
                  "-Wl,-Bsymbolic", "-pthread", "-latomic", NULL};
  const double t0 = now();
  if (stage(b, 1, 3, "verilate", verilate, log, err, n) ||
      stage(b, 2, 3, what_cc, make, log, err, n) ||
      stage(b, 3, 3, "link the shared object", link, log, err, n)) {
    /* the log outlives the temporary: its path and last lines */
    char kept[4400], tail[LOG_TAIL * 170];
    snprintf(kept, sizeof kept, "%s.failed.log", final);
    const char *at = rename(log, kept) == 0 ? kept : log;
    log_tail(at, tail, sizeof tail);
    size_t used = strlen(err);
    snprintf(err + used, n - used, "; log %s:%s", at, tail);
    rm_tree(tmp);
    return -1;
  }
  /* the object files are not needed once linked */
  rm_tree(obj);
  char mtext[1024];
  uint64_t so_hash;
  long long size;
  if (manifest_of(so, b, mtext, sizeof mtext, &size, &so_hash)) {
    snprintf(err, n, "%s: %s", so, strerror(errno));
    rm_tree(tmp);
    return -1;
  }
  if (fp3_write_text_atomic(man, mtext, msg, sizeof msg)) {
    snprintf(err, n, "%s", msg);
    rm_tree(tmp);
    return -1;
  }
  if (rename(tmp, final) != 0) {
    if (errno == EEXIST || errno == ENOTEMPTY) { /* a concurrent build won */
      fprintf(stderr, "%s: another process built %s meanwhile: using it\n", env->label, final);
      rm_tree(tmp);
      return 0;
    }
    snprintf(err, n, "rename %s to %s: %s", tmp, final, strerror(errno));
    rm_tree(tmp);
    return -1;
  }
  char stale[4400]; /* an earlier build's failure log is history now */
  snprintf(stale, sizeof stale, "%s.failed.log", final);
  unlink(stale);
  fprintf(stderr, "%s: built %s in %.1f s\n", env->label, final, now() - t0);
  return 0;
}

/* Find, check, or build and load the entry of b into s.  0, or -1. */
static int cache_open(const build *b, const char *model, const char *integ, shim *s,
                      char *entry, size_t en, char *err, size_t n) {
  const fp3_spatial_env *env = b->env;
  uint64_t key;
  if (cache_key(b, &key, err, n)) return -1;
  if (mkdir(env->cache, 0777) != 0 && errno != EEXIST) {
    snprintf(err, n, "cache folder %s: %s", env->cache, strerror(errno));
    return -1;
  }
  snprintf(entry, en, "%s/%s-%016" PRIx64, env->cache, b->module, key);
  char so[4300], why[512];
  snprintf(so, sizeof so, "%s/spatial.so", entry);
  struct stat sb;
  int loaded = 0; /* an unusable object was loaded into this process */
  if (stat(entry, &sb) == 0) {
    if (entry_check(entry, b, why, sizeof why) == 0 && shim_load(s, so, why, sizeof why) == 0) {
      loaded = 1;
      if (chip_check(s, b, why, sizeof why) == 0) return 0;
    }
    /* unusable: moved aside (atomically, so a concurrent reader sees it
     * whole or not at all), removed, built again */
    fprintf(stderr, "%s: cache entry %s is unusable (%s): building it again\n", env->label,
            entry, why);
    char aside[4400];
    snprintf(aside, sizeof aside, "%s.stale.%ld", entry, (long)getpid());
    if (rename(entry, aside) == 0) rm_tree(aside);
  }
  fprintf(stderr, "%s: building %s %s (Verilator) into %s\n", env->label, model, integ, entry);
  if (build_entry(b, entry, err, n)) return -1;
  /* the dynamic loader knows a loaded object by its path: the new one,
   * after an unusable one was loaded, by another spelling of it */
  if (loaded) snprintf(so, sizeof so, "%s/./spatial.so", entry);
  if (shim_load(s, so, why, sizeof why) || chip_check(s, b, why, sizeof why)) {
    snprintf(err, n, "%s: the new build does not load: %s", so, why);
    return -1;
  }
  return 0;
}

/* ---- the engine ----------------------------------------------------------------- */

static int sp_load(fp3_engine *e, const uint64_t *words, size_t n) {
  spatial_engine *s = of(e);
  const fp3_image *img = fp3_compiled_image(s->c);
  if (n != img->n || memcmp(words, img->words, n * sizeof *words) != 0) {
    snprintf(e->error, sizeof e->error,
             "the spatial engine runs only the compiled model it was built for (%s); this "
             "program is another", fp3_spatial_module(s->sp));
    return -1;
  }
  return 0;
}

static int sp_write(fp3_engine *e, unsigned ctx, unsigned reg, uint32_t v) {
  spatial_engine *s = of(e);
  if (ctx >= s->slots || reg >= s->nregs) {
    snprintf(e->error, sizeof e->error, "slot %u register %u is beyond the engine's %u x %u",
             ctx, reg, s->slots, s->nregs);
    return -1;
  }
  s->bank[(size_t)ctx * s->nregs + reg] = v;
  s->dirty[ctx] = 1;
  return 0;
}

static int sp_read(fp3_engine *e, unsigned ctx, unsigned reg, uint32_t *v) {
  spatial_engine *s = of(e);
  if (ctx >= s->slots || reg >= s->nregs) {
    snprintf(e->error, sizeof e->error, "slot %u register %u is beyond the engine's %u x %u",
             ctx, reg, s->slots, s->nregs);
    return -1;
  }
  *v = s->bank[(size_t)ctx * s->nregs + reg];
  return 0;
}

/* The engine's error: what failed, and the chip's answer in m. */
static int sp_fail(fp3_engine *e, const char *m) {
  snprintf(e->error, sizeof e->error, "%s", m);
  return -1;
}

/* Bring the chip's copy of slots 0 .. n-1 up to their banks: the inputs
 * and carried values of each slot the host wrote; the awake list 0 ..
 * n-1 (the identity: one pipeline); COUNT = n.  0, or -1. */
static int sync_slots(spatial_engine *s, unsigned n, char *m, size_t mn) {
  shim *sh = &s->sh;
  for (unsigned o = 0; o < n; o++) {
    if (!s->dirty[o]) continue;
    const uint32_t *bank = s->bank + (size_t)o * s->nregs;
    for (unsigned k = 0; k < s->nin; k++)
      if (ax_write(sh, FP3S_INPUT_BASE + o * sh->istride + k, bank[s->in_reg[k]], m, mn))
        return -1;
    for (unsigned w = 0; w < s->nc; w++)
      if (ax_write(sh, FP3S_STATE_BASE + o * sh->sstride + w, bank[s->y_reg[w]], m, mn))
        return -1;
    s->dirty[o] = 0;
  }
  for (; s->awake_n < n; s->awake_n++)
    if (ax_write(sh, FP3S_AWAKE_BASE + s->awake_n, s->awake_n, m, mn)) return -1;
  if (s->count_reg != n) {
    if (ax_write(sh, FP3S_COUNT, n, m, mn)) return -1;
    s->count_reg = n;
  }
  return 0;
}

/* One run of the chip: START, STATUS polled until DONE (at most `limit`
 * cycles), its CYCLES added to *cycles and its FLAGS ORed into *flags.
 * 0, or -1. */
static int chip_run(spatial_engine *s, uint64_t limit, uint64_t *cycles, uint32_t *flags,
                    char *m, size_t mn) {
  shim *sh = &s->sh;
  uint32_t status = 0, lo, hi, fl;
  if (ax_write(sh, FP3S_CTRL, FP3S_CTRL_START, m, mn)) return -1;
  const uint64_t t0 = sh->cycles(sh->dut);
  do {
    if (ax_read(sh, FP3S_STATUS, &status, m, mn)) return -1;
    if (sh->cycles(sh->dut) - t0 > limit) {
      snprintf(m, mn, "the chip hung: no DONE %" PRIu64 " cycles after START", limit);
      return -1;
    }
  } while (!(status & FP3S_STATUS_DONE));
  if (ax_read(sh, FP3S_CYCLES_LO, &lo, m, mn) || ax_read(sh, FP3S_CYCLES_HI, &hi, m, mn) ||
      ax_read(sh, FP3S_FLAGS, &fl, m, mn))
    return -1;
  *cycles += (uint64_t)hi << 32 | lo;
  *flags |= fl;
  return 0;
}

/* Every carried value of slots 0 .. n-1 from the state window into
 * rd_data[o * nc + w], the reads back to back.  0, or -1. */
static int read_states(spatial_engine *s, unsigned n, char *m, size_t mn) {
  shim *sh = &s->sh;
  const size_t words = (size_t)n * s->nc;
  for (unsigned o = 0; o < n; o++)
    for (unsigned w = 0; w < s->nc; w++)
      s->rd_addr[(size_t)o * s->nc + w] = FP3S_BYTE(FP3S_STATE_BASE + o * sh->sstride + w);
  const size_t got = sh->read_many(sh->dut, s->rd_addr, words, s->rd_data, s->rd_resp);
  for (size_t i = 0; i < words; i++)
    if (i >= got || s->rd_resp[i] != 0) {
      snprintf(m, mn, "the chip answered %s to a read of word 0x%06" PRIX32,
               i >= got ? "nothing" : s->rd_resp[i] == 2 ? "SLVERR" : "an error",
               s->rd_addr[i] / 4);
      return -1;
    }
  return 0;
}

/* What the trace callback needs during a run. */
typedef struct trace_run {
  spatial_engine *s;
  const fp3_observer *obs;
  unsigned n;         /* slots of the run                                 */
  uint32_t steps;     /* K                                                */
  uint64_t t0;        /* the shim's cycle at START                        */
  int bad;            /* 1: a write-back of no slot of the run; 2: one too many */
  uint32_t bad_obj;
} trace_run;

/* One write-back from the trace port: the object's k-th of the run is its
 * state after integration k (the frame writes each awake object back once
 * a step, in step order); into its bank, and to the observer. */
static void on_trace(void *ctx, uint32_t obj, const uint32_t *y, unsigned nc, uint64_t cycle) {
  trace_run *tr = ctx;
  spatial_engine *s = tr->s;
  if (obj >= tr->n || s->steps_done[obj] >= tr->steps || nc != s->nc) {
    if (!tr->bad) {
      tr->bad_obj = obj;
      tr->bad = obj >= tr->n || nc != s->nc ? 1 : 2;
    }
    return;
  }
  const uint32_t k = ++s->steps_done[obj];
  uint32_t *bank = s->bank + (size_t)obj * s->nregs;
  for (unsigned w = 0; w < nc; w++) {
    bank[s->y_reg[w]] = y[w];
    fp3_observe_write(tr->obs, obj, s->y_reg[w], y[w], k);
  }
  fp3_observe_endi(tr->obs, obj, k, cycle - tr->t0);
}

/* Run slots 0 .. n-1 for `steps` steps each on the chip (see
 * engine_spatial.h): one START of all the steps, every write-back taken
 * from the trace port as the model runs (into the banks and to the
 * observer); at the end, every object must have been written back
 * `steps` times, and the state window, read back, must hold what the
 * trace showed last. */
static int sp_run(fp3_engine *e, uint32_t steps, unsigned n, const fp3_observer *obs,
                  fp3_status *st) {
  spatial_engine *s = of(e);
  shim *sh = &s->sh;
  char m[sizeof e->error];
  memset(st, 0, sizeof *st);
  if (n == 0 || n > s->slots) {
    snprintf(e->error, sizeof e->error, "%u objects: the engine runs 1 .. %u a run", n,
             s->slots);
    return -1;
  }
  /* a run of K steps takes (K - 1) max(R, L + 3) + R + L + 4 cycles
   * with R = ceil(n / N) <= n (docs/spatial.md): far more is a hang */
  const uint64_t limit = 4 * ((uint64_t)steps + 1) * ((uint64_t)n + s->lat + 4) + 10000;
  for (unsigned o = 0; o < n; o++) s->steps_done[o] = 0;
  if (sync_slots(s, n, m, sizeof m)) return sp_fail(e, m);
  if (s->steps_reg != steps) {
    if (ax_write(sh, FP3S_STEPS, steps, m, sizeof m)) return sp_fail(e, m);
    s->steps_reg = steps;
  }
  trace_run tr = {.s = s, .obs = obs, .n = n, .steps = steps, .t0 = sh->cycles(sh->dut)};
  if (sh->trace(sh->dut, s->pipelines, s->nc, on_trace, &tr)) return sp_fail(e, "the shim cannot trace");
  const int rc = chip_run(s, limit, &st->cycles, &st->flags, m, sizeof m);
  sh->trace(sh->dut, s->pipelines, s->nc, NULL, NULL);
  if (rc) return sp_fail(e, m);
  if (tr.bad == 1) {
    snprintf(m, sizeof m,
             "the trace port showed a write-back of object %" PRIu32 ", not one of the run's "
             "%u objects", tr.bad_obj, n);
    return sp_fail(e, m);
  }
  if (tr.bad == 2) {
    snprintf(m, sizeof m,
             "the trace port showed more than %" PRIu32 " write-backs of object %" PRIu32
             " in a run of %" PRIu32 " steps", steps, tr.bad_obj, steps);
    return sp_fail(e, m);
  }
  for (unsigned o = 0; o < n; o++)
    if (s->steps_done[o] != steps) {
      snprintf(m, sizeof m,
               "the trace port showed %" PRIu32 " write-backs of object %u in a run of %" PRIu32
               " steps", s->steps_done[o], o, steps);
      return sp_fail(e, m);
    }
  /* the memory path: the state window holds the last write-backs */
  if (read_states(s, n, m, sizeof m)) return sp_fail(e, m);
  for (unsigned o = 0; o < n; o++)
    for (unsigned w = 0; w < s->nc; w++) {
      const uint32_t got = s->rd_data[(size_t)o * s->nc + w],
                     want = s->bank[(size_t)o * s->nregs + s->y_reg[w]];
      if (got != want) {
        snprintf(m, sizeof m,
                 "object %u carried word %u: the state window holds 0x%08" PRIX32
                 " after the run, the trace port's last write-back 0x%08" PRIX32,
                 o, w, got, want);
        return sp_fail(e, m);
      }
    }
  st->done = 1;
  st->steps_done = steps;
  for (int u = 0; u < FP3_NUM_UNITS; u++) {
    st->unit_issued[u] = s->ops[u] * n * (uint64_t)steps;
    st->issued += st->unit_issued[u];
  }
  return 0;
}

static int sp_ctx_status(fp3_engine *e, unsigned ctx, fp3_ctx_status *cs) {
  spatial_engine *s = of(e);
  memset(cs, 0, sizeof *cs);
  if (ctx >= s->slots) {
    snprintf(e->error, sizeof e->error, "no slot %u", ctx);
    return -1;
  }
  cs->steps_done = s->steps_done[ctx];
  return 0;
}

static void sp_destroy(fp3_engine *e) {
  spatial_engine *s = of(e);
  if (s->sh.dut) s->sh.destroy(s->sh.dut);
  /* the shared object stays loaded: a Verilated model's runtime keeps
   * thread-local state that dlclose would leave dangling */
  fp3_spatial_free(s->sp);
  free(s->top_text);
  free(s->in_reg);
  free(s->y_reg);
  free(s->bank);
  free(s->dirty);
  free(s->rd_addr);
  free(s->rd_data);
  free(s->rd_resp);
  free(s->steps_done);
  free(s);
}

static const fp3_engine_ops spatial_ops = {
    .name = "spatial",
    .load_program = sp_load,
    .write_reg = sp_write,
    .read_reg = sp_read,
    .run = sp_run,
    .ctx_status = sp_ctx_status,
    .destroy = sp_destroy,
    .untraced = 0,
};

int fp3_engine_spatial_is(const fp3_engine *e) { return e && e->ops == &spatial_ops; }

unsigned fp3_engine_spatial_latency(const fp3_engine *e) {
  return fp3_engine_spatial_is(e) ? ((const spatial_engine *)e)->lat : 0;
}

unsigned fp3_engine_spatial_cores(const fp3_engine *e) {
  return fp3_engine_spatial_is(e) ? ((const spatial_engine *)e)->ncores : 0;
}

/* The unit (FP3_UNIT_*) of an IR operation kind. */
static int unit_of(int kind) {
  switch (kind) {
  case FP3_IR_ADD:
  case FP3_IR_SUB: return FP3_UNIT_ADD;
  case FP3_IR_MUL: return FP3_UNIT_MUL;
  case FP3_IR_DIV:
  case FP3_IR_SQRT: return FP3_UNIT_DIV;
  default: return FP3_UNIT_MOV;
  }
}

fp3_engine *fp3_engine_spatial_new(fp3_compiled *c, const fp3_model *m, const char *integ,
                                   fpref_mode mode, const fp3_spatial_env *env, char *err,
                                   size_t n) {
  fp3_spatial_opts o;
  if (env->cores) o = *env->cores;
  else fp3_spatial_defaults(&o);
  o.rtz = mode.round == FPREF_RTZ;
  o.ftz = mode.ftz;
  /* (fp3_spatial_top refuses N beyond FP3S_MAX_PIPELINES) */
  const unsigned np = env->pipelines ? env->pipelines : 1;
  spatial_engine *s = calloc(1, sizeof *s);
  if (!s) {
    snprintf(err, n, "out of memory");
    return NULL;
  }
  s->base.ops = &spatial_ops;
  s->c = c;
  s->pipelines = np;
  s->slots = (FP3_SPATIAL_SLOTS + np - 1) / np * np; /* >= 2 N for any N <= 512 */
  char msg[512];
  if (fp3_spatial_build(c, m, integ, &o, &s->sp, msg, sizeof msg)) {
    snprintf(err, n, "%s: %s", m->file, msg);
    goto fail;
  }
  const fp3_spatial_stats *ps = fp3_spatial_stats_of(s->sp);
  s->nin = ps->inputs;
  s->nc = ps->carried;
  s->lat = ps->latency;
  s->ncores = ps->ncores;
  s->nregs = fp3_compiled_stats(c)->num_regs;
  for (int k = FP3_IR_ADD; k < FP3_IR_KINDS; k++) s->ops[unit_of(k)] += ps->cores[k];
  s->in_reg = malloc((s->nin ? s->nin : 1) * sizeof *s->in_reg);
  s->y_reg = malloc((s->nc ? s->nc : 1) * sizeof *s->y_reg);
  s->bank = calloc((size_t)s->slots * s->nregs, sizeof *s->bank);
  s->steps_done = calloc(s->slots, sizeof *s->steps_done);
  s->dirty = malloc(s->slots);
  const size_t words = (size_t)s->slots * (s->nc ? s->nc : 1);
  s->rd_addr = malloc(words * sizeof *s->rd_addr);
  s->rd_data = malloc(words * sizeof *s->rd_data);
  s->rd_resp = malloc(words * sizeof *s->rd_resp);
  if (!s->in_reg || !s->y_reg || !s->bank || !s->steps_done || !s->dirty || !s->rd_addr ||
      !s->rd_data || !s->rd_resp) {
    snprintf(err, n, "out of memory");
    goto fail;
  }
  for (unsigned k = 0; k < s->nin; k++) {
    const int node = fp3_spatial_input_node(s->sp, k);
    s->in_reg[k] = fp3_ir_node_reg(c, (unsigned)node);
    if (s->in_reg[k] < 0 || (unsigned)s->in_reg[k] >= s->nregs) {
      snprintf(err, n, "%s: input %u of the pipeline (IR node %d) has no register in the "
               "compiled program", m->file, k, node);
      goto fail;
    }
  }
  for (unsigned w = 0; w < s->nc; w++) {
    s->y_reg[w] = fp3_compiled_state_reg(c, w);
    if (s->y_reg[w] >= s->nregs) {
      snprintf(err, n, "%s: carried value %u has no register in the compiled program", m->file,
               w);
      goto fail;
    }
  }
  fp3_config *cf = &s->base.config;
  cf->num_contexts = s->slots;
  cf->num_lanes = 1;
  cf->num_regs = s->nregs;
  cf->imem_depth = (unsigned)fp3_compiled_image(c)->n;
  cf->add_latency = o.add_latency;
  cf->mul_latency = o.mul_latency;
  cf->div_latency = o.div_latency;
  cf->mode = mode;
  cf->has_add = cf->has_sub = cf->has_mul = cf->has_div = cf->has_sqrt = cf->has_sign = 1;

  char top[160];
  if (fp3_spatial_top(s->sp, s->pipelines, s->slots, 1, top, sizeof top, &s->top_text, msg,
                      sizeof msg)) {
    snprintf(err, n, "%s: %s", m->file, msg);
    goto fail;
  }
  build b = {.env = env, .module = fp3_spatial_module(s->sp),
             .verilog = fp3_spatial_verilog(s->sp), .top = top, .top_verilog = s->top_text,
             .pipelines = s->pipelines, .nin = s->nin, .nc = s->nc, .lat = s->lat, .objects = s->slots};
  b.text_hash = fp3_spatial_hash(s->sp);
  /* the Verilator: the one asked for (an unset or empty $VERILATOR:
   * NULL or ""), else "verilator" on the PATH */
  const char *verilator = env->verilator && env->verilator[0] ? env->verilator : "verilator";
  b.verilator = verilator;
  char cmd[1200];
  snprintf(cmd, sizeof cmd, "'%s' --getenv VERILATOR_ROOT 2>/dev/null", verilator);
  cmd_line(cmd, b.vroot, sizeof b.vroot);
  snprintf(cmd, sizeof cmd, "'%s' --version 2>/dev/null", verilator);
  cmd_line(cmd, b.vversion, sizeof b.vversion);
  if (!b.vroot[0] || !b.vversion[0]) {
    snprintf(err, n, "%s: not found, or it does not answer --version (the spatial engine "
             "Verilates the model's pipeline on first use; scripts/setup.sh installs it)",
             verilator);
    goto fail;
  }
  /* the model's C++ compiler: the one asked for, else clang++ if there */
  if (env->cxx && env->cxx[0]) {
    snprintf(b.cxx, sizeof b.cxx, "%s", env->cxx);
  } else {
    char probe[32];
    cmd_line("clang++ --version 2>/dev/null", probe, sizeof probe);
    snprintf(b.cxx, sizeof b.cxx, "%s", probe[0] ? "clang++" : "g++");
  }
  if (cache_open(&b, m->name, integ, &s->sh, s->entry, sizeof s->entry, err, n)) goto fail;
  /* the chip's object memory is unknown: every slot is written before it
   * runs; COUNT and STEPS are 0 after reset */
  memset(s->dirty, 1, s->slots);
  return &s->base;
fail:
  sp_destroy(&s->base);
  return NULL;
}
