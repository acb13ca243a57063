;; BYO corpus, switches, small task (8 objects): light the porch lamp.  A storm
;; tripped the house breaker, which feeds the porch and hall switches; the
;; porch switch is off.  Reset the breaker, then turn the porch switch on
;; (turn-on, the skill the robot lacks), then press the lamp's button.  The
;; garage breaker is up; no light is on.
(define (problem switches-porch-light)
  (:domain switches)
  (:objects house-breaker garage-breaker - breaker
            porch-switch hall-switch garage-switch - switch
            porch-lamp hall-lamp garage-lamp - lamp)
  (:init (breaker-up garage-breaker)
         (feeds house-breaker porch-switch) (feeds house-breaker hall-switch)
         (feeds garage-breaker garage-switch)
         (wired porch-switch porch-lamp) (wired hall-switch hall-lamp)
         (wired garage-switch garage-lamp))
  (:goal (and (lit porch-lamp))))
