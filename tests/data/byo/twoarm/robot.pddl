;; BYO corpus, twoarm: the robot's domain (human.pddl without remove-lid).
;; A robot with two arms (arm objects).  Items lie on the table or in boxes; a
;; box is closed while a lid lies on it ((lid-on ?l ?b)) and open once the lid
;; is lifted off ((box-open ?b)); lids are interchangeable.  An arm lifts a lid
;; off and can put a held lid onto an open box; items go into and out of an
;; open box only.  One arm can hold the lid while the other takes an item out.
;; Every thing is always somewhere: on the table, in an arm, in a box (items)
;; or on a box (lids).
;; Hand facts take the arm first: (grasped ?a ?o) / (free ?a).
;; This robot cannot lift a lid off a box: remove-lid is the skill it must be
;; taught (it can put a held lid onto a box).
(define (domain twoarm)
  (:requirements :strips :typing)
  (:types item lid - thing
          thing arm box - object)
  (:predicates (free ?a - arm)
               (grasped ?a - arm ?o - thing)
               (on-table ?o - thing)
               (in-box ?i - item ?b - box)
               (lid-on ?l - lid ?b - box)
               (box-open ?b - box))

  ;; Put the held lid onto an open box: the box is closed.
  (:action put-lid
    :parameters (?a - arm ?l - lid ?b - box)
    :precondition (and (grasped ?a ?l) (box-open ?b))
    :effect (and (lid-on ?l ?b) (free ?a) (not (grasped ?a ?l)) (not (box-open ?b))))

  ;; Take a thing (an item, a lid set aside) from the table.
  (:action pick
    :parameters (?a - arm ?o - thing)
    :precondition (and (free ?a) (on-table ?o))
    :effect (and (grasped ?a ?o) (not (on-table ?o)) (not (free ?a))))

  ;; Set the held thing down on the table.
  (:action place
    :parameters (?a - arm ?o - thing)
    :precondition (grasped ?a ?o)
    :effect (and (on-table ?o) (free ?a) (not (grasped ?a ?o))))

  ;; Take an item out of an open box.
  (:action take-out
    :parameters (?a - arm ?i - item ?b - box)
    :precondition (and (free ?a) (in-box ?i ?b) (box-open ?b))
    :effect (and (grasped ?a ?i) (not (in-box ?i ?b)) (not (free ?a))))

  ;; Put the held item into an open box.
  (:action put-in
    :parameters (?a - arm ?i - item ?b - box)
    :precondition (and (grasped ?a ?i) (box-open ?b))
    :effect (and (in-box ?i ?b) (free ?a) (not (grasped ?a ?i))))
)
