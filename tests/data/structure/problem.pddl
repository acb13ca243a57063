; A parcel at the depot of city 1 must reach the airport of city 2.  The truck
; waits at city 1's airport; without drive-truck it cannot fetch the parcel.
(define (problem parcel)
  (:domain logistics-untyped)
  (:objects p1 t1 a1 depot1 airport1 airport2 c1 c2)
  (:init (package p1) (truck t1) (airplane a1) (city c1) (city c2)
         (location depot1) (location airport1) (location airport2) (airport airport1) (airport airport2)
         (in-city depot1 c1) (in-city airport1 c1) (in-city airport2 c2)
         (at p1 depot1) (at t1 airport1) (at a1 airport1))
  (:goal (at p1 airport2)))
