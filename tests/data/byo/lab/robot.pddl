;; BYO corpus, lab: the robot's domain (human.pddl without write-label).
;; A one-handed lab assistant files sample tubes into the fridge.  Tubes stand
;; in racks; a tube arrives capped and is uncapped (for good: a used cap goes
;; to the waste) to take an aliquot.  Only a labelled tube may go into the
;; fridge, and a tube is labelled with a marker held in the hand, capped or not:
;; no skill cares whether a tube is capped.
;; Hand facts: (in-palm ?o) / (palm-free).  This robot cannot write: write-label
;; is the skill it must be taught.
(define (domain lab)
  (:requirements :strips :typing :negative-preconditions)
  (:types tube marker - portable
          portable rack fridge - object)
  (:predicates (palm-free)
               (in-palm ?o - portable)
               (on-bench ?m - marker)
               (in-rack ?t - tube ?r - rack)
               (in-fridge ?t - tube ?f - fridge)
               (capped ?t - tube)
               (labelled ?t - tube))

  ;; Take a marker from the bench.
  (:action grab-marker
    :parameters (?m - marker)
    :precondition (and (palm-free) (on-bench ?m))
    :effect (and (in-palm ?m) (not (on-bench ?m)) (not (palm-free))))

  ;; Lay the held marker back on the bench.
  (:action drop-marker
    :parameters (?m - marker)
    :precondition (in-palm ?m)
    :effect (and (on-bench ?m) (palm-free) (not (in-palm ?m))))

  ;; Twist the cap off a tube standing in a rack.
  (:action uncap
    :parameters (?t - tube ?r - rack)
    :precondition (and (palm-free) (in-rack ?t ?r) (capped ?t))
    :effect (not (capped ?t)))

  ;; Lift a tube out of its rack.
  (:action lift-tube
    :parameters (?t - tube ?r - rack)
    :precondition (and (palm-free) (in-rack ?t ?r))
    :effect (and (in-palm ?t) (not (in-rack ?t ?r)) (not (palm-free))))

  ;; Stand the held tube in a rack.
  (:action rack-tube
    :parameters (?t - tube ?r - rack)
    :precondition (in-palm ?t)
    :effect (and (in-rack ?t ?r) (palm-free) (not (in-palm ?t))))

  ;; File the held tube, labelled, into the fridge.
  (:action file-away
    :parameters (?t - tube ?f - fridge)
    :precondition (and (in-palm ?t) (labelled ?t))
    :effect (and (in-fridge ?t ?f) (palm-free) (not (in-palm ?t))))
)
