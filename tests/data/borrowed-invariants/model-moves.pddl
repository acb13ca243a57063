(define (domain world)
  (:requirements :strips :typing)
  (:types thing place)
  (:predicates (at ?x - thing ?p - place) (flag) (done))
  (:action move
    :parameters (?x - thing ?a - place ?b - place)
    :precondition (at ?x ?a)
    :effect (and (not (at ?x ?a)) (at ?x ?b)))
  (:action finish
    :parameters (?x - thing)
    :precondition (and (at ?x l2) (flag))
    :effect (done)))
