;; A robot's prior skills: it can take and put, not open drawers.
(define (domain kitchen)
  (:requirements :strips :typing :negative-preconditions)
  (:types item furniture - object
          surface drawer - furniture)
  (:predicates (on_top ?i - item ?s - surface)
               (inside ?i - item ?d - drawer)
               (open ?d - drawer)
               (in_hand ?i - item)
               (hand_free))
  (:action take
    :parameters (?i - item ?s - surface)
    :precondition (and (on_top ?i ?s) (hand_free))
    :effect (and (in_hand ?i) (not (on_top ?i ?s)) (not (hand_free))))
  (:action put_inside
    :parameters (?i - item ?d - drawer)
    :precondition (and (in_hand ?i) (open ?d))
    :effect (and (inside ?i ?d) (hand_free) (not (in_hand ?i)))))
