; An ADL model of another world: none of the kitchen robot's predicates, a disjunction and a conditional effect.
; Given as --invariants-from it groups none of the task's atoms (the excuse is the literal one).
(define (domain workshop)
  (:requirements :adl :typing)
  (:types thing)
  (:predicates (jammed ?t - thing) (free ?t - thing))
  (:action unjam
    :parameters (?t - thing)
    :precondition (or (jammed ?t) (free ?t))
    :effect (and (free ?t) (forall (?u - thing) (when (jammed ?u) (not (jammed ?u)))))))
