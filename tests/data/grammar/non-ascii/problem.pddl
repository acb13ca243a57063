; Die Küche: a comment.
(define (problem house-1) (:domain house)
  (:objects kitchen - room front - door)
  (:init (in kitchen))
  (:goal (open front)))
