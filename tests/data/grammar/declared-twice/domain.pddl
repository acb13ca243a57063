; A delivery robot's map, its types written in two places: 'area' first among the plain types, then again below
; 'place' (Fast Downward reads it as one type below both, which is below 'place'). The predicate 'home' and the
; object 'home' share a name (predicates and objects are separate namespaces, as for Fast Downward).
(define (domain delivery)
  (:requirements :strips :typing)
  (:types robot place area parcel - object
          area - place)
  (:predicates (at ?r - robot ?p - place) (in ?x - parcel ?p - place) (carries ?r - robot ?x - parcel)
               (home ?a - area))
  (:action go
    :parameters (?r - robot ?from ?to - place)
    :precondition (at ?r ?from)
    :effect (and (at ?r ?to) (not (at ?r ?from))))
  (:action pick
    :parameters (?r - robot ?x - parcel ?p - place)
    :precondition (and (at ?r ?p) (in ?x ?p))
    :effect (and (carries ?r ?x) (not (in ?x ?p))))
  (:action drop-home
    :parameters (?r - robot ?x - parcel ?a - area)
    :precondition (and (at ?r ?a) (carries ?r ?x) (home ?a))
    :effect (and (in ?x ?a) (not (carries ?r ?x)))))
