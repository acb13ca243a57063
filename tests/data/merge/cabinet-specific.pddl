(define (domain specific)
  (:requirements :strips :typing)
  (:types furniture - object cabinet - furniture)
  (:predicates (locked ?c - cabinet))
  (:action unlock
    :parameters (?c - cabinet)
    :precondition (locked ?c)
    :effect (not (locked ?c))))
