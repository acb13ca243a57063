;; BYO corpus, switches, larger task (18 objects): evening lights in a house
;; with three breakers (the upper-floor and garden ones tripped), seven wall
;; switches and eight lamps.  The kitchen already has light.  The optimal plan
;; resets the upper breaker and turns on three switches (the reading lamp and
;; the desk lamp share the study switch): turn-on three times.
(define (problem switches-evening-lights)
  (:domain switches)
  (:objects ground-breaker upper-breaker garden-breaker - breaker
            kitchen-switch study-switch porch-switch stair-switch
            bedroom-switch bath-switch shed-switch - switch
            kitchen-lamp reading-lamp desk-lamp porch-lamp stair-lamp
            bedside-lamp bath-lamp shed-lamp - lamp)
  (:init (breaker-up ground-breaker)
         (feeds ground-breaker kitchen-switch) (feeds ground-breaker study-switch)
         (feeds ground-breaker porch-switch) (feeds ground-breaker stair-switch)
         (feeds upper-breaker bedroom-switch) (feeds upper-breaker bath-switch)
         (feeds garden-breaker shed-switch)
         (wired kitchen-switch kitchen-lamp)
         (wired study-switch reading-lamp) (wired study-switch desk-lamp)
         (wired porch-switch porch-lamp) (wired stair-switch stair-lamp)
         (wired bedroom-switch bedside-lamp) (wired bath-switch bath-lamp)
         (wired shed-switch shed-lamp)
         (on kitchen-switch) (lit kitchen-lamp))
  (:goal (and (lit reading-lamp) (lit desk-lamp) (lit porch-lamp)
              (lit bedside-lamp) (lit kitchen-lamp))))
