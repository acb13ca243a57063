(define (problem pe) (:domain e) (:objects t - truck a b - place) (:init (at t a)) (:goal (goal-at b)))
