; One box at the dock must reach the shelf and another in cart2 the yard: the
; carts stay where they are (the box moves: 2 changes) or cart2 stays.
(define (problem keep-the-carts)
  (:domain carts)
  (:objects dock shelf yard - place cart1 cart2 - cart b1 b2 - box)
  (:init (at cart1 dock) (at cart2 shelf) (at b1 dock) (in b2 cart2))
  (:goal (and (at b1 shelf) (at b2 yard))))
