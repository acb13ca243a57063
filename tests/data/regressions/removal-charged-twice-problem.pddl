(define (problem t1) (:domain removal-charged-twice) (:init (q)) (:goal (g)))
