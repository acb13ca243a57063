;; Kitchen II's robot after a round whose learned skill it can never use (issue #23): push_obstacle
;; needs (hand-empty), a hand fact no action here makes true.  tests/test_teach_outcomes.py has the
;; session learn this domain from a demonstration that did the whole task: the goal is then reached only
;; through the demonstration, and `teach` must not call the task solved.
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
               (hand-empty))

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

  ;; Learned from a demonstration written in another hand vocabulary: it needs (hand-empty), which no
  ;; action of this domain makes true and Kitchen II's problem does not state.
  (:action push_obstacle
    :parameters (?c - obstacle ?from - furniture ?to - furniture)
    :precondition (and (blocking ?c ?from) (clear ?to) (hand-empty))
    :effect (and (not (blocking ?c ?from)) (clear ?from)
                 (blocking ?c ?to) (not (clear ?to))))
)
