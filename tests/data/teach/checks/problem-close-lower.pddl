;; As problem.pddl, and the lower cabinet must end closed: with robot-no-close.pddl (no open-cabinet, no
;; close-cabinet) the request is two changes, Cabinet-open upper-cabinet and Not cabinet-open lower-cabinet.
(define (problem fetch-blue-cup-close-lower)
  (:domain fetch)
  (:objects blue-cup red-cup green-cup - cup
            upper-cabinet lower-cabinet side-cabinet - cabinet)
  (:init (hand-empty)
         (in blue-cup upper-cabinet)
         (in red-cup lower-cabinet) (cabinet-open lower-cabinet)
         (on-counter green-cup))
  (:goal (and (on-counter blue-cup) (not (cabinet-open lower-cabinet)))))
