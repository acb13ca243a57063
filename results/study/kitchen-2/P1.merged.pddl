;; Merged by guided-lfd: kitchen-2/robot.pddl + P1-excuse
(define (domain kitchen)
  (:requirements :strips :typing :negative-preconditions)
  (:types furniture item obstacle - object drawer surface - furniture)
  (:predicates (blocking ?x0 - obstacle ?x1 - object)
               (clear ?x0 - object)
               (graspable ?x0 - item)
               (hand_free)
               (in_hand ?x0 - item)
               (inside ?x0 - item ?x1 - drawer)
               (on_top ?x0 - item ?x1 - surface)
               (open ?x0 - drawer))

  ;; from data/domains/kitchen-2/robot.pddl (action take)
  ;;   Take an item from a surface that is not blocked.
  (:action take
    :parameters (?i - item ?s - surface)
    :precondition (and (graspable ?i) (on_top ?i ?s) (clear ?s) (hand_free))
    :effect (and (in_hand ?i) (not (on_top ?i ?s)) (not (hand_free))))

  ;; from data/domains/kitchen-2/robot.pddl (action put_on)
  ;;   Put the held item on a surface.
  (:action put_on
    :parameters (?i - item ?s - surface)
    :precondition (and (in_hand ?i) (clear ?s))
    :effect (and (on_top ?i ?s) (hand_free) (not (in_hand ?i))))

  ;; from data/domains/kitchen-2/robot.pddl (action put_inside)
  ;;   Put the held item inside an open drawer.
  (:action put_inside
    :parameters (?i - item ?d - drawer)
    :precondition (and (in_hand ?i) (open ?d) (clear ?d))
    :effect (and (inside ?i ?d) (hand_free) (not (in_hand ?i))))

  ;; from data/domains/kitchen-2/robot.pddl (action open_drawer)
  ;;   Open a closed drawer that nothing blocks.
  ;; also from <learned> (action open_drawer)
  ;;   learned from 1 demonstration(s): kitchen-2/P1-excuse segment 7 (Open bluedrawer)
  (:action open_drawer
    :parameters (?d - drawer)
    :precondition (and (clear ?d) (hand_free) (not (open ?d)))
    :effect (open ?d))

  ;; from data/domains/kitchen-2/robot.pddl (action close_drawer)
  ;;   Close an open drawer that nothing blocks (closing needs the drawer as
  ;;   accessible as opening it does).
  (:action close_drawer
    :parameters (?d - drawer)
    :precondition (and (open ?d) (clear ?d) (hand_free))
    :effect (not (open ?d)))

  ;; from <learned> (action push_obstacle)
  ;;   learned from 1 demonstration(s): kitchen-2/P1-excuse segment 3 (Push chair)
  ;; evidence (held in / demonstrations): (blocking ?o1 ?o3) 1/1, (clear ?o2) 1/1, (hand_free) 1/1
  (:action push_obstacle
    :parameters (?o1 - obstacle ?o2 - furniture ?o3 - drawer)
    :precondition (and (blocking ?o1 ?o3) (clear ?o2) (hand_free))
    :effect (and (blocking ?o1 ?o2) (clear ?o3) (not (blocking ?o1 ?o3)) (not (clear ?o2))))
)
