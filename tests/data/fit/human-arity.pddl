; Kitchen I's human model with (open ?d ?s): a predicate of the robot's name with another arity.
;; Kitchen scenario (human demonstrator: all skills) of "Enabling Robots to Identify Missing Steps in
;; Robot Tasks for Guided Learning from Demonstration" (Diehl, Chakraborti,
;; Ramirez-Amaro).  Fluents as in the paper's VR teaching system: on_top,
;; inside, clear, open, graspable, plus the hand state (in_hand, hand_free).
;; (clear ?f): nothing (the chair) blocks furniture ?f.
(define (domain kitchen)
  (:requirements :strips :typing :negative-preconditions)
  (:types item furniture obstacle - object
          surface drawer - furniture)
  (:predicates (on_top ?i - item ?s - surface)
               (inside ?i - item ?d - drawer)
               (open ?d - drawer ?s - surface)
               (clear ?f - furniture)
               (graspable ?i - item)
               (in_hand ?i - item)
               (hand_free)
               (blocking ?c - obstacle ?f - furniture))

  ;; Take an item from a surface that is not blocked.
  (:action take
    :parameters (?i - item ?s - surface)
    :precondition (and (graspable ?i) (on_top ?i ?s) (clear ?s) (hand_free))
    :effect (and (in_hand ?i) (not (on_top ?i ?s)) (not (hand_free))))

  ;; Put the held item on a surface.
  (:action put_on
    :parameters (?i - item ?s - surface)
    :precondition (and (in_hand ?i) (clear ?s))
    :effect (and (on_top ?i ?s) (hand_free) (not (in_hand ?i))))

  ;; Put the held item inside an open drawer.
  (:action put_inside
    :parameters (?i - item ?d - drawer ?s - surface)
    :precondition (and (in_hand ?i) (open ?d ?s) (clear ?d))
    :effect (and (inside ?i ?d) (hand_free) (not (in_hand ?i))))

  ;; Open a closed drawer that nothing blocks.
  (:action open_drawer
    :parameters (?d - drawer ?s - surface)
    :precondition (and (clear ?d) (hand_free) (not (open ?d ?s)))
    :effect (open ?d ?s))

  ;; Close an open drawer that nothing blocks (closing needs the drawer as
  ;; accessible as opening it does).
  (:action close_drawer
    :parameters (?d - drawer ?s - surface)
    :precondition (and (open ?d ?s) (clear ?d) (hand_free))
    :effect (not (open ?d ?s)))

  ;; Take an item out of an open drawer.
  (:action take_from_drawer
    :parameters (?i - item ?d - drawer ?s - surface)
    :precondition (and (graspable ?i) (inside ?i ?d) (open ?d ?s) (clear ?d) (hand_free))
    :effect (and (in_hand ?i) (not (inside ?i ?d)) (not (hand_free))))

  ;; Push the chair away from the furniture it blocks to a free one.
  (:action move_chair
    :parameters (?c - obstacle ?from - furniture ?to - furniture)
    :precondition (and (blocking ?c ?from) (clear ?to) (hand_free))
    :effect (and (not (blocking ?c ?from)) (clear ?from)
                 (blocking ?c ?to) (not (clear ?to))))
)
