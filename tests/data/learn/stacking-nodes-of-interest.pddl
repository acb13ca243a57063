;; Stacking skills as the nodes-of-interest rule learns them, before dropping implied preconditions
;; (tests/test_implied.py): the held block's clear and graspable, the lower block's graspable.
(define (domain stacking-learned)
  (:requirements :strips :typing :negative-preconditions)
  (:types block surface - object)
  (:predicates (on_top ?b - block ?s - surface) (on ?b - block ?c - block) (clear ?b - block)
               (graspable ?b - block) (in_hand ?b - block) (hand_free))
  (:action take_block_surface
    :parameters (?o1 - block ?o2 - surface)
    :precondition (and (clear ?o1) (graspable ?o1) (hand_free) (on_top ?o1 ?o2))
    :effect (and (in_hand ?o1) (not (hand_free)) (not (on_top ?o1 ?o2))))
  (:action take_block_block
    :parameters (?o1 ?o2 - block)
    :precondition (and (clear ?o1) (graspable ?o1) (graspable ?o2) (hand_free) (on ?o1 ?o2))
    :effect (and (clear ?o2) (in_hand ?o1) (not (hand_free)) (not (on ?o1 ?o2))))
  (:action stack_block_block
    :parameters (?o1 ?o2 - block)
    :precondition (and (clear ?o1) (clear ?o2) (graspable ?o1) (graspable ?o2) (in_hand ?o1))
    :effect (and (hand_free) (on ?o1 ?o2) (not (clear ?o2)) (not (in_hand ?o1))))
  (:action put_block_surface
    :parameters (?o1 - block ?o2 - surface)
    :precondition (and (clear ?o1) (graspable ?o1) (in_hand ?o1))
    :effect (and (hand_free) (on_top ?o1 ?o2) (not (in_hand ?o1))))
)
