; A robot that picks things up where it stands, and cannot drive: the skill
; that moves it is missing.  (at ?r ?x) places the robot; no action of this
; domain changes it, so no invariant synthesis says the robot is in one room.
(define (domain fetch)
  (:requirements :strips :typing)
  (:types robot room item)
  (:predicates (at ?r - robot ?x - room) (lies ?i - item ?x - room) (holding ?r - robot ?i - item))
  (:action pick :parameters (?r - robot ?i - item ?x - room)
    :precondition (and (at ?r ?x) (lies ?i ?x))
    :effect (and (not (lies ?i ?x)) (holding ?r ?i))))
