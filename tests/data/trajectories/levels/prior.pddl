; A crane moves goods between stock levels: the goods' level goes from ?low to ?high while the depot's goes
; from ?dhigh to ?dlow (after TPP's load).  The bodies are to learn.  Every step passes one level twice: alone,
; the first trajectory cannot tell whether the goods' new level is ?high or ?dhigh; with the second, whose
; levels coincide another way, each step tells the other.
(define (domain levels)
  (:requirements :strips :typing)
  (:types goods level)
  (:predicates (stock ?g - goods ?l - level) (depot ?g - goods ?l - level) (next ?hi ?lo - level))
  (:action lift :parameters (?g - goods ?low ?high ?dlow ?dhigh - level) :precondition (and) :effect (and)))
