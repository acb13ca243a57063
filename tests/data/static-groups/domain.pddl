; Carts carry boxes between places.  The robot's version of this domain has no
; "push" action, so a cart's place never changes: its place is a static mutex
; group (tests/test_static_groups.py).
(define (domain carts)
  (:requirements :strips :typing)
  (:types place locatable - object cart box - locatable)
  (:predicates (at ?o - locatable ?p - place) (in ?b - box ?c - cart))
  (:action load
    :parameters (?b - box ?c - cart ?p - place)
    :precondition (and (at ?b ?p) (at ?c ?p))
    :effect (and (in ?b ?c) (not (at ?b ?p))))
  (:action unload
    :parameters (?b - box ?c - cart ?p - place)
    :precondition (and (in ?b ?c) (at ?c ?p))
    :effect (and (at ?b ?p) (not (in ?b ?c)))))
