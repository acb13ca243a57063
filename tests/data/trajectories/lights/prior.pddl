; The lights domain with the operators' signatures only: the bodies are to learn.
(define (domain lights)
  (:requirements :strips :typing)
  (:types room switch)
  (:predicates (power) (wired ?s - switch ?r - room) (up ?s - switch) (lit ?r - room))
  (:action breaker-on :parameters () :precondition (and) :effect (and))
  (:action flip-up :parameters (?r - room ?s - switch) :precondition (and) :effect (and))
  (:action flip-down :parameters (?r - room ?s - switch) :precondition (and) :effect (and)))
