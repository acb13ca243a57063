; The rule derives (qq ?x), a predicate :predicates does not declare (the action needs (q ?x)).
(define (domain derived)
  (:requirements :adl :typing :derived-predicates)
  (:types thing)
  (:predicates (p ?x - thing) (e ?x ?y - thing) (q ?x - thing) (done))
  (:derived (qq ?x - thing) (p ?x))
  (:action finish
    :parameters (?x - thing)
    :precondition (q ?x)
    :effect (done)))
