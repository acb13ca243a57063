; '(not (= a b))' holds (two constants are two objects); Fast Downward reads it; the STRIPS goal reader refused it.
(define (problem finish-b)
  (:domain goal-equality)
  (:init)
  (:goal (and (done b) (not (= a b)))))
