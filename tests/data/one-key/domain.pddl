; One key for two doors: unlocking a door leaves the key in its lock.
; The delete relaxation keeps the key after the first door, so it reaches a
; goal of two unlocked doors from any state with the key; the robot does not.
(define (domain one-key)
  (:requirements :strips :typing)
  (:types door)
  (:predicates (has-key) (unlocked ?d - door))
  (:action unlock
    :parameters (?d - door)
    :precondition (has-key)
    :effect (and (unlocked ?d) (not (has-key)))))
