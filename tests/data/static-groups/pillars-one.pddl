(define (problem pillars-one) (:domain pillars)
  (:objects p1 - place p3 - spot z1 z2 z3 - zone pil - pillar)
  (:init (at pil p1) (clear p1) (clear z1) (clear z2) (clear z3))
  (:goal (and (done1) (done2))))
