; A robot that teleports without leaving (no delete): the models' invariants are not its own.
(define (domain world)
  (:requirements :strips :typing)
  (:types thing place)
  (:predicates (at ?x - thing ?p - place) (flag) (done))
  (:action teleport
    :parameters (?x - thing ?a - place ?b - place)
    :precondition (at ?x ?a)
    :effect (at ?x ?b))
  (:action finish
    :parameters (?x - thing)
    :precondition (and (at ?x l2) (flag))
    :effect (done)))
