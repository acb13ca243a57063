;; BYO corpus, shelves: the human demonstrator's complete domain.
;; A stockroom robot with one claw moves boxes between wall shelves and a
;; trolley.  Static structure: (within-reach ?s), the claw reaches the shelf
;; (the low shelves and the middle ones; the top shelves are out of reach),
;; and (low ?s), the shelf is a low one.  Whether a shelf is low matters to no
;; skill: a box comes down from any shelf within reach.
;; Hand facts: (in-claw ?b) / (claw-empty).  The robot (robot.pddl) lacks take-down.
(define (domain shelves)
  (:requirements :strips :typing)
  (:types box shelf trolley)
  (:predicates (claw-empty)
               (in-claw ?b - box)
               (on-shelf ?b - box ?s - shelf)
               (on-trolley ?b - box ?t - trolley)
               (within-reach ?s - shelf)
               (low ?s - shelf))

  ;; Take a box down from a shelf within reach.
  (:action take-down
    :parameters (?b - box ?s - shelf)
    :precondition (and (claw-empty) (on-shelf ?b ?s) (within-reach ?s))
    :effect (and (in-claw ?b) (not (on-shelf ?b ?s)) (not (claw-empty))))

  ;; Put the box in the claw up on a shelf within reach.
  (:action put-up
    :parameters (?b - box ?s - shelf)
    :precondition (and (in-claw ?b) (within-reach ?s))
    :effect (and (on-shelf ?b ?s) (claw-empty) (not (in-claw ?b))))

  ;; Lift a box off the trolley.
  (:action unload
    :parameters (?b - box ?t - trolley)
    :precondition (and (claw-empty) (on-trolley ?b ?t))
    :effect (and (in-claw ?b) (not (on-trolley ?b ?t)) (not (claw-empty))))

  ;; Set the box in the claw down on the trolley.
  (:action load
    :parameters (?b - box ?t - trolley)
    :precondition (in-claw ?b)
    :effect (and (on-trolley ?b ?t) (claw-empty) (not (in-claw ?b))))
)
