;; A robot whose own pick-up does not check that the block is clear (it can hold a block with one on top).
(define (domain stacking-robot)
  (:requirements :strips :typing :negative-preconditions)
  (:types block surface - object)
  (:predicates (on_top ?b - block ?s - surface) (on ?b - block ?c - block) (clear ?b - block)
               (graspable ?b - block) (in_hand ?b - block) (hand_free))
  (:action pick_up
    :parameters (?b - block ?s - surface)
    :precondition (and (graspable ?b) (hand_free) (on_top ?b ?s))
    :effect (and (in_hand ?b) (not (hand_free)) (not (on_top ?b ?s)))))
