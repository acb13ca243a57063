; Kitchen I's human, with a type of its own for what it opens: a widget is no
; type of the robot's, and no drawer is a widget, so (open ?w - widget) could
; be true of none of the task's objects.
(define (domain kitchen)
  (:requirements :strips :typing)
  (:types widget)
  (:predicates (open ?w - widget))
  (:action open_widget :parameters (?w - widget)
    :precondition (not (open ?w)) :effect (open ?w)))
