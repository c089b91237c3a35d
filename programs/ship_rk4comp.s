; ship_rk4comp.s -- the paper's RK4 (programs/ship_rk4.s) with both state
; updates compensated (Kahan summation):
;
;   y = d - c;  t = x + y;  c = (t - x) - y;  x = t      for x += d
;
; for v += dv and s += h v1.  c keeps what rounding dropped from x, so a
; step smaller than half an ulp of x is not lost: v reaches T/C and s keeps
; moving after 10^7 integrations where the plain program stagnates.
; Golden model: rk4comp_step in sw/ref/integrators.c.
;
; Only v and s are results, so the compensation terms c of integration k
; are computed at the top of integration k+1 (from the saved x and y),
; where they fill stalls; the prologue makes the first ones 0.  Costs 8
; more cycles than the plain program (128 against 113 per integration,
; ADD_LATENCY 4, MUL_LATENCY 3): y = d - c lies on the chain, twice.

.include "ship_scene.inc"        ; T C minv h v s and their bindings
.integrator rk4secomp            ; the golden model it computes (docs/models.md)

.reg half  r7
.reg two   r8
.reg sixth r9
.reg cv    r10
.reg F     r11
.reg a     r12
.reg hk    r13
.reg vt    r14
.reg k1    r15
.reg k2    r16
.reg k3    r17
.reg k4    r18
.reg t2    r19
.reg t3    r20
.reg sum   r21
.reg dv    r22
.reg hv    r23
.reg vold  r24      ; v before the latest update
.reg yv    r25      ; dv - cvc of the latest update
.reg zv    r26      ; v - vold
.reg cvc   r27      ; compensation of v
.reg sold  r28
.reg ys    r29
.reg zs    r30
.reg cs    r31      ; compensation of s

        li   half,  0.5
        li   two,   2.0
        li   sixth, 0.16666667
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
        add  vt, v, hk
        mul  cv, C, vt
        sub  F, T, cv
        mul  a, F, minv
        mul  k2, h, a
        mul  hk, half, k2                 ; k3
        mul  t2, two, k2
        add  vt, v, hk
        add  sum, k1, t2
        mul  cv, C, vt
        sub  F, T, cv
        mul  a, F, minv
        mul  k3, h, a
        add  vt, v, k3                    ; k4
        mul  t3, two, k3
        mul  cv, C, vt
        add  sum, sum, t3
        sub  F, T, cv
        mul  a, F, minv
        mul  k4, h, a
        add  sum, sum, k4
        mul  dv, sixth, sum
        sub  yv, dv, cvc                  ; y = dv - c
        add  v, v, yv                     ; v1 = v + y
        mul  hv, h, v
        sub  ys, hv, cs                   ; y = h v1 - c
        add  s, s, ys                     ; s1 = s + y
        endi body
