; The pillar moved to either spot passes the relaxation and fails the real check; each
; such candidate then branches on every relevant change, the other spot included
; (tests/test_static_groups.py).
(define (domain relaxfail) (:requirements :strips :typing)
  (:types place thing - object spot - place pillar box - thing)
  (:predicates (at ?t - thing ?p - place) (tok) (mid) (done) (m1) (m2) (m3) (m4) (m5))
  (:action push :parameters (?b - box ?from - place ?to - place)
    :precondition (at ?b ?from) :effect (and (at ?b ?to) (not (at ?b ?from))))
  (:action first :parameters (?t - pillar ?s - spot) :precondition (and (at ?t ?s) (tok)) :effect (and (mid) (not (tok))))
  (:action second :parameters () :precondition (and (mid) (tok)) :effect (done))
  (:action shortcut :parameters () :precondition (and (m1) (m2) (m3) (m4) (m5)) :effect (done)))
