; The mail in the corridor goes to the office, behind its closed door; the lab door is open.
(define (problem deliver-mail)
  (:domain courier)
  (:objects corridor office lab - room office-door lab-door - door mail - mail)
  (:init (robot-at corridor) (gripper-free) (at-obj mail corridor)
         (connects office-door corridor office) (connects office-door office corridor)
         (connects lab-door corridor lab) (connects lab-door lab corridor)
         (door-closed office-door) (door-open lab-door))
  (:goal (at-obj mail office)))
