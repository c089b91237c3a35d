; ship_rk4vscomp.s -- classic RK4 on (v, s) (programs/ship_rk4vs.s) with both
; state updates compensated (Kahan summation, as programs/ship_rk4comp.s):
;
;   y = d - c;  t = x + y;  c = (t - x) - y;  x = t      for x += d
;
; for v += dv and s += h/6 (v + 2 vt2 + 2 vt3 + vt4).  Fourth order in v
; and s, and no binary32 stagnation over long runs.  Golden model:
; rk4vscomp_step in sw/ref/integrators.c.  As in ship_rk4comp.s the
; compensations c of integration k are computed at the top of integration
; k+1 from the saved x and y (they are no results); the prologue makes the
; first ones 0.  The dv and y = dv - c of v lie on the chain: 117 cycles
; per integration against rk4vs's 107 (ADD_LATENCY 4, MUL_LATENCY 3).

.include "ship_scene.inc"        ; T C minv h v s and their bindings
.integrator rk4vscomp            ; the golden model it computes (docs/models.md)

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
.reg t2    r19      ; 2 k2, then 2 k3
.reg sum   r21      ; k1 + 2 k2 + 2 k3 + k4, then dv = sum / 6
.reg vt3   r23      ; v + k2/2
.reg vt4   r25      ; v + k3
.reg w     r26      ; vt2 + vt3, then 2 (vt2 + vt3)
.reg u     r27      ; v + 2 vt2 + 2 vt3 + vt4
.reg ds    r28      ; h/6 u
.reg vold  r0       ; v before the latest update
.reg yv    r30      ; dv - cvc of the latest update
.reg cvc   r31      ; compensation of v
.reg sold  r29      ; s before the latest update
.reg ys    r20      ; ds - cs of the latest update
.reg cs    r22      ; compensation of s
.reg zv    r13      ; v - vold (shares r13 with hk: dead by then)
.reg zs    r18      ; s - sold (shares r18 with k4: dead by then)

        li   half,  0.5
        li   two,   2.0
        li   sixth, 0.16666667
        mul  h6, h, sixth
        li   yv,    0.0                   ; first compensations: (x - x) - 0 = 0
        li   ys,    0.0
        mov  vold,  v
        mov  sold,  s

body:
        mul  cv, C, v                     ; k1
        sub  zv, v, vold                  ; previous v update: t - x
        sub  zs, s, sold                  ; previous s update: t - x
        sub  F, T, cv
        sub  cvc, zv, yv                  ; c = (t - x) - y
        sub  cs, zs, ys
        mul  a, F, minv
        mov  vold, v
        mov  sold, s
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
        mul  w, two, w                    ; s line: 2 (vt2 + vt3)
        mul  a, F, minv
        add  u, v, w                      ; s line: v + 2 vt2 + 2 vt3
        mul  k3, h, a
        add  vt4, v, k3                   ; k4
        mul  t2, two, k3                  ; 2 k3
        mul  cv, C, vt4
        add  sum, sum, t2                 ; + 2 k3
        add  u, u, vt4                    ; s line: + vt4
        sub  F, T, cv
        mul  ds, h6, u                    ; s line: h/6 u
        mul  a, F, minv
        sub  ys, ds, cs                   ; s line: y = ds - c
        mul  k4, h, a
        add  sum, sum, k4                 ; v1 = v + (k1 + 2 k2 + 2 k3 + k4)/6
        add  s, s, ys                     ; s1 = s + y (fills a stall)
        mul  sum, sixth, sum              ; dv
        sub  yv, sum, cvc                 ; y = dv - c
        add  v, v, yv                     ; v1 = v + y
        endi body
