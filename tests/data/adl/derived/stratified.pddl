; Well-formed: (q ?x) from (p ?x), (far ?x) where no q-thing is reachable in one step (q used negatively: q first).
(define (domain derived)
  (:requirements :adl :typing :derived-predicates)
  (:types thing)
  (:predicates (p ?x - thing) (e ?x ?y - thing) (q ?x - thing) (far ?x - thing) (done))
  (:derived (q ?x - thing) (p ?x))
  (:derived (far ?x - thing) (not (exists (?y - thing) (and (e ?x ?y) (q ?y)))))
  (:action finish
    :parameters (?x - thing)
    :precondition (q ?x)
    :effect (done)))
