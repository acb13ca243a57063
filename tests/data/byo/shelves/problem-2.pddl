;; BYO corpus, shelves, second task (skills that carry): put the paint tin on
;; the trolley.  It stands on eye-shelf, a high shelf within reach: a situation
;; the first demonstration (the screw box, from a low shelf) did not show.  The
;; take-down learned from the first task requires (low ?s); taking the tin down
;; needs it without: one demonstration more, asked for as a skill excuse
;; (dropping (low ?s) costs 1; moving the tin to a low shelf costs 2, and
;; whether a shelf is low or within reach no skill changes).
(define (problem shelves-paint-to-trolley)
  (:domain shelves)
  (:objects paint-tin brush-box tape-box - box
            floor-shelf eye-shelf ceiling-shelf - shelf
            stock-trolley - trolley)
  (:init (claw-empty)
         (low floor-shelf) (within-reach floor-shelf) (within-reach eye-shelf)
         (on-shelf brush-box floor-shelf)
         (on-shelf paint-tin eye-shelf)
         (on-shelf tape-box ceiling-shelf))
  (:goal (and (on-trolley paint-tin stock-trolley))))
