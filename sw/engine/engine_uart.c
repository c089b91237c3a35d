/*
 * engine_uart.c -- an FP3 on an FPGA board, behind a serial line, as an
 * engine: `--engine uart:DEVICE[@BAUD]` or `uart:socket://HOST:PORT`.
 *
 * The board's UART bridge (rtl/fp3_uartbone.v) speaks LiteX's UARTBone
 * protocol: a frame cmd, len, addr[4], data[4 len], big-endian, word
 * addresses; cmd 0x01 writes len words at addr, addr + 1, ...; 0x02 reads
 * len words, answered by exactly 4 len bytes.  Word address N is FP3's
 * host register N (sw/isa/fp3_isa.h FP3_HOSTREGS), the same map the RTL
 * engine drives on the Verilated host port, so this file does what
 * engine_rtl.c does, in frames:
 *   - writes are gathered: consecutive addresses become one frame of up
 *     to 255 words (a program, a register bank), and every frame waiting
 *     is sent with one write() before the next read;
 *   - a slot's registers are read as one burst of NUM_REGS words and kept
 *     until the next write or run;
 *   - a write is never answered, so wherever its outcome matters (a
 *     program loaded, a run started, the status read back) the bridge's
 *     read-to-clear status word (BRIDGE_STATUS, 0x1000) is read: any bus
 *     error, dropped frame, framing error or overrun fails the operation
 *     with a message naming the device;
 *   - every wait is bounded: each answer within FP3_UART_TIMEOUT_MS
 *     (default 5000 ms), a run within fp3_config_cycle_limit's cycles at
 *     1 MHz (a simulated board is slower than the real 100 MHz) plus 30 s.
 * A run reports no events to its observer: the board has no trace port
 * (fp3_engine_ops.untraced); the caller compares the state it reads back
 * after the run.  The cycle counts are the board's own counters.
 */
#define _DEFAULT_SOURCE /* cfmakeraw, CRTSCTS, the Bnnnnnnn rates above 38400, SOCK_NONBLOCK */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include "engine.h"
#include "fp3_isa.h"

#define CMD_WRITE 0x01u          /* write, address incrementing */
#define CMD_READ 0x02u           /* read, address incrementing  */
#define MAX_WORDS 255u           /* words a frame               */
#define BRIDGE_STATUS 0x1000u    /* rtl/fp3_uartbone.v          */
#define DEFAULT_BAUD 3000000L
#define DEFAULT_TIMEOUT_MS 5000
#define OUT_MAX (16 * (6 + 4 * MAX_WORDS)) /* frames gathered before a send */

typedef struct uart_engine {
  fp3_engine base;
  int fd;
  char dev[80];           /* "uart:SPEC", for messages (cut at 79 characters) */
  int timeout_ms;
  int stats;              /* FP3_UART_STATS: counts on stderr at the end    */
  /* the write frame being gathered, and the frames waiting to be sent */
  uint32_t w_addr, w_data[MAX_WORDS];
  unsigned w_n;
  unsigned char out[OUT_MAX];
  size_t out_n;
  unsigned ctx_sel, lane_sel;   /* CTX, LANE as last written (UINT_MAX: unknown) */
  int cache_slot;               /* the slot whose bank is in cache (-1: none)    */
  uint32_t cache[FP3_MAX_REGS];
  fp3_ctx_status *cs;           /* [slot], of the last run                       */
  unsigned long long frames, words_out, words_in;
} uart_engine;

static double now_ms(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec / 1e6;
}

/* ---- bytes on the line ------------------------------------------------------- */

static int io_write(uart_engine *u, const unsigned char *b, size_t n) {
  double deadline = now_ms() + u->timeout_ms;
  while (n > 0) {
    ssize_t k = write(u->fd, b, n);
    if (k > 0) {
      b += k;
      n -= (size_t)k;
      continue;
    }
    if (k < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
      snprintf(u->base.error, sizeof u->base.error, "%s: write failed: %s", u->dev,
               strerror(errno));
      return -1;
    }
    int left = (int)(deadline - now_ms());
    struct pollfd p = {u->fd, POLLOUT, 0};
    if (left <= 0 || poll(&p, 1, left) == 0) {
      snprintf(u->base.error, sizeof u->base.error,
               "%s: the line took no data for %d ms (FP3_UART_TIMEOUT_MS)", u->dev,
               u->timeout_ms);
      return -1;
    }
  }
  return 0;
}

