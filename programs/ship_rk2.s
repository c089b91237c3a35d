; ship_rk2.s -- the midpoint method (second-order Runge-Kutta) on the
; state (v, s) of Bourg's ship:
;
;   vm = v + h/2 f(v)              f(v) = (T - C v) * minv
;   s  = s + h vm                  (the s-stage of the midpoint: f_s = v)
;   v  = v + h f(vm)
;
; Second order in v and s; stable for h/tau < 2.  Golden model:
; rk2_init / rk2_step in sw/ref/integrators.c.

.include "ship_scene.inc"        ; T C minv h v s and their bindings
.integrator rk2                  ; the golden model it computes (docs/models.md)

.reg half  r7       ; 0.5
.reg hh    r8       ; h/2
.reg cv    r10
.reg F     r11
.reg a     r12
.reg hk    r13      ; h/2 f(v)
.reg vm    r14      ; midpoint velocity
.reg hv    r15      ; h vm
.reg k2    r16      ; h f(vm)

        li   half, 0.5
        mul  hh, half, h

body:
        mul  cv, C, v                     ; C v
        sub  F, T, cv                     ; T - C v
        mul  a, F, minv                   ; f(v)
        mul  hk, hh, a                    ; h/2 f(v)
        add  vm, v, hk                    ; vm
        mul  cv, C, vm                    ; C vm
        mul  hv, h, vm                    ; h vm (fills a stall)
        sub  F, T, cv                     ; T - C vm
        add  s, s, hv                     ; s + h vm (fills a stall)
        mul  a, F, minv                   ; f(vm)
        mul  k2, h, a                     ; h f(vm)
        add  v, v, k2                     ; v1
        endi body
