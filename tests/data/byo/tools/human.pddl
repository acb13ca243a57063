;; BYO corpus, tools: the human demonstrator's complete domain.
;; Tool use in a workshop: a shelf carries things only once the bolt holding it
;; to the wall is tight (static (bolted ?b ?s)), and a bolt is tightened with a
;; wrench that fits it (static (fits ?w ?b)) held in the hand; a picture hangs
;; on a nail once the nail is driven in with a hammer held in the hand.
;; Hand facts: (holding ?o) / (handempty).
;; The robot (robot.pddl) lacks both tool skills: tighten and drive.
(define (domain tools)
  (:requirements :strips :typing :negative-preconditions)
  (:types wrench hammer - tool
          tool item - portable
          portable bolt nail shelf - object)
  (:predicates (handempty)
               (holding ?o - portable)
               (on-bench ?o - portable)
               (fits ?w - wrench ?b - bolt)
               (tight ?b - bolt)
               (driven ?n - nail)
               (bolted ?b - bolt ?s - shelf)
               (on-shelf ?i - item ?s - shelf)
               (hanging ?i - item ?n - nail))

  ;; Take a tool or an item from the workbench.
  (:action pick-up
    :parameters (?o - portable)
    :precondition (and (handempty) (on-bench ?o))
    :effect (and (holding ?o) (not (on-bench ?o)) (not (handempty))))

  ;; Put the held tool or item down on the workbench.
  (:action put-down
    :parameters (?o - portable)
    :precondition (holding ?o)
    :effect (and (on-bench ?o) (handempty) (not (holding ?o))))

  ;; Tighten a loose bolt with the held wrench that fits it.
  (:action tighten
    :parameters (?b - bolt ?w - wrench)
    :precondition (and (holding ?w) (fits ?w ?b) (not (tight ?b)))
    :effect (tight ?b))

  ;; Drive a nail into the wall with the held hammer.
  (:action drive
    :parameters (?n - nail ?h - hammer)
    :precondition (and (holding ?h) (not (driven ?n)))
    :effect (driven ?n))

  ;; Put the held item on a shelf whose bolt is tight.
  (:action place-on-shelf
    :parameters (?i - item ?s - shelf ?b - bolt)
    :precondition (and (holding ?i) (bolted ?b ?s) (tight ?b))
    :effect (and (on-shelf ?i ?s) (handempty) (not (holding ?i))))

  ;; Hang the held item on a driven nail.
  (:action hang
    :parameters (?i - item ?n - nail)
    :precondition (and (holding ?i) (driven ?n))
    :effect (and (hanging ?i ?n) (handempty) (not (holding ?i))))
)
