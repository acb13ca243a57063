;; Regression: the consistent semantics' removal charge for q was added to
;; making p true while "not q" also cost w(q) on its own (review, bug 1).
(define (domain removal-charged-twice) (:requirements :strips :negative-preconditions)
 (:predicates (p) (q) (s) (g) (k))
 (:action sw :parameters () :precondition (and (q) (k)) :effect (and (p) (not (q))))
 (:action a :parameters () :precondition (and (p) (not (q))) :effect (g))
 (:action b :parameters () :precondition (s) :effect (g)))
