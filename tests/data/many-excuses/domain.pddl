; Any one of the keys opens the gate: with no key, every (has-key k) is a minimal excuse of its own.
(define (domain gate)
  (:requirements :strips :typing)
  (:types key)
  (:predicates (has-key ?k - key) (open))
  (:action unlock :parameters (?k - key) :precondition (has-key ?k) :effect (open)))
