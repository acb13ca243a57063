;; Learned by guided-lfd from data/demos/kitchen-1/P2-excuse.csv
(define (domain learned-kitchen-1-p2-excuse)
  (:requirements :strips :typing :negative-preconditions)
  (:types drawer furniture item obstacle surface - object)
  (:predicates (clear ?x0 - drawer)
               (hand_free)
               (open ?x0 - drawer))

  ;; learned from 4 demonstration(s): kitchen-1/P2-excuse segment 3 (Open pinkdrawer); kitchen-1/P2-excuse segment 11 (Open pinkdrawer); kitchen-1/P2-excuse segment 19 (Open pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 4/4, (hand_free) 4/4, (not (open ?o1)) 4/4
  (:action open_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (not (open ?o1)))
    :effect (open ?o1))

  ;; learned from 3 demonstration(s): kitchen-1/P2-excuse segment 7 (Close pinkdrawer); kitchen-1/P2-excuse segment 15 (Close pinkdrawer); kitchen-1/P2-excuse segment 23 (Close pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 3/3, (hand_free) 3/3, (open ?o1) 3/3
  (:action close_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (open ?o1))
    :effect (not (open ?o1)))
)
