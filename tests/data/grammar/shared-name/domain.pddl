; A type and an object of the same name (IPC tidybot: type 'cart', object
; 'cart'): types and objects are separate namespaces in PDDL.  Here the
; domain constant 'gripper' is of type 'gripper' as well.
(define (domain carts)
  (:requirements :strips :typing)
  (:types cart gripper item location - object)
  (:constants gripper - gripper)
  (:predicates (at ?x - (either cart item) ?l - location)
               (holding ?g - gripper ?c - cart)
               (free ?g - gripper))

  (:action grasp
    :parameters (?c - cart ?l - location)
    :precondition (and (at ?c ?l) (free gripper))
    :effect (and (not (free gripper)) (holding gripper ?c)))

  (:action push
    :parameters (?c - cart ?from ?to - location)
    :precondition (and (holding gripper ?c) (at ?c ?from))
    :effect (and (not (at ?c ?from)) (at ?c ?to))))
