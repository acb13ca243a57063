; LM-cut's goal zone must not leak through an achiever that already has a
; precondition in the zone: `leak` achieves (g1) from (b) and (z); (z) is in
; the zone through `take`, so (b), the other goal's precondition, must stay
; out, or one cut {+z, +b} makes both goals free and the bound is 1, not 2.
(define (domain zone-leak)
  (:requirements :strips)
  (:predicates (b) (z) (g1) (g2))
  (:action take :parameters () :precondition (z) :effect (g1))
  (:action leak :parameters () :precondition (and (b) (z)) :effect (g1))
  (:action other :parameters () :precondition (b) :effect (g2)))
