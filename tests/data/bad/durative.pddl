(define (domain rover-time)
  (:requirements :strips :typing :negative-preconditions)
  (:types rover place)
  (:predicates (at ?r - rover ?p - place))
  (:durative-action drive
    :parameters (?r - rover ?from ?to - place)
    :duration (= ?duration 5)
    :condition (at start (at ?r ?from))
    :effect (and (at start (not (at ?r ?from))) (at end (at ?r ?to)))))
