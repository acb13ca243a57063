; A survey drone clears a quarry's cells with charges and collects relics.  A blast clears whatever is in
; the next cell: rubble, a boulder, and a relic too (the trajectories never show that: no one blasts a relic).
(define (domain quarry)
  (:requirements :strips :typing)
  (:types cell)
  (:predicates (drone-at ?c - cell) (next ?a ?b - cell) (clear ?c - cell) (rubble ?c - cell)
               (boulder ?c - cell) (relic ?c - cell) (hazard ?c - cell) (carrying))
  (:action fly
    :parameters (?from ?to - cell)
    :precondition (and (drone-at ?from) (next ?from ?to) (clear ?to))
    :effect (and (drone-at ?to) (not (drone-at ?from))))
  (:action blast
    :parameters (?from ?to - cell)
    :precondition (and (drone-at ?from) (next ?from ?to))
    :effect (and (clear ?to) (not (rubble ?to)) (not (boulder ?to)) (not (relic ?to))))
  (:action collect
    :parameters (?c - cell)
    :precondition (and (drone-at ?c) (relic ?c))
    :effect (and (carrying) (not (relic ?c)))))
