; The desk lamp is off and lights the study; the hall lamp is on and lights no place the robot goes.
; The novel can be read only under a lamp that is on.
(define (problem read-in-the-study)
  (:domain reading)
  (:objects desk-lamp hall-lamp - lamp novel - book shelf study - place)
  (:init (robot-at shelf) (book-at novel shelf) (lights desk-lamp study) (off desk-lamp) (on hall-lamp))
  (:goal (read novel)))
