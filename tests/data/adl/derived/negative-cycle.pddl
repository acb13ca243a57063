; (q ?x) holds where it does not hold: no stratification exists (Fast Downward: "The axioms are not stratifiable").
(define (domain derived)
  (:requirements :adl :typing :derived-predicates)
  (:types thing)
  (:predicates (p ?x - thing) (e ?x ?y - thing) (q ?x - thing) (done))
  (:derived (q ?x - thing) (and (p ?x) (not (q ?x))))
  (:action finish
    :parameters (?x - thing)
    :precondition (q ?x)
    :effect (done)))