/* Exactly n bytes, or an error saying what was asked and what came. */
static int io_read(uart_engine *u, unsigned char *b, size_t n, const char *what) {
  double deadline = now_ms() + u->timeout_ms;
  size_t got = 0;
  while (got < n) {
    int left = (int)(deadline - now_ms());
    struct pollfd p = {u->fd, POLLIN, 0};
    int r = left > 0 ? poll(&p, 1, left) : 0;
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) {
      snprintf(u->base.error, sizeof u->base.error,
               "%s: %s within %d ms: %zu of %zu bytes of %s (FP3's bitstream loaded? "
               "cable? baud rate?)", u->dev,
               got ? "short read" : "no answer", u->timeout_ms, got, n, what);
      return -1;
    }
    ssize_t k = read(u->fd, b + got, n - got);
    if (k > 0) {
      got += (size_t)k;
    } else if (k == 0) {
      snprintf(u->base.error, sizeof u->base.error,
               "%s: the line was closed after %zu of %zu bytes of %s", u->dev, got, n, what);
      return -1;
    } else if (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
      snprintf(u->base.error, sizeof u->base.error, "%s: read failed: %s", u->dev,
               strerror(errno));
      return -1;
    }
  }
  return 0;
}

/* ---- frames -------------------------------------------------------------------- */

static void put32(unsigned char *b, uint32_t v) {
  b[0] = (unsigned char)(v >> 24);
  b[1] = (unsigned char)(v >> 16);
  b[2] = (unsigned char)(v >> 8);
  b[3] = (unsigned char)v;
}

/* Send every frame waiting. */
static int send_out(uart_engine *u) {
  if (u->out_n == 0) return 0;
  int rc = io_write(u, u->out, u->out_n);
  u->out_n = 0;
  return rc;
}

/* Close the write frame being gathered (into the frames waiting). */
static int close_write(uart_engine *u) {
  if (u->w_n == 0) return 0;
  if (u->out_n + 6 + 4 * u->w_n > OUT_MAX && send_out(u)) return -1;
  unsigned char *b = u->out + u->out_n;
  b[0] = CMD_WRITE;
  b[1] = (unsigned char)u->w_n;
  put32(b + 2, u->w_addr);
  for (unsigned i = 0; i < u->w_n; i++) put32(b + 6 + 4 * i, u->w_data[i]);
  u->out_n += 6 + 4 * u->w_n;
  u->frames++;
  u->words_out += u->w_n;
  u->w_n = 0;
  return 0;
}

/* Write a host register: joins the frame being gathered when it follows
 * its last word. */
static int bus_write(uart_engine *u, unsigned addr, uint32_t v) {
  u->cache_slot = -1;
  if (u->w_n > 0 && (addr != u->w_addr + u->w_n || u->w_n == MAX_WORDS) && close_write(u))
    return -1;
  if (u->w_n == 0) u->w_addr = addr;
  u->w_data[u->w_n++] = v;
  return 0;
}

/* Read n words from addr (one frame, n <= MAX_WORDS), after every write. */
static int bus_read(uart_engine *u, unsigned addr, unsigned n, uint32_t *v) {
  unsigned char b[4 * MAX_WORDS];
  char what[48];
  if (close_write(u)) return -1;
  if (u->out_n + 6 > OUT_MAX && send_out(u)) return -1;
  unsigned char *f = u->out + u->out_n;
  f[0] = CMD_READ;
  f[1] = (unsigned char)n;
  put32(f + 2, addr);
  u->out_n += 6;
  u->frames++;
  if (send_out(u)) return -1;
  snprintf(what, sizeof what, "a read of %u word%s at 0x%03x", n, n == 1 ? "" : "s", addr);
  if (io_read(u, b, 4 * (size_t)n, what)) return -1;
  for (unsigned i = 0; i < n; i++)
    v[i] = (uint32_t)b[4 * i] << 24 | (uint32_t)b[4 * i + 1] << 16 |
           (uint32_t)b[4 * i + 2] << 8 | b[4 * i + 3];
  u->words_in += n;
  return 0;
}

