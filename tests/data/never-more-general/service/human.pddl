;; A service robot that drives between rooms through doors (issue #51): the human demonstrator's domain.
;; Static structure: (connects ?d ?from ?to), listed in both directions; no other fact says which rooms a
;; door joins.  A door is opened from one of its own rooms, so open-door needs (connects ?d ?from ?to):
;; a learned open-door without it would open any door from any room.
;; Hand facts: (holding ?o) / (gripper-free).  The robot (robot.pddl) lacks open-door.
(define (domain service)
  (:requirements :strips :typing :negative-preconditions)
  (:types room door item)
  (:predicates (robot-at ?r - room)
               (gripper-free)
               (holding ?o - item)
               (item-at ?o - item ?r - room)
               (door-open ?d - door)
               (connects ?d - door ?from - room ?to - room))

  (:action go
    :parameters (?from - room ?to - room ?d - door)
    :precondition (and (robot-at ?from) (door-open ?d) (connects ?d ?from ?to))
    :effect (and (robot-at ?to) (not (robot-at ?from))))

  (:action pick
    :parameters (?o - item ?r - room)
    :precondition (and (robot-at ?r) (item-at ?o ?r) (gripper-free))
    :effect (and (holding ?o) (not (item-at ?o ?r)) (not (gripper-free))))

  (:action place
    :parameters (?o - item ?r - room)
    :precondition (and (robot-at ?r) (holding ?o))
    :effect (and (item-at ?o ?r) (gripper-free) (not (holding ?o))))

  (:action open-door
    :parameters (?d - door ?from - room ?to - room)
    :precondition (and (robot-at ?from) (gripper-free) (connects ?d ?from ?to) (not (door-open ?d)))
    :effect (door-open ?d))
)
