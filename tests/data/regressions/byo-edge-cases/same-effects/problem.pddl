(define (problem doors-1) (:domain doors)
  (:objects d1 - door r1 r2 - room)
  (:init (at r1) (connects d1 r1 r2))
  (:goal (at r2)))
