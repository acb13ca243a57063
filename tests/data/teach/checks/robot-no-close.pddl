;; The fetch robot (tests/data/byo/fetch/robot.pddl) without close-cabinet either.
;; A one-handed fetch robot in a kitchen: cups stand in cabinets or on the
;; counter; a cup can be taken out of (or put into) a cabinet only while the
;; cabinet is open.  Hand facts: (holding ?o) / (hand-empty).
;; This robot can neither open nor close a cabinet (tests/data/teach/checks: a request of two changes).
(define (domain fetch)
  (:requirements :strips :typing :negative-preconditions)
  (:types cup cabinet)
  (:predicates (hand-empty)
               (holding ?o - cup)
               (in ?o - cup ?c - cabinet)
               (on-counter ?o - cup)
               (cabinet-open ?c - cabinet))


  ;; Take a cup out of an open cabinet.
  (:action pick-from-cabinet
    :parameters (?o - cup ?c - cabinet)
    :precondition (and (hand-empty) (in ?o ?c) (cabinet-open ?c))
    :effect (and (holding ?o) (not (in ?o ?c)) (not (hand-empty))))

  ;; Put the held cup into an open cabinet.
  (:action place-in-cabinet
    :parameters (?o - cup ?c - cabinet)
    :precondition (and (holding ?o) (cabinet-open ?c))
    :effect (and (in ?o ?c) (hand-empty) (not (holding ?o))))

  ;; Take a cup from the counter.
  (:action pick-from-counter
    :parameters (?o - cup)
    :precondition (and (hand-empty) (on-counter ?o))
    :effect (and (holding ?o) (not (on-counter ?o)) (not (hand-empty))))

  ;; Put the held cup on the counter.
  (:action place-on-counter
    :parameters (?o - cup)
    :precondition (holding ?o)
    :effect (and (on-counter ?o) (hand-empty) (not (holding ?o))))
)
