;; BYO corpus, shelves, small task (7 objects): put the screw box on the
;; trolley.  It stands on bottom-shelf, a low shelf, beside the nail box; the
;; middle shelf, within reach, is empty, and the glue box is out of reach on
;; the top shelf.  The screw box must come down (take-down, the skill the
;; robot lacks; asked for a full claw, the simulated human takes down the nail
;; box beside it).  Every box within reach being on a low shelf, one
;; demonstration teaches a take-down that requires (low ?s) beside
;; (within-reach ?s): over-specific by design (see problem-2.pddl).
(define (problem shelves-screws-to-trolley)
  (:domain shelves)
  (:objects screw-box nail-box glue-box - box
            bottom-shelf middle-shelf top-shelf - shelf
            stock-trolley - trolley)
  (:init (claw-empty)
         (low bottom-shelf) (within-reach bottom-shelf) (within-reach middle-shelf)
         (on-shelf screw-box bottom-shelf)
         (on-shelf nail-box bottom-shelf)
         (on-shelf glue-box top-shelf))
  (:goal (and (on-trolley screw-box stock-trolley))))
