; The main door is a constant: walking anywhere needs it open, and one action closes it.
(define (domain door)
  (:requirements :strips :typing)
  (:types room)
  (:constants main - room)
  (:predicates (open ?r - room) (in ?r - room))
  (:action close-main :parameters () :precondition (open main) :effect (not (open main)))
  (:action walk :parameters (?r - room) :precondition (open main) :effect (in ?r)))
