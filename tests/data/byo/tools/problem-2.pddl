;; BYO corpus, tools, second task (8 objects): put the desk clock on the wall
;; shelf and hang the sea painting on the hall nail.  The wall shelf's bolt is
;; loose and only the 13 mm wrench fits it (tighten with another bolt/wrench
;; pair than the first demonstration's 10 mm wrench on the book-shelf bolt), and
;; the robot starts holding the hammer, not the empty hand of the first task,
;; so it can drive the hall nail (another nail) before it puts the hammer down.
;; The tighten and drive learned there carry.
(define (problem tools-clock-and-painting)
  (:domain tools)
  (:objects wrench-10mm wrench-13mm - wrench
            claw-hammer - hammer
            wall-bolt - bolt
            hall-nail - nail
            wall-shelf - shelf
            desk-clock sea-painting - item)
  (:init (holding claw-hammer)
         (on-bench wrench-10mm) (on-bench wrench-13mm)
         (on-bench desk-clock) (on-bench sea-painting)
         (fits wrench-13mm wall-bolt)
         (bolted wall-bolt wall-shelf))
  (:goal (and (on-shelf desk-clock wall-shelf)
              (hanging sea-painting hall-nail))))
