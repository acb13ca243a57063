(define (problem t1) (:domain inherited-removal-share) (:init (q)) (:goal (g)))
