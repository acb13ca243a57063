;; Learned from a demonstration: a flat type hierarchy, the robot's `take`
;; again (parameters renamed and swapped), a new `open_drawer`, and a `take`
;; that differs from the robot's (it needs the item graspable).
(define (domain learned)
  (:requirements :strips :typing :negative-preconditions)
  (:types item drawer surface - object)
  (:predicates (on_top ?a - item ?b - surface)
               (open ?a - drawer)
               (graspable ?a - item)
               (in_hand ?a - item)
               (hand_free))
  ;; learned from 2 demonstration(s)
  (:action take_item
    :parameters (?o1 - surface ?o2 - item)
    :precondition (and (hand_free) (on_top ?o2 ?o1))
    :effect (and (not (hand_free)) (not (on_top ?o2 ?o1)) (in_hand ?o2)))
  (:action open_drawer
    :parameters (?o1 - drawer)
    :precondition (and (hand_free) (not (open ?o1)))
    :effect (open ?o1))
  (:action take
    :parameters (?o1 - item ?o2 - surface)
    :precondition (and (graspable ?o1) (on_top ?o1 ?o2) (hand_free))
    :effect (and (in_hand ?o1) (not (on_top ?o1 ?o2)) (not (hand_free)))))
