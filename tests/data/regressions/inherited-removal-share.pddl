;; Regression: a child that removes a group atom inherited landmark shares
;; that already charged that removal (review, bug 2).
(define (domain inherited-removal-share) (:requirements :strips :negative-preconditions)
 (:predicates (p1) (p2) (q) (r) (g))
 (:action a1 :parameters () :precondition (and (p1) (r)) :effect (g))
 (:action a2 :parameters () :precondition (and (p2) (r)) :effect (g)))
