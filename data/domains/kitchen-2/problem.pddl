;; Kitchen II: as Kitchen I, but the chair blocks PinkDrawer.
;; Goal as in the study: RedPlate inside PinkDrawer.
(define (problem kitchen-2-store-plate)
  (:domain kitchen)
  (:objects RedPlate - item
            Table Counter - surface
            PinkDrawer BlueDrawer - drawer
            Corner - furniture
            Chair - obstacle)
  (:init (graspable RedPlate) (on_top RedPlate Table) (hand_free)
         (clear Table) (clear Counter) (clear Corner) (clear BlueDrawer)
         (blocking Chair PinkDrawer))
  (:goal (and (inside RedPlate PinkDrawer))))
