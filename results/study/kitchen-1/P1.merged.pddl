;; Merged by guided-lfd: kitchen-1/robot.pddl + P1-excuse
(define (domain kitchen)
  (:requirements :strips :typing :negative-preconditions)
  (:types furniture item obstacle - object drawer surface - furniture)
  (:predicates (blocking ?x0 - obstacle ?x1 - furniture)
               (clear ?x0 - furniture)
               (graspable ?x0 - item)
               (hand_free)
               (in_hand ?x0 - item)
               (inside ?x0 - item ?x1 - drawer)
               (on_top ?x0 - item ?x1 - surface)
               (open ?x0 - drawer))

  ;; from data/domains/kitchen-1/robot.pddl (action take)
  ;;   Take an item from a surface that is not blocked.
  (:action take
    :parameters (?i - item ?s - surface)
    :precondition (and (graspable ?i) (on_top ?i ?s) (clear ?s) (hand_free))
    :effect (and (in_hand ?i) (not (on_top ?i ?s)) (not (hand_free))))

  ;; from data/domains/kitchen-1/robot.pddl (action put_on)
  ;;   Put the held item on a surface.
  (:action put_on
    :parameters (?i - item ?s - surface)
    :precondition (and (in_hand ?i) (clear ?s))
    :effect (and (on_top ?i ?s) (hand_free) (not (in_hand ?i))))

  ;; from data/domains/kitchen-1/robot.pddl (action put_inside)
  ;;   Put the held item inside an open drawer.
  (:action put_inside
    :parameters (?i - item ?d - drawer)
    :precondition (and (in_hand ?i) (open ?d) (clear ?d))
    :effect (and (inside ?i ?d) (hand_free) (not (in_hand ?i))))

  ;; from <learned> (action open_drawer)
  ;;   learned from 2 demonstration(s): kitchen-1/P1-excuse segment 3 (Open pinkdrawer); kitchen-1/P1-excuse segment 11 (Open pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 2/2, (hand_free) 2/2, (not (open ?o1)) 2/2
  (:action open_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (not (open ?o1)))
    :effect (open ?o1))

  ;; from <learned> (action close_drawer)
  ;;   learned from 1 demonstration(s): kitchen-1/P1-excuse segment 7 (Close pinkdrawer)
  ;; evidence (held in / demonstrations): (clear ?o1) 1/1, (hand_free) 1/1, (open ?o1) 1/1
  (:action close_drawer
    :parameters (?o1 - drawer)
    :precondition (and (clear ?o1) (hand_free) (open ?o1))
    :effect (not (open ?o1)))
)
