;; Kitchen I for a robot that can take things and put them on surfaces, but has no skill that puts
;; anything inside a drawer (nor opens one): no excuse exists for "RedPlate inside PinkDrawer", as no
;; skill of the robot makes (inside ...) true.  `teach` names that goal atom and asks for a demonstration
;; of a new skill that makes it true (tests/test_teach_outcomes.py).
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
)
