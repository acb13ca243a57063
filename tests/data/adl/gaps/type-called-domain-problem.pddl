(define (problem p1) (:domain courier-like) (:objects t1 - truck a b - place) (:init (at t1 a)) (:goal (at t1 b)))
