; The newspaper robot without its pick-up skill.
(define (domain newspapers)
  (:requirements :strips :typing)
  (:types loc paper)
  (:predicates (at ?l - loc) (is-home-base ?l - loc) (satisfied ?l - loc) (wants-paper ?l - loc)
               (safe ?l - loc) (unpacked ?p - paper) (carrying ?p - paper))
  (:action move
    :parameters (?from ?to - loc)
    :precondition (and (at ?from) (safe ?from))
    :effect (and (at ?to) (not (at ?from))))
  (:action deliver
    :parameters (?p - paper ?l - loc)
    :precondition (and (at ?l) (carrying ?p))
    :effect (and (not (carrying ?p)) (satisfied ?l))))
