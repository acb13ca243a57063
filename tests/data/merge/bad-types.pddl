(define (domain other)
  (:requirements :strips :typing)
  (:types container - object
          drawer - container)
  (:predicates (shut ?d - drawer))
  (:action shut
    :parameters (?d - drawer)
    :precondition (and)
    :effect (shut ?d)))
