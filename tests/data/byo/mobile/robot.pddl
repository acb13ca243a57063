;; BYO corpus, mobile: the robot's domain (human.pddl without open-door).
;; A mobile manipulator with one gripper drives between rooms through doors and
;; carries objects.  Static structure: (door-connects ?d ?r1 ?r2), listed in
;; both directions, and (door-in ?d ?r), the door lies in a wall of room ?r
;; (listed for both its rooms).  A door can be passed only while open, and is
;; opened or closed from either of its rooms with a free gripper.
;; go requires every static fact about its door and rooms (both directions and
;; both walls): a demonstration shows them all, and a learner keeps them all;
;; (not (robot-at ?to)) too, as no mutex of one predicate implies it.
;; Hand facts: (carrying ?o) / (gripper-free).  This robot cannot open a door:
;; open-door is the skill it must be taught (it can close one).
(define (domain mobile)
  (:requirements :strips :typing :negative-preconditions)
  (:types room door item)
  (:predicates (robot-at ?r - room)
               (gripper-free)
               (carrying ?o - item)
               (obj-at ?o - item ?r - room)
               (door-open ?d - door)
               (door-connects ?d - door ?r1 - room ?r2 - room)
               (door-in ?d - door ?r - room))

  ;; Drive from one room to the next through the open door between them.
  (:action go
    :parameters (?from - room ?to - room ?d - door)
    :precondition (and (robot-at ?from) (not (robot-at ?to)) (door-open ?d)
                       (door-connects ?d ?from ?to) (door-connects ?d ?to ?from)
                       (door-in ?d ?from) (door-in ?d ?to))
    :effect (and (robot-at ?to) (not (robot-at ?from))))

  ;; Pick up an object in the robot's room.
  (:action pick
    :parameters (?o - item ?r - room)
    :precondition (and (robot-at ?r) (obj-at ?o ?r) (gripper-free))
    :effect (and (carrying ?o) (not (obj-at ?o ?r)) (not (gripper-free))))

  ;; Put the carried object down in the robot's room.
  (:action place
    :parameters (?o - item ?r - room)
    :precondition (and (robot-at ?r) (carrying ?o))
    :effect (and (obj-at ?o ?r) (gripper-free) (not (carrying ?o))))

  ;; Close an open door in a wall of the robot's room.
  (:action close-door
    :parameters (?d - door ?r - room)
    :precondition (and (robot-at ?r) (door-in ?d ?r) (gripper-free) (door-open ?d))
    :effect (not (door-open ?d)))
)
