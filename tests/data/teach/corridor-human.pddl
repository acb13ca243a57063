; The human of the corridor task: walks, picks up keys, and unlocks a door with its key from anywhere.
(define (domain corridor)
  (:requirements :strips :typing)
  (:types room door key)
  (:predicates (at ?r - room) (connects ?d - door ?a ?b - room) (unlocked ?d - door)
               (has ?k - key) (opens ?k - key ?d - door) (key-at ?k - key ?r - room))
  (:action walk
    :parameters (?d - door ?a ?b - room)
    :precondition (and (at ?a) (connects ?d ?a ?b) (unlocked ?d))
    :effect (and (not (at ?a)) (at ?b)))
  (:action pick
    :parameters (?k - key ?r - room)
    :precondition (and (at ?r) (key-at ?k ?r))
    :effect (and (has ?k) (not (key-at ?k ?r))))
  (:action unlock
    :parameters (?k - key ?d - door)
    :precondition (and (has ?k) (opens ?k ?d))
    :effect (unlocked ?d)))
