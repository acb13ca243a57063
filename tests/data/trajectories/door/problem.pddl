(define (problem walk-in) (:domain door) (:objects r2 - room) (:init) (:goal (in r2)))
