(define (domain kitchen)
  (:requirements :strips :typing :negative-preconditions)
  (:types furniture item obstacle - object drawer surface - furniture)
  (:predicates (blocking ?x0 - obstacle ?x1 - furniture)
               (clear ?x0 - furniture)
               (graspable ?x0 - item)
               (hand_free)
               (in_hand ?x0 - item)
               (inside ?x0 - item ?x1 - drawer)
               (on_top ?x0 - item ?x1 - surface)
               (open ?x0 - drawer))

  (:action take
    :parameters (?i - item ?s - surface)
    :precondition (and (graspable ?i) (on_top ?i ?s) (clear ?s) (hand_free))
    :effect (and (in_hand ?i) (not (on_top ?i ?s)) (not (hand_free))))

  (:action put_on
    :parameters (?i - item ?s - surface)
    :precondition (and (in_hand ?i) (clear ?s))
    :effect (and (on_top ?i ?s) (hand_free) (not (in_hand ?i))))

  (:action put_inside
    :parameters (?i - item ?d - drawer)
    :precondition (and (in_hand ?i) (open ?d) (clear ?d))
    :effect (and (inside ?i ?d) (hand_free) (not (in_hand ?i))))

  (:action open_drawer
    :parameters (?d - drawer)
    :precondition (and (clear ?d) (hand_free) (not (open ?d)))
    :effect (open ?d))

  (:action close_drawer
    :parameters (?d - drawer)
    :precondition (and (open ?d) (clear ?d) (hand_free))
    :effect (not (open ?d)))

  (:action take_from_drawer
    :parameters (?i - item ?d - drawer)
    :precondition (and (graspable ?i) (inside ?i ?d) (open ?d) (clear ?d) (hand_free))
    :effect (and (in_hand ?i) (not (inside ?i ?d)) (not (hand_free))))

  (:action move_chair
    :parameters (?c - obstacle ?from ?to - furniture)
    :precondition (and (blocking ?c ?from) (clear ?to) (hand_free))
    :effect (and (clear ?from) (blocking ?c ?to) (not (blocking ?c ?from)) (not (clear ?to))))
)
