; The initial state lists (q b), an atom of a derived predicate (Fast Downward: "appears in :init fact").
(define (problem derived-1)
  (:domain derived)
  (:objects a b - thing)
  (:init (p a) (q b))
  (:goal (done)))
