; The household task with the plate declared twice (alike): Fast Downward refuses it ("duplicate objects"); the
; ADL path read it without a word.
(define (problem tidy-kitchen)
  (:domain adl-household)
  (:objects kitchen - room
            counter sink pantry - place
            tray1 - tray
            cup plate spoon - item
            plate - item)
  (:init (in-room counter kitchen) (in-room sink kitchen) (in-room pantry kitchen)
         (cupboard pantry) (has-door pantry)
         (tray-at tray1 counter)
         (item-at cup counter) (item-at plate counter) (item-at spoon sink)
         (belongs cup kitchen) (belongs plate kitchen) (belongs spoon kitchen))
  (:goal (and (tidy kitchen) (exists (?p - place) (tray-at tray1 ?p)))))
