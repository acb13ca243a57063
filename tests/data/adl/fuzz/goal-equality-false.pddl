; '(= a b)' never holds: unsolvable, not unsupported.
(define (problem finish-b-as-a)
  (:domain goal-equality)
  (:init)
  (:goal (and (done b) (= a b))))
