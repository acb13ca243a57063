; The cup is in the kitchen, the book in the study, the robot in the hall.
; Standing in both rooms at once (+(at bot kitchen) +(at bot study)) is no
; state a person can make; moving the robot or the things is.
(define (problem fetch-two)
  (:domain fetch)
  (:objects bot - robot hall kitchen study - room cup book - item)
  (:init (at bot hall) (lies cup kitchen) (lies book study))
  (:goal (and (holding bot cup) (holding bot book))))