/* The bridge's status after `what`: -1 with a message if it saw an error. */
static int check_bridge(uart_engine *u, const char *what) {
  uint32_t st;
  if (bus_read(u, BRIDGE_STATUS, 1, &st)) return -1;
  if ((st & 0xF) == 0) return 0;
  snprintf(u->base.error, sizeof u->base.error,
           "%s: the board's bridge reports%s%s%s%s after %s (status 0x%x)", u->dev,
           st & 1 ? " a bus error (an access FP3 refused)" : "",
           st & 2 ? " a dropped frame" : "", st & 4 ? " a framing error (baud rate?)" : "",
           st & 8 ? " an overrun" : "", what, st);
  return -1;
}

/* ---- the engine's operations ------------------------------------------------------ */

static void select_ctx(uart_engine *u, unsigned c) {
  if (u->ctx_sel == c) return;
  bus_write(u, FP3_HR_CTX, c);
  u->ctx_sel = c;
}

static void select_lane(uart_engine *u, unsigned l) {
  if (u->lane_sel == l) return;
  bus_write(u, FP3_HR_LANE, l);
  u->lane_sel = l;
}

static int check_slot(fp3_engine *e, unsigned slot, unsigned reg) {
  if (slot >= fp3_config_slots(&e->config)) {
    snprintf(e->error, sizeof e->error,
             "object slot %u out of range (the board has %u contexts x %u lanes)", slot,
             e->config.num_contexts, e->config.num_lanes);
    return -1;
  }
  if (reg >= e->config.num_regs) {
    snprintf(e->error, sizeof e->error, "register r%u out of range (the board has %u)", reg,
             e->config.num_regs);
    return -1;
  }
  return 0;
}

static int uart_load_program(fp3_engine *e, const uint64_t *words, size_t n) {
  uart_engine *u = (uart_engine *)e;
  if (n > e->config.imem_depth) {
    snprintf(e->error, sizeof e->error,
             "program of %zu instructions does not fit the instruction memory (%u entries)", n,
             e->config.imem_depth);
    return -1;
  }
  /* every entry, so that a shorter program leaves no stale words */
  for (size_t i = 0; i < e->config.imem_depth; i++) {
    uint64_t w = i < n ? words[i] : 0;
    bus_write(u, FP3_HR_IMEM_BASE + 2 * (unsigned)i, (uint32_t)w);
    bus_write(u, FP3_HR_IMEM_BASE + 2 * (unsigned)i + 1, (uint32_t)(w >> 32));
  }
  return check_bridge(u, "loading the program");
}

static int uart_write_reg(fp3_engine *e, unsigned slot, unsigned reg, uint32_t value) {
  uart_engine *u = (uart_engine *)e;
  if (check_slot(e, slot, reg)) return -1;
  select_ctx(u, slot % e->config.num_contexts);
  select_lane(u, slot / e->config.num_contexts);
  return bus_write(u, FP3_HR_REG_BASE + reg, value);
}

static int uart_read_reg(fp3_engine *e, unsigned slot, unsigned reg, uint32_t *value) {
  uart_engine *u = (uart_engine *)e;
  if (check_slot(e, slot, reg)) return -1;
  if (u->cache_slot != (int)slot) {
    select_ctx(u, slot % e->config.num_contexts);
    select_lane(u, slot / e->config.num_contexts);
    /* (CTX and LANE are in range, check_slot: their writes cannot fail
     * while no run is in progress; the bridge's status is read with the
     * next run or program) */
    if (bus_read(u, FP3_HR_REG_BASE, e->config.num_regs, u->cache)) return -1;
    u->cache_slot = (int)slot;
  }
  *value = u->cache[reg];
  return 0;
}

static int uart_ctx_status(fp3_engine *e, unsigned slot, fp3_ctx_status *cs) {
  if (check_slot(e, slot, 0)) return -1;
  *cs = ((uart_engine *)e)->cs[slot];
  return 0;
}

