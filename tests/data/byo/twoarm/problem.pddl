;; BYO corpus, twoarm, small task (8 objects): put the tape roll away into the
;; tool-box.  The tape roll is in the open shoe-box (its lid on the table); the
;; tool-box is closed by its lid, which must come off first (remove-lid, the
;; skill the robot lacks): one arm can hold the lid while the other moves the tape.
(define (problem twoarm-store-tape)
  (:domain twoarm)
  (:objects left-arm right-arm - arm
            tape-roll screw-driver - item
            tool-lid shoe-lid - lid
            tool-box shoe-box - box)
  (:init (free left-arm) (free right-arm)
         (in-box screw-driver tool-box) (lid-on tool-lid tool-box)
         (in-box tape-roll shoe-box) (box-open shoe-box) (on-table shoe-lid))
  (:goal (and (in-box tape-roll tool-box))))
