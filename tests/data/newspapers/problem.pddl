; Two houses want a paper; two papers wait at the home base.
(define (problem newspapers-2)
  (:domain newspapers)
  (:objects home house-1 house-2 - loc paper-0 paper-1 - paper)
  (:init (at home) (is-home-base home) (safe home) (safe house-1) (safe house-2)
         (wants-paper house-1) (wants-paper house-2) (unpacked paper-0) (unpacked paper-1))
  (:goal (and (satisfied house-1) (satisfied house-2))))
