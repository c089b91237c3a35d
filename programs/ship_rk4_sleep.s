; ship_rk4_sleep.s -- ship_rk4.s with sleeping (docs/skipping.md "Sleeping objects"):
; an object whose velocity reached a fixed point skips the velocity stages.
;
; RK4 maps v0 to v1 = F(v0) with T, C, 1/m, h fixed.  If one integration
; leaves v bit-identical (v1 == v0 as bit patterns), every later one would
; compute the same F(v0) again, with the same roundings and flags: v stays
; v0 forever, and only s = s + h v1 still changes.  The body starts with
; `beq v, vp, coast`, where vp is the v0 of the last integration that ran the
; velocity stages; it jumps over them while v == vp.  The results are
; bit-identical to ship_rk4.s in every integration (its golden model, rk4,
; checks this program: `fp3 run --program programs/ship_rk4_sleep.s`).
;
; The host starts (or wakes, after changing T, C or m) an object with
; vp = nv0 = -v0, which is never bit-identical to v0: the first integration
; runs every stage.  An object at rest (v = 0, T = 0) settles after one
; integration; a cruising one when v reaches its binary32 fixed point.
;
; Cost: the beq and the mov are two more instructions in an awake
; integration, and a context fetches nothing behind a beq until it is
; resolved (FP3_BEQ_CYCLES); asleep, an integration is 4 instructions
; (beq, mul, add, endi) instead of 33.

.include "ship_rk4_common.inc"   ; registers, bindings, prologue
.integrator rk4se                ; the golden model it computes (docs/models.md)

.reg vp    r24      ; the velocity the last velocity stages started from
.in  -v0,  vp       ; -v0: never bit-identical to v0, so the first beq falls through

body:
        ; Asleep: the last integration left v bit-identical (v1 == v0 with
        ; the same T, C, m, h), so every later one would too: skip to s.
        beq  v, vp, coast
        mov  vp, v                        ; v0 of this integration
.include "ship_rk4_velocity.inc" ; k1, k2, k3, k4 and v1

        ; s = s + h v1: every integration, asleep or not
coast:
        mul  hv, h, v                     ; h v1
        add  s, s, hv                     ; s + h v1

        endi body                         ; next integration from v1, s
