;; The cupboard scene of tests/data/traces/generate.py: the mug on the table, both doors closed.
;; Goal: the mug inside, the doors closed again (as the demonstrations end).
(define (problem cupboard-store-mug)
  (:domain cupboard)
  (:objects Mug - item
            Table - surface
            Cupboard - cupboard
            LeftDoor RightDoor - door)
  (:init (graspable Mug) (on_top Mug Table) (door_of LeftDoor Cupboard) (door_of RightDoor Cupboard)
         (hand_free))
  (:goal (and (inside Mug Cupboard) (not (open LeftDoor)) (not (open RightDoor)))))
