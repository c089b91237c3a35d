#!/usr/bin/env python3
"""board-csr.py FP3_ISA_H OUT.csv -- a LiteX csr.csv of FP3's host registers,
so that LiteX's litex_cli names them (docs/board.md):
    litex_cli --csr-csv OUT.csv --port 1234 --regs
One csr_register row per scalar register the host may read (access R or RW
in the FP3_HOSTREGS table of sw/isa/fp3_isa.h), at its byte address (word
address x 4, the bridge's map), 1 word, mode ro or rw, named in lower case.
CTRL (write-only: reading it is a bus error), the register and program
windows and the bridge's read-to-clear status are left out, so that --regs
reads nothing that errs or changes state.
"""
import re
import sys


def main():
    src, out = sys.argv[1:3]
    text = open(src).read()
    table = text[text.index("#define FP3_HOSTREGS(X)"):]
    table = table[:table.index("\n\n")]
    rows = []
    for name, addr, acc in re.findall(r'X\((\w+),\s*(0x[0-9A-Fa-f]+),\s*"(\w+)"', table):
        if "R" not in acc or name.endswith("_BASE"):
            continue
        mode = "rw" if "W" in acc else "ro"
        rows.append(f"csr_register,{name.lower()},0x{4 * int(addr, 16):08x},1,{mode}")
    if not rows:
        sys.exit(f"board-csr.py: no host register found in {src}")
    with open(out, "w") as f:
        f.write("#--------------------------------------------------------------------------------\n")
        f.write(f"# FP3 host registers behind the UARTBone bridge, from {src} (scripts/board-csr.py)\n")
        f.write("#--------------------------------------------------------------------------------\n")
        # the bus: 32-bit registers, 32-bit addresses (LiteX's CSRBuilder reads these)
        f.write("constant,config_csr_data_width,32,,\n")
        f.write("constant,config_bus_address_width,32,,\n")
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()
