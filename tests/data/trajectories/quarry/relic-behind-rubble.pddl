; The relic lies behind rubble: blast the rubble, fly past it, collect the relic.
(define (problem relic-behind-rubble)
  (:domain quarry)
  (:objects c1 c2 c3 - cell)
  (:init (drone-at c1) (clear c1) (rubble c2) (clear c3) (relic c3)
         (next c1 c2) (next c2 c1) (next c2 c3) (next c3 c2))
  (:goal (carrying)))
