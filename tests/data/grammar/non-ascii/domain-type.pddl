; A type named tür (door).
(define (domain house)
  (:requirements :strips :typing)
  (:types room tür)
  (:predicates (open ?d - tür) (in ?r - room))
  (:action open-door
    :parameters (?d - tür)
    :precondition (not (open ?d))
    :effect (open ?d)))
