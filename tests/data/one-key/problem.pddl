; No key, both doors locked; the goal is both doors unlocked.
(define (problem two-doors)
  (:domain one-key)
  (:objects front back - door)
  (:init)
  (:goal (and (unlocked front) (unlocked back))))
