;; BYO corpus, lab, second task (skills that carry): file three aliquots into
;; the fridge.  They were uncapped for pipetting and stand open in the
;; pipetting rack, unlabelled: a situation the first demonstration (a capped
;; tube) did not show.  The write-label learned from the first task requires
;; (capped ?t); labelling the aliquots needs it without: one demonstration
;; more, asked for as a skill excuse (dropping (capped ?t) costs 1; capping the
;; three tubes again costs 3, and no skill of the human's caps a tube).
(define (problem lab-file-aliquots)
  (:domain lab)
  (:objects aliquot-1 aliquot-2 aliquot-3 - tube
            fine-marker - marker
            pipetting-rack - rack
            sample-fridge - fridge)
  (:init (palm-free)
         (on-bench fine-marker)
         (in-rack aliquot-1 pipetting-rack)
         (in-rack aliquot-2 pipetting-rack)
         (in-rack aliquot-3 pipetting-rack))
  (:goal (and (in-fridge aliquot-1 sample-fridge)
              (in-fridge aliquot-2 sample-fridge)
              (in-fridge aliquot-3 sample-fridge))))
