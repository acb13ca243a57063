;; mv with ?x = ?y deletes and adds the same (p ?x): PDDL keeps it true.
(define (domain kitchen)
  (:requirements :strips :typing :negative-preconditions)
  (:types item - object)
  (:predicates (p ?i - item) (done))
  (:action mv
    :parameters (?x ?y - item)
    :precondition (p ?x)
    :effect (and (not (p ?x)) (p ?y)))
  (:action fin
    :parameters (?z - item)
    :precondition (not (p ?z))
    :effect (done)))
