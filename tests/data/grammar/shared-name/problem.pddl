(define (problem carts-1)
  (:domain carts)
  (:objects cart - cart
            kitchen hall - location)
  (:init (at cart kitchen) (free gripper))
  (:goal (at cart hall)))
