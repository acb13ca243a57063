; The courier without `grab`: it can move and drop, never pick a parcel up.
(define (domain courier)
  (:requirements :strips :typing)
  (:types room parcel)
  (:predicates (robot-in ?r - room) (parcel-in ?p - parcel ?r - room) (carried ?p - parcel) (free))
  (:action move
    :parameters (?from ?to - room)
    :precondition (robot-in ?from)
    :effect (and (not (robot-in ?from)) (robot-in ?to)))
  (:action drop
    :parameters (?p - parcel ?r - room)
    :precondition (and (robot-in ?r) (carried ?p))
    :effect (and (parcel-in ?p ?r) (free) (not (carried ?p)))))
