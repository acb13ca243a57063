; (r ?x) uses itself inside a forall, which Fast Downward's translator compiles into
; (not (exists (?y) (and (e ?x ?y) (not (r ?y))))): a negative cycle through (e a b) (e b a).
(define (domain derived)
  (:requirements :adl :typing :derived-predicates)
  (:types thing)
  (:predicates (p ?x - thing) (e ?x ?y - thing) (r ?x - thing) (done))
  (:derived (r ?x - thing) (forall (?y - thing) (imply (e ?x ?y) (r ?y))))
  (:action finish
    :parameters (?x - thing)
    :precondition (r ?x)
    :effect (done)))
