(define (domain other)
  (:requirements :strips :typing)
  (:types inside - object)
  (:predicates (used ?x - inside))
  (:action use
    :parameters (?x - inside)
    :precondition (and)
    :effect (used ?x)))
