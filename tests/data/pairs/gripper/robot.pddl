; The robot's domain (without open-gripper) of: A packing robot whose gripper is open or closed: it can close it on a part and release it into a box,
; but its domain lacks open-gripper, and the gripper starts closed.
(define (domain packing)
  (:requirements :strips :typing)
  (:types gripper part box)
  (:predicates (gripper-open ?g - gripper) (gripper-closed ?g - gripper) (holds ?g - gripper ?p - part)
               (empty ?g - gripper) (on-table ?p - part) (in ?p - part ?b - box))
  (:action grasp
    :parameters (?g - gripper ?p - part)
    :precondition (and (gripper-open ?g) (empty ?g) (on-table ?p))
    :effect (and (holds ?g ?p) (gripper-closed ?g) (not (gripper-open ?g)) (not (empty ?g)) (not (on-table ?p))))
  (:action release
    :parameters (?g - gripper ?p - part ?b - box)
    :precondition (and (holds ?g ?p) (gripper-closed ?g))
    :effect (and (in ?p ?b) (empty ?g) (not (holds ?g ?p)))))
