(define (problem zone-leak-1)
  (:domain zone-leak)
  (:init)
  (:goal (and (g1) (g2))))
