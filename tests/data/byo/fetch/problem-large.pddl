;; BYO corpus, fetch, larger task (12 objects): set the counter for tea.
;; Cups wait in two closed cabinets (left-wall-cabinet, corner-cabinet) and an
;; open one; a dirty cup on the counter goes into the open sink-cabinet.
;; Both closed cabinets must be opened (open-cabinet twice).
(define (problem fetch-tea-for-four)
  (:domain fetch)
  (:objects tea-cup-1 tea-cup-2 tea-cup-3 tea-cup-4
            espresso-cup-1 espresso-cup-2 dirty-mug beer-mug glass-cup - cup
            left-wall-cabinet corner-cabinet sink-cabinet - cabinet)
  (:init (hand-empty)
         (in tea-cup-1 left-wall-cabinet) (in tea-cup-2 left-wall-cabinet)
         (in espresso-cup-1 left-wall-cabinet)
         (in tea-cup-3 corner-cabinet) (in beer-mug corner-cabinet)
         (in tea-cup-4 sink-cabinet) (in espresso-cup-2 sink-cabinet)
         (cabinet-open sink-cabinet)
         (on-counter dirty-mug) (on-counter glass-cup))
  (:goal (and (on-counter tea-cup-1) (on-counter tea-cup-2)
              (on-counter tea-cup-3) (on-counter tea-cup-4)
              (in dirty-mug sink-cabinet))))
