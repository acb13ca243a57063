;; BYO corpus, lab, larger task (13 objects): the evening round.  Three capped
;; samples, unlabelled, go into the two fridges (write-label three times); the
;; control tube, labelled already, is filed as it is; the spare tubes stay in
;; their racks.  The tubes to label are capped, so a robot taught the first
;; task alone (its write-label asks for a capped tube) plans it too.
(define (problem lab-evening-round)
  (:domain lab)
  (:objects serum-a serum-b plasma-c control-tube spare-tube-1 spare-tube-2 - tube
            felt-marker fine-marker - marker
            bench-rack cold-rack centrifuge-rack - rack
            sample-fridge reagent-fridge - fridge)
  (:init (palm-free)
         (on-bench felt-marker) (on-bench fine-marker)
         (in-rack serum-a bench-rack) (capped serum-a)
         (in-rack serum-b bench-rack) (capped serum-b)
         (in-rack plasma-c centrifuge-rack) (capped plasma-c)
         (in-rack control-tube cold-rack) (labelled control-tube)
         (in-rack spare-tube-1 bench-rack) (capped spare-tube-1)
         (in-rack spare-tube-2 cold-rack))
  (:goal (and (in-fridge serum-a sample-fridge)
              (in-fridge serum-b sample-fridge)
              (in-fridge plasma-c reagent-fridge)
              (in-fridge control-tube reagent-fridge))))