static int uart_run(fp3_engine *e, uint32_t steps, unsigned contexts, const fp3_observer *obs,
                    fp3_status *st) {
  uart_engine *u = (uart_engine *)e;
  const unsigned nc = e->config.num_contexts, nl = e->config.num_lanes;
  (void)obs; /* no trace port: no events (fp3_engine_ops.untraced) */
  memset(st, 0, sizeof *st);
  memset(u->cs, 0, (size_t)nc * nl * sizeof *u->cs);
  const unsigned hw = contexts <= nc || contexts > nc * nl ? contexts : nc;
  bus_write(u, FP3_HR_STEPS, steps);
  bus_write(u, FP3_HR_CONTEXTS, hw);
  /* START's outcome (SLVERR: a run in progress) is in the bridge's
   * status, read at the end; a refused START leaves RUNNING clear */
  bus_write(u, FP3_HR_CTRL, FP3_CTRL_START);
  /* wait for the run's end: RUNNING clear */
  const double limit_ms =
      30e3 + (double)fp3_config_cycle_limit(&e->config, steps, hw) / 1e6 * 1e3;
  const double t0 = now_ms();
  uint32_t w[16]; /* STATUS .. STALLS_HI of context 0; [11 ..]: another's STATUS .. FLAGS */
  for (;;) {
    if (bus_read(u, FP3_HR_STATUS, 1, w)) return -1;
    if (!(w[0] & FP3_STATUS_RUNNING)) break;
    if (now_ms() - t0 > limit_ms) {
      snprintf(e->error, sizeof e->error,
               "%s: the board still runs after %.0f s, longer than %llu cycles at 1 MHz "
               "(hung?)", u->dev, limit_ms / 1e3,
               (unsigned long long)fp3_config_cycle_limit(&e->config, steps, hw));
      return -1;
    }
  }
  /* context 0: STATUS .. STALLS_HI in one burst (its status, the selected
   * lane's FLAGS, the counters); every other context that ran: STATUS ..
   * FLAGS (0x001 .. 0x005); the other lanes' FLAGS one by one.  Contexts
   * that did not run keep a zero status. */
  const unsigned ran = hw < nc ? hw : nc;
  if (u->lane_sel == UINT_MAX) select_lane(u, 0);
  for (unsigned c = 0; c < ran; c++) {
    select_ctx(u, c);
    if (bus_read(u, FP3_HR_STATUS, c == 0 ? FP3_HR_STALLS_HI - FP3_HR_STATUS + 1 : 5,
                 c == 0 ? w : w + 11))
      return -1;
    const uint32_t *x = c == 0 ? w : w + 11;
    fp3_ctx_status cs;
    cs.error = (x[0] >> FP3_STATUS_ERROR_LSB) & 0xF;
    cs.steps_done = x[FP3_HR_STEPS_DONE - FP3_HR_STATUS];
    cs.fault_pc = x[FP3_HR_FAULT_PC - FP3_HR_STATUS];
    uint32_t flags = x[FP3_HR_FLAGS - FP3_HR_STATUS];
    const unsigned first = u->lane_sel; /* the lane whose FLAGS came with the burst */
    for (unsigned l = 0; l < nl; l++) {
      unsigned lane = (first + l) % nl;
      if (l > 0) {
        select_lane(u, lane);
        if (bus_read(u, FP3_HR_FLAGS, 1, &flags)) return -1;
      }
      cs.flags = flags;
      u->cs[lane * nc + c] = cs;
      if (lane * nc + c < contexts) st->flags |= cs.flags;
    }
  }
  uint32_t status = w[0];
#define W(r) ((uint64_t)w[FP3_HR_##r - FP3_HR_STATUS])
  st->done = (status & FP3_STATUS_DONE) != 0;
  st->any_error = (status & FP3_STATUS_ANY_ERROR) != 0;
  st->error = u->cs[0].error;
  st->fault_pc = u->cs[0].fault_pc;
  st->steps_done = u->cs[0].steps_done;
  st->cycles = W(CYCLES_LO) | W(CYCLES_HI) << 32;
  st->issued = W(ISSUED_LO) | W(ISSUED_HI) << 32;
  st->stalls = W(STALLS_LO) | W(STALLS_HI) << 32;
#undef W
  bus_write(u, FP3_HR_CTRL, FP3_CTRL_CLEAR);
  return check_bridge(u, "the run");
}

static void uart_destroy(fp3_engine *e) {
  uart_engine *u = (uart_engine *)e;
  if (close_write(u) == 0) send_out(u);
  if (u->stats)
    fprintf(stderr, "fp3: %s: %llu frames, %llu words written, %llu words read\n", u->dev,
            u->frames, u->words_out, u->words_in);
  if (u->fd >= 0) close(u->fd);
  free(u->cs);
  free(u);
}

static const fp3_engine_ops uart_ops = {
    "uart", uart_load_program, uart_write_reg, uart_read_reg, uart_run, uart_ctx_status,
    uart_destroy, 1,
};

