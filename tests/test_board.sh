#!/usr/bin/env bash
# test_board.sh -- FP3 on a board, end to end, in simulation: the ULX3S
# top (boards/ulx3s/fp3_ulx3s.v: the UART, the UARTBone bridge, fp3_axil
# in the build for clock rate) Verilated with its PLL bypassed behind a
# pseudo-terminal or a TCP socket (sim/board_sim.cpp, 4 clocks a bit),
# driven by
#   - fp3 run --engine uart:PTY: the ship program (programs/ship_rk4.s,
#     fp3 run's default) and a model scene (spring, 4 objects), each
#     bit-exact with the golden model and with the same results as
#     --engine rtl; the ship once more over uart:socket://; fp3 frames of
#     3 springs;
#   - LiteX's own client: litex_server --uart on the same pty and
#     tests/board_remote.py (RemoteClient): the ID register and one
#     integration of a program it encodes itself; litex_cli --regs with the
#     csr.csv of scripts/board-csr.py (ID, and INFO2: 8 contexts, 1 lane,
#     no div/sqrt);
#   - raw frames: a frame cut in the middle is dropped after the bridge's
#     timeout (its DROPPED bit set, the half-written registers untouched)
#     and the next frame works;
#   - devices that are not FP3 (tests/board_fake_device.py): a wrong ID, a
#     short answer, no answer, no device: the engine's error names the
#     device, exit status 1.
# CLI $FP3_BIN (default build/fp3), harness $BOARD_SIM_BIN (default
# build/board-sim/ulx3s/fp3-board-sim).  Exit status non-zero if any check
# fails.
set -u
cd "$(dirname "$0")/.."
FP3=${FP3_BIN:-$PWD/build/fp3}
SIM=${BOARD_SIM_BIN:-$PWD/build/board-sim/ulx3s/fp3-board-sim}
for b in "$FP3" "$SIM"; do
  [ -x "$b" ] || { echo "test_board: $b not built (make $b)"; exit 1; }
done
# LiteX's tools from the project's virtual environment (scripts/setup.sh),
# never a litex that the system's Python may have
VENV=$PWD/.venv/bin
for b in litex_server litex_cli python; do
  [ -x "$VENV/$b" ] || { echo "test_board: $VENV/$b missing (scripts/setup.sh installs litex into .venv)"; exit 1; }
done
T=$(mktemp -d /tmp/fp3_test_board.XXXXXX)
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
  wait 2>/dev/null
  rm -rf "$T"
}
trap cleanup EXIT

pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok: $*"; }
bad() { fail=$((fail + 1)); echo "FAILED: $*"; }

# wait_ready FILE: the harness (or fake device) has opened its line.
wait_ready() {
  for _ in $(seq 200); do [ -s "$1" ] && return 0; sleep 0.05; done
  echo "test_board: $1 did not appear"; return 1
}

# same_results A.json B.json: A valid against docs/fp3.schema.json, pass true
# in both, the same "results" (every object's state, golden, reference).
same_results() { python3 tests/same_results.py "$1" "$2"; }

# ---- the simulated board on a pseudo-terminal --------------------------------
"$SIM" --pty "$T/tty" --ready "$T/ready" --max-seconds 240 2>"$T/sim.err" &
pids+=($!)
wait_ready "$T/ready" || exit 1
DEV="uart:$T/tty"

# fp3 run's default program, the ship (programs/ship_rk4.s), on engine $1
# for $2 integrations: bit-exact, the results of --engine rtl
ship_on() {
  if "$FP3" run --engine "$1" --steps "$2" --json >"$T/ship_uart.json" 2>"$T/err" &&
     "$FP3" run --engine rtl --steps "$2" --json >"$T/ship_rtl.json" &&
     same_results "$T/ship_uart.json" "$T/ship_rtl.json"; then
    ok "the ship program on $1: bit-exact, the results of --engine rtl"
  else
    bad "the ship program on $1"; cat "$T/err"
  fi
}
ship_on "$DEV" 500
# ... and its text report says what was compared
if "$FP3" run --engine "$DEV" --steps 50 >"$T/ship.txt" 2>"$T/err" &&
   grep -q "golden model: 0 mismatches in 50 integrations (the final state only)" "$T/ship.txt" &&
   grep -q "^PASS: 50 integrations on $DEV bit-exact" "$T/ship.txt"; then
  ok "the text report on $DEV"
else
  bad "the text report on $DEV"; cat "$T/ship.txt" "$T/err"
fi

# a model scene: 4 springs (one batch, 4 of the board's 8 contexts)
if "$FP3" run --engine "$DEV" --model models/spring.fp3m --objects 4 --steps 300 --json \
     >"$T/spring_uart.json" 2>"$T/err" &&
   "$FP3" run --engine rtl --model models/spring.fp3m --objects 4 --steps 300 --json \
     >"$T/spring_rtl.json" &&
   same_results "$T/spring_uart.json" "$T/spring_rtl.json"; then
  ok "4 springs on $DEV: bit-exact, the results of --engine rtl"
else
  bad "4 springs on $DEV"; cat "$T/err"
fi

# fp3 frames: 3 springs, 20 frames (a START each), every frame compared
if "$FP3" frames --engine "$DEV" --model models/spring.fp3m --objects 3 --frames 20 --json \
     >"$T/frames.json" 2>"$T/err" &&
   python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); sys.exit(0 if r["pass"] and r["golden_mismatches"] == 0 else 1)' "$T/frames.json"; then
  ok "fp3 frames on $DEV: 3 springs, 20 frames, bit-identical every frame"
else
  bad "fp3 frames on $DEV"; cat "$T/err" "$T/frames.json"
