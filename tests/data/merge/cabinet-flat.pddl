(define (domain flat)
  (:requirements :strips :typing)
  (:types cabinet - object)
  (:predicates (locked ?c - cabinet))
  (:action lock
    :parameters (?c - cabinet)
    :precondition (and)
    :effect (locked ?c)))
