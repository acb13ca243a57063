; '(not (= a a))' never holds: unsolvable. Read as literals alone, the STRIPS grounder took '=' for an atom no state
; holds, so the empty plan 'reached' the goal and failed the planner's own check (an internal error).
(define (problem finish-b-unlike-itself)
  (:domain goal-equality)
  (:init)
  (:goal (and (done b) (not (= a a)))))
