; A robot that drives between connected rooms and nothing else.  No room
; connects to the lab, so only a change to the map (a fixed graph over rooms)
; is an excuse: no person can demonstrate it.
(define (domain rooms)
  (:requirements :strips :typing)
  (:types robot room)
  (:predicates (at ?r - robot ?x - room) (connected ?x ?y - room))
  (:action drive :parameters (?r - robot ?from ?to - room)
    :precondition (and (at ?r ?from) (connected ?from ?to))
    :effect (and (not (at ?r ?from)) (at ?r ?to))))
