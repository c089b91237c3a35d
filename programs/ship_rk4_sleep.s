; ship_rk4_sleep.s -- ship_rk4.s with sleeping (README "Sleeping objects"):
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

; ---- scene parameters, written by the host before the run -------------
.reg T     r1       ; thrust [N]
.reg C     r2       ; drag coefficient [kg/s]
.reg minv  r3       ; 1/m [1/kg] (the host rounds 1.0f/m)
.reg h     r4       ; time step [s]
.reg v     r5       ; velocity [m/s]: v0 in, v1 out of every integration
.reg s     r6       ; displacement [m]

.in  T,    T
.in  C,    C
.in  minv, minv
.in  h,    h
.in  v0,   v
.in  s0,   s
.out v,    v
.out s,    s

; ---- constants (the prologue loads them once) -------------------------
.reg half  r7       ; 0.5
.reg two   r8       ; 2.0
.reg sixth r9       ; 0.16666667 replaces the division by 6

; ---- temporaries -------------------------------------------------------
.reg cv    r10      ; C * v
.reg F     r11      ; force T - C v [N]
.reg a     r12      ; acceleration F / m [m/s^2]
.reg hk    r13      ; k/2
.reg vt    r14      ; trial velocity v0 + k/2, v0 + k3
.reg k1    r15
.reg k2    r16
.reg k3    r17
.reg k4    r18
.reg t2    r19      ; 2 k2
.reg t3    r20      ; 2 k3
.reg sum   r21      ; k1 + 2 k2 + 2 k3 + k4, accumulated left to right
.reg dv    r22      ; sum / 6
.reg hv    r23      ; h v1
.reg vp    r24      ; the velocity the last velocity stages started from
.in  nv0,  vp       ; -v0: never bit-identical to v0, so the first beq falls through

; ---- prologue: register initialisation, run once ------------------------
        li   half,  0.5
        li   two,   2.0
        li   sixth, 0.16666667            ; 0x3E2AAAAB

; ---- one integration ----------------------------------------------------
body:
        ; Asleep: the last integration left v bit-identical (v1 == v0 with
        ; the same T, C, m, h), so every later one would too: skip to s.
        beq  v, vp, coast
        mov  vp, v                        ; v0 of this integration

        ; k1 = h a,  a = F/m,  F = T - C v0
        mul  cv, C, v                     ; F = T - C v0    (C v0)
        sub  F, T, cv                     ; F = T - C v0
        mul  a, F, minv                   ; a = F/m
        mul  k1, h, a                     ; k1 = h a

        ; k2: F = T - C (v0 + k1/2); a = F/m; k2 = h a
        mul  hk, half, k1                 ; k1/2
        add  vt, v, hk                    ; v0 + k1/2
        mul  cv, C, vt                    ; C (v0 + k1/2)
        sub  F, T, cv                     ; F = T - C (v0 + k1/2)
        mul  a, F, minv                   ; a = F/m
        mul  k2, h, a                     ; k2 = h a

        ; k3: F = T - C (v0 + k2/2); a = F/m; k3 = h a
        mul  hk, half, k2                 ; k2/2
        mul  t2, two, k2                  ; v1 line: 2 k2   (fills a stall)
        add  vt, v, hk                    ; v0 + k2/2
        add  sum, k1, t2                  ; v1 line: k1 + 2 k2 (fills a stall)
        mul  cv, C, vt                    ; C (v0 + k2/2)
        sub  F, T, cv                     ; F = T - C (v0 + k2/2)
        mul  a, F, minv                   ; a = F/m
        mul  k3, h, a                     ; k3 = h a

        ; k4: F = T - C (v0 + k3); a = F/m; k4 = h a
        add  vt, v, k3                    ; v0 + k3
        mul  t3, two, k3                  ; v1 line: 2 k3   (fills a stall)
        mul  cv, C, vt                    ; C (v0 + k3)
        add  sum, sum, t3                 ; v1 line: + 2 k3 (fills a stall)
        sub  F, T, cv                     ; F = T - C (v0 + k3)
        mul  a, F, minv                   ; a = F/m
        mul  k4, h, a                     ; k4 = h a

        ; v1 = v0 + 0.16666667 (k1 + 2 k2 + 2 k3 + k4)
        add  sum, sum, k4                 ; + k4
        mul  dv, sixth, sum               ; / 6
        add  v, v, dv                     ; v1

        ; s = s + h v1: every integration, asleep or not
coast:
        mul  hv, h, v                     ; h v1
        add  s, s, hv                     ; s + h v1

        endi body                         ; next integration from v1, s
