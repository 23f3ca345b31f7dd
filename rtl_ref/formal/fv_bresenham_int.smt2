; fv_bresenham_int.smt2 — formal-only (docs/FORMAL.md, proof rephase_div), second half of the
; lemma: the reference step of fv_bresenham.v on integers (fv_rephase_div.v shows the 13-bit
; Verilog step equals it for every legal P) keeps the division invariant
;   Inv(q, r, tr):  0 <= tr <= P,  0 <= r < P,  q * P + r = d * tr      (so (q, r) = divmod(d*tr, P))
; and Inv gives the facts F1..F4 that proof rephase assumes in stage 2. Every P >= 8, every d in
; [0, P), integers without bounds (QF_NIA). Each check-sat must answer unsat.
; Run: z3 rtl_ref/formal/fv_bresenham_int.smt2   (scripts/formal.sh rephase_div)
(set-logic QF_NIA)
(declare-const P Int)
(declare-const d Int)
(declare-const q Int)
(declare-const r Int)
(declare-const tr Int)
(declare-const up Bool)
(assert (>= P 8))
(assert (and (<= 0 d) (< d P)))
(define-fun inv ((q Int) (r Int) (tr Int)) Bool
  (and (<= 0 tr) (<= tr P) (<= 0 r) (< r P) (= (+ (* q P) r) (* d tr))))

; 1. base: (q, r) = (0, 0) at tr = 0 (point A)
(push)
(assert (not (inv 0 0 0)))
(check-sat)
(pop)

; 2. step: tr + 1 when tr < P (r + d >= P carries), tr - 1 when tr > 0 (r < d borrows)
(push)
(assert (inv q r tr))
(assert (ite up (< tr P) (> tr 0)))
(define-fun tr2 () Int (ite up (+ tr 1) (- tr 1)))
(define-fun r2 () Int (ite up (ite (>= (+ r d) P) (- (+ r d) P) (+ r d)) (ite (< r d) (- (+ r P) d) (- r d))))
(define-fun q2 () Int (ite up (ite (>= (+ r d) P) (+ q 1) q) (ite (< r d) (- q 1) q)))
(assert (not (inv q2 r2 tr2)))
(check-sat)
(pop)

; 3. the facts: F1 0 <= q <= d and q <= tr (the adjustment stays in [0, d]); F2 tr = 0 gives
;    (0, 0) (going back to A undoes it); F3 at tr = P - 1, (d - 1, P - d), or (0, 0) when d = 0
;    (the homing count then carries exactly to q = d); F4 at tr = P, (d, 0)
(push)
(assert (inv q r tr))
(assert (not (and (<= 0 q) (<= q d) (<= q tr)
                  (=> (= tr 0) (and (= q 0) (= r 0)))
                  (=> (= tr (- P 1)) (ite (= d 0) (and (= q 0) (= r 0))
                                                  (and (= q (- d 1)) (= r (- P d)))))
                  (=> (= tr P) (and (= q d) (= r 0))))))
(check-sat)
(pop)
