; Eight keys, none held: eight minimal excuses.
(define (problem gate-8)
  (:domain gate)
  (:objects k1 k2 k3 k4 k5 k6 k7 k8 - key)
  (:init)
  (:goal (open)))
