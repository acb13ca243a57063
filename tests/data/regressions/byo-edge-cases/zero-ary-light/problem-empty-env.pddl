(define (problem z1) (:domain twoarm-light)
  (:objects left-arm right-arm - arm cup - item wall-switch - switch)
  (:init (grasped left-arm cup) (free right-arm))
  (:goal (and (light-on) (grasped left-arm cup))))
