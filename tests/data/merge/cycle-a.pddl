(define (domain cycle-a)
  (:requirements :strips :typing)
  (:types y - object x - y)
  (:predicates (mark ?v - x))
  (:action mark
    :parameters (?v - x)
    :precondition (and)
    :effect (mark ?v)))
