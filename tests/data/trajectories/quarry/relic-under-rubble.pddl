; The relic lies under rubble: blasting the rubble destroys it, so no plan collects it.
(define (problem relic-under-rubble)
  (:domain quarry)
  (:objects c1 c2 c3 - cell)
  (:init (drone-at c1) (clear c1) (rubble c2) (relic c2) (clear c3)
         (next c1 c2) (next c2 c1) (next c2 c3) (next c3 c2))
  (:goal (carrying)))