/* ---- opening the line ------------------------------------------------------------------ */

static speed_t baud_code(long baud) {
  static const struct { long b; speed_t c; } t[] = {
      {9600, B9600},       {19200, B19200},     {38400, B38400},     {57600, B57600},
      {115200, B115200},   {230400, B230400},   {460800, B460800},   {500000, B500000},
      {921600, B921600},   {1000000, B1000000}, {1500000, B1500000}, {2000000, B2000000},
      {2500000, B2500000}, {3000000, B3000000}, {3500000, B3500000}, {4000000, B4000000}};
  for (size_t i = 0; i < sizeof t / sizeof t[0]; i++)
    if (t[i].b == baud) return t[i].c;
  return 0;
}

static int open_tty(const char *dev, long baud, char *err, size_t n) {
  speed_t code = baud_code(baud);
  if (!code) {
    snprintf(err, n, "uart:%s@%ld: %ld baud is not one of the standard rates 9600 .. 4000000",
             dev, baud, baud);
    return -1;
  }
  int fd = open(dev, O_RDWR | O_NOCTTY | O_NONBLOCK);
  if (fd < 0) {
    snprintf(err, n, "uart:%s: cannot open: %s", dev, strerror(errno));
    return -1;
  }
  struct termios t;
  if (tcgetattr(fd, &t) != 0) {
    snprintf(err, n, "uart:%s: not a serial line: %s", dev, strerror(errno));
    close(fd);
    return -1;
  }
  cfmakeraw(&t);
  t.c_cflag |= CLOCAL | CREAD;
  t.c_cflag &= ~(tcflag_t)CRTSCTS;
  t.c_cc[VMIN] = 0;
  t.c_cc[VTIME] = 0;
  cfsetispeed(&t, code);
  cfsetospeed(&t, code);
  if (tcsetattr(fd, TCSANOW, &t) != 0) {
    snprintf(err, n, "uart:%s: cannot set %ld baud, raw: %s", dev, baud, strerror(errno));
    close(fd);
    return -1;
  }
  tcflush(fd, TCIOFLUSH); /* nothing stale from an earlier session */
  return fd;
}

static int open_socket(const char *spec, int timeout_ms, char *err, size_t n) {
  char host[128];
  const char *hp = spec + strlen("socket://");
  const char *colon = strrchr(hp, ':');
  if (!colon || colon == hp || (size_t)(colon - hp) >= sizeof host || !colon[1]) {
    snprintf(err, n, "uart:%s: give socket://HOST:PORT", spec);
    return -1;
  }
  memcpy(host, hp, (size_t)(colon - hp));
  host[colon - hp] = '\0';
  struct addrinfo hints, *res = NULL;
  memset(&hints, 0, sizeof hints);
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  int g = getaddrinfo(host, colon + 1, &hints, &res);
  if (g != 0) {
    snprintf(err, n, "uart:%s: %s", spec, gai_strerror(g));
    return -1;
  }
  int fd = -1, saved = 0;
  for (struct addrinfo *a = res; a && fd < 0; a = a->ai_next) {
    fd = socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK, a->ai_protocol);
    if (fd < 0) continue;
    if (connect(fd, a->ai_addr, a->ai_addrlen) != 0 && errno != EINPROGRESS) {
      saved = errno;
      close(fd);
      fd = -1;
      continue;
    }
    struct pollfd p = {fd, POLLOUT, 0};
    int so = 0;
    socklen_t sl = sizeof so;
    if (poll(&p, 1, timeout_ms) <= 0 || getsockopt(fd, SOL_SOCKET, SO_ERROR, &so, &sl) || so) {
      saved = so ? so : ETIMEDOUT;
      close(fd);
      fd = -1;
    }
  }
  freeaddrinfo(res);
  if (fd < 0) {
    snprintf(err, n, "uart:%s: cannot connect: %s", spec, strerror(saved));
    return -1;
  }
  int one = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  return fd;
}

