; A fact that is both true and added by a precondition-free action was queued
; twice by the list h^max, so `x` fired before (b) was reached: h^max(g) = 0
; instead of the cost of adding (b), and LM-cut lost the landmark {+(b)}.
(define (domain hmax-fact-queued-twice)
  (:requirements :strips)
  (:predicates (a) (b) (g))
  (:action free
    :parameters ()
    :precondition (and)
    :effect (a))
  (:action x
    :parameters ()
    :precondition (and (a) (b))
    :effect (g)))
