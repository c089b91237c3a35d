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
; (sw/golden.c), so every engine must match it bit for bit.  Only the
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

; ---- prologue: register initialisation, run once ------------------------
        li   half,  0.5
        li   two,   2.0
        li   sixth, 0.16666667            ; 0x3E2AAAAB

; ---- one integration ----------------------------------------------------
body:
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

        ; s = s + h v1
        mul  hv, h, v                     ; h v1
        add  s, s, hv                     ; s + h v1

        endi body                         ; next integration from v1, s