fp3_engine *fp3_engine_uart_new(const char *spec, char *err, size_t n) {
  uart_engine *u = calloc(1, sizeof *u);
  if (!u) {
    snprintf(err, n, "uart:%s: out of memory", spec);
    return NULL;
  }
  u->base.ops = &uart_ops;
  u->fd = -1;
  u->ctx_sel = u->lane_sel = UINT_MAX;
  u->cache_slot = -1;
  snprintf(u->dev, sizeof u->dev, "uart:%s", spec);
  const char *t = getenv("FP3_UART_TIMEOUT_MS");
  u->timeout_ms = t && atoi(t) > 0 ? atoi(t) : DEFAULT_TIMEOUT_MS;
  const char *s = getenv("FP3_UART_STATS");
  u->stats = s && strcmp(s, "1") == 0;
  if (strncmp(spec, "socket://", 9) == 0) {
    u->fd = open_socket(spec, u->timeout_ms, err, n);
  } else {
    char dev[4096];
    long baud = DEFAULT_BAUD;
    const char *at = strrchr(spec, '@');
    size_t len = at ? (size_t)(at - spec) : strlen(spec);
    if (len == 0 || len >= sizeof dev) {
      snprintf(err, n, "uart:%s: give uart:DEVICE[@BAUD] or uart:socket://HOST:PORT", spec);
      free(u);
      return NULL;
    }
    memcpy(dev, spec, len);
    dev[len] = '\0';
    if (at) {
      char *end;
      baud = strtol(at + 1, &end, 10);
      if (*end || baud <= 0) {
        snprintf(err, n, "uart:%s: the baud rate '%s' is not a number", spec, at + 1);
        free(u);
        return NULL;
      }
    }
    u->fd = open_tty(dev, baud, err, n);
  }
  if (u->fd < 0) {
    free(u);
    return NULL;
  }
  /* the build: INFO0, INFO1, ID, CTX, CONTEXTS, INFO2 (0x00C .. 0x011);
   * the bridge's status first, which clears what an earlier session left */
  uint32_t st, w[6];
  if (bus_read(u, BRIDGE_STATUS, 1, &st) || bus_read(u, FP3_HR_INFO0, 6, w)) {
    snprintf(err, n, "%s", u->base.error);
    uart_destroy(&u->base);
    return NULL;
  }
  if (w[FP3_HR_ID - FP3_HR_INFO0] != FP3_ID_VALUE) {
    snprintf(err, n, "%s: wrong ID register 0x%08x (FP3 answers 0x%08x): not an FP3 "
             "bitstream, or not a board at all", u->dev, w[FP3_HR_ID - FP3_HR_INFO0],
             FP3_ID_VALUE);
    uart_destroy(&u->base);
    return NULL;
  }
  const uint32_t info0 = w[0], info1 = w[1], info2 = w[5];
  fp3_config *c = &u->base.config;
  c->num_contexts = info2 & 0xFFFF;
  c->has_add = (info2 >> 16) & 1;
  c->has_sub = (info2 >> 17) & 1;
  c->has_mul = (info2 >> 18) & 1;
  c->has_div = (info2 >> 19) & 1;
  c->has_sqrt = (info2 >> 20) & 1;
  c->has_sign = (info2 >> 21) & 1;
  c->wb_ports = (info2 >> 22) & 1 ? 1 : 4;
  c->num_lanes = info2 >> 24;
  c->num_regs = info0 & 0xFFFF;
  c->imem_depth = info0 >> 16;
  c->add_latency = info1 & 0xFF;
  c->mul_latency = (info1 >> 8) & 0xFF;
  c->mode.round = (info1 >> 16) & 1 ? FPREF_RTZ : FPREF_RNE;
  c->mode.ftz = (info1 >> 17) & 1;
  c->fmax_pipe = (info1 >> 18) & 1;
  c->div_latency = (info1 >> 19) & 0xFF;
  if (c->num_contexts == 0 || c->num_contexts > FP3_MAX_CONTEXTS || c->num_lanes == 0 ||
      c->num_lanes > FP3_MAX_LANES || c->num_regs > FP3_MAX_REGS ||
      c->imem_depth > 1024) {
    snprintf(err, n, "%s: the board reports %u contexts, %u lanes, %u registers, %u "
             "instructions, outside what this host handles", u->dev, c->num_contexts,
             c->num_lanes, c->num_regs, c->imem_depth);
    uart_destroy(&u->base);
    return NULL;
  }
  u->cs = calloc((size_t)c->num_contexts * c->num_lanes, sizeof *u->cs);
  if (!u->cs) {
    snprintf(err, n, "%s: out of memory", u->dev);
    uart_destroy(&u->base);
    return NULL;
  }
  return &u->base;
}
