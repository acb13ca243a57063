; A robot that walks through unlocked doors (corridor task for --slack): the direct door's key is two
; rooms away (the minimal excuse, one change, takes the human 4 actions), the two doors of the detour
; open with one key at hand (two changes, 3 actions): the shorter demonstration is within a slack of 1.
(define (domain corridor)
  (:requirements :strips :typing)
  (:types room door key)
  (:predicates (at ?r - room) (connects ?d - door ?a ?b - room) (unlocked ?d - door)
               (has ?k - key) (opens ?k - key ?d - door) (key-at ?k - key ?r - room))
  (:action walk
    :parameters (?d - door ?a ?b - room)
    :precondition (and (at ?a) (connects ?d ?a ?b) (unlocked ?d))
    :effect (and (not (at ?a)) (at ?b))))
