; As in the unsolvability track's unsat-tpp: a type called `domain`, named only
; as the parent of others (never declared on its own), which tarski's grammar
; refuses (a keyword) and Fast Downward reads.
(define (domain courier-like)
  (:requirements :strips :typing)
  (:types place - domain locatable - domain truck - locatable)
  (:predicates (at ?t - locatable ?p - place))
  (:action drive :parameters (?t - truck ?a ?b - place)
    :precondition (at ?t ?a) :effect (and (at ?t ?b) (not (at ?t ?a)))))
