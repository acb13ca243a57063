(define (problem hmax-fact-queued-twice-1)
  (:domain hmax-fact-queued-twice)
  (:init (a))
  (:goal (g)))
