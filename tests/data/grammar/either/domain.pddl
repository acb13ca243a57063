; 'either' types of predicate parameters, as Fast Downward's translator reads them
; (zenotravel's (at ?x - (either person aircraft) ?c - city)); 'aircraft' is a
; subtype of 'vehicle', so an aircraft fits (either person vehicle).
(define (domain shuttle)
  (:requirements :strips :typing)
  (:types vehicle person city - object
          aircraft - vehicle)
  (:predicates (at ?x - (either person vehicle) ?c - city)
               (in ?p - person ?a - aircraft))

  (:action board
    :parameters (?p - person ?a - aircraft ?c - city)
    :precondition (and (at ?p ?c) (at ?a ?c))
    :effect (and (not (at ?p ?c)) (in ?p ?a)))

  (:action debark
    :parameters (?p - person ?a - aircraft ?c - city)
    :precondition (and (in ?p ?a) (at ?a ?c))
    :effect (and (not (in ?p ?a)) (at ?p ?c)))

  (:action fly
    :parameters (?a - aircraft ?from ?to - city)
    :precondition (at ?a ?from)
    :effect (and (not (at ?a ?from)) (at ?a ?to))))
