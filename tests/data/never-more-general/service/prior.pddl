;; A service robot that drives between rooms through doors (issue #51): the prior for learning from
;; trajectories (human.pddl with every action's body left out: the operators' signatures only).
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
    :precondition (and)
    :effect (and))

  (:action pick
    :parameters (?o - item ?r - room)
    :precondition (and)
    :effect (and))

  (:action place
    :parameters (?o - item ?r - room)
    :precondition (and)
    :effect (and))

  (:action open-door
    :parameters (?d - door ?from - room ?to - room)
    :precondition (and)
    :effect (and))
)
