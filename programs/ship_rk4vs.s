; ship_rk4vs.s -- classic fourth-order Runge-Kutta on the whole state
; (v, s) of Bourg's ship.  The velocity stages are the paper's
; (programs/ship_rk4.s); the displacement stages of s' = v are the trial
; velocities themselves, so
;
;   s1 = s + h/6 (v + 2 vt2 + 2 vt3 + vt4)
;   vt2 = v + k1/2,  vt3 = v + k2/2,  vt4 = v + k3
;
; instead of the paper's first-order s = s + h v1.  Fourth order in v and
; s; stable for h/tau < 2.785.  Golden model: rk4vs_init / rk4vs_step in
; sw/ref/integrators.c.  The s work does not wait for v1, so it fills stalls
; of the velocity chain and the integration is shorter than the paper's:
; the endi issues right after v1 (107 cycles per integration measured,
; ADD_LATENCY 4, MUL_LATENCY 3).

.include "ship_scene.inc"        ; T C minv h v s and their bindings
.integrator rk4vs                ; the golden model it computes (docs/models.md)

.reg half  r7       ; 0.5
.reg two   r8       ; 2.0
.reg sixth r9       ; 0.16666667
.reg h6    r24      ; h * 0.16666667
.reg cv    r10
.reg F     r11
.reg a     r12
.reg hk    r13
.reg vt2   r14      ; v + k1/2
.reg k1    r15
.reg k2    r16
.reg k3    r17
.reg k4    r18
.reg t2    r19
.reg t3    r20
.reg sum   r21
.reg dv    r22
.reg vt3   r23      ; v + k2/2
.reg vt4   r25      ; v + k3
.reg w     r26      ; vt2 + vt3, then 2 (vt2 + vt3)
.reg u     r27      ; v + 2 vt2 + 2 vt3 + vt4
.reg ds    r28      ; h/6 u
.reg w2    r29

        li   half,  0.5
        li   two,   2.0
        li   sixth, 0.16666667
        mul  h6, h, sixth

body:
        mul  cv, C, v                     ; k1
        sub  F, T, cv
        mul  a, F, minv
        mul  k1, h, a
        mul  hk, half, k1                 ; k2
        add  vt2, v, hk
        mul  cv, C, vt2
        sub  F, T, cv
        mul  a, F, minv
        mul  k2, h, a
        mul  hk, half, k2                 ; k3
        mul  t2, two, k2                  ; 2 k2
        add  vt3, v, hk
        add  sum, k1, t2                  ; k1 + 2 k2
        mul  cv, C, vt3
        add  w, vt2, vt3                  ; s line: vt2 + vt3
        sub  F, T, cv
        mul  w2, two, w                   ; s line: 2 (vt2 + vt3)
        mul  a, F, minv
        add  u, v, w2                     ; s line: v + 2 vt2 + 2 vt3
        mul  k3, h, a
        add  vt4, v, k3                   ; k4
        mul  t3, two, k3                  ; 2 k3
        mul  cv, C, vt4
        add  sum, sum, t3                 ; + 2 k3
        add  u, u, vt4                    ; s line: + vt4
        sub  F, T, cv
        mul  ds, h6, u                    ; s line: h/6 u
        mul  a, F, minv
        add  s, s, ds                     ; s1
        mul  k4, h, a
        add  sum, sum, k4                 ; v1 = v + (k1 + 2 k2 + 2 k3 + k4)/6
        mul  dv, sixth, sum
        add  v, v, dv
        endi body
