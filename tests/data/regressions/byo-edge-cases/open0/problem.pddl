(define (problem open0-1) (:domain open0)
  (:objects s1 - switch l1 - lamp)
  (:init (wired s1 l1))
  (:goal (and (lit l1))))
