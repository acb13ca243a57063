(define (problem named) (:domain digit) (:objects domain - robot a b - room) (:init (at domain a)) (:goal (at domain b)))
