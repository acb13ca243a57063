; The task every domain of this folder is read with: reach (done) through a derived predicate.
(define (problem derived-1)
  (:domain derived)
  (:objects a b - thing)
  (:init (p a) (e a b) (e b a))
  (:goal (done)))
