;; Stacking scenario of the independent trace source (tests/data/traces, issue #14): blocks on a
;; table, stacked and unstacked with the hand.  Fluents as in the kitchen's VR system: on_top (on a
;; surface), on (on a block), clear (nothing on the block), graspable, plus the hand state.
;; A block in the hand stays clear (nothing is on it).
(define (domain stacking)
  (:requirements :strips :typing :negative-preconditions)
  (:types block surface - object)
  (:predicates (on_top ?b - block ?s - surface)
               (on ?b - block ?c - block)
               (clear ?b - block)
               (graspable ?b - block)
               (in_hand ?b - block)
               (hand_free))

  ;; Take a block with nothing on it from the table.
  (:action take
    :parameters (?b - block ?s - surface)
    :precondition (and (graspable ?b) (on_top ?b ?s) (clear ?b) (hand_free))
    :effect (and (in_hand ?b) (not (on_top ?b ?s)) (not (hand_free))))

  ;; Put the held block on the table.
  (:action put_on
    :parameters (?b - block ?s - surface)
    :precondition (and (in_hand ?b))
    :effect (and (on_top ?b ?s) (hand_free) (not (in_hand ?b))))

  ;; Stack the held block on a clear block.
  (:action stack
    :parameters (?b - block ?c - block)
    :precondition (and (in_hand ?b) (clear ?c))
    :effect (and (on ?b ?c) (not (clear ?c)) (hand_free) (not (in_hand ?b))))

  ;; Take the top block off another block.
  (:action unstack
    :parameters (?b - block ?c - block)
    :precondition (and (graspable ?b) (on ?b ?c) (clear ?b) (hand_free))
    :effect (and (in_hand ?b) (not (on ?b ?c)) (clear ?c) (not (hand_free))))
)
