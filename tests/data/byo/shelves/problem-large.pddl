;; BYO corpus, shelves, larger task (14 objects): restock two aisles.  Three
;; boxes on low shelves go onto the trolleys (take-down three times); the box on
;; the return trolley goes up on a middle shelf.  Boxes on the middle and top
;; shelves stay where they are, so a robot taught the first task alone (its
;; take-down asks for a low shelf) plans it too.
(define (problem shelves-restock-aisles)
  (:domain shelves)
  (:objects bolt-box hinge-box washer-box fuse-box cable-box lamp-box drill-box - box
            low-shelf-a low-shelf-b mid-shelf-a mid-shelf-b top-shelf-a - shelf
            pick-trolley return-trolley - trolley)
  (:init (claw-empty)
         (low low-shelf-a) (low low-shelf-b)
         (within-reach low-shelf-a) (within-reach low-shelf-b)
         (within-reach mid-shelf-a) (within-reach mid-shelf-b)
         (on-shelf bolt-box low-shelf-a) (on-shelf hinge-box low-shelf-a)
         (on-shelf washer-box low-shelf-b)
         (on-shelf fuse-box mid-shelf-a) (on-shelf cable-box mid-shelf-b)
         (on-shelf lamp-box top-shelf-a)
         (on-trolley drill-box return-trolley))
  (:goal (and (on-trolley bolt-box pick-trolley)
              (on-trolley hinge-box pick-trolley)
              (on-trolley washer-box return-trolley)
              (on-shelf drill-box mid-shelf-a))))
