(define (problem relaxfail-1) (:domain relaxfail)
  (:objects p1 - place sa sb - spot pil - pillar bx - box)
  (:init (at pil p1) (at bx p1) (tok))
  (:goal (done)))
