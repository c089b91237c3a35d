// board_sim.cpp -- a board top (boards/BOARD/, e.g. fp3_ulx3s) simulated
// by Verilator behind a serial line that a host program opens as it opens
// the real board's: a pseudo-terminal or a TCP socket.
//
//   fp3-board-sim --pty LINK | --tcp PORT  [--clks-per-bit N]
//                 [--ready FILE] [--idle-cycles N] [--max-seconds S]
//
//   --pty LINK      a pseudo-terminal in raw mode; LINK becomes a symbolic
//                   link to its slave (/dev/pts/N), which the harness keeps
//                   open itself, so that clients may come and go (fp3 run
//                   --engine uart:LINK, litex_server --uart-port LINK)
//   --tcp PORT      a TCP server on 127.0.0.1:PORT (0: any free port), one
//                   client at a time (uart:socket://127.0.0.1:PORT,
//                   litex_server --uart-port socket://127.0.0.1:PORT)
//   --clks-per-bit  the top's CLKS_PER_BIT (boards/BOARD/board.mk
//                   BOARD_SIM_PARAMS), the harness's bit time
//   --ready FILE    written once the line is open: "pty PATH" or "tcp PORT"
//   --idle-cycles   cycles simulated per millisecond while the line and the
//                   processor are idle (default 256), see below
//   --max-seconds   end after S seconds of wall time (default 0: never);
//                   SIGINT and SIGTERM end it too
//
// The line: the top's serial input (ftdi_txd on the ULX3S) and output
// (ftdi_rxd) are driven and sampled every clock, bit by bit, 8N1, one bit
// CLKS_PER_BIT clocks long, as the board's USB-serial chip would at the
// baud rate: bytes the client writes are sent to the top one after
// another (no gap), bytes the top sends go to the client.  The PLL is
// bypassed (PLL_BYPASS=1): the harness's clock is the system clock.
//
// Time: while bytes are on their way, or the processor runs (LED 0), or
// within 200 bit times of the last character, the clock runs as fast as
// the model does.  Otherwise the harness waits for the client (poll, 1 ms)
// and simulates --idle-cycles clocks per millisecond, so that the
// bridge's timeout (TIMEOUT cycles: dropping an unfinished frame) passes
// in wall time too while using little CPU.
#include <arpa/inet.h>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <deque>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <string>
#include <sys/socket.h>
#include <termios.h>
#include <unistd.h>

#include "verilated.h"
#include VBOARD_HEADER

static volatile sig_atomic_t stop_flag = 0;
static void on_signal(int) { stop_flag = 1; }

