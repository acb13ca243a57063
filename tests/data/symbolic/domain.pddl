(define (domain roads)
  (:requirements :strips :typing)
  (:types obj loc)
  (:predicates (at ?o - obj ?l - loc) (road ?a - loc ?b - loc))
  (:action move
    :parameters (?o - obj ?a - loc ?b - loc)
    :precondition (and (at ?o ?a) (road ?a ?b))
    :effect (and (at ?o ?b) (not (at ?o ?a)))))
