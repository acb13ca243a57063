;; BYO corpus, lab, small task (6 objects): file the blood sample into the
;; fridge.  It stands capped in the bench rack, not yet labelled: someone must
;; write its label (write-label, the skill the robot lacks) before it may go in.
;; The other tube, the urine sample, is capped too.  Every tube being capped,
;; one demonstration teaches a write-label that requires (capped ?t):
;; over-specific by design (see problem-2.pddl).
(define (problem lab-file-blood-sample)
  (:domain lab)
  (:objects blood-sample urine-sample - tube
            felt-marker - marker
            bench-rack - rack
            sample-fridge - fridge)
  (:init (palm-free)
         (on-bench felt-marker)
         (in-rack blood-sample bench-rack) (capped blood-sample)
         (in-rack urine-sample bench-rack) (capped urine-sample))
  (:goal (and (in-fridge blood-sample sample-fridge))))
