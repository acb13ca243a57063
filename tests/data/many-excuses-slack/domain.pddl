; A gate opened by one key, or by two different parts together: the keys are
; the minimal excuses, and every pair of parts is an excuse one change larger
; that contains none of them (what --slack 1 lists: 3 + 15 here).
(define (domain gate2)
  (:requirements :strips :typing :equality :negative-preconditions)
  (:types key part)
  (:predicates (has ?k - key) (has-part ?p - part) (open))
  (:action open-with-key :parameters (?k - key) :precondition (has ?k) :effect (open))
  (:action open-with-parts :parameters (?a ?b - part)
    :precondition (and (has-part ?a) (has-part ?b) (not (= ?a ?b))) :effect (open)))
