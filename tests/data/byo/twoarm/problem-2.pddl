;; BYO corpus, twoarm, second task (8 objects): the left arm holds the paint
;; brush, which goes into the closed paint-box, and the box is closed again.
;; With the left arm busy, the right arm must lift the paint-box lid off
;; (remove-lid with the other arm and another box, which the first
;; demonstration, the left arm lifting the tool-box lid, did not show) and put
;; it back once the brush is in.  The remove-lid learned there (a free arm, a
;; lid on a box) carries.
(define (problem twoarm-store-brush)
  (:domain twoarm)
  (:objects left-arm right-arm - arm
            paint-brush glue-stick - item
            paint-lid craft-lid - lid
            paint-box craft-box - box)
  (:init (grasped left-arm paint-brush) (free right-arm)
         (lid-on paint-lid paint-box)
         (in-box glue-stick craft-box) (lid-on craft-lid craft-box))
  (:goal (and (in-box paint-brush paint-box) (lid-on paint-lid paint-box))))
