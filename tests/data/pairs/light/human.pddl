; A reading robot: it fetches a book and reads it under a lamp that must be on.
; The human can switch the lamp on and off; the robot's domain lacks switch-on.
(define (domain reading)
  (:requirements :strips :typing)
  (:types lamp book place)
  (:predicates (on ?l - lamp) (off ?l - lamp) (lights ?l - lamp ?p - place)
               (robot-at ?p - place) (book-at ?b - book ?p - place) (carrying ?b - book) (read ?b - book))
  (:action go
    :parameters (?from - place ?to - place)
    :precondition (robot-at ?from)
    :effect (and (robot-at ?to) (not (robot-at ?from))))
  (:action take
    :parameters (?b - book ?p - place)
    :precondition (and (robot-at ?p) (book-at ?b ?p))
    :effect (and (carrying ?b) (not (book-at ?b ?p))))
  (:action read-book
    :parameters (?b - book ?l - lamp ?p - place)
    :precondition (and (robot-at ?p) (carrying ?b) (lights ?l ?p) (on ?l))
    :effect (read ?b))
  (:action switch-on
    :parameters (?l - lamp)
    :precondition (off ?l)
    :effect (and (on ?l) (not (off ?l))))
  (:action switch-off
    :parameters (?l - lamp)
    :precondition (on ?l)
    :effect (and (off ?l) (not (on ?l)))))
