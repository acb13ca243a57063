; The lights prior with one ADL action of its own (a forall with a when): its body is kept as written, the
; operators with empty bodies are learned from the trajectories as with the STRIPS prior.
(define (domain lights)
  (:requirements :adl :typing)
  (:types room switch)
  (:predicates (power) (wired ?s - switch ?r - room) (up ?s - switch) (lit ?r - room))
  (:action breaker-on :parameters () :precondition (and) :effect (and))
  (:action flip-up :parameters (?r - room ?s - switch) :precondition (and) :effect (and))
  (:action flip-down :parameters (?r - room ?s - switch) :precondition (and) :effect (and))
  (:action all-off
    :parameters ()
    :precondition (power)
    :effect (and (not (power))
                 (forall (?s - switch) (when (up ?s) (not (up ?s))))
                 (forall (?r - room) (when (lit ?r) (not (lit ?r)))))))
