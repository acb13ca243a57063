;; Service robot: open the garage door while standing in the hall.  The garage door joins the garage and the
;; yard, neither of which the hall leads to: the human cannot do it (unsolvable), and a robot taught open-door
;; must not either (a learned open-door without (connects ?d ?from ?to) would open it from the hall).
(define (problem service-garage-door-from-the-hall)
  (:domain service)
  (:objects hall kitchen garage yard - room
            kitchen-door garage-door - door
            cup - item)
  (:init (robot-at hall) (gripper-free)
         (connects kitchen-door hall kitchen) (connects kitchen-door kitchen hall)
         (connects garage-door garage yard) (connects garage-door yard garage)
         (item-at cup kitchen))
  (:goal (door-open garage-door)))
