; Parcels carried from a depot to their houses by a courier who walks back
; after each: the relaxed plan of a state orders the carries before the walks
; back, so the lookahead's harmless-first rule matters.
(define (domain parcels)
  (:requirements :strips :typing)
  (:types place parcel)
  (:predicates (courier-at ?p - place) (at ?x - parcel ?p - place) (carrying ?x - parcel) (free))
  (:action take
    :parameters (?x - parcel ?p - place)
    :precondition (and (courier-at ?p) (at ?x ?p) (free))
    :effect (and (carrying ?x) (not (at ?x ?p)) (not (free))))
  (:action put
    :parameters (?x - parcel ?p - place)
    :precondition (and (courier-at ?p) (carrying ?x))
    :effect (and (at ?x ?p) (free) (not (carrying ?x))))
  (:action walk
    :parameters (?from - place ?to - place)
    :precondition (courier-at ?from)
    :effect (and (courier-at ?to) (not (courier-at ?from)))))
