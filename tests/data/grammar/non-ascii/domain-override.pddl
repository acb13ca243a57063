; An action name with a right-to-left override (U+202E) inside: it displays as another name.
(define (domain house)
  (:requirements :strips :typing)
  (:types room door)
  (:predicates (open ?d - door) (in ?r - room))
  (:action open-‮rood
    :parameters (?d - door)
    :precondition (not (open ?d))
    :effect (open ?d)))
