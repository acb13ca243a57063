;; Merged by guided-lfd merge from: prior.pddl, learned.pddl
;; take_item (learned.pddl) equals take up to parameter renaming: kept once
;; take (learned.pddl) differs from the take already merged: renamed to take_2
(define (domain kitchen)
  (:requirements :strips :typing :negative-preconditions)
  (:types furniture item - object drawer surface - furniture)
  (:predicates (graspable ?x0 - item)
               (hand_free)
               (in_hand ?x0 - item)
               (inside ?x0 - item ?x1 - drawer)
               (on_top ?x0 - item ?x1 - surface)
               (open ?x0 - drawer))

  ;; from prior.pddl (action take)
  ;; also from learned.pddl (action take_item)
  ;;   learned from 2 demonstration(s)
  (:action take
    :parameters (?i - item ?s - surface)
    :precondition (and (on_top ?i ?s) (hand_free))
    :effect (and (in_hand ?i) (not (on_top ?i ?s)) (not (hand_free))))

  ;; from prior.pddl (action put_inside)
  (:action put_inside
    :parameters (?i - item ?d - drawer)
    :precondition (and (in_hand ?i) (open ?d))
    :effect (and (inside ?i ?d) (hand_free) (not (in_hand ?i))))

  ;; from learned.pddl (action open_drawer)
  (:action open_drawer
    :parameters (?o1 - drawer)
    :precondition (and (hand_free) (not (open ?o1)))
    :effect (open ?o1))

  ;; from learned.pddl (action take)
  (:action take_2
    :parameters (?o1 - item ?o2 - surface)
    :precondition (and (graspable ?o1) (on_top ?o1 ?o2) (hand_free))
    :effect (and (in_hand ?o1) (not (on_top ?o1 ?o2)) (not (hand_free))))
)
