; Found by tests/test_fuzz_adl.py: an action whose effect is its cost alone, '(and (increase (total-cost) 1))'.
; The model writes it back for Fast Downward's translator as a bare '(increase ...)', on which its parser fails.
(define (domain cost-alone)
  (:requirements :adl :action-costs)
  (:predicates (p) (q))
  (:functions (total-cost) - number)
  (:action wait
    :parameters ()
    :precondition (or (p) (q))
    :effect (and (increase (total-cost) 1)))
  (:action make
    :parameters ()
    :precondition (and)
    :effect (and (p) (increase (total-cost) 2))))
