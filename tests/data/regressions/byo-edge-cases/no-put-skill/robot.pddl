;; BYO corpus, fetch: the human demonstrator's complete domain.
;; A one-handed fetch robot in a kitchen: cups stand in cabinets or on the
;; counter; a cup can be taken out of (or put into) a cabinet only while the
;; cabinet is open.  Hand facts: (holding ?o) / (hand-empty).
;; The robot (robot.pddl) lacks open-cabinet.
(define (domain fetch)
  (:requirements :strips :typing :negative-preconditions)
  (:types cup cabinet)
  (:predicates (hand-empty)
               (holding ?o - cup)
               (in ?o - cup ?c - cabinet)
               (on-counter ?o - cup)
               (cabinet-open ?c - cabinet))

  ;; Open a closed cabinet (the hand must be empty to pull the door).
  (:action open-cabinet
    :parameters (?c - cabinet)
    :precondition (and (hand-empty) (not (cabinet-open ?c)))
    :effect (cabinet-open ?c))

  ;; Close an open cabinet.
  (:action close-cabinet
    :parameters (?c - cabinet)
    :precondition (and (hand-empty) (cabinet-open ?c))
    :effect (not (cabinet-open ?c)))

  ;; Take a cup out of an open cabinet.
  (:action pick-from-cabinet
    :parameters (?o - cup ?c - cabinet)
    :precondition (and (hand-empty) (in ?o ?c) (cabinet-open ?c))
    :effect (and (holding ?o) (not (in ?o ?c)) (not (hand-empty))))

  ;; Take a cup from the counter.
  (:action pick-from-counter
    :parameters (?o - cup)
    :precondition (and (hand-empty) (on-counter ?o))
    :effect (and (holding ?o) (not (on-counter ?o)) (not (hand-empty))))
)
