; An action with a cost adds the derived predicate (q ?x): derived predicates follow from the basic ones,
; no action changes them (Fast Downward: "derived predicate 'q' appears in effect of action 'make'").
(define (domain derived)
  (:requirements :adl :typing :derived-predicates :action-costs)
  (:types thing)
  (:predicates (p ?x - thing) (e ?x ?y - thing) (q ?x - thing) (done))
  (:functions (total-cost) - number)
  (:derived (q ?x - thing) (p ?x))
  (:action make
    :parameters (?x - thing)
    :precondition (not (p ?x))
    :effect (and (q ?x) (increase (total-cost) 2)))
  (:action finish
    :parameters (?x - thing)
    :precondition (q ?x)
    :effect (and (done) (increase (total-cost) 1))))
