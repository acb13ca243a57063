(define (problem p) (:domain boxes)
  (:objects bot - robot b1 - box hall office - room)
  (:init (at bot hall) (placed b1 hall) (connected hall office) (connected office hall))
  (:goal (cleaned hall)))
