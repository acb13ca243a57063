;; BYO corpus, switches: the robot's domain (human.pddl without turn-on).
;; Lights and power, no hand at all: a wall switch can be turned on only while
;; the breaker feeding it (static (feeds ?c ?s)) is up; a lamp lights when its
;; own button is pressed while the wall switch it is wired to (static
;; (wired ?s ?l)) is on.  A tripped breaker can be reset.
;; No hand facts.  This robot cannot turn a wall switch on: turn-on is the
;; skill it must be taught (it can turn one off).
(define (domain switches)
  (:requirements :strips :typing :negative-preconditions)
  (:types breaker switch lamp)
  (:predicates (breaker-up ?c - breaker)
               (feeds ?c - breaker ?s - switch)
               (on ?s - switch)
               (wired ?s - switch ?l - lamp)
               (lit ?l - lamp))

  ;; Reset a tripped breaker.
  (:action reset-breaker
    :parameters (?c - breaker)
    :precondition (not (breaker-up ?c))
    :effect (breaker-up ?c))

  ;; Turn a wall switch off.
  (:action turn-off
    :parameters (?s - switch ?c - breaker)
    :precondition (and (feeds ?c ?s) (breaker-up ?c) (on ?s))
    :effect (not (on ?s)))

  ;; Press a dark lamp's button: it lights if its wall switch is on.
  (:action light
    :parameters (?l - lamp ?s - switch)
    :precondition (and (wired ?s ?l) (on ?s) (not (lit ?l)))
    :effect (lit ?l))
)
