(define (problem p1) (:domain boxes)
  (:objects cup - item crate - box)
  (:init (holding cup) (closed crate))
  (:goal (inside cup crate)))
