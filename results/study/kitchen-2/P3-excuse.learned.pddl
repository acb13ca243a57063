;; Learned by guided-lfd from data/demos/kitchen-2/P3-excuse.csv
(define (domain learned-kitchen-2-p3-excuse)
  (:requirements :strips :typing :negative-preconditions)
  (:types drawer furniture item obstacle surface - object)
  (:predicates (blocking ?x0 - obstacle ?x1 - object)
               (clear ?x0 - object)
               (hand_free)
               (open ?x0 - drawer))

  ;; learned from 1 demonstration(s): kitchen-2/P3-excuse segment 3 (Push chair)
  ;; evidence (held in / demonstrations): (blocking ?o1 ?o3) 1/1, (clear ?o2) 1/1, (hand_free) 1/1
  (:action push_obstacle
    :parameters (?o1 - obstacle ?o2 - furniture ?o3 - drawer)
    :precondition (and (blocking ?o1 ?o3) (clear ?o2) (hand_free))
    :effect (and (blocking ?o1 ?o2) (clear ?o3) (not (blocking ?o1 ?o3)) (not (clear ?o2))))

  ;; learned from 1 demonstration(s): kitchen-2/P3-excuse segment 7 (Open bluedrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 1/1, (hand_free) 1/1, (not (open ?o1)) 1/1
  (:action open_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (not (open ?o1)))
    :effect (open ?o1))
)
