(define (problem pillars-two) (:domain pillars)
  (:objects p1 - place s - spot z1 z2 z3 z4 - zone pa pb - pillar)
  (:init (at pa p1) (at pb p1) (clear z1) (clear z2) (clear z3) (clear z4))
  (:goal (and (done1) (done2))))