static double now_s() {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

static void die(const char *what) {
  fprintf(stderr, "fp3-board-sim: %s: %s\n", what, strerror(errno));
  exit(1);
}

static void set_nonblock(int fd) {
  int fl = fcntl(fd, F_GETFL);
  if (fl < 0 || fcntl(fd, F_SETFL, fl | O_NONBLOCK) < 0) die("fcntl");
}

// The client side of the line: a pty master, or the accepted TCP client.
struct Line {
  int fd = -1;        // where bytes go and come from (-1: no TCP client yet)
  int listen_fd = -1; // TCP: the listening socket
  int slave_fd = -1;  // pty: the slave, kept open
  std::string link;   // pty: the symbolic link

  // Accept a TCP client when none is connected.
  void accept_client() {
    if (listen_fd < 0 || fd >= 0) return;
    int c = accept(listen_fd, nullptr, nullptr);
    if (c < 0) return;
    set_nonblock(c);
    int one = 1;
    setsockopt(c, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
    fd = c;
  }
  // The client went away (TCP: wait for the next one).
  void lost() {
    if (listen_fd >= 0 && fd >= 0) {
      close(fd);
      fd = -1;
    }
  }
  int wait_fd() const { return fd >= 0 ? fd : listen_fd; }
};

static void open_pty(Line &l, const char *link) {
  int m = posix_openpt(O_RDWR | O_NOCTTY);
  if (m < 0 || grantpt(m) || unlockpt(m)) die("posix_openpt");
  const char *name = ptsname(m);
  if (!name) die("ptsname");
  int s = open(name, O_RDWR | O_NOCTTY);
  if (s < 0) die(name);
  struct termios t;
  if (tcgetattr(s, &t)) die("tcgetattr");
  cfmakeraw(&t);
  if (tcsetattr(s, TCSANOW, &t)) die("tcsetattr");
  set_nonblock(m);
  unlink(link);
  if (symlink(name, link)) die(link);
  l.fd = m;
  l.slave_fd = s;
  l.link = link;
}

static int open_tcp(Line &l, int port) {
  int s = socket(AF_INET, SOCK_STREAM, 0);
  if (s < 0) die("socket");
  int one = 1;
  setsockopt(s, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  struct sockaddr_in a;
  memset(&a, 0, sizeof a);
  a.sin_family = AF_INET;
  a.sin_port = htons((uint16_t)port);
  a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (bind(s, (struct sockaddr *)&a, sizeof a) || listen(s, 1)) die("bind/listen");
  socklen_t n = sizeof a;
  if (getsockname(s, (struct sockaddr *)&a, &n)) die("getsockname");
  set_nonblock(s);
  l.listen_fd = s;
  return ntohs(a.sin_port);
}

int main(int argc, char **argv) {
  const char *pty = nullptr, *ready = nullptr;
  int tcp = -1;
  long cpb = 4, idle_cycles = 256;
  double max_s = 0;
  for (int i = 1; i < argc; i++) {
    std::string a = argv[i];
    const char *v = i + 1 < argc ? argv[i + 1] : nullptr;
    if (a == "--pty" && v) pty = argv[++i];
    else if (a == "--tcp" && v) tcp = atoi(argv[++i]);
    else if (a == "--clks-per-bit" && v) cpb = atol(argv[++i]);
    else if (a == "--ready" && v) ready = argv[++i];
    else if (a == "--idle-cycles" && v) idle_cycles = atol(argv[++i]);
    else if (a == "--max-seconds" && v) max_s = atof(argv[++i]);
    else {
      fprintf(stderr, "usage: fp3-board-sim --pty LINK | --tcp PORT [--clks-per-bit N] "
                      "[--ready FILE] [--idle-cycles N] [--max-seconds S]\n");
      return 2;
    }
  }
  if ((pty != nullptr) == (tcp >= 0) || cpb < 2 || idle_cycles < 1) {
    fprintf(stderr, "fp3-board-sim: give one of --pty LINK and --tcp PORT "
                    "(and --clks-per-bit >= 2, --idle-cycles >= 1)\n");
    return 2;
  }
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);
  signal(SIGPIPE, SIG_IGN);

  Line line;
  std::string where;
  if (pty) {
    open_pty(line, pty);
    where = std::string("pty ") + ptsname(line.fd);
  } else {
    where = "tcp " + std::to_string(open_tcp(line, tcp));
  }

  VerilatedContext ctx;
  VBOARD top(&ctx);
  top.clk_25mhz = 0;
  top.ftdi_txd = 1;
  top.btn = 1; // PWR not pressed (active low)
  top.eval();

  if (ready) {
    std::string tmp = std::string(ready) + ".tmp";
    FILE *f = fopen(tmp.c_str(), "w");
    if (!f || fprintf(f, "%s\n", where.c_str()) < 0 || fclose(f) || rename(tmp.c_str(), ready))
      die(ready);
  }
  fprintf(stderr, "fp3-board-sim: serial line on %s, %ld clocks a bit\n", where.c_str(), cpb);

  std::deque<uint8_t> to_top, to_client;
  // host -> top: the character being sent
  int tx_bit = -1;         // -1 idle; 0 start, 1..8 data, 9 stop
  long tx_left = 0;        // clocks left of this bit
  unsigned tx_char = 0;
  // top -> host: the character being received
  int rx_bit = -1;         // -1 idle; 0 start (checking), 1..8 data, 9 stop
  long rx_left = 0;
  unsigned rx_char = 0;
  uint64_t cycle = 0, last_activity = 0;
  const uint64_t quiet = 200 * 10 * (uint64_t)cpb;
  const double t0 = now_s();
  uint8_t buf[4096];

  while (!stop_flag && !ctx.gotFinish()) {
    // ---- the client: accept, read, write --------------------------------------
    const bool idle = to_top.empty() && tx_bit < 0 && rx_bit < 0 && to_client.empty() &&
                      !(top.led & 1) && cycle - last_activity > quiet;
    if (idle || (cycle & 1023) == 0) {
      if (max_s > 0 && now_s() - t0 > max_s) {
        fprintf(stderr, "fp3-board-sim: --max-seconds %g reached\n", max_s);
        break;
      }
      line.accept_client();
      if (idle) {
        int wfd = line.wait_fd();
        struct pollfd p = {wfd, POLLIN, 0};
        poll(&p, 1, 1);
        line.accept_client();
      }
      if (line.fd >= 0) {
        ssize_t n = read(line.fd, buf, sizeof buf);
        if (n > 0) {
          to_top.insert(to_top.end(), buf, buf + n);
          last_activity = cycle;
        } else if (n == 0 || (errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR)) {
          line.lost();
        }
      }
      if (line.fd >= 0 && !to_client.empty()) {
        size_t k = 0;
        while (k < to_client.size() && k < sizeof buf) buf[k] = to_client[k], k++;
        ssize_t n = write(line.fd, buf, k);
        if (n > 0) to_client.erase(to_client.begin(), to_client.begin() + n);
        else if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) line.lost();
      }
      if (line.fd < 0) to_client.clear(); // no one listens (TCP between clients)
    }
    const long steps = idle && to_top.empty() ? idle_cycles : 1;

    for (long s = 0; s < steps; s++) {
      // ---- host -> top, the input changed while the clock is low ----------------
      if (tx_bit < 0 && !to_top.empty()) {
        tx_char = to_top.front();
        to_top.pop_front();
        tx_bit = 0;
        tx_left = cpb;
      }
      if (tx_bit >= 0) {
        top.ftdi_txd = tx_bit == 0 ? 0 : tx_bit == 9 ? 1 : (tx_char >> (tx_bit - 1)) & 1;
        if (--tx_left == 0) {
          tx_left = cpb;
          if (++tx_bit == 10) tx_bit = -1;
        }
        last_activity = cycle;
      } else {
        top.ftdi_txd = 1;
      }
      top.clk_25mhz = 1;
      top.eval();
      top.clk_25mhz = 0;
      top.eval();
      cycle++;

      // ---- top -> host: sample the line in the middle of each bit ----------------
      const int level = top.ftdi_rxd & 1;
      if (rx_bit < 0) {
        if (!level) {
          rx_bit = 0;
          rx_left = cpb / 2;
          rx_char = 0;
        }
      } else if (--rx_left <= 0) {
        rx_left = cpb;
        if (rx_bit == 0) {
          if (level) rx_bit = -1; // a glitch
          else rx_bit = 1;
        } else if (rx_bit <= 8) {
          rx_char |= (unsigned)level << (rx_bit - 1);
          rx_bit++;
        } else {
          if (level) to_client.push_back((uint8_t)rx_char);
          else fprintf(stderr, "fp3-board-sim: framing error from the top (cycle %llu)\n",
                       (unsigned long long)cycle);
          rx_bit = -1;
        }
        last_activity = cycle;
      }
    }
  }
  top.final();
  if (!line.link.empty()) unlink(line.link.c_str());
  return 0;
}
