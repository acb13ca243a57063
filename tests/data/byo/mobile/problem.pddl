;; BYO corpus, mobile, small task (7 objects): bring the coffee mug from the
;; kitchen to the living room.  The kitchen door (hallway | kitchen) is closed:
;; someone must open it (open-door, the skill the robot lacks).
(define (problem mobile-fetch-mug)
  (:domain mobile)
  (:objects living-room hallway kitchen - room
            arch-door kitchen-door - door
            coffee-mug news-paper - item)
  (:init (robot-at living-room) (gripper-free)
         (door-in arch-door living-room) (door-in arch-door hallway) (door-open arch-door)
         (door-connects arch-door living-room hallway) (door-connects arch-door hallway living-room)
         (door-in kitchen-door hallway) (door-in kitchen-door kitchen)
         (door-connects kitchen-door hallway kitchen) (door-connects kitchen-door kitchen hallway)
         (obj-at coffee-mug kitchen)
         (obj-at news-paper living-room))
  (:goal (and (obj-at coffee-mug living-room))))
