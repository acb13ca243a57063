; Both boxes ride in cart1 at the dock and must reach the shelf: moving cart1
; (2 changes) beats moving both boxes (4).
(define (problem move-the-cart)
  (:domain carts)
  (:objects dock shelf yard - place cart1 cart2 - cart b1 b2 - box)
  (:init (at cart1 dock) (at cart2 yard) (in b1 cart1) (in b2 cart1))
  (:goal (and (at b1 shelf) (at b2 shelf))))
