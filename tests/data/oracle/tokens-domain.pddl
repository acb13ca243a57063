; Two tokens in three slots: a goal of three full slots is unreachable, but
; every pair of full slots is reachable, so h^2 cannot refute it and the
; exhaustive search must.
(define (domain tokens)
  (:requirements :strips :typing :negative-preconditions)
  (:types slot)
  (:predicates (full ?s - slot))
  (:action move
    :parameters (?from - slot ?to - slot)
    :precondition (and (full ?from) (not (full ?to)))
    :effect (and (full ?to) (not (full ?from)))))
