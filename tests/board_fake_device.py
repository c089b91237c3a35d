#!/usr/bin/env python3
"""board_fake_device.py READY_FILE MODE -- a TCP server on 127.0.0.1 that is
not an FP3 board, for the host engine's error paths (tests/test_board.sh).
It parses UARTBone frames as the bridge does and answers each read with
  MODE id      0x12345678 for every word (a device with a wrong ID)
  MODE short   the first 2 bytes of the answer only (a short read)
  MODE silent  nothing
Writes the port to READY_FILE, serves clients until killed.
"""
import socket
import struct
import sys


def serve(conn, mode):
    buf = b""
    while True:
        data = conn.recv(4096)
        if not data:
            return
        buf += data
        while len(buf) >= 6:
            cmd, n = buf[0], buf[1]
            if cmd in (1, 3):
                if len(buf) < 6 + 4 * n:
                    break
                buf = buf[6 + 4 * n:]
            elif cmd in (2, 4):
                buf = buf[6:]
                answer = struct.pack(">I", 0x12345678) * n
                if mode == "id":
                    conn.sendall(answer)
                elif mode == "short":
                    conn.sendall(answer[:2])
            else:
                buf = buf[1:]


def main():
    ready, mode = sys.argv[1], sys.argv[2]
    s = socket.socket()
    s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    s.bind(("127.0.0.1", 0))
    s.listen(1)
    with open(ready + ".tmp", "w") as f:
        f.write(f"tcp {s.getsockname()[1]}\n")
    import os
    os.rename(ready + ".tmp", ready)
    while True:
        conn, _ = s.accept()
        with conn:
            serve(conn, mode)


if __name__ == "__main__":
    main()
