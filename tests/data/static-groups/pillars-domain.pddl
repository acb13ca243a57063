; A pillar's place is a static group; moving it onto an irrelevant zone still
; matters, since a zone must be either clear or occupied (an exactly-one group)
; and "finish" needs a zone that is not clear (tests/test_static_groups.py).
(define (domain pillars) (:requirements :strips :typing :negative-preconditions)
  (:types place thing - object spot zone - place box pillar - thing)
  (:predicates (at ?t - thing ?p - place) (clear ?p - place) (done1) (done2) (magic))
  (:action move :parameters (?b - box ?from - place ?to - place)
    :precondition (and (at ?b ?from) (clear ?to))
    :effect (and (at ?b ?to) (clear ?from) (not (at ?b ?from)) (not (clear ?to))))
  (:action finish-b :parameters (?t - pillar ?p - spot) :precondition (at ?t ?p) :effect (done1))
  (:action finish-c :parameters () :precondition (magic) :effect (done1))
  (:action finish :parameters (?z - zone) :precondition (not (clear ?z)) :effect (done2)))
