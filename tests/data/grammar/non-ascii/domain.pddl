; Türen öffnen: non-ASCII characters in comments are fine (Fast Downward's translator reads them).
(define (domain house)
  (:requirements :strips :typing)
  (:types room door)
  (:predicates (open ?d - door) (in ?r - room))
  (:action open-door
    :parameters (?d - door)
    :precondition (not (open ?d))
    :effect (open ?d)))
