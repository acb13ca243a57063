(define (problem press-once)
  (:domain press)
  (:init (at-left))
  (:goal (pressed)))
