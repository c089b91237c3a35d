#!/usr/bin/env python3
"""uart-throughput.py PORT [BAUD] [--bursts N] -- how many host-register
words a second the serial line to an FP3 board carries (docs/board.md "How
fast the link is"): N write frames of 255 words into the program window
(harmless while no run is in progress; the next program load overwrites
them), then N read frames of 255 words at the ID register (UARTBone's
fixed-address read, cmd 0x04), each read waited for before the next.

PORT is a serial device or pseudo-terminal (BAUD default 3000000), or
socket://HOST:PORT (the simulated board's --tcp).  Checks the ID first
and the bridge's status at the end; exit status 1 on a wrong ID, a short
answer within 5 s, or a bridge error.  Run it with the project's Python,
.venv/bin/python (pyserial: scripts/setup.sh installs it there).
"""
import argparse
import struct
import sys
import time

try:
    import serial  # pyserial
except ImportError:
    sys.exit("uart-throughput.py: no pyserial: run it with .venv/bin/python (scripts/setup.sh installs pyserial there)")

ID, IMEM_BASE, BRIDGE_STATUS = 0x00E, 0x800, 0x1000
ID_VALUE = 0x46503301


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("port")
    ap.add_argument("baud", nargs="?", type=int, default=3000000)
    ap.add_argument("--bursts", type=int, default=20)
    a = ap.parse_args()
    line = serial.serial_for_url(a.port, baudrate=a.baud, timeout=5)

    def read(addr, n, cmd=0x02):
        line.write(bytes([cmd, n]) + struct.pack(">I", addr))
        b = line.read(4 * n)
        if len(b) != 4 * n:
            sys.exit(f"uart-throughput: {a.port}: {len(b)} of {4 * n} bytes within 5 s")
        return struct.unpack(">%dI" % n, b)

    read(BRIDGE_STATUS, 1)
    ident = read(ID, 1)[0]
    if ident != ID_VALUE:
        sys.exit(f"uart-throughput: {a.port}: ID 0x{ident:08x}, not FP3's 0x{ID_VALUE:08x}")
    frame = bytes([0x01, 255]) + struct.pack(">I", IMEM_BASE) + bytes(4 * 255)
    t = time.time()
    for _ in range(a.bursts):
        line.write(frame)
    read(ID, 1)                      # every write has reached the board
    tw = time.time() - t
    t = time.time()
    for _ in range(a.bursts):
        read(ID, 255, cmd=0x04)
    tr = time.time() - t
    status = read(BRIDGE_STATUS, 1)[0]
    n = 255 * a.bursts
    print(f"{a.port}: {n / tw:,.0f} words/s written, {n / tr:,.0f} words/s read "
          f"({a.bursts} frames of 255 words each way; bridge status 0x{status:x})")
    return 1 if status else 0


if __name__ == "__main__":
    sys.exit(main())
