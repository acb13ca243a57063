;; Learned by guided-lfd from data/demos/kitchen-1/P4-excuse.csv
(define (domain learned-kitchen-1-p4-excuse)
  (:requirements :strips :typing :negative-preconditions)
  (:types drawer furniture item obstacle surface - object)
  (:predicates (clear ?x0 - drawer)
               (hand_free)
               (open ?x0 - drawer))

  ;; learned from 2 demonstration(s): kitchen-1/P4-excuse segment 3 (Open pinkdrawer); kitchen-1/P4-excuse segment 11 (Open pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 2/2, (hand_free) 2/2, (not (open ?o1)) 2/2
  (:action open_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (not (open ?o1)))
    :effect (open ?o1))

  ;; learned from 1 demonstration(s): kitchen-1/P4-excuse segment 7 (Close pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 1/1, (hand_free) 1/1, (open ?o1) 1/1
  (:action close_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (open ?o1))
    :effect (not (open ?o1)))
)
