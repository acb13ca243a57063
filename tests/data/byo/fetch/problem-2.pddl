;; BYO corpus, fetch, second task (7 objects): the robot starts holding the
;; dirty mug, which goes into the closed sink cabinet, and the two tea cups in
;; the closed pantry cabinet go to the counter.  Both cabinets must be opened
;; (open-cabinet twice), and the hand is full at the start: the robot must set
;; the mug down (in the open wall cabinet or on the counter) before it can pull
;; a door.  The first demonstration (the upper cabinet, one cup inside, the
;; hand empty) did not show a cabinet holding several cups, nor a cabinet
;; opened to put a cup in; the open-cabinet learned there (the hand empty, the
;; cabinet closed) carries.
(define (problem fetch-mug-and-tea-cups)
  (:domain fetch)
  (:objects dirty-mug tea-cup-1 tea-cup-2 glass-cup - cup
            pantry-cabinet sink-cabinet wall-cabinet - cabinet)
  (:init (holding dirty-mug)
         (in tea-cup-1 pantry-cabinet) (in tea-cup-2 pantry-cabinet)
         (in glass-cup wall-cabinet) (cabinet-open wall-cabinet))
  (:goal (and (in dirty-mug sink-cabinet)
              (on-counter tea-cup-1) (on-counter tea-cup-2))))
