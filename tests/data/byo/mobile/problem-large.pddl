;; BYO corpus, mobile, larger task (18 objects): a flat of seven rooms.  The
;; cereal box is in the pantry behind two closed doors (kitchen-door,
;; pantry-door); the towel in the bathroom goes to the kitchen.  The optimal
;; plan opens both closed doors on the way (open-door twice); the garage door
;; stays shut.
(define (problem mobile-flat-errands)
  (:domain mobile)
  (:objects living-room hallway kitchen pantry bed-room bath-room garage - room
            arch-door kitchen-door pantry-door bedroom-door bathroom-door garage-door - door
            coffee-mug cereal-box bath-towel tool-box story-book - item)
  (:init (robot-at living-room) (gripper-free)
         (door-in arch-door living-room) (door-in arch-door hallway) (door-open arch-door)
         (door-connects arch-door living-room hallway) (door-connects arch-door hallway living-room)
         (door-in kitchen-door hallway) (door-in kitchen-door kitchen)
         (door-connects kitchen-door hallway kitchen) (door-connects kitchen-door kitchen hallway)
         (door-in pantry-door kitchen) (door-in pantry-door pantry)
         (door-connects pantry-door kitchen pantry) (door-connects pantry-door pantry kitchen)
         (door-in bedroom-door hallway) (door-in bedroom-door bed-room) (door-open bedroom-door)
         (door-connects bedroom-door hallway bed-room) (door-connects bedroom-door bed-room hallway)
         (door-in bathroom-door bed-room) (door-in bathroom-door bath-room) (door-open bathroom-door)
         (door-connects bathroom-door bed-room bath-room) (door-connects bathroom-door bath-room bed-room)
         (door-in garage-door hallway) (door-in garage-door garage)
         (door-connects garage-door hallway garage) (door-connects garage-door garage hallway)
         (obj-at coffee-mug living-room)
         (obj-at cereal-box pantry)
         (obj-at bath-towel bath-room)
         (obj-at tool-box garage)
         (obj-at story-book bed-room))
  (:goal (and (obj-at cereal-box living-room)
              (obj-at bath-towel kitchen))))
