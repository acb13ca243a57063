;; Skills that carry: the first blocks task. c stands on a, which stands on the table: one demonstration of
;; unstack c a shows (ontable ?y) held, so the learned unstack requires it.
(define (problem bw-t1)
  (:domain BLOCKS)
  (:objects a b c - block)
  (:init (handempty) (ontable a) (on c a) (clear c) (ontable b) (clear b))
  (:goal (and (on c b))))
