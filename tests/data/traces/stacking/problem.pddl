;; The stacking scene of tests/data/traces/generate.py: three blocks on the table.
;; Goal: a tower, BlueBlock on GreenBlock on RedBlock (as the D2 demonstrations end).
(define (problem stacking-tower)
  (:domain stacking)
  (:objects RedBlock GreenBlock BlueBlock - block
            Table - surface)
  (:init (graspable RedBlock) (graspable GreenBlock) (graspable BlueBlock)
         (on_top RedBlock Table) (on_top GreenBlock Table) (on_top BlueBlock Table)
         (clear RedBlock) (clear GreenBlock) (clear BlueBlock) (hand_free))
  (:goal (and (on BlueBlock GreenBlock) (on GreenBlock RedBlock))))
