.include "missing.inc"
li r1, 0x3f800000
li r2, -1.5e-3
halt
