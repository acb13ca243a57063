; The human model types the vehicle (either truck plane): related to the robot's truck.
(define (domain e)
  (:requirements :strips :typing)
  (:types truck plane place)
  (:predicates (at ?v - (either truck plane) ?p - place) (goal-at ?p - place))
  (:action move :parameters (?v - truck ?a ?b - place) :precondition (at ?v ?a) :effect (and (not (at ?v ?a)) (at ?v ?b))))
