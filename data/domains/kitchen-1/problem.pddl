;; Kitchen I: the plate is on the table, PinkDrawer is closed; the chair stands in the corner.
;; Goal as in the study: RedPlate inside PinkDrawer.
(define (problem kitchen-1-store-plate)
  (:domain kitchen)
  (:objects RedPlate - item
            Table Counter - surface
            PinkDrawer BlueDrawer - drawer
            Corner - furniture
            Chair - obstacle)
  (:init (graspable RedPlate) (on_top RedPlate Table) (hand_free)
         (clear Table) (clear Counter) (clear PinkDrawer) (clear BlueDrawer)
         (blocking Chair Corner))
  (:goal (and (inside RedPlate PinkDrawer))))
