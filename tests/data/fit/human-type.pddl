; A model whose (open ?x) is about items, where the robot's is about drawers (an unrelated type).
(define (domain kitchen-1-human)
  (:requirements :strips :typing)
  (:types furniture - object surface drawer - furniture item obstacle - object)
  (:predicates (open ?x - item) (in_hand ?i - item))
  (:action wave :parameters (?i - item) :precondition (in_hand ?i) :effect (open ?i)))
