; Painting and washing boards; the bodies are to learn.  No step ever paints a wet board, so nothing shows
; whether painting needs the board dry or makes it dry.
(define (domain paint)
  (:requirements :strips :typing :negative-preconditions)
  (:types board place)
  (:predicates (wet ?b - board) (red ?b - board) (at ?b - board ?p - place) (shop ?p - place))
  (:action paint :parameters (?b - board) :precondition (and) :effect (and))
  (:action wash :parameters (?b - board) :precondition (and) :effect (and))
  (:action carry :parameters (?b - board ?from ?to - place) :precondition (and) :effect (and)))
