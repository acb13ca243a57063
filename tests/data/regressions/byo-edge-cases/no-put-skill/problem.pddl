;; BYO corpus, fetch, small task (5 objects): the blue cup is in the closed
;; upper cabinet; bring it to the counter.  The upper cabinet must be opened
;; first (open-cabinet, the skill the robot lacks).
(define (problem fetch-blue-cup)
  (:domain fetch)
  (:objects blue-cup red-cup green-cup - cup
            upper-cabinet lower-cabinet - cabinet)
  (:init (hand-empty)
         (in blue-cup lower-cabinet)
         (in red-cup lower-cabinet) (cabinet-open lower-cabinet)
         (on-counter green-cup))
  (:goal (and (on-counter blue-cup))))
