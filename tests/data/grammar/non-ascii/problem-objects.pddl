; Objects named in German and Chinese: küche (kitchen), 盘子 (plate).
(define (problem house-1) (:domain house)
  (:objects küche - room 盘子 - door)
  (:init (in küche))
  (:goal (open 盘子)))
