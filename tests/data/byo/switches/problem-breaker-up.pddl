;; The switches task with the house breaker already up: the demonstration never changes breaker-up, yet
;; turn-on needs it (a human action resets breakers): the learner must not take it for a static relation.
(define (problem switches-porch-light)
  (:domain switches)
  (:objects house-breaker garage-breaker - breaker
            porch-switch hall-switch garage-switch - switch
            porch-lamp hall-lamp garage-lamp - lamp)
  (:init (breaker-up garage-breaker) (breaker-up house-breaker)
         (feeds house-breaker porch-switch) (feeds house-breaker hall-switch)
         (feeds garage-breaker garage-switch)
         (wired porch-switch porch-lamp) (wired hall-switch hall-lamp)
         (wired garage-switch garage-lamp))
  (:goal (and (lit porch-lamp))))
