(define (domain other)
  (:requirements :strips :typing)
  (:types item - object)
  (:predicates (open ?a - item ?b - item))
  (:action shut
    :parameters (?a ?b - item)
    :precondition (open ?a ?b)
    :effect (not (open ?a ?b))))
