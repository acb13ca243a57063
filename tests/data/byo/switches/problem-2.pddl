;; BYO corpus, switches, second task (7 objects): light the cellar lamps and
;; the attic lamp.  The cellar breaker is up and feeds the cellar switch, wired
;; to two lamps; the attic breaker is tripped.  Turn the cellar switch on with
;; its breaker up all along, and the attic switch on after resetting its
;; breaker (turn-on for two other breaker/switch pairs; the first
;; demonstration turned on the porch switch right after resetting the house
;; breaker, and never with a breaker that was up from the start).  The turn-on
;; learned there carries.
(define (problem switches-cellar-and-attic)
  (:domain switches)
  (:objects cellar-breaker attic-breaker - breaker
            cellar-switch attic-switch - switch
            cellar-lamp stair-lamp attic-lamp - lamp)
  (:init (breaker-up cellar-breaker)
         (feeds cellar-breaker cellar-switch) (feeds attic-breaker attic-switch)
         (wired cellar-switch cellar-lamp) (wired cellar-switch stair-lamp)
         (wired attic-switch attic-lamp))
  (:goal (and (lit cellar-lamp) (lit stair-lamp) (lit attic-lamp))))
