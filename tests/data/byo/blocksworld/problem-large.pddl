;; BYO corpus, blocksworld, larger task (12 blocks): three towers and three
;; loose blocks.  block-a2 and block-b1 must be uncovered and lifted off what
;; they stand on: the optimal plan unstacks three times (a3 from a2, a2 from
;; a1, b2 from b1); tower c only receives loose-z on top.
(define (problem blocks-rebuild-twelve)
  (:domain BLOCKS)
  (:objects block-a1 block-a2 block-a3
            block-b1 block-b2
            block-c1 block-c2 block-c3 block-c4
            loose-x loose-y loose-z - block)
  (:init (handempty)
         ;; tower a: a3 on a2 on a1 (a1 on the table)
         (ontable block-a1) (on block-a2 block-a1) (on block-a3 block-a2) (clear block-a3)
         ;; tower b: b2 on b1
         (ontable block-b1) (on block-b2 block-b1) (clear block-b2)
         ;; tower c: c4 on c3 on c2 on c1 (left alone by the goal)
         (ontable block-c1) (on block-c2 block-c1) (on block-c3 block-c2) (on block-c4 block-c3)
         (clear block-c4)
         (ontable loose-x) (clear loose-x)
         (ontable loose-y) (clear loose-y)
         (ontable loose-z) (clear loose-z))
  (:goal (and (on block-a2 loose-x)
              (on block-b1 loose-y)
              (on loose-z block-c4))))
