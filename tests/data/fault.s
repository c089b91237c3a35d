; fault.s -- a ship program that faults on purpose (tests/test_cli.sh,
; tests/test_json.sh): its second word is an illegal instruction
; (ILLEGAL_INSN at pc 1) on every engine.
.integrator euler
.in v0, r5
.in s0, r6
.out v, r5
.out s, r6
b:      nop
        .word 0x0F00000000000000
        endi b
