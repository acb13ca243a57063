;; BYO corpus, blocksworld, small task (4 blocks): the green block sits on the
;; red one, which sits on the yellow one; the goal is the green block on the
;; blue one.  The green block must come off the red one first: unstack
;; green-block red-block (the skill the robot lacks).  The red block is not on
;; the table, so one demonstration of that unstack shows exactly its
;; preconditions (nothing about the lower block's support).
(define (problem blocks-move-green)
  (:domain BLOCKS)
  (:objects red-block blue-block green-block yellow-block - block)
  (:init (handempty)
         (ontable yellow-block) (on red-block yellow-block) (on green-block red-block)
         (clear green-block)
         (ontable blue-block) (clear blue-block))
  (:goal (and (on green-block blue-block))))
