; The rule's head (q ?x ?y) has two arguments; :predicates declares (q ?x) with one.
(define (domain derived)
  (:requirements :adl :typing :derived-predicates)
  (:types thing)
  (:predicates (p ?x - thing) (e ?x ?y - thing) (q ?x - thing) (done))
  (:derived (q ?x ?y - thing) (and (p ?x) (e ?x ?y)))
  (:action finish
    :parameters (?x - thing)
    :precondition (q ?x)
    :effect (done)))