fi

# ---- LiteX's own client: litex_server --uart on the same pty ------------------
port=$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])')
"$VENV/litex_server" --uart --uart-port "$T/tty" --uart-baudrate 3000000 --bind-port "$port" \
  >"$T/litex.log" 2>&1 &
lpid=$!; pids+=($lpid)
for _ in $(seq 100); do
  python3 -c "import socket,sys; socket.create_connection(('127.0.0.1',$port),0.2)" 2>/dev/null && break
  sleep 0.1
done
if timeout 60 "$VENV/python" tests/board_remote.py "$port" >"$T/remote.txt" 2>&1; then
  ok "litex_server + RemoteClient: ID and one integration"; cat "$T/remote.txt"
else
  bad "litex_server + RemoteClient"; cat "$T/remote.txt" "$T/litex.log"
fi
# litex_cli --regs names FP3's registers from a csr.csv of the host-port map
python3 scripts/board-csr.py sw/isa/fp3_isa.h "$T/csr.csv"
if (cd "$T" && timeout 60 "$VENV/litex_cli" --csr-csv csr.csv --port "$port" --regs) >"$T/regs.txt" 2>&1 &&
   grep -q "^0x00000038 : 0x46503301 id$" "$T/regs.txt" &&
   grep -q "^0x00000044 : 0x01270008 info2$" "$T/regs.txt"; then
  ok "litex_cli --regs with scripts/board-csr.py's csr.csv: $(wc -l < "$T/regs.txt") registers by name"
else
  bad "litex_cli --regs"; cat "$T/regs.txt"
fi
kill "$lpid" 2>/dev/null; wait "$lpid" 2>/dev/null

# ---- a frame cut in the middle --------------------------------------------------
# A write of two words to r5, r6 of context 0 stops after 3 of its 8 data
# bytes; after the bridge's timeout (65,536 idle cycles, about 0.26 s of
# the harness's idle clock) it is dropped: the next frames read the ID,
# find r5 and r6 as they were and the DROPPED bit (0x2) set.
if timeout 30 python3 - "$T/tty" >"$T/cut.txt" 2>&1 <<'PY'
import os, struct, sys, time, termios, tty
fd = os.open(sys.argv[1], os.O_RDWR | os.O_NOCTTY)
tty.setraw(fd)
def frame(cmd, addr, words=(), n=None):
    n = len(words) if n is None else n
    return bytes([cmd, n]) + struct.pack(">I", addr) + b"".join(struct.pack(">I", w) for w in words)
def read(addr, n):
    os.write(fd, frame(2, addr, n=n))
    b = b""
    t0 = time.time()
    while len(b) < 4 * n and time.time() - t0 < 10:
        b += os.read(fd, 4 * n - len(b))
    return struct.unpack(">%dI" % n, b)
read(0x1000, 1)                                   # the bridge status, cleared
os.write(fd, frame(1, 0x00F, [0]))                # CTX 0
os.write(fd, frame(1, 0x105, [0x11111111, 0x22222222]))
before = read(0x105, 2)
os.write(fd, frame(1, 0x105, [0xAAAAAAAA, 0xBBBBBBBB])[:9])   # cut after 3 data bytes
time.sleep(2.0)
ident = read(0x00E, 1)[0]
after = read(0x105, 2)
status = read(0x1000, 1)[0]
print(f"ID 0x{ident:08x}, r5 r6 before {[hex(v) for v in before]}, after {[hex(v) for v in after]}, bridge status 0x{status:x}")
sys.exit(0 if ident == 0x46503301 and after == before == (0x11111111, 0x22222222) and status == 0x2 else 1)
PY
then
  ok "a cut frame is dropped, the next frame works"; cat "$T/cut.txt"
else
  bad "a cut frame"; cat "$T/cut.txt"
fi

# ---- the same board on a TCP socket -------------------------------------------------
"$SIM" --tcp 0 --ready "$T/ready_tcp" --max-seconds 120 2>"$T/sim_tcp.err" &
pids+=($!)
wait_ready "$T/ready_tcp" || exit 1
tport=$(awk '{print $2}' "$T/ready_tcp")
ship_on "uart:socket://127.0.0.1:$tport" 200

# ---- not an FP3: the engine's errors name the device, exit status 1 ----------------
# expect_error WHAT PATTERN ENGINE: fp3 run exits 1 with PATTERN on stderr.
expect_error() {
  local what=$1 pat=$2 eng=$3 rc=0
  FP3_UART_TIMEOUT_MS=300 timeout 20 "$FP3" run --engine "$eng" --steps 10 >"$T/out" 2>"$T/err" || rc=$?
  if [ "$rc" -eq 1 ] && grep -q -- "$pat" "$T/err"; then
    ok "$what: exit 1, $(head -1 "$T/err")"
  else
    bad "$what: exit $rc, stderr: $(cat "$T/err")"
  fi
}
for mode in id short silent; do
  python3 tests/board_fake_device.py "$T/fake_$mode" "$mode" &
  pids+=($!)
  wait_ready "$T/fake_$mode" || exit 1
done
fp() { echo "uart:socket://127.0.0.1:$(awk '{print $2}' "$T/fake_$1")"; }
expect_error "a wrong ID" "$(fp id): wrong ID register 0x12345678" "$(fp id)"
expect_error "a short answer" "$(fp short): short read within 300 ms: 2 of 4 bytes" "$(fp short)"
expect_error "no answer" "$(fp silent): no answer within 300 ms" "$(fp silent)"
expect_error "no device" "uart:$T/none: cannot open" "uart:$T/none"

echo "test_board: $pass passed, $fail failed"
[ "$fail" -eq 0 ]
