; The same, the cost written without '(and ...)' (valid PDDL: an effect may be one p-effect).
(define (domain cost-alone)
  (:requirements :adl :action-costs)
  (:predicates (p) (q))
  (:functions (total-cost) - number)
  (:action wait
    :parameters ()
    :precondition (or (p) (q))
    :effect (increase (total-cost) 1))
  (:action make
    :parameters ()
    :precondition (and)
    :effect (and (p) (increase (total-cost) 2))))
