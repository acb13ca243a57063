; Roads with lengths: the cheapest route is not the shortest one.
(define (domain roads)
  (:requirements :strips :typing :action-costs)
  (:types place)
  (:predicates (at ?p - place) (road ?a ?b - place) (visited ?p - place))
  (:functions (total-cost) - number
              (road-length ?a ?b - place) - number)
  (:action drive
    :parameters (?a ?b - place)
    :precondition (and (at ?a) (road ?a ?b))
    :effect (and (not (at ?a)) (at ?b) (visited ?b)
                 (increase (total-cost) (road-length ?a ?b))))
  (:action teleport
    :parameters (?a ?b - place)
    :precondition (at ?a)
    :effect (and (not (at ?a)) (at ?b) (increase (total-cost) 50)))
  (:action look
    :parameters (?a - place)
    :precondition (at ?a)
    :effect (visited ?a)))
