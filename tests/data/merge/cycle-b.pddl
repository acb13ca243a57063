(define (domain cycle-b)
  (:requirements :strips :typing)
  (:types x - object y - x)
  (:predicates (mark ?v - x))
  (:action mark
    :parameters (?v - x)
    :precondition (and)
    :effect (mark ?v)))
