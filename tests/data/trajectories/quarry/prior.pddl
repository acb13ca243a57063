; The quarry's vocabulary and the drone's skills, bodies to learn.
(define (domain quarry)
  (:requirements :strips :typing)
  (:types cell)
  (:predicates (drone-at ?c - cell) (next ?a ?b - cell) (clear ?c - cell) (rubble ?c - cell)
               (boulder ?c - cell) (relic ?c - cell) (hazard ?c - cell) (carrying))
  (:action fly :parameters (?from ?to - cell) :precondition (and) :effect (and))
  (:action blast :parameters (?from ?to - cell) :precondition (and) :effect (and))
  (:action collect :parameters (?c - cell) :precondition (and) :effect (and)))
