; A predicate named geöffnet (open).
(define (domain house)
  (:requirements :strips :typing)
  (:types room door)
  (:predicates (geöffnet ?d - door) (open ?d - door) (in ?r - room))
  (:action open-door
    :parameters (?d - door)
    :precondition (not (open ?d))
    :effect (and (open ?d) (geöffnet ?d))))
