; A household robot with ADL skills: a tray carries whatever is on it,
; a cupboard is usable when its door is open or it has no door,
; and a room is tidy when every item in it is put away (a derived predicate).
(define (domain adl-household)
  (:requirements :adl :derived-predicates)
  (:types room place - object
          tray item - object)
  (:predicates (in-room ?p - place ?r - room)
               (tray-at ?t - tray ?p - place)
               (item-at ?i - item ?p - place)
               (on-tray ?i - item ?t - tray)
               (has-door ?p - place)
               (door-open ?p - place)
               (cupboard ?p - place)
               (stored ?i - item)
               (belongs ?i - item ?r - room)
               (tidy ?r - room))

  (:derived (tidy ?r - room)
    (forall (?i - item) (imply (belongs ?i ?r) (stored ?i))))

  (:action open-door
    :parameters (?p - place)
    :precondition (and (has-door ?p) (not (door-open ?p)))
    :effect (door-open ?p))

  (:action load
    :parameters (?i - item ?t - tray ?p - place)
    :precondition (and (item-at ?i ?p) (tray-at ?t ?p) (not (stored ?i)))
    :effect (and (on-tray ?i ?t) (not (item-at ?i ?p))))

  (:action carry
    :parameters (?t - tray ?from ?to - place)
    :precondition (and (tray-at ?t ?from) (not (= ?from ?to)))
    :effect (and (tray-at ?t ?to) (not (tray-at ?t ?from))))

  (:action unload-all
    :parameters (?t - tray ?p - place)
    :precondition (and (tray-at ?t ?p)
                       (exists (?i - item) (on-tray ?i ?t))
                       (or (not (cupboard ?p)) (not (has-door ?p)) (door-open ?p)))
    :effect (forall (?i - item)
              (when (on-tray ?i ?t)
                (and (item-at ?i ?p) (not (on-tray ?i ?t))
                     (when (cupboard ?p) (stored ?i)))))))
