;; Cupboard-with-doors scenario of the independent trace source (tests/data/traces, issue #14): a
;; wall cupboard with two hinged doors; a mug goes inside through an open door.
;; (door_of ?d ?c): door ?d closes cupboard ?c (static).
(define (domain cupboard)
  (:requirements :strips :typing :negative-preconditions)
  (:types item surface cupboard door - object)
  (:predicates (on_top ?i - item ?s - surface)
               (inside ?i - item ?c - cupboard)
               (open ?d - door)
               (door_of ?d - door ?c - cupboard)
               (graspable ?i - item)
               (in_hand ?i - item)
               (hand_free))

  ;; Take an item from a surface.
  (:action take
    :parameters (?i - item ?s - surface)
    :precondition (and (graspable ?i) (on_top ?i ?s) (hand_free))
    :effect (and (in_hand ?i) (not (on_top ?i ?s)) (not (hand_free))))

  ;; Put the held item on a surface.
  (:action put_on
    :parameters (?i - item ?s - surface)
    :precondition (and (in_hand ?i))
    :effect (and (on_top ?i ?s) (hand_free) (not (in_hand ?i))))

  ;; Swing a closed door open.
  (:action open_door
    :parameters (?d - door)
    :precondition (and (hand_free) (not (open ?d)))
    :effect (open ?d))

  ;; Swing an open door shut.
  (:action close_door
    :parameters (?d - door)
    :precondition (and (hand_free) (open ?d))
    :effect (not (open ?d)))

  ;; Put the held item inside a cupboard through one of its open doors.
  (:action put_inside
    :parameters (?i - item ?c - cupboard ?d - door)
    :precondition (and (in_hand ?i) (door_of ?d ?c) (open ?d))
    :effect (and (inside ?i ?c) (hand_free) (not (in_hand ?i))))

  ;; Take an item out of a cupboard through one of its open doors.
  (:action take_from_cupboard
    :parameters (?i - item ?c - cupboard ?d - door)
    :precondition (and (graspable ?i) (inside ?i ?c) (door_of ?d ?c) (open ?d) (hand_free))
    :effect (and (in_hand ?i) (not (inside ?i ?c)) (not (hand_free))))
)
