;; Kitchen II for a robot that can neither open drawers nor move the chair (take and put only), after
;; "Enabling Robots to Identify Missing Steps in Robot Tasks for Guided Learning from Demonstration"
;; (Diehl, Chakraborti, Ramirez-Amaro), Section III-B-1: the minimal excuse is to clear and open
;; PinkDrawer, but asking only "Open PinkDrawer" suffices, as the human must clear it first.
;; Fluents as in the paper's VR teaching system: on_top, inside, clear, open, graspable, plus the
;; hand state (in_hand, hand_free).  (clear ?f): nothing (the chair) blocks furniture ?f.
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

  ;; Put the held item inside an open drawer.
  (:action put_inside
    :parameters (?i - item ?d - drawer)
    :precondition (and (in_hand ?i) (open ?d) (clear ?d))
    :effect (and (inside ?i ?d) (hand_free) (not (in_hand ?i))))
)
