; A box placed in the hall stands in the way of cleaning it, and nothing here moves boxes: (placed ?b ?x) is
; a placing relation; taking the box away (-(placed b1 hall)) leaves it in no place, which "one place" allows.
(define (domain boxes)
  (:requirements :strips :typing :negative-preconditions)
  (:types robot box room)
  (:predicates (at ?r - robot ?x - room) (placed ?b - box ?x - room) (connected ?x ?y - room) (cleaned ?x - room))
  (:action drive :parameters (?r - robot ?from ?to - room)
    :precondition (and (at ?r ?from) (connected ?from ?to))
    :effect (and (not (at ?r ?from)) (at ?r ?to)))
  (:action clean :parameters (?r - robot ?b - box ?x - room)
    :precondition (and (at ?r ?x) (not (placed ?b ?x)))
    :effect (cleaned ?x)))
