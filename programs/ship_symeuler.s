; ship_symeuler.s -- semi-implicit (symplectic) Euler on Bourg's ship.
;
;   a  = (T - C v) * minv
;   v  = v + h a
;   s  = s + h v          (the new v)
;
; First order; stable for h/tau < 2 (the velocity update is Euler's).
; Golden model: symeuler_step in sw/ref/integrators.c.  One dependent chain:
; nothing to fill the stalls with.

.include "ship_scene.inc"        ; T C minv h v s and their bindings
.integrator symeuler             ; the golden model it computes (docs/models.md)

.reg cv    r10      ; C v
.reg F     r11      ; T - C v [N]
.reg a     r12      ; F / m [m/s^2]
.reg dv    r13      ; h a
.reg hv    r14      ; h v (new v)

body:
        mul  cv, C, v                     ; C v
        sub  F, T, cv                     ; F = T - C v
        mul  a, F, minv                   ; a = F/m
        mul  dv, h, a                     ; h a
        add  v, v, dv                     ; v1 = v + h a
        mul  hv, h, v                     ; h v1
        add  s, s, hv                     ; s + h v1
        endi body
