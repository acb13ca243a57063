(define (problem p1) (:domain world)
  (:objects x - thing l1 l2 - place)
  (:init (at x l1))
  (:goal (done)))
