#!/usr/bin/env python3
"""board_remote.py PORT -- LiteX's own client drives FP3's board
(tests/test_board.sh): RemoteClient talks to litex_server on
localhost:PORT, which serves the board's UARTBone bridge.  Nothing of FP3's
host code is used: the registers are named from sw/isa/fp3_isa.h's map by
hand, the program is encoded here (fp3_isa.h: opcode [63:56], rd [55:48],
ra [47:40], rb [39:32], imm [31:0]), and the results are checked against
binary32 arithmetic done here.

Reads the ID register, loads a three-instruction program (r3 = r1 * r2,
r4 = r3 + r1, endi), writes r1 and r2, runs one integration and reads
STATUS, STEPS_DONE, r3 and r4.  Exit status 0 when all agree, 1 otherwise.
Run with the project's Python, .venv/bin/python (litex: scripts/setup.sh).
"""
import struct
import sys
import time

try:
    from litex import RemoteClient
except ImportError:
    sys.exit("board_remote.py: no litex: run it with .venv/bin/python (scripts/setup.sh installs litex there)")

# host registers (word addresses; RemoteClient takes byte addresses)
CTRL, STATUS, STEPS, STEPS_DONE, ID, CTX, CONTEXTS = 0x000, 0x001, 0x002, 0x003, 0x00E, 0x00F, 0x010
REG_BASE, IMEM_BASE, BRIDGE_STATUS = 0x100, 0x800, 0x1000
ID_VALUE = 0x46503301
OP_ADD, OP_MUL, OP_ENDI = 0x01, 0x03, 0x06


def insn(opc, rd=0, ra=0, rb=0, imm=0):
    return opc << 56 | rd << 48 | ra << 40 | rb << 32 | imm


def bits(x):
    return struct.unpack("<I", struct.pack("<f", x))[0]


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def main():
    port = int(sys.argv[1])
    bus = RemoteClient(port=port, csr_csv=None)
    bus.open()
    fails = 0

    def check(what, got, want):
        nonlocal fails
        ok = got == want
        fails += not ok
        print(f"  {what}: 0x{got:08x} {'==' if ok else '!='} 0x{want:08x}")

    check("ID", bus.read(4 * ID), ID_VALUE)
    prog = [insn(OP_MUL, 3, 1, 2), insn(OP_ADD, 4, 3, 1), insn(OP_ENDI, imm=0)]
    words = []
    for w in prog:
        words += [w & 0xFFFFFFFF, w >> 32]
    bus.write(4 * IMEM_BASE, words)          # one burst
    a, b = f32(1.7), f32(-2.3)
    bus.write(4 * CTX, 0)
    bus.write(4 * (REG_BASE + 1), [bits(a), bits(b)])
    bus.write(4 * STEPS, 1)
    bus.write(4 * CONTEXTS, 1)
    bus.write(4 * CTRL, 1)                   # START
    for _ in range(1000):
        if not bus.read(4 * STATUS) & 1:     # RUNNING
            break
        time.sleep(0.001)
    check("STATUS (DONE, no error)", bus.read(4 * STATUS), 0x2)
    check("STEPS_DONE", bus.read(4 * STEPS_DONE), 1)
    p = f32(a * b)
    r3, r4 = bus.read(4 * (REG_BASE + 3), 2)
    check("r3 = r1 * r2", r3, bits(p))
    check("r4 = r3 + r1", r4, bits(f32(p + a)))
    check("bridge status", bus.read(4 * BRIDGE_STATUS), 0)
    bus.write(4 * CTRL, 2)                   # CLEAR
    bus.close()
    print("board_remote: " + ("PASS" if fails == 0 else f"FAIL ({fails})"))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
