; Every reader extension at once: action costs, an 'either' predicate type,
; a type named like an object (cart), and an implicit constant (wrench).
(define (domain workshop)
  (:requirements :strips :typing :action-costs)
  (:types tool cart place - object)
  (:predicates (at ?x - (either tool cart) ?p - place) (have ?t - tool) (road ?a ?b - place))
  (:functions (total-cost) - number (distance ?a ?b - place) - number)
  (:action push
    :parameters (?c - cart ?a ?b - place)
    :precondition (and (at ?c ?a) (road ?a ?b))
    :effect (and (not (at ?c ?a)) (at ?c ?b) (increase (total-cost) (distance ?a ?b))))
  (:action grab
    :parameters (?c - cart ?p - place)
    :precondition (and (at ?c ?p) (at wrench ?p))
    :effect (and (have wrench) (not (at wrench ?p)) (increase (total-cost) 1))))
