;; The fetch robot (tests/data/byo/fetch) with a second closed cabinet, side-cabinet, beside the upper one:
;; a demonstration may open the wrong one.  The robot must be taught open-cabinet.
(define (problem fetch-blue-cup-two-closed)
  (:domain fetch)
  (:objects blue-cup red-cup green-cup - cup
            upper-cabinet lower-cabinet side-cabinet - cabinet)
  (:init (hand-empty)
         (in blue-cup upper-cabinet)
         (in red-cup lower-cabinet) (cabinet-open lower-cabinet)
         (on-counter green-cup))
  (:goal (and (on-counter blue-cup))))
