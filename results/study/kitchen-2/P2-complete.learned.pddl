;; Learned by guided-lfd from data/demos/kitchen-2/P2-complete.csv
(define (domain learned-kitchen-2-p2-complete)
  (:requirements :strips :typing :negative-preconditions)
  (:types drawer furniture item obstacle surface - object)
  (:predicates (blocking ?x0 - obstacle ?x1 - object)
               (clear ?x0 - object)
               (graspable ?x0 - item)
               (hand_free)
               (in_hand ?x0 - item)
               (inside ?x0 - item ?x1 - drawer)
               (on_top ?x0 - item ?x1 - surface)
               (open ?x0 - drawer))

  ;; learned from 15 demonstration(s): kitchen-2/P2-complete segment 3 (Push chair); kitchen-2/P2-complete segment 16 (Push chair); kitchen-2/P2-complete segment 20 (Push chair)
  ;; evidence (held in / demonstrations): (blocking ?o1 ?o3) 15/15, (clear ?o2) 15/15, (hand_free) 15/15
  (:action push_obstacle
    :parameters (?o1 - obstacle ?o2 ?o3 - object)
    :precondition (and (blocking ?o1 ?o3) (clear ?o2) (hand_free))
    :effect (and (blocking ?o1 ?o2) (clear ?o3) (not (blocking ?o1 ?o3)) (not (clear ?o2))))

  ;; learned from 2 demonstration(s): kitchen-2/P2-complete segment 7 (Open pinkdrawer); kitchen-2/P2-complete segment 72 (Open bluedrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 2/2, (hand_free) 2/2, (not (open ?o1)) 2/2
  (:action open_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (not (open ?o1)))
    :effect (open ?o1))

  ;; learned from 1 demonstration(s): kitchen-2/P2-complete segment 11 (Take redplate)
  ;; evidence (held in / demonstrations): (clear ?o2) 1/1, (graspable ?o1) 1/1, (hand_free) 1/1, (on_top ?o1 ?o2) 1/1
  (:action take_item
    :parameters (?o1 - item ?o2 - surface)
    :precondition (and (clear ?o2) (graspable ?o1) (hand_free) (on_top ?o1 ?o2))
    :effect (and (in_hand ?o1) (not (hand_free)) (not (on_top ?o1 ?o2))))

  ;; learned from 1 demonstration(s): kitchen-2/P2-complete segment 12 (Put redplate pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o2) 1/1, (in_hand ?o1) 1/1, (open ?o2) 1/1
  (:action put_item_drawer
    :parameters (?o1 - item ?o2 - drawer)
    :precondition (and (clear ?o2) (in_hand ?o1) (open ?o2))
    :effect (and (hand_free) (inside ?o1 ?o2) (not (in_hand ?o1))))
)
