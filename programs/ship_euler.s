; ship_euler.s -- explicit Euler on Bourg's ship (v' = (T - C v)/m, s' = v).
;
;   a  = (T - C v) * minv
;   s  = s + h v          (the old v: both updates use the state at t)
;   v  = v + h a
;
; First order in v and s; stable for h/tau < 2 (tau = m/C).  Golden model:
; euler_step in sw/ref/integrators.c, the same operations in the same order
; per result.  Independent work (h v, s + h v) fills the stalls of the
; chain C v -> F -> a -> h a -> v.

.include "ship_scene.inc"        ; T C minv h v s and their bindings
.integrator euler                ; the golden model it computes (docs/models.md)

.reg cv    r10      ; C v
.reg F     r11      ; T - C v [N]
.reg a     r12      ; F / m [m/s^2]
.reg dv    r13      ; h a
.reg hv    r14      ; h v

body:
        mul  cv, C, v                     ; C v
        mul  hv, h, v                     ; h v (old v)
        sub  F, T, cv                     ; F = T - C v
        add  s, s, hv                     ; s + h v
        mul  a, F, minv                   ; a = F/m
        mul  dv, h, a                     ; h a
        add  v, v, dv                     ; v + h a
        endi body
