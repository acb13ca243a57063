; The roads domain for a robot that cannot refuel: a task without fuel needs an excuse,
; and from the excuse state the cheapest plan (three short roads) is not the shortest (one long road).
(define (domain roads)
  (:requirements :strips :typing :action-costs)
  (:types place)
  (:predicates (at ?p - place) (road ?a ?b - place) (fuel))
  (:functions (total-cost) - number
              (road-length ?a ?b - place) - number)
  (:action drive
    :parameters (?a ?b - place)
    :precondition (and (at ?a) (road ?a ?b) (fuel))
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) (road-length ?a ?b)))))
