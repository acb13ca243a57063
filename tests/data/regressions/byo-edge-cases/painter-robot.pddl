; A robot in blocksworld's types that only paints blocks: no grasping actions, so its hand facts cannot be
; read off it. A demonstration without vocabulary rows then speaks the kitchens' in_hand/hand_free, and the
; skills learned from it could never run beside this robot's (issue #23: refused, exit 34).
(define (domain painter)
  (:requirements :strips :typing :negative-preconditions)
  (:types block)
  (:predicates (painted ?b - block) (clear ?x - block))
  (:action paint
    :parameters (?b - block)
    :precondition (and (clear ?b) (not (painted ?b)))
    :effect (painted ?b)))
