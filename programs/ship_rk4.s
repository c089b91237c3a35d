; ship_rk4.s -- fourth-order Runge-Kutta on Bourg's ship, Equations (1) of
; Woulfe & Manzke (2006), then the displacement update s = s + h*v1.
;
;   f(v) = (T - C v) / m           (division replaced by a product with 1/m)
;   k1 = h f(v0)
;   k2 = h f(v0 + k1/2)     k3 = h f(v0 + k2/2)     k4 = h f(v0 + k3)
;   v1 = v0 + 0.16666667 (k1 + 2 k2 + 2 k3 + k4)
;   s  = s + h v1
;
; The operations and their operands are exactly those of the golden model
; (sw/ref/golden.c), so every engine must match it bit for bit.  Only the
; order of independent instructions differs: the processor issues in
; order, one instruction per cycle, and stalls an instruction until its
; operands are written (add/sub: 5 cycles issue to dependent issue, mul:
; 4; the register-file read stage plus the core latency).  The one chain k1 -> k2 -> k3 -> k4 -> v1 -> s fixes almost the whole
; order; the off-chain work 2*k2, k1 + 2*k2, 2*k3 and (k1 + 2k2) + 2k3 is
; placed in cycles where the chain would stall anyway.  Each destination
; is written again only long after its previous write has retired.
;
; Timing with ADD_LATENCY 4, MUL_LATENCY 3 (measured on the RTL): 121
; cycles for the first integration, 113 for each later one.  The chain
; from v0 to v1 alone is 105 cycles (17 for k1, 26 each for k2 and k3, 22
; for k4, 14 for v1); h*v1 and s + h*v1 must precede the endi and delay
; the next integration's C*v1 by 6; one context issues at most every
; other cycle, which costs 2 more.  Every instruction issues inside the
; chain's latency, so only more objects in flight would go faster.
;
; Registers: 9 hold the scene and the constants, 14 are temporaries.

.include "ship_rk4_common.inc"   ; registers, bindings, prologue
.integrator rk4se                ; the golden model it computes (docs/models.md)

body:
.include "ship_rk4_velocity.inc" ; k1, k2, k3, k4 and v1

        ; s = s + h v1
        mul  hv, h, v                     ; h v1
        add  s, s, hv                     ; s + h v1

        endi body                         ; next integration from v1, s
