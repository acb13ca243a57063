(define (domain world)
  (:requirements :strips :typing)
  (:types thing place)
  (:predicates (at ?x - thing ?p - place) (flag) (done))
  (:action finish
    :parameters (?x - thing)
    :precondition (and (at ?x l2) (flag))
    :effect (done)))
