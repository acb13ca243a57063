;; Kitchen II's human, who can move only a light chair: Kitchen II's chair is not (the problem says
;; nothing of (light Chair)), so this human has no plan to "Clear PinkDrawer", the robot's request.
;; `teach --simulate` then ends no-demonstration naming that change (tests/test_teach_outcomes.py).
(define (domain kitchen)
  (:requirements :strips :typing :negative-preconditions)
  (:types item furniture obstacle - object
          surface drawer - furniture)
  (:predicates (on_top ?i - item ?s - surface)
               (inside ?i - item ?d - drawer)
               (open ?d - drawer)
               (clear ?f - furniture)
               (graspable ?i - item)
               (in_hand ?i - item)
               (hand_free)
               (blocking ?c - obstacle ?f - furniture)
               (light ?c - obstacle))

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
    :parameters (?i - item ?d - drawer)
    :precondition (and (in_hand ?i) (open ?d) (clear ?d))
    :effect (and (inside ?i ?d) (hand_free) (not (in_hand ?i))))

  ;; Open a closed drawer that nothing blocks.
  (:action open_drawer
    :parameters (?d - drawer)
    :precondition (and (clear ?d) (hand_free) (not (open ?d)))
    :effect (open ?d))

  ;; Close an open drawer that nothing blocks (closing needs the drawer as
  ;; accessible as opening it does).
  (:action close_drawer
    :parameters (?d - drawer)
    :precondition (and (open ?d) (clear ?d) (hand_free))
    :effect (not (open ?d)))

  ;; Take an item out of an open drawer.
  (:action take_from_drawer
    :parameters (?i - item ?d - drawer)
    :precondition (and (graspable ?i) (inside ?i ?d) (open ?d) (clear ?d) (hand_free))
    :effect (and (in_hand ?i) (not (inside ?i ?d)) (not (hand_free))))

  ;; Push a light chair away from the furniture it blocks to a free one (Kitchen II's chair is not light).
  (:action move_chair
    :parameters (?c - obstacle ?from - furniture ?to - furniture)
    :precondition (and (blocking ?c ?from) (clear ?to) (hand_free) (light ?c))
    :effect (and (not (blocking ?c ?from)) (clear ?from)
                 (blocking ?c ?to) (not (clear ?to))))
)
