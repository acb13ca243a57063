; 'dock' is declared twice: Fast Downward's translator refuses it ("duplicate objects"), and so does guided-lfd.
(define (problem delivery-1) (:domain delivery)
  (:objects r1 - robot dock - place home - area box - parcel
            dock - place)
  (:init (at r1 home) (in box dock) (home home))
  (:goal (in box home)))
