;; Learned by guided-lfd from data/demos/kitchen-1/P5-complete.csv
(define (domain learned-kitchen-1-p5-complete)
  (:requirements :strips :typing :negative-preconditions)
  (:types drawer furniture item obstacle surface - object)
  (:predicates (clear ?x0 - object)
               (graspable ?x0 - item)
               (hand_free)
               (in_hand ?x0 - item)
               (inside ?x0 - item ?x1 - drawer)
               (on_top ?x0 - item ?x1 - surface)
               (open ?x0 - drawer))

  ;; learned from 3 demonstration(s): kitchen-1/P5-complete segment 3 (Open pinkdrawer); kitchen-1/P5-complete segment 16 (Open pinkdrawer); kitchen-1/P5-complete segment 24 (Open pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 3/3, (hand_free) 3/3, (not (open ?o1)) 3/3
  (:action open_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (not (open ?o1)))
    :effect (open ?o1))

  ;; learned from 1 demonstration(s): kitchen-1/P5-complete segment 7 (Take redplate)
  ;; evidence (held in / demonstrations): (clear ?o2) 1/1, (graspable ?o1) 1/1, (hand_free) 1/1, (on_top ?o1 ?o2) 1/1
  (:action take_item
    :parameters (?o1 - item ?o2 - surface)
    :precondition (and (clear ?o2) (graspable ?o1) (hand_free) (on_top ?o1 ?o2))
    :effect (and (in_hand ?o1) (not (hand_free)) (not (on_top ?o1 ?o2))))

  ;; learned from 1 demonstration(s): kitchen-1/P5-complete segment 8 (Put redplate pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o2) 1/1, (in_hand ?o1) 1/1, (open ?o2) 1/1
  (:action put_item_drawer
    :parameters (?o1 - item ?o2 - drawer)
    :precondition (and (clear ?o2) (in_hand ?o1) (open ?o2))
    :effect (and (hand_free) (inside ?o1 ?o2) (not (in_hand ?o1))))

  ;; learned from 2 demonstration(s): kitchen-1/P5-complete segment 12 (Close pinkdrawer); kitchen-1/P5-complete segment 20 (Close pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 2/2, (hand_free) 2/2, (open ?o1) 2/2
  (:action close_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (open ?o1))
    :effect (not (open ?o1)))
)
