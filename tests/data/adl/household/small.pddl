(define (problem tidy-cup)
  (:domain adl-household)
  (:objects kitchen - room
            counter pantry - place
            tray1 - tray
            cup - item)
  (:init (in-room counter kitchen) (in-room pantry kitchen)
         (cupboard pantry) (has-door pantry)
         (tray-at tray1 counter)
         (item-at cup counter) (belongs cup kitchen))
  (:goal (tidy kitchen)))
