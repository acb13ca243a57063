;; BYO corpus, twoarm, larger task (17 objects): pack a gift.  Two closed boxes
;; (sewing-box, jewel-box) hold what goes into the open gift-box; the cookie
;; tin stays closed.  Both closed boxes' lids must come off (remove-lid twice).
(define (problem twoarm-pack-gift)
  (:domain twoarm)
  (:objects left-arm right-arm - arm
            silk-ribbon pin-cushion gold-ring pearl-necklace butter-cookie
            greeting-card paper-star - item
            sewing-lid jewel-lid tin-lid gift-lid - lid
            sewing-box jewel-box cookie-tin gift-box - box)
  (:init (free left-arm) (free right-arm)
         (in-box silk-ribbon sewing-box) (in-box pin-cushion sewing-box) (lid-on sewing-lid sewing-box)
         (in-box gold-ring jewel-box) (in-box pearl-necklace jewel-box) (lid-on jewel-lid jewel-box)
         (in-box butter-cookie cookie-tin) (lid-on tin-lid cookie-tin)
         (box-open gift-box) (on-table gift-lid)
         (on-table greeting-card) (on-table paper-star))
  (:goal (and (in-box silk-ribbon gift-box)
              (in-box gold-ring gift-box)
              (in-box greeting-card gift-box))))
