(define (problem delivery-1) (:domain delivery)
  (:objects r1 - robot dock - place home - area box - parcel)
  (:init (at r1 home) (in box dock) (home home))
  (:goal (in box home)))
