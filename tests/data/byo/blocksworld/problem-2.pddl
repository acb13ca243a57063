;; BYO corpus, blocksworld, second task (5 blocks): the orange block sits on
;; the purple one, which stands on the table; the goal is the purple block on
;; the white one and the orange block on the black one.  The orange block must
;; come off the purple one first: unstack orange-block purple-block, from a
;; block that stands on the table, which the first demonstration (the green
;; block off the red one, itself on the yellow one) did not show.  The unstack
;; learned there asks nothing of the lower block's support, so it carries.
(define (problem blocks-move-purple)
  (:domain BLOCKS)
  (:objects orange-block purple-block white-block black-block grey-block - block)
  (:init (handempty)
         (ontable purple-block) (on orange-block purple-block) (clear orange-block)
         (ontable white-block) (clear white-block)
         (ontable black-block) (on grey-block black-block) (clear grey-block))
  (:goal (and (on purple-block white-block) (on orange-block grey-block))))
