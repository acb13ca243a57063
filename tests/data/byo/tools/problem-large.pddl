;; BYO corpus, tools, larger task (16 objects): furnish the study.  Two shelves,
;; each held by a loose bolt that only one of the wrenches fits, and two nails
;; not yet driven in; a third nail and a spare wrench are not needed.  The
;; optimal plan tightens both bolts and drives both nails (each tool skill twice).
(define (problem tools-furnish-study)
  (:domain tools)
  (:objects wrench-10mm wrench-13mm wrench-17mm - wrench
            claw-hammer - hammer
            upper-bolt lower-bolt - bolt
            left-nail right-nail spare-nail - nail
            upper-shelf lower-shelf - shelf
            flower-vase photo-album desk-clock family-photo sea-painting - item)
  (:init (handempty)
         (on-bench wrench-10mm) (on-bench wrench-13mm) (on-bench wrench-17mm)
         (on-bench claw-hammer)
         (on-bench flower-vase) (on-bench photo-album) (on-bench desk-clock)
         (on-bench family-photo) (on-bench sea-painting)
         (fits wrench-10mm upper-bolt) (fits wrench-13mm lower-bolt)
         (bolted upper-bolt upper-shelf) (bolted lower-bolt lower-shelf))
  (:goal (and (on-shelf flower-vase upper-shelf)
              (on-shelf photo-album lower-shelf)
              (on-shelf desk-clock lower-shelf)
              (hanging family-photo left-nail)
              (hanging sea-painting right-nail))))
