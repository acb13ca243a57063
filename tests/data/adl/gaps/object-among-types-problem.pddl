(define (problem p1) (:domain objfirst) (:objects r1 - robot a b - room) (:init (at r1 a)) (:goal (at r1 b)))
