(define (problem zero-1) (:domain zero)
  (:init)
  (:goal (and (lamp-on) (fan-on))))
