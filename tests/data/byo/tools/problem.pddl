;; BYO corpus, tools, small task (8 objects): put the flower vase on the book
;; shelf and hang the family photo on the wall nail.  The shelf's bolt is loose
;; (tighten it with the wrench that fits, the 10 mm one) and the nail is not
;; driven in (drive it with the hammer): the robot lacks both tool skills.
(define (problem tools-shelf-and-photo)
  (:domain tools)
  (:objects wrench-10mm wrench-13mm - wrench
            claw-hammer - hammer
            shelf-bolt - bolt
            wall-nail - nail
            book-shelf - shelf
            flower-vase family-photo - item)
  (:init (handempty)
         (on-bench wrench-10mm) (on-bench wrench-13mm) (on-bench claw-hammer)
         (on-bench flower-vase) (on-bench family-photo)
         (fits wrench-10mm shelf-bolt)
         (bolted shelf-bolt book-shelf))
  (:goal (and (on-shelf flower-vase book-shelf)
              (hanging family-photo wall-nail))))
