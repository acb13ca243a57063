(define (domain adl-household)
  (:requirements :strips :typing :negative-preconditions :equality :adl :conditional-effects :derived-predicates :disjunctive-preconditions :quantified-preconditions)
  (:types item place room tray - object)
  (:predicates (belongs ?i - item ?r - room)
               (cupboard ?p - place)
               (door-open ?p - place)
               (has-door ?p - place)
               (in-room ?p - place ?r - room)
               (item-at ?i - item ?p - place)
               (on-tray ?i - item ?t - tray)
               (stored ?i - item)
               (tidy ?r - room)
               (tray-at ?t - tray ?p - place))

  (:derived (tidy ?r - room)
    (forall (?i - item) (or (not (belongs ?i ?r)) (stored ?i))))

  (:action open-door
    :parameters (?p - place)
    :precondition (and (has-door ?p) (not (door-open ?p)))
    :effect (door-open ?p))

  (:action load
    :parameters (?i - item ?t - tray ?p - place)
    :precondition (and (item-at ?i ?p) (tray-at ?t ?p) (not (stored ?i)))
    :effect (and (on-tray ?i ?t) (not (item-at ?i ?p))))

  (:action carry
    :parameters (?t - tray ?from ?to - place)
    :precondition (and (tray-at ?t ?from) (not (= ?from ?to)))
    :effect (and (tray-at ?t ?to) (not (tray-at ?t ?from))))

  (:action unload-all
    :parameters (?t - tray ?p - place)
    :precondition (and (tray-at ?t ?p) (exists (?i - item) (on-tray ?i ?t)) (or (not (cupboard ?p)) (not (has-door ?p)) (door-open ?p)))
    :effect (and (forall (?i1 - item) (when (on-tray ?i1 ?t) (item-at ?i1 ?p))) (forall (?i2 - item) (when (on-tray ?i2 ?t) (not (on-tray ?i2 ?t)))) (forall (?i3 - item) (when (and (on-tray ?i3 ?t) (cupboard ?p)) (stored ?i3)))))
)
