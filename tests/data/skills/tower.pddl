;; Skills that carry: the second blocks task, a reverse tower. Unstacking c from b needs the learned unstack
;; without (ontable ?y): b stands on a.
(define (problem bw-t2)
  (:domain BLOCKS)
  (:objects a b c - block)
  (:init (handempty) (ontable a) (on b a) (on c b) (clear c))
  (:goal (and (on a b) (on b c))))
