; The robot's domain (without fill) of: A watering robot: it waters plants from cans that are full or empty; the human fills cans at the tap,
; the robot's domain lacks fill.
(define (domain watering)
  (:requirements :strips :typing)
  (:types can plant)
  (:predicates (full ?c - can) (empty ?c - can) (holding ?c - can) (hand-free) (can-on-floor ?c - can)
               (watered ?p - plant))
  (:action pick-up
    :parameters (?c - can)
    :precondition (and (hand-free) (can-on-floor ?c))
    :effect (and (holding ?c) (not (hand-free)) (not (can-on-floor ?c))))
  (:action put-down
    :parameters (?c - can)
    :precondition (holding ?c)
    :effect (and (hand-free) (can-on-floor ?c) (not (holding ?c))))
  (:action water
    :parameters (?c - can ?p - plant)
    :precondition (and (holding ?c) (full ?c))
    :effect (and (watered ?p) (empty ?c) (not (full ?c)))))
