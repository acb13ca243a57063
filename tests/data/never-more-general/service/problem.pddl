;; Service robot, small task: bring the cup from the kitchen to the hall.  The kitchen door is closed; the
;; garage door (between the garage and the yard, rooms the robot never visits) is closed too: a learned
;; open-door without (connects ?d ?from ?to) could open it from the hall.
(define (problem service-fetch-cup)
  (:domain service)
  (:objects hall kitchen garage yard - room
            kitchen-door garage-door - door
            cup - item)
  (:init (robot-at hall) (gripper-free)
         (connects kitchen-door hall kitchen) (connects kitchen-door kitchen hall)
         (connects garage-door garage yard) (connects garage-door yard garage)
         (item-at cup kitchen))
  (:goal (item-at cup hall)))
