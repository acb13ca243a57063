;; Says a drawer is a surface: merged, the prior's put-on-a-surface skills
;; would accept drawers, so merge refuses it.
(define (domain other)
  (:requirements :strips :typing)
  (:types furniture - object surface - furniture drawer - surface)
  (:predicates (shut ?d - drawer))
  (:action shut
    :parameters (?d - drawer)
    :precondition (and)
    :effect (shut ?d)))
