; A two-handed press: the robot's one skill moves its single arm between the two buttons, so "the arm is at
; one button" is an invariant of its skills; pressing needs both buttons held at once (a second arm).
(define (domain press)
  (:requirements :strips)
  (:predicates (at-left) (at-right) (pressed))
  (:action swing-right :parameters () :precondition (at-left) :effect (and (at-right) (not (at-left))))
  (:action swing-left :parameters () :precondition (at-right) :effect (and (at-left) (not (at-right))))
  (:action press :parameters () :precondition (and (at-left) (at-right)) :effect (pressed)))
