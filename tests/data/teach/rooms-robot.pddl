; A robot that walks through unlocked doors but cannot unlock them (no keys in its skills).
; Two doors lead to the goal room: each one unlocked is a minimal excuse of size 1, but the
; human needs 2 actions to unlock bdoor (its key is here) and 4 to unlock adoor (its key is in
; the hall): the preferred excuse (paper, III-B-2, Case 1) is bdoor.
(define (domain rooms)
  (:requirements :strips :typing)
  (:types room door key)
  (:predicates (at ?r - room) (connects ?d - door ?a ?b - room) (unlocked ?d - door)
               (has ?k - key) (opens ?k - key ?d - door) (key-at ?k - key ?r - room))
  (:action walk
    :parameters (?d - door ?a ?b - room)
    :precondition (and (at ?a) (connects ?d ?a ?b) (unlocked ?d))
    :effect (and (not (at ?a)) (at ?b))))
