; Independent two-step errands: every relaxed plan is a plan, so one
; lookahead from the start reaches the goal.
(define (domain errands)
  (:requirements :strips :typing)
  (:types errand)
  (:predicates (open ?e - errand) (begun ?e - errand) (done ?e - errand))
  (:action begin
    :parameters (?e - errand)
    :precondition (open ?e)
    :effect (and (begun ?e) (not (open ?e))))
  (:action finish
    :parameters (?e - errand)
    :precondition (begun ?e)
    :effect (and (done ?e) (not (begun ?e)))))
