; ship_verlet.s -- velocity Verlet on Bourg's ship.  The force depends on
; the velocity, so the new acceleration is evaluated at a velocity
; predicted by Euler, and the acceleration of the new velocity is carried
; to the next integration (computed once in the prologue for v0):
;
;   s  = s + (h v + h^2/2 a)
;   vp = v + h a,   ap = f(vp)
;   v  = v + h/2 (a + ap)
;   a  = f(v)                      f(v) = (T - C v) * minv
;
; Second order in v and s; the velocity update is Heun's, stable for
; h/tau < 2.  Golden model: verlet_init / verlet_step, sw/ref/integrators.c.

.include "ship_scene.inc"        ; T C minv h v s and their bindings
.integrator verletp              ; the golden model it computes (docs/models.md)

.reg half  r7       ; 0.5
.reg hh    r8       ; h/2
.reg hh2   r9       ; h^2/2
.reg a     r10      ; f(v), carried
.reg cv    r11
.reg F     r12
.reg hsq   r13      ; h^2
.reg hv    r14      ; h v
.reg q     r15      ; h^2/2 a
.reg ds    r16      ; h v + h^2/2 a
.reg ea    r17      ; h a
.reg vp    r18      ; predicted v
.reg ap    r19      ; f(vp)
.reg sa    r20      ; a + ap
.reg dv    r21      ; h/2 (a + ap)

; ---- prologue: constants and a = f(v0) ------------------------------------
        li   half, 0.5
        mul  cv, C, v
        mul  hsq, h, h
        mul  hh, half, h
        sub  F, T, cv
        mul  hh2, half, hsq
        mul  a, F, minv

body:
        mul  ea, h, a                     ; h a
        mul  hv, h, v                     ; h v
        mul  q, hh2, a                    ; h^2/2 a
        add  vp, v, ea                    ; vp = v + h a
        add  ds, hv, q                    ; h v + h^2/2 a
        mul  cv, C, vp                    ; C vp
        sub  F, T, cv                     ; T - C vp
        add  s, s, ds                     ; s1 (fills a stall)
        mul  ap, F, minv                  ; ap = f(vp)
        add  sa, a, ap                    ; a + ap
        mul  dv, hh, sa                   ; h/2 (a + ap)
        add  v, v, dv                     ; v1
        mul  cv, C, v                     ; a = f(v1) for the next step
        sub  F, T, cv
        mul  a, F, minv
        endi body
