; The true domain of prior.pddl.
(define (domain levels)
  (:requirements :strips :typing)
  (:types goods level)
  (:predicates (stock ?g - goods ?l - level) (depot ?g - goods ?l - level) (next ?hi ?lo - level))
  (:action lift
    :parameters (?g - goods ?low ?high ?dlow ?dhigh - level)
    :precondition (and (stock ?g ?low) (next ?high ?low) (depot ?g ?dhigh) (next ?dhigh ?dlow))
    :effect (and (stock ?g ?high) (not (stock ?g ?low)) (depot ?g ?dlow) (not (depot ?g ?dhigh)))))
