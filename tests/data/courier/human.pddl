; A courier robot's world: rooms joined by doors, doors open or closed (the common STRIPS pair),
; mail carried from room to room.  The human can open and close doors; the robot's domain lacks open-door.
(define (domain courier)
  (:requirements :strips :typing)
  (:types room door mail)
  (:predicates (robot-at ?r - room) (connects ?d - door ?from - room ?to - room)
               (door-open ?d - door) (door-closed ?d - door)
               (at-obj ?m - mail ?r - room) (holding ?m - mail) (gripper-free))
  (:action move
    :parameters (?d - door ?from - room ?to - room)
    :precondition (and (robot-at ?from) (connects ?d ?from ?to) (door-open ?d))
    :effect (and (robot-at ?to) (not (robot-at ?from))))
  (:action pick
    :parameters (?m - mail ?r - room)
    :precondition (and (robot-at ?r) (at-obj ?m ?r) (gripper-free))
    :effect (and (holding ?m) (not (at-obj ?m ?r)) (not (gripper-free))))
  (:action drop
    :parameters (?m - mail ?r - room)
    :precondition (and (robot-at ?r) (holding ?m))
    :effect (and (at-obj ?m ?r) (gripper-free) (not (holding ?m))))
  (:action open-door
    :parameters (?d - door ?from - room ?to - room)
    :precondition (and (robot-at ?from) (connects ?d ?from ?to) (door-closed ?d))
    :effect (and (door-open ?d) (not (door-closed ?d))))
  (:action close-door
    :parameters (?d - door ?from - room ?to - room)
    :precondition (and (robot-at ?from) (connects ?d ?from ?to) (door-open ?d))
    :effect (and (door-closed ?d) (not (door-open ?d)))))
