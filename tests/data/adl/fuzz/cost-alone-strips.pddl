; The same in STRIPS: read, but written back for the translator's invariant synthesis as a bare cost.
(define (domain cost-alone)
  (:requirements :strips :action-costs)
  (:predicates (p) (q))
  (:functions (total-cost) - number)
  (:action wait
    :parameters ()
    :precondition (q)
    :effect (and (increase (total-cost) 1)))
  (:action make
    :parameters ()
    :precondition (and)
    :effect (and (p) (increase (total-cost) 2))))
