; A building's lights: a breaker feeds the switches, a switch lights its room.
; No hand, no robot-at: the learner must not assume the kitchens' vocabulary.
(define (domain lights)
  (:requirements :strips :typing)
  (:types room switch)
  (:predicates (power) (wired ?s - switch ?r - room) (up ?s - switch) (lit ?r - room))
  (:action breaker-on
    :parameters ()
    :precondition (and)
    :effect (power))
  ; parameters in an order no learner would guess: the room first
  (:action flip-up
    :parameters (?r - room ?s - switch)
    :precondition (and (power) (wired ?s ?r))
    :effect (and (up ?s) (lit ?r)))
  (:action flip-down
    :parameters (?r - room ?s - switch)
    :precondition (and (up ?s) (wired ?s ?r))
    :effect (and (not (up ?s)) (not (lit ?r)))))
