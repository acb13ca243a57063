; A robot that carries one parcel at a time between rooms.  `move` has no
; inequality between its rooms: moving "from a room to itself" is allowed and
; changes nothing, a case the checker's lifted proof that `move` keeps the
; robot in exactly one room has to consider.
(define (domain courier)
  (:requirements :strips :typing)
  (:types room parcel)
  (:predicates (robot-in ?r - room) (parcel-in ?p - parcel ?r - room) (carried ?p - parcel) (free))
  (:action move
    :parameters (?from ?to - room)
    :precondition (robot-in ?from)
    :effect (and (not (robot-in ?from)) (robot-in ?to)))
  (:action grab
    :parameters (?p - parcel ?r - room)
    :precondition (and (robot-in ?r) (parcel-in ?p ?r) (free))
    :effect (and (not (parcel-in ?p ?r)) (not (free)) (carried ?p)))
  (:action drop
    :parameters (?p - parcel ?r - room)
    :precondition (and (robot-in ?r) (carried ?p))
    :effect (and (parcel-in ?p ?r) (free) (not (carried ?p)))))
