(define (problem 1-move) (:domain digit) (:objects 1robot - robot 2a b - room) (:init (at 1robot 2a)) (:goal (at 1robot b)))
