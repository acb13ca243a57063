(define (problem shuttle-1)
  (:domain shuttle)
  (:objects plane - aircraft
            ann bob - person
            home away - city)
  (:init (at plane home) (at ann home) (at bob away))
  (:goal (and (at ann away) (at bob home))))
