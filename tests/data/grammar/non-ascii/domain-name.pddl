; The domain is called küche; the problem names it so.
(define (domain küche)
  (:requirements :strips :typing)
  (:types room door)
  (:predicates (open ?d - door) (in ?r - room))
  (:action open-door
    :parameters (?d - door)
    :precondition (not (open ?d))
    :effect (open ?d)))
